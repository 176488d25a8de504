import { SPHERE_BASES, type SphereBase, subdivideSphere } from '@shadelab/sphere';
import { MAX_SPHERE_ERROR_LEVEL, sphereError } from '@shadelab/sphere/detail';
import fc from 'fast-check';
import { IcosahedronGeometry, OctahedronGeometry } from 'three';
import { describe, expect, it } from 'vitest';
import {
  closestPointError,
  lectureSubdivision,
  lectureTetrahedron,
  meshRadialError,
  meshTriangles,
  unitTriangles,
} from './meshChecks.test-util.js';

type Vec = readonly [number, number, number];

/** Exact (double) vertices of three's octahedron and icosahedron: (±1, 0, 0)…, and (±1, ±φ, 0) cycled, normalised. */
function exactVertices(base: 'octahedron' | 'icosahedron'): Vec[] {
  if (base === 'octahedron') {
    return [
      [1, 0, 0],
      [-1, 0, 0],
      [0, 1, 0],
      [0, -1, 0],
      [0, 0, 1],
      [0, 0, -1],
    ];
  }
  const t = (1 + Math.sqrt(5)) / 2;
  const l = Math.hypot(1, t);
  const out: Vec[] = [];
  for (const s of [-1, 1]) {
    for (const u of [-1, 1]) {
      out.push([s / l, (u * t) / l, 0], [0, s / l, (u * t) / l], [(u * t) / l, 0, s / l]);
    }
  }
  return out;
}

/** Level-0 triangles in double precision: the lecture's tetrahedron, or three's faces snapped to exact vertices. */
function referenceBase(base: SphereBase): Vec[][] {
  if (base === 'tetrahedron') return lectureTetrahedron();
  const geometry = base === 'octahedron' ? new OctahedronGeometry(1, 0) : new IcosahedronGeometry(1, 0);
  const exact = exactVertices(base);
  const snap = (v: Vec) =>
    exact.reduce((a, b) =>
      Math.hypot(a[0] - v[0], a[1] - v[1], a[2] - v[2]) < Math.hypot(b[0] - v[0], b[1] - v[1], b[2] - v[2])
        ? a
        : b,
    );
  return unitTriangles(geometry.getAttribute('position').array).map((t) => t.map(snap));
}

/** Brute force: the largest 1 − min |p| over every face of the whole double-precision mesh. */
function bruteForce(base: SphereBase, level: number): number {
  let worst = 0;
  for (const [a, b, c] of lectureSubdivision(referenceBase(base), level)) {
    worst = Math.max(worst, closestPointError(a, b, c));
  }
  return worst;
}

const BRUTE_FORCE_LEVELS: Record<SphereBase, number> = { tetrahedron: 7, octahedron: 7, icosahedron: 6 };

