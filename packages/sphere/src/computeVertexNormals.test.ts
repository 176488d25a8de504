import { subdivideSphere } from '@shadelab/sphere';
import { computeVertexNormals, type NormalWeighting } from '@shadelab/sphere/normals';
import fc from 'fast-check';
import { BoxGeometry, BufferAttribute, BufferGeometry, TorusKnotGeometry } from 'three';
import { describe, expect, it } from 'vitest';

const WEIGHTINGS: NormalWeighting[] = ['average', 'area', 'angle'];

function expectUnitFinite(normals: Float32Array) {
  for (let i = 0; i < normals.length; i += 3) {
    const length = Math.hypot(normals[i], normals[i + 1], normals[i + 2]);
    expect(Number.isFinite(length)).toBe(true);
    expect(Math.abs(length - 1)).toBeLessThan(1e-6);
  }
}

function maxDifference(a: ArrayLike<number>, b: ArrayLike<number>) {
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
}

/** The lecture's rule written out directly: n = Σ n̂_f / |Σ n̂_f| over the faces using the vertex. */
function lectureAverage(positions: number[], indices: number[]): number[] {
  const sums = positions.map(() => 0);
  for (let t = 0; t < indices.length; t += 3) {
    const [a, b, c] = [indices[t], indices[t + 1], indices[t + 2]].map((i) =>
      [0, 1, 2].map((k) => positions[3 * i + k]),
    );
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const l = Math.hypot(n[0], n[1], n[2]);
    for (const i of [indices[t], indices[t + 1], indices[t + 2]])
      for (let k = 0; k < 3; k++) sums[3 * i + k] += n[k] / l;
  }
  const out: number[] = [];
  for (let i = 0; i < sums.length; i += 3) {
    const l = Math.hypot(sums[i], sums[i + 1], sums[i + 2]);
    out.push(sums[i] / l, sums[i + 1] / l, sums[i + 2] / l);
  }
  return out;
}

