import {
  DEFAULT_SPHERE_MAX_BYTES,
  estimateSphereBytes,
  SPHERE_BASES,
  type SphereBase,
  sphereCounts,
  subdivideSphere,
} from '@shadelab/sphere';
import fc from 'fast-check';
import { IcosahedronGeometry, OctahedronGeometry } from 'three';
import { describe, expect, it } from 'vitest';
import {
  checkClosedOriented,
  countAllocatedBytes,
  duplicateVertices,
  FLOAT32_RADIUS_TOLERANCE,
  inwardFaces,
  lectureSubdivision,
  lectureTetrahedron,
  maxRadialDeviation,
  meshTriangles,
  triangleIndices,
  triangleKeys,
  unitTriangles,
  unmatchedTriangles,
  weld,
} from './meshChecks.test-util.js';

const F0: Record<SphereBase, number> = { tetrahedron: 4, octahedron: 8, icosahedron: 20 };

/** The base solid's level-0 triangles from a trusted source: the lecture, or three.js at detail 0. */
function referenceBase(base: SphereBase) {
  if (base === 'tetrahedron') return lectureTetrahedron();
  const geometry = base === 'octahedron' ? new OctahedronGeometry(1, 0) : new IcosahedronGeometry(1, 0);
  return unitTriangles(geometry.getAttribute('position').array) as never;
}

describe('subdivideSphere counts (docs/design.md extremes: level 0 … 10, every base)', () => {
  for (const base of SPHERE_BASES) {
    for (let level = 0; level <= 10; level++) {
      it(`${base} level ${level}: T = ${F0[base]}·4^${level}, V = 2 + T/2, all vertices at the radius`, () => {
        const T = F0[base] * 4 ** level;
        const V = 2 + T / 2;
        const radius = 2.5;
        // High levels: indexed without normals keeps the suite fast (the icosahedron at 10 is 21M triangles).
        const mesh = subdivideSphere({ base, level, radius, normals: level <= 7 ? 'smooth' : 'none' });
        expect(mesh.positions.length).toBe(3 * V);
        expect(mesh.indices?.length).toBe(3 * T);
        expect(mesh.indices).toBeInstanceOf(V <= 65536 ? Uint16Array : Uint32Array);
        expect(sphereCounts(base, level)).toEqual({ triangles: T, vertices: V, edges: (3 * T) / 2 });
        expect(maxRadialDeviation(mesh.positions, radius)).toBeLessThan(FLOAT32_RADIUS_TOLERANCE);
        if (level <= 7) expect(mesh.normals?.length).toBe(3 * V);
        let maxIndex = 0;
        for (const i of mesh.indices ?? []) if (i > maxIndex) maxIndex = i;
        expect(maxIndex).toBe(V - 1);
      });
    }
    for (let level = 0; level <= 5; level++) {
      it(`${base} level ${level} non-indexed: 3T vertices at the radius, smooth and flat normals`, () => {
        const T = F0[base] * 4 ** level;
        for (const normals of ['smooth', 'flat', 'none'] as const) {
          const mesh = subdivideSphere({ base, level, normals, indexed: false, radius: 0.75 });
          expect(mesh.positions.length).toBe(9 * T);
          expect(mesh.indices).toBeUndefined();
          expect(mesh.normals?.length).toBe(normals === 'none' ? undefined : 9 * T);
          expect(maxRadialDeviation(mesh.positions, 0.75)).toBeLessThan(FLOAT32_RADIUS_TOLERANCE);
        }
      });
    }
  }
});

describe('subdivideSphere topology and winding', () => {
  for (const base of SPHERE_BASES) {
    const top = base === 'tetrahedron' ? 10 : 8;
    for (let level = 0; level <= top; level++) {
      it(`${base} level ${level}: closed, every edge in exactly two faces, V − E + F = 2, outward, no duplicates`, () => {
        const mesh = subdivideSphere({ base, level, normals: 'none' });
        const indices = mesh.indices!;
        const { V, E, F, problems } = checkClosedOriented(indices);
        expect(problems).toBe(0);
        expect(F).toBe(F0[base] * 4 ** level);
        expect(V).toBe(mesh.positions.length / 3);
        expect(V - E + F).toBe(2);
        expect(E).toBe((3 * F) / 2);
        expect(inwardFaces(mesh.positions, indices)).toBe(0);
        // No two vertices at the same place.
        expect(duplicateVertices(mesh.positions)).toBe(0);
      });
      if (level > 5) continue; // soups: the same code path, welded by a slower sort
      it(`${base} level ${level} non-indexed: the same closed oriented surface once welded`, () => {
        const soup = subdivideSphere({ base, level, normals: 'none', indexed: false });
        const welded = weld(soup.positions, triangleIndices(soup.positions));
        const { V, E, F, problems } = checkClosedOriented(welded);
        expect(problems).toBe(0);
        expect(V - E + F).toBe(2);
        expect(V).toBe(2 + F / 2);
        expect(inwardFaces(soup.positions, triangleIndices(soup.positions))).toBe(0);
      });
    }
  }
});

