import {
  estimateSphereBytes,
  SubdivisionSphereGeometry,
  sphereCounts,
  subdivideSphere,
} from '@shadelab/sphere';
import { chooseSphereDetail, sphereError } from '@shadelab/sphere/detail';
import { computeVertexNormals } from '@shadelab/sphere/normals';
import fc from 'fast-check';
import { afterAll, describe, expect, it } from 'vitest';
import { fuzzSeed, hostileNumbers, hostileValue, worksOrNamedError } from '../../../test-utils/fuzz.js';

// Issue 8: every public entry point, fed hostile values, either works with finite results or throws a
// TypeError/RangeError naming the parameter. Nothing non-finite reaches an array.

const hostileNumber = hostileNumbers(2 ** 53, -1, 0.5);
const hostile = hostileValue(hostileNumber, { values: ['1', 'NaN', [1, 2, 3]] });

/** A field that is sometimes valid (`valid`), sometimes hostile, sometimes missing. */
const field = <T>(valid: fc.Arbitrary<T>) =>
  fc.option(fc.oneof(valid, hostile), { nil: undefined, freq: 4 }) as fc.Arbitrary<unknown>;

const level = field(fc.integer({ min: 0, max: 5 }));
const base = field(fc.constantFrom('tetrahedron', 'octahedron', 'icosahedron'));
const sphereOptions = fc.record(
  {
    level,
    base,
    radius: field(fc.double({ min: 1e-30, max: 1e30, noNaN: true })),
    normals: field(fc.constantFrom('smooth', 'flat', 'none')),
    indexed: field(fc.boolean()),
    maxBytes: field(fc.constantFrom(1e3, 1e6, 1e9)),
  },
  { requiredKeys: [] },
);

const counts = { calls: 0, threw: 0 };
afterAll(() => {
  console.log(
    `sphere fuzz: seed ${fuzzSeed()}, ${counts.calls} calls, ${counts.threw} refused with a named TypeError/RangeError`,
  );
});

/** Call `fn`: it either returns (then `check` runs on the result) or is refused by name (worksOrNamedError). */
function worksThen<T>(names: readonly string[], fn: () => T, check: (result: T) => void): void {
  let result!: T;
  if (
    worksOrNamedError(counts, names, () => {
      result = fn();
    })
  ) {
    check(result);
  }
}

function expectFinite(array: ArrayLike<number> | undefined, what: string): void {
  if (array === undefined) return;
  for (let i = 0; i < array.length; i++) {
    if (!Number.isFinite(array[i])) expect.fail(`${what}[${i}] = ${array[i]}`);
  }
}

const OPTION_NAMES = ['options', 'level', 'base', 'radius', 'normals', 'indexed', 'maxBytes'];