describe('computeVertexNormals', () => {
  it("'area' equals three.js's BufferGeometry.computeVertexNormals (area-weighted) on three's own meshes", () => {
    for (const geometry of [new TorusKnotGeometry(1, 0.3, 64, 8), new BoxGeometry(1, 2, 3, 2, 3, 4)]) {
      const positions = geometry.getAttribute('position').array as Float32Array;
      const indices = geometry.getIndex()!.array as Uint16Array;
      const reference = new BufferGeometry();
      reference.setAttribute('position', new BufferAttribute(positions, 3));
      reference.setIndex(new BufferAttribute(indices, 1));
      reference.computeVertexNormals();
      const ours = computeVertexNormals(positions, indices, 'area');
      expect(maxDifference(ours, reference.getAttribute('normal').array)).toBeLessThan(1e-5);
    }
  });

  it("'average' is the lecture's normalised sum of unit face normals", () => {
    const mesh = subdivideSphere({ base: 'icosahedron', level: 2, radius: 2, normals: 'none' });
    const ours = computeVertexNormals(mesh.positions, mesh.indices, 'average');
    expect(
      maxDifference(ours, lectureAverage(Array.from(mesh.positions), Array.from(mesh.indices!))),
    ).toBeLessThan(1e-6);
    // … and on a sphere it approaches the exact normal, position / radius.
    expect(
      maxDifference(
        ours,
        Array.from(mesh.positions, (x) => x / 2),
      ),
    ).toBeLessThan(0.02);
  });

  it("'angle' is independent of the triangulation: a cube corner gets (1, 1, 1)/√3, 'average' does not", () => {
    // Unit cube corners; each square split into two triangles along a diagonal, counter-clockwise outward.
    const p = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1];
    const quads = [
      [0, 3, 2, 1],
      [4, 5, 6, 7],
      [0, 1, 5, 4],
      [2, 3, 7, 6],
      [1, 2, 6, 5],
      [0, 4, 7, 3],
    ];
    const indices = quads.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]);
    const angle = computeVertexNormals(p, indices, 'angle');
    const average = computeVertexNormals(p, indices, 'average');
    for (let v = 0; v < 8; v++) {
      const expected = [0, 1, 2].map((k) => (p[3 * v + k] - 0.5) / (0.5 * Math.sqrt(3)));
      expect(maxDifference(angle.subarray(3 * v, 3 * v + 3), expected)).toBeLessThan(1e-6);
    }
    expect(maxDifference(average, angle)).toBeGreaterThan(0.05);
  });

  it('every weighting: a symmetric pyramid apex points straight up; a flat patch gets the plane normal', () => {
    const pyramid = [0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0];
    const fan = [0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1];
    const flat = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.3, 0.6, 0];
    const flatIndices = [4, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0];
    for (const w of WEIGHTINGS) {
      expect(maxDifference(computeVertexNormals(pyramid, fan, w).subarray(0, 3), [0, 0, 1])).toBeLessThan(
        1e-7,
      );
      const n = computeVertexNormals(flat, flatIndices, w);
      for (let i = 0; i < n.length; i += 3) expect([n[i], n[i + 1], n[i + 2]]).toEqual([0, 0, 1]);
    }
  });

  it('a triangle soup (indices null) gets its face normals', () => {
    const soup = subdivideSphere({ base: 'octahedron', level: 2, normals: 'flat', indexed: false });
    for (const w of WEIGHTINGS) {
      expect(maxDifference(computeVertexNormals(soup.positions, null, w), soup.normals!)).toBeLessThan(1e-6);
    }
  });

  it('extremes: zero-area faces and repeated vertices give finite unit normals (documented fallbacks)', () => {
    // Vertex 0, 1, 2: a proper triangle. 3: only in a face with a repeated index. 4, 5: only in a collinear face.
    // 6: unused, at the origin. 7: unused, off the origin. 8: only in degenerate faces at the origin.
    const positions = [0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 0, 0, 3, 0, 0, 6, 0, 0, 0, 0, -5, 0, 0, 0, 0];
    const indices = [0, 1, 2, 3, 3, 1, 0, 4, 5, 8, 8, 8, 0, 0, 0];
    for (const w of WEIGHTINGS) {
      const n = computeVertexNormals(positions, indices, w);
      expectUnitFinite(n);
      expect(Array.from(n.subarray(0, 9))).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1]); // the real face
      expect(Array.from(n.subarray(9, 12))).toEqual([1, 0, 0]); // fallback: the position's direction
      expect(Array.from(n.subarray(12, 18))).toEqual([0, 0, 1, 0, 0, 1]);
      expect(Array.from(n.subarray(18, 21))).toEqual([0, 0, 1]); // at the origin: (0, 0, 1)
      expect(Array.from(n.subarray(21, 24))).toEqual([0, -1, 0]);
      expect(Array.from(n.subarray(24, 27))).toEqual([0, 0, 1]);
    }
  });

  it('extremes: meshes scaled by 1e-20 and 1e20 get the same normals as at scale 1', () => {
    const mesh = subdivideSphere({ base: 'icosahedron', level: 1, normals: 'none' });
    for (const w of WEIGHTINGS) {
      const reference = computeVertexNormals(mesh.positions, mesh.indices, w);
      for (const scale of [1e-20, 1e20, 1e-150, 1e150]) {
        const scaled = Float64Array.from(mesh.positions, (x) => x * scale);
        const n = computeVertexNormals(scaled, mesh.indices, w);
        expectUnitFinite(n);
        expect(maxDifference(n, reference)).toBeLessThan(1e-6);
      }
    }
  });

  it('property: any mesh, including degenerate ones, gives finite unit normals for every weighting', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 12 }).chain((v) =>
          fc.tuple(
            fc.array(fc.oneof(fc.double({ min: -10, max: 10, noNaN: true }), fc.constantFrom(0, 1, -1)), {
              minLength: 3 * v,
              maxLength: 3 * v,
            }),
            fc
              .array(fc.integer({ min: 0, max: v - 1 }), { maxLength: 60 })
              .map((a) => a.slice(0, a.length - (a.length % 3))),
          ),
        ),
        fc.constantFrom(...WEIGHTINGS),
        ([positions, indices], weighting) => {
          expectUnitFinite(computeVertexNormals(positions, indices, weighting));
        },
      ),
      { numRuns: 300 },
    );
  });

  it('property: the normal of a vertex used by proper faces has a positive component along each of them', () => {
    fc.assert(
      fc.property(
        fc.constantFrom('tetrahedron', 'octahedron', 'icosahedron' as const),
        fc.integer({ min: 0, max: 3 }),
        fc.constantFrom(...WEIGHTINGS),
        (base, level, weighting) => {
          const { positions, indices } = subdivideSphere({ base, level, normals: 'none' });
          const n = computeVertexNormals(positions, indices, weighting);
          // Sphere meshes are convex: every vertex normal points outwards.
          for (let i = 0; i < positions.length; i += 3) {
            expect(
              n[i] * positions[i] + n[i + 1] * positions[i + 1] + n[i + 2] * positions[i + 2],
            ).toBeGreaterThan(0);
          }
        },
      ),
      { numRuns: 20 },
    );
  });

  it('bad input: RangeError / TypeError naming the parameter, the value and the allowed range', () => {
    expect(() => computeVertexNormals([0, 0], [])).toThrow('positions.length must be a multiple of 3; got 2');
    expect(() => computeVertexNormals([0, 0, 0], [0, 0])).toThrow(
      'indices.length must be a multiple of 3; got 2',
    );
    expect(() => computeVertexNormals([0, 0, 0], [0, 0, 1])).toThrow(
      'indices[2] must be an integer from 0 to 0 (vertex count − 1); got 1',
    );
    expect(() => computeVertexNormals([0, 0, 0], [0, 0, 0.5])).toThrow(RangeError);
    expect(() => computeVertexNormals([0, 0, 0], [0, 0, -1])).toThrow(RangeError);
    expect(() => computeVertexNormals([0, 0, 0], [0, 0, 0], 'median' as never)).toThrow(
      "weighting must be 'average', 'area' or 'angle'; got 'median'",
    );
    expect(() => computeVertexNormals([0, 0, 0], [0, 0, 0], 3 as never)).toThrow(TypeError);
    expect(() => computeVertexNormals(undefined as never, [])).toThrow(TypeError);
    expect(() => computeVertexNormals([0, 0, 0, 1, 1, 1], null)).toThrow(/multiple of 3; got 2/);
  });
});