describe('the mesh checks find what they look for', () => {
  const tetrahedron = () => subdivideSphere({ base: 'tetrahedron', level: 1, normals: 'none' });
  it('a closed oriented mesh has no problems; a flipped, a missing or a repeated triangle does', () => {
    const { indices } = tetrahedron();
    expect(checkClosedOriented(indices!).problems).toBe(0);
    const flipped = Uint32Array.from(indices!);
    [flipped[1], flipped[2]] = [flipped[2]!, flipped[1]!];
    expect(checkClosedOriented(flipped).problems).toBeGreaterThan(0);
    expect(checkClosedOriented(indices!.slice(3)).problems).toBeGreaterThan(0);
    const repeated = Uint32Array.from([...indices!, ...indices!.slice(0, 3)]);
    expect(checkClosedOriented(repeated).problems).toBeGreaterThan(0);
    expect(checkClosedOriented([0, 0, 1, 1, 0, 0]).problems).toBeGreaterThan(0); // degenerate
  });
  it('duplicate vertices: exact float equality, −0 equal to 0', () => {
    const { positions } = tetrahedron();
    expect(duplicateVertices(positions)).toBe(0);
    const copy = new Float32Array([...positions, ...positions.slice(3, 6)]);
    expect(duplicateVertices(copy)).toBe(1);
    expect(duplicateVertices(new Float32Array([0, 1, 2, -0, 1, 2, 0, 1, 2.0000002]))).toBe(1);
  });
});

describe('subdivideSphere against trusted references', () => {
  it("level 0 of the tetrahedron is the lecture's: a vertex at (0, 0, 1) and its four faces", () => {
    const mesh = subdivideSphere({ base: 'tetrahedron', level: 0, normals: 'none' });
    expect(Array.from(mesh.positions.slice(0, 3))).toEqual([0, 0, 1]);
    expect(triangleKeys(meshTriangles(mesh.positions, mesh.indices!))).toEqual(
      triangleKeys(lectureTetrahedron()),
    );
  });

  it("level 0 of the octahedron and icosahedron has three.js's triangles (detail 0), same winding", () => {
    for (const [base, geometry] of [
      ['octahedron', new OctahedronGeometry(3, 0)],
      ['icosahedron', new IcosahedronGeometry(3, 0)],
    ] as const) {
      const mesh = subdivideSphere({ base, level: 0, radius: 3, normals: 'none' });
      const ours = triangleKeys(meshTriangles(mesh.positions, mesh.indices!, 3));
      expect(ours).toEqual(triangleKeys(unitTriangles(geometry.getAttribute('position').array)));
    }
  });

  for (const base of SPHERE_BASES) {
    it(`${base} levels 1–4 have exactly the triangles of the lecture's divideTriangle recursion`, () => {
      for (let level = 1; level <= 4; level++) {
        const mesh = subdivideSphere({ base, level, normals: 'none' });
        const ours = meshTriangles(mesh.positions, mesh.indices!);
        const reference = lectureSubdivision(referenceBase(base), level);
        expect(ours.length).toBe(reference.length);
        expect(unmatchedTriangles(ours, reference, 1e-6)).toBe(0);
      }
    });
  }

  it('non-indexed output is the indexed mesh expanded, triangle by triangle', () => {
    const indexed = subdivideSphere({ base: 'icosahedron', level: 3, radius: 4 });
    const soup = subdivideSphere({ base: 'icosahedron', level: 3, radius: 4, indexed: false });
    const idx = indexed.indices!;
    const expected = Float32Array.from(
      { length: 3 * idx.length },
      (_, i) => indexed.positions[3 * idx[Math.floor(i / 3)] + (i % 3)],
    );
    const expectedNormals = Float32Array.from(
      { length: 3 * idx.length },
      (_, i) => indexed.normals![3 * idx[Math.floor(i / 3)] + (i % 3)],
    );
    expect(soup.positions).toEqual(expected);
    expect(soup.normals).toEqual(expectedNormals);
  });
});

