import { FLAT_CORNERS, FLAT_PROVOKING_VERTEX, flatShadingGeometry, SPHERE_FLAG } from '@shadelab/material';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import fc from 'fast-check';
import { BufferAttribute, BufferGeometry, IcosahedronGeometry } from 'three';
import { describe, expect, it } from 'vitest';

/** The corners of triangle k as position triples. */
function corners(g: BufferGeometry, k: number): number[][] {
  const p = g.getAttribute('position');
  return [0, 1, 2].map((c) => {
    const i = g.index === null ? 3 * k + c : g.index.getX(3 * k + c);
    return [p.getX(i), p.getY(i), p.getZ(i)];
  });
}

/** Every property flat shading relies on, checked triangle by triangle against the source geometry. */
function expectFlatReady(
  source: BufferGeometry,
  out: BufferGeometry,
  provokingVertex: 'first' | 'last' = 'last',
): void {
  expect(out.userData[FLAT_PROVOKING_VERTEX]).toBe(provokingVertex);
  const index = out.index!;
  const triangles = index.count / 3;
  expect(triangles).toBe((source.index?.count ?? source.getAttribute('position').count) / 3);
  const position = out.getAttribute('position');
  const [a, b] = FLAT_CORNERS.map((name) => out.getAttribute(name));
  expect(a.count).toBe(position.count);
  expect(b.count).toBe(position.count);
  // The source vertices come first, unchanged.
  const sourcePosition = source.getAttribute('position');
  for (let i = 0; i < sourcePosition.count; i++) {
    expect([position.getX(i), position.getY(i), position.getZ(i)]).toEqual([
      sourcePosition.getX(i),
      sourcePosition.getY(i),
      sourcePosition.getZ(i),
    ]);
  }
  const provoking = new Set<number>();
  for (let k = 0; k < triangles; k++) {
    const first = provokingVertex === 'first';
    const last = index.getX(3 * k + (first ? 0 : 2));
    // Each face has a provoking vertex (the last, or the first) of its own.
    expect(provoking.has(last), `triangle ${k}: vertex ${last} already provokes a face`).toBe(false);
    provoking.add(last);
    // Same face, same winding: the corners are a cyclic rotation of the source's.
    const want = corners(source, k);
    const got = corners(out, k);
    const rotations = [0, 1, 2].map((r) => [got[r], got[(r + 1) % 3], got[(r + 2) % 3]]);
    expect(rotations).toContainEqual(want);
    // The provoking vertex carries the other two corners, in winding order after it: (A, B, provoking).
    expect([a.getX(last), a.getY(last), a.getZ(last)]).toEqual(got[first ? 1 : 0]);
    expect([b.getX(last), b.getY(last), b.getZ(last)]).toEqual(got[first ? 2 : 1]);
  }
  expect(position.count).toBeGreaterThanOrEqual(triangles);
}

describe('flatShadingGeometry', () => {
  it('gives every face of the subdivision sphere its own last vertex, keeping faces and winding', () => {
    for (const level of [0, 1, 2, 3, 4]) {
      const sphere = new SubdivisionSphereGeometry({ level, base: 'tetrahedron', normals: 'none' });
      expectFlatReady(sphere, flatShadingGeometry(sphere));
    }
  });

  it("with provokingVertex 'first' (WebGPU's), every face has a first vertex of its own, same faces, same vertex count", () => {
    for (const level of [0, 2, 4]) {
      const sphere = new SubdivisionSphereGeometry({ level, base: 'icosahedron', normals: 'none' });
      const first = flatShadingGeometry(sphere, { provokingVertex: 'first' });
      expectFlatReady(sphere, first, 'first');
      const last = flatShadingGeometry(sphere);
      // The same vertices (positions and corners): only each triangle's index order is rotated.
      expect(first.getAttribute('position').array).toEqual(last.getAttribute('position').array);
      expect(first.getAttribute(FLAT_CORNERS[0]).array).toEqual(last.getAttribute(FLAT_CORNERS[0]).array);
    }
    const soup = new IcosahedronGeometry(1, 1);
    expectFlatReady(soup, flatShadingGeometry(soup, { provokingVertex: 'first' }), 'first');
    expect(() => flatShadingGeometry(soup, { provokingVertex: 'middle' as never })).toThrow(
      /flatShadingGeometry\.provokingVertex must be one of/,
    );
  });

  it('a closed sphere (V = T/2 + 2) gets exactly V′ = T vertices: a third of the soup’s vertex-shader runs', () => {
    for (const base of ['tetrahedron', 'octahedron', 'icosahedron'] as const) {
      const sphere = new SubdivisionSphereGeometry({ level: 5, base, normals: 'none' });
      const triangles = sphere.index!.count / 3;
      const out = flatShadingGeometry(sphere);
      expect(out.getAttribute('position').count).toBe(triangles);
      expect(out.index!.array).toBeInstanceOf(Uint16Array);
    }
    const big = flatShadingGeometry(new SubdivisionSphereGeometry({ level: 8, normals: 'none' }));
    expect(big.index!.array).toBeInstanceOf(Uint32Array);
  });

  it('accepts a triangle soup and any indexed mesh (property); only a sphere stays flagged as one', () => {
    const soup = new IcosahedronGeometry(1, 1); // non-indexed
    expectFlatReady(soup, flatShadingGeometry(soup));
    expect(flatShadingGeometry(soup).userData[SPHERE_FLAG]).toBeUndefined();
    expect(flatShadingGeometry(new SubdivisionSphereGeometry({ level: 1 })).userData[SPHERE_FLAG]).toBe(true);
    fc.assert(
      fc.property(
        fc.integer({ min: 3, max: 12 }).chain((n) =>
          fc.tuple(
            fc.array(fc.float({ min: -10, max: 10, noNaN: true }), { minLength: 3 * n, maxLength: 3 * n }),
            fc.array(fc.tuple(fc.nat(n - 1), fc.nat(n - 1), fc.nat(n - 1)), {
              minLength: 1,
              maxLength: 40,
            }),
          ),
        ),
        ([xyz, faces]) => {
          const g = new BufferGeometry();
          g.setAttribute('position', new BufferAttribute(new Float32Array(xyz), 3));
          g.setIndex(faces.flat());
          expectFlatReady(g, flatShadingGeometry(g));
        },
      ),
      { numRuns: 200 },
    );
  });

  it('refuses a geometry without a 3-component position or with a partial triangle, naming it', () => {
    expect(() => flatShadingGeometry(new BufferGeometry())).toThrow(/position attribute/);
    expect(() => flatShadingGeometry(null as unknown as BufferGeometry)).toThrow(TypeError);
    const partial = new BufferGeometry();
    partial.setAttribute('position', new BufferAttribute(new Float32Array(12), 3));
    expect(() => flatShadingGeometry(partial)).toThrow(/multiple of 3, got 4/);
  });
});