describe('sphereError', () => {
  for (const base of SPHERE_BASES) {
    it(`${base}: equals the brute-force max over every face of the mesh (closest point to the centre), 1e-6 relative`, () => {
      for (let level = 0; level <= BRUTE_FORCE_LEVELS[base]; level++) {
        const brute = bruteForce(base, level);
        expect(Math.abs(sphereError(base, level) - brute)).toBeLessThanOrEqual(1e-6 * brute);
      }
    });
  }

  it('agrees with dense sampling of the float32 mesh subdivideSphere builds (within float32 rounding)', () => {
    for (const base of SPHERE_BASES) {
      for (const level of [0, 1, 2, 3]) {
        const mesh = subdivideSphere({ base, level, normals: 'none' });
        let worst = 0;
        const n = 24;
        for (const [a, b, c] of meshTriangles(mesh.positions, mesh.indices!)) {
          for (let i = 0; i <= n; i++) {
            for (let j = 0; i + j <= n; j++) {
              const u = i / n;
              const v = j / n;
              const w = 1 - u - v;
              const p = [0, 1, 2].map((k) => u * a[k] + v * b[k] + w * c[k]);
              worst = Math.max(worst, 1 - Math.hypot(p[0], p[1], p[2]));
            }
          }
        }
        const exact = sphereError(base, level);
        expect(worst).toBeLessThanOrEqual(exact * (1 + 1e-4) + 1e-7); // sampling can only underestimate
        expect(worst).toBeGreaterThan(exact * 0.98);
      }
    }
  });

  // sphereError is exact for the exact-vertex mesh. The mesh subdivideSphere returns stores float32
  // coordinates: rounding one moves it by at most half an ulp, ≤ 2^-24 · |coordinate|, so a vertex moves by at
  // most 2^-24 · radius and so does every point of a face (a convex combination of its corners). A second
  // 2^-24 · radius covers the drift of midpoints computed from already-rounded parents (a face's circumradius ρ
  // moves by a few 2^-24, its depth by ρ times that) and the measurement's own double arithmetic. Measured:
  // at most 0.43 · 2^-24 · radius, either sign.
  const FLOAT32_ERROR_TOLERANCE = 2 ** -23;
  const FLOAT32_LEVELS: [SphereBase, number[], number][] = [
    ['tetrahedron', [6, 7, 8, 9, 10], 1],
    ['octahedron', [6, 7, 8, 9], 3.7],
    ['icosahedron', [6, 7, 8], 1],
  ];
  for (const [base, levels, radius] of FLOAT32_LEVELS) {
    it(`${base} levels ${levels[0]}–${levels.at(-1)}, radius ${radius}: the float32 mesh's error is radius · sphereError within radius · 2^-23`, () => {
      for (const level of levels) {
        const mesh = subdivideSphere({ base, level, radius, normals: 'none' });
        const measured = radius * meshRadialError(mesh.positions, mesh.indices!, radius);
        const exact = radius * sphereError(base, level);
        expect(Math.abs(measured - exact), `level ${level}`).toBeLessThanOrEqual(
          FLOAT32_ERROR_TOLERANCE * radius,
        );
      }
    });
  }

  it('level 0: the inradius gap of each solid, 1 − √(1 − ρ²) with ρ the face circumradius', () => {
    expect(sphereError('tetrahedron', 0)).toBeCloseTo(2 / 3, 14); // inradius 1/3
    expect(sphereError('octahedron', 0)).toBeCloseTo(1 - 1 / Math.sqrt(3), 14);
    const chord = 1 / Math.sin((2 * Math.PI) / 5); // icosahedron edge for circumradius 1
    expect(sphereError('icosahedron', 0)).toBeCloseTo(1 - Math.sqrt(1 - chord ** 2 / 3), 14);
  });

  it('the edge sagitta alone understates the error (about 3/4 of it on near-equilateral faces)', () => {
    // Icosahedron level 0: equilateral faces; the sagitta of an edge is 1 − cos(θ/2), with θ its arc.
    const chord = 1 / Math.sin((2 * Math.PI) / 5);
    const sagitta = 1 - Math.sqrt(1 - chord ** 2 / 4);
    const error = sphereError('icosahedron', 0);
    expect(sagitta).toBeLessThan(error);
    expect(sagitta / error).toBeGreaterThan(0.6);
    expect(sagitta / error).toBeLessThan(0.8);
  });

  it('falls with every level and approaches a constant × 4^−level; memoised', () => {
    for (const base of SPHERE_BASES) {
      let previous = Number.POSITIVE_INFINITY;
      for (let level = 0; level <= MAX_SPHERE_ERROR_LEVEL; level++) {
        const e = sphereError(base, level);
        expect(e).toBeGreaterThan(0);
        expect(e).toBeLessThan(previous);
        expect(sphereError(base, level)).toBe(e);
        previous = e;
      }
      const ratio = sphereError(base, 20) / sphereError(base, 19);
      expect(ratio).toBeCloseTo(1 / 4, 5);
    }
  });

  it('level 1 of the tetrahedron contains the octahedron: the same error as octahedron level 0', () => {
    for (let level = 0; level <= 8; level++) {
      expect(sphereError('tetrahedron', level + 1)).toBeCloseTo(sphereError('octahedron', level), 12);
    }
  });

  it('bad base or level: RangeError / TypeError naming it and the allowed range', () => {
    expect(() => sphereError('cube' as never, 1)).toThrow(RangeError);
    expect(() => sphereError('cube' as never, 1)).toThrow(
      /base must be 'tetrahedron', 'octahedron' or 'icosahedron'; got 'cube'/,
    );
    expect(() => sphereError(undefined as never, 1)).toThrow(TypeError);
    for (const level of [-1, 0.5, Number.NaN, MAX_SPHERE_ERROR_LEVEL + 1, Number.POSITIVE_INFINITY]) {
      expect(() => sphereError('icosahedron', level)).toThrow(RangeError);
      expect(() => sphereError('icosahedron', level)).toThrow(
        `level must be an integer from 0 to 20; got ${level}`,
      );
    }
    expect(() => sphereError('icosahedron', '2' as never)).toThrow(TypeError);
  });

  it('property: the error bounds every sampled point of every face at small levels', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...SPHERE_BASES),
        fc.integer({ min: 0, max: 4 }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (base, level, s, t) => {
          const u = Math.min(s, t);
          const v = Math.max(s, t) - u;
          const w = 1 - u - v;
          const e = sphereError(base, level);
          for (const [a, b, c] of lectureSubdivision(referenceBase(base), level)) {
            const p = [0, 1, 2].map((k) => u * a[k] + v * b[k] + w * c[k]);
            expect(1 - Math.hypot(p[0], p[1], p[2])).toBeLessThanOrEqual(e + 1e-12);
          }
        },
      ),
      { numRuns: 25 },
    );
  });
});