describe('subdivideSphere normals', () => {
  it('smooth normals are position / radius (unit, within float32 rounding), indexed and not', () => {
    for (const indexed of [true, false]) {
      for (const base of SPHERE_BASES) {
        const radius = 7.25;
        const { positions, normals } = subdivideSphere({ base, level: 4, radius, indexed });
        let worst = 0;
        for (let i = 0; i < positions.length; i++) {
          worst = Math.max(worst, Math.abs(normals![i] - positions[i] / radius));
        }
        expect(worst).toBeLessThan(4e-7);
      }
    }
  });

  it('flat normals are unit, perpendicular to their face and outward, the same on its three corners', () => {
    for (const base of SPHERE_BASES) {
      for (const level of [0, 2, 5]) {
        const { positions: p, normals: n } = subdivideSphere({ base, level, normals: 'flat', radius: 3 });
        let worstLength = 0;
        let worstCos = 0;
        let differing = 0;
        let inward = 0;
        for (let i = 0; i < p.length; i += 9) {
          const nx = n![i];
          const ny = n![i + 1];
          const nz = n![i + 2];
          worstLength = Math.max(worstLength, Math.abs(Math.hypot(nx, ny, nz) - 1));
          for (let k = 3; k < 9; k += 3) {
            if (n![i + k] !== nx || n![i + k + 1] !== ny || n![i + k + 2] !== nz) differing++;
            const e = [p[i + k] - p[i], p[i + k + 1] - p[i + 1], p[i + k + 2] - p[i + 2]];
            worstCos = Math.max(
              worstCos,
              Math.abs(e[0] * nx + e[1] * ny + e[2] * nz) / Math.hypot(e[0], e[1], e[2]),
            );
          }
          if (
            nx * (p[i] + p[i + 3] + p[i + 6]) +
              ny * (p[i + 1] + p[i + 4] + p[i + 7]) +
              nz * (p[i + 2] + p[i + 5] + p[i + 8]) <=
            0
          ) {
            inward++;
          }
        }
        expect(worstLength).toBeLessThan(1e-6);
        expect(worstCos).toBeLessThan(1e-4);
        expect(differing).toBe(0);
        expect(inward).toBe(0);
      }
    }
  });

  it("defaults: level 6 tetrahedron, radius 1, smooth normals, indexed; 'flat' alone means non-indexed", () => {
    const mesh = subdivideSphere();
    expect(mesh.indices?.length).toBe(3 * 4 * 4 ** 6);
    expect(mesh.normals?.length).toBe(mesh.positions.length);
    expect(maxRadialDeviation(mesh.positions, 1)).toBeLessThan(FLOAT32_RADIUS_TOLERANCE);
    const flat = subdivideSphere({ level: 1, normals: 'flat' });
    expect(flat.indices).toBeUndefined();
    expect(flat.positions.length).toBe(9 * 16);
  });
});