describe('sphere fuzz (hostile values everywhere)', () => {
  it('subdivideSphere: finite arrays or a named error', () => {
    fc.assert(
      fc.property(fc.oneof({ weight: 9, arbitrary: sphereOptions }, hostile), (options) => {
        worksThen(
          OPTION_NAMES,
          () => subdivideSphere(options as never),
          (mesh) => {
            expect(mesh.positions.length).toBeGreaterThan(0);
            expectFinite(mesh.positions, 'positions');
            expectFinite(mesh.normals, 'normals');
          },
        );
      }),
      { numRuns: 600 },
    );
  });

  it('SubdivisionSphereGeometry: finite attributes and bounds, or a named error', () => {
    fc.assert(
      fc.property(fc.oneof({ weight: 9, arbitrary: sphereOptions }, hostile), (options) => {
        worksThen(
          OPTION_NAMES,
          () => new SubdivisionSphereGeometry(options as never),
          (geometry) => {
            for (const name of Object.keys(geometry.attributes)) {
              expectFinite(geometry.getAttribute(name).array as Float32Array, name);
            }
            const { center, radius } = geometry.boundingSphere!;
            expectFinite([center.x, center.y, center.z, radius], 'boundingSphere');
            geometry.dispose();
          },
        );
      }),
      { numRuns: 300 },
    );
  });

  it('estimateSphereBytes, sphereCounts, sphereError: finite numbers or a named error', () => {
    fc.assert(
      fc.property(sphereOptions, base, fc.oneof(level, hostile), (options, b, l) => {
        worksThen(
          OPTION_NAMES,
          () => estimateSphereBytes(options as never),
          (bytes) => {
            // Documented: Infinity for levels whose counts overflow a double (past ~509), so they are refused.
            expect(bytes).toBeGreaterThan(0);
            if (bytes === Number.POSITIVE_INFINITY)
              expect((options as { level: number }).level).toBeGreaterThan(500);
          },
        );
        worksThen(
          ['base', 'level'],
          () => sphereCounts(b as never, l as never),
          (c) => {
            expectFinite([c.triangles, c.vertices, c.edges], 'sphereCounts');
          },
        );
        worksThen(
          ['base', 'level'],
          () => sphereError(b as never, l as never),
          (e) => {
            expect(e).toBeGreaterThanOrEqual(0);
            expect(e).toBeLessThan(1);
          },
        );
      }),
      { numRuns: 600 },
    );
  });

  it('absurd levels are refused by a RangeError with the bytes even when maxBytes is Infinity', () => {
    for (const level of [16, 40, 511, 1e308, Number.MAX_SAFE_INTEGER]) {
      for (const maxBytes of [Number.POSITIVE_INFINITY, Number.MAX_VALUE]) {
        expect(() => subdivideSphere({ level, maxBytes })).toThrow(RangeError);
        expect(() => subdivideSphere({ level, maxBytes })).toThrow(
          /subdivideSphere: level .* needs about .*bytes/,
        );
        expect(() => new SubdivisionSphereGeometry({ level, maxBytes, normals: 'none' })).toThrow(/level/);
      }
    }
    expect(() => sphereCounts('icosahedron', 510)).toThrow(/level .*finite.* got 510/);
    expect(sphereCounts('icosahedron', 509).triangles).toBe(20 * 4 ** 509);
    expect(sphereCounts('tetrahedron', 510).triangles).toBe(4 * 4 ** 510);
  });

  it('chooseSphereDetail: a finite detail or a named error', () => {
    const options = fc.record(
      {
        radiusPx: field(fc.double({ min: 0, max: 1e6, noNaN: true })),
        maxErrorPx: field(fc.double({ min: 1e-3, max: 10, noNaN: true })),
        bases: field(fc.subarray(['tetrahedron', 'octahedron', 'icosahedron'] as const, { minLength: 1 })),
        maxLevel: field(fc.integer({ min: 0, max: 10 })),
      },
      { requiredKeys: [] },
    );
    fc.assert(
      fc.property(fc.oneof({ weight: 9, arbitrary: options }, hostile), (o) => {
        worksThen(
          ['options', 'radiusPx', 'maxErrorPx', 'bases', 'maxLevel'],
          () => chooseSphereDetail(o as never),
          (d) => {
            expectFinite([d.level, d.triangles, d.errorPx], 'detail');
          },
        );
      }),
      { numRuns: 600 },
    );
  });

  it('computeVertexNormals: finite unit normals or a named error, whatever the positions hold', () => {
    const positions = fc.oneof(
      { weight: 6, arbitrary: fc.array(hostileNumber, { maxLength: 30 }) },
      fc.array(fc.double({ min: -10, max: 10, noNaN: true }), { maxLength: 30 }),
      hostile,
    );
    const indices = fc.oneof(fc.array(fc.oneof(fc.integer({ min: 0, max: 9 }), hostileNumber)), hostile);
    const weighting = fc.oneof(fc.constantFrom('average', 'area', 'angle'), hostile);
    fc.assert(
      fc.property(positions, indices, weighting, (p, i, w) => {
        worksThen(
          ['positions', 'indices', 'weighting'],
          () => computeVertexNormals(p as never, i as never, w as never),
          (normals) => {
            expectFinite(normals, 'normals');
            for (let k = 0; k < normals.length; k += 3) {
              expect(Math.hypot(normals[k], normals[k + 1], normals[k + 2])).toBeCloseTo(1, 5);
            }
          },
        );
      }),
      { numRuns: 1000 },
    );
  });
});