describe('subdivideSphere extremes (docs/design.md extremes table)', () => {
  it.each([-1, 1.5, Number.NaN, Number.POSITIVE_INFINITY, -0.5])(
    'level %s is a RangeError naming it',
    (level) => {
      expect(() => subdivideSphere({ level })).toThrow(RangeError);
      expect(() => subdivideSphere({ level })).toThrow(/level must be an integer ≥ 0; got /);
      expect(() => subdivideSphere({ level })).toThrow(String(level));
    },
  );

  it('a level that is not a number is a TypeError naming it', () => {
    expect(() => subdivideSphere({ level: '3' as never })).toThrow(TypeError);
    expect(() => subdivideSphere({ level: '3' as never })).toThrow(/level .*got '3'/);
  });

  it.each([0, -1, -0, Number.NaN, Number.POSITIVE_INFINITY, Number.NEGATIVE_INFINITY, 1e31, 1e-31])(
    'radius %s is a RangeError naming it and the allowed range',
    (radius) => {
      expect(() => subdivideSphere({ radius })).toThrow(RangeError);
      expect(() => subdivideSphere({ radius })).toThrow(/radius must be a number from 1e-30 to 1e30; got /);
    },
  );

  it('unknown base or normals: RangeError naming the parameter and the allowed values; wrong types: TypeError', () => {
    expect(() => subdivideSphere({ base: 'cube' as never })).toThrow(RangeError);
    expect(() => subdivideSphere({ base: 'cube' as never })).toThrow(
      "base must be 'tetrahedron', 'octahedron' or 'icosahedron'; got 'cube'",
    );
    expect(() => subdivideSphere({ base: 4 as never })).toThrow(TypeError);
    expect(() => subdivideSphere({ normals: 'phong' as never })).toThrow(
      "normals must be 'smooth', 'flat' or 'none'; got 'phong'",
    );
    expect(() => subdivideSphere({ normals: null as never })).toThrow(TypeError);
    expect(() => subdivideSphere({ indexed: 1 as never })).toThrow(TypeError);
    expect(() => subdivideSphere(null as never)).toThrow(TypeError);
  });

  it('flat normals with indexed: true is a RangeError (a shared corner has several face normals)', () => {
    expect(() => subdivideSphere({ normals: 'flat', indexed: true })).toThrow(RangeError);
    expect(() => subdivideSphere({ normals: 'flat', indexed: true })).toThrow(/'flat' needs indexed: false/);
  });

  it('a level past the memory limit is a RangeError giving the estimated bytes, before allocating', () => {
    const options = { base: 'icosahedron', level: 11, normals: 'none' } as const;
    const bytes = estimateSphereBytes(options);
    expect(bytes).toBeGreaterThan(DEFAULT_SPHERE_MAX_BYTES);
    expect(() => subdivideSphere(options)).toThrow(RangeError);
    expect(() => subdivideSphere(options)).toThrow(
      `(${bytes} bytes), above maxBytes = 537 MB (536870912 bytes)`,
    );
    // Absurd levels are refused the same way (the estimate is Infinity beyond 2^1024).
    expect(() => subdivideSphere({ level: 600 })).toThrow(/needs about .*bytes, above maxBytes/);
    expect(() => subdivideSphere({ level: 40 })).toThrow(RangeError);
  });

  it('maxBytes moves the limit both ways, and must be > 0', () => {
    const options = { base: 'octahedron', level: 5 } as const;
    const bytes = estimateSphereBytes(options);
    expect(() => subdivideSphere({ ...options, maxBytes: bytes - 1 })).toThrow(String(bytes));
    expect(subdivideSphere({ ...options, maxBytes: bytes }).positions.length).toBe(3 * (2 + 4096));
    expect(() => subdivideSphere({ maxBytes: 0 })).toThrow(/maxBytes must be a number > 0/);
    expect(() => subdivideSphere({ maxBytes: Number.NaN })).toThrow(RangeError);
  });

  it('the estimate is exactly the bytes of every typed array the build allocates (counted), levels 0–8', () => {
    for (const base of SPHERE_BASES) {
      for (let level = 0; level <= 8; level++) {
        for (const normals of ['smooth', 'flat', 'none'] as const) {
          for (const indexed of normals === 'flat' ? [false] : [true, false]) {
            if (!indexed && level > 6) continue; // soups: the same code path, only bigger
            const options = { base, level, normals, indexed };
            const { result: mesh, bytes } = countAllocatedBytes(() => subdivideSphere(options));
            const out =
              mesh.positions.byteLength + (mesh.normals?.byteLength ?? 0) + (mesh.indices?.byteLength ?? 0);
            expect(bytes, JSON.stringify(options)).toBe(estimateSphereBytes(options));
            expect(bytes).toBeGreaterThanOrEqual(out);
          }
        }
      }
    }
  });
});

/** What the README and the estimateSphereBytes TSDoc promise at level 10 under the default 512 MiB. */
const LEVEL_10_DEFAULT_LIMIT: {
  base: SphereBase;
  indexed: boolean;
  normals: 'smooth' | 'flat' | 'none';
  bytes: number;
  fits: boolean;
}[] = [
  { base: 'tetrahedron', indexed: true, normals: 'smooth', bytes: 100_663_344, fits: true },
  { base: 'tetrahedron', indexed: true, normals: 'none', bytes: 75_497_496, fits: true },
  { base: 'tetrahedron', indexed: false, normals: 'smooth', bytes: 377_487_384, fits: true },
  { base: 'tetrahedron', indexed: false, normals: 'flat', bytes: 377_487_384, fits: true },
  { base: 'tetrahedron', indexed: false, normals: 'none', bytes: 226_492_440, fits: true },
  { base: 'octahedron', indexed: true, normals: 'smooth', bytes: 201_326_640, fits: true },
  { base: 'octahedron', indexed: true, normals: 'none', bytes: 150_994_968, fits: true },
  { base: 'octahedron', indexed: false, normals: 'smooth', bytes: 754_974_744, fits: false },
  { base: 'octahedron', indexed: false, normals: 'flat', bytes: 754_974_744, fits: false },
  { base: 'octahedron', indexed: false, normals: 'none', bytes: 452_984_856, fits: true },
  { base: 'icosahedron', indexed: true, normals: 'smooth', bytes: 503_316_528, fits: true },
  { base: 'icosahedron', indexed: true, normals: 'none', bytes: 377_487_384, fits: true },
  { base: 'icosahedron', indexed: false, normals: 'smooth', bytes: 1_887_436_824, fits: false },
  { base: 'icosahedron', indexed: false, normals: 'flat', bytes: 1_887_436_824, fits: false },
  { base: 'icosahedron', indexed: false, normals: 'none', bytes: 1_132_462_104, fits: false },
];

describe('subdivideSphere level 10 under the default 512 MiB limit (the documented table)', () => {
  for (const { base, indexed, normals, bytes, fits } of LEVEL_10_DEFAULT_LIMIT) {
    const options = { base, level: 10, indexed, normals };
    const name = `${base} ${indexed ? 'indexed' : 'non-indexed'} normals '${normals}'`;
    expect(estimateSphereBytes(options)).toBe(bytes);
    expect(bytes <= DEFAULT_SPHERE_MAX_BYTES).toBe(fits);
    if (!fits) {
      it(`${name}: refused with the estimate (${bytes} bytes), nothing allocated`, () => {
        const { bytes: allocated } = countAllocatedBytes(() =>
          expect(() => subdivideSphere(options)).toThrow(`(${bytes} bytes), above maxBytes`),
        );
        expect(allocated).toBe(0);
      });
    } else if (indexed && normals === 'smooth') {
      // The default options: built, with exact counts and exactly the estimated allocations.
      it(`${name} (default options): builds, allocating exactly the ${bytes} bytes estimated`, () => {
        const T = F0[base] * 4 ** 10;
        const { result: mesh, bytes: allocated } = countAllocatedBytes(() => subdivideSphere(options));
        expect(allocated).toBe(bytes);
        expect(mesh.positions.length).toBe(3 * (2 + T / 2));
        expect(mesh.normals?.length).toBe(3 * (2 + T / 2));
        expect(mesh.indices).toBeInstanceOf(Uint32Array);
        expect(mesh.indices?.length).toBe(3 * T);
      });
    }
  }
  it('the tetrahedron builds non-indexed with smooth normals at level 10 within the estimate', () => {
    const options = { base: 'tetrahedron', level: 10, indexed: false } as const;
    const { result: mesh, bytes } = countAllocatedBytes(() => subdivideSphere(options));
    expect(bytes).toBe(estimateSphereBytes(options));
    expect(mesh.positions.length).toBe(9 * 4 * 4 ** 10);
  });
});

describe('subdivideSphere properties (fast-check)', () => {
  const arbitraryOptions = fc
    .record({
      base: fc.constantFrom(...SPHERE_BASES),
      level: fc.integer({ min: 0, max: 5 }),
      radius: fc.oneof(
        fc.double({ min: 1e-30, max: 1e30, noNaN: true }),
        fc.double({ min: 0.01, max: 100, noNaN: true }),
      ),
      normals: fc.constantFrom('smooth', 'flat', 'none' as const),
      indexed: fc.boolean(),
    })
    .map((o) => ({ ...o, indexed: o.normals === 'flat' ? false : o.indexed }));

  it('any base, level ≤ 5 and radius: exact counts, every vertex at the radius, every face outward', () => {
    fc.assert(
      fc.property(arbitraryOptions, (options) => {
        const mesh = subdivideSphere(options);
        const T = F0[options.base] * 4 ** options.level;
        const vertices = options.indexed ? 2 + T / 2 : 3 * T;
        expect(mesh.positions.length).toBe(3 * vertices);
        expect(mesh.indices?.length).toBe(options.indexed ? 3 * T : undefined);
        expect(mesh.normals?.length).toBe(options.normals === 'none' ? undefined : 3 * vertices);
        expect(maxRadialDeviation(mesh.positions, options.radius)).toBeLessThan(FLOAT32_RADIUS_TOLERANCE);
        expect(inwardFaces(mesh.positions, triangleIndices(mesh.positions, mesh.indices))).toBe(0);
        expect((mesh.normals ?? []).every(Number.isFinite)).toBe(true);
      }),
      { numRuns: 40 },
    );
  });

  it('scaling the radius scales the positions (same mesh, up to float32 rounding)', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...SPHERE_BASES),
        fc.integer({ min: 0, max: 4 }),
        fc.double({ min: 1e-3, max: 1e3, noNaN: true }),
        (base, level, radius) => {
          const unit = subdivideSphere({ base, level, normals: 'none' });
          const scaled = subdivideSphere({ base, level, radius, normals: 'none' });
          expect(scaled.indices).toEqual(unit.indices);
          let worst = 0;
          for (let i = 0; i < unit.positions.length; i++) {
            worst = Math.max(worst, Math.abs(scaled.positions[i] / radius - unit.positions[i]));
          }
          expect(worst).toBeLessThan(1e-6);
        },
      ),
      { numRuns: 30 },
    );
  });
});
