import { SPHERE_BASES, type SphereBase, sphereCounts } from '@shadelab/sphere';
import { chooseSphereDetail, sphereError } from '@shadelab/sphere/detail';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';

/** Every (base, level) that is cheaper than `triangles` and within maxLevel. */
function cheaperCandidates(bases: readonly SphereBase[], maxLevel: number, triangles: number) {
  const out: { base: SphereBase; level: number }[] = [];
  for (const base of bases) {
    for (let level = 0; level <= maxLevel; level++) {
      if (sphereCounts(base, level).triangles < triangles) out.push({ base, level });
    }
  }
  return out;
}

/** The choice meets the budget and, checked exhaustively, nothing cheaper does. */
function expectCheapest(
  radiusPx: number,
  maxErrorPx: number,
  bases: readonly SphereBase[] = SPHERE_BASES,
  maxLevel = 10,
) {
  const choice = chooseSphereDetail({ radiusPx, maxErrorPx, bases, maxLevel });
  expect(bases).toContain(choice.base);
  expect(choice.level).toBeLessThanOrEqual(maxLevel);
  expect(choice.triangles).toBe(sphereCounts(choice.base, choice.level).triangles);
  expect(choice.errorPx).toBe(radiusPx * sphereError(choice.base, choice.level));
  expect(choice.errorPx).toBeLessThanOrEqual(maxErrorPx);
  for (const { base, level } of cheaperCandidates(bases, maxLevel, choice.triangles)) {
    expect(radiusPx * sphereError(base, level)).toBeGreaterThan(maxErrorPx);
  }
  return choice;
}

describe('chooseSphereDetail', () => {
  it('meets the budget with the fewest triangles: exhaustive over a grid of budgets', () => {
    for (const radiusPx of [0, 0.5, 1, 10, 64, 100, 300, 1000, 4096, 20000]) {
      for (const maxErrorPx of [0.01, 0.05, 0.1, 0.25, 0.5, 1, 2, 5, 50]) {
        try {
          expectCheapest(radiusPx, maxErrorPx);
        } catch (error) {
          // Only an unreachable budget may throw, and then no base and level ≤ 10 meets it.
          expect(error).toBeInstanceOf(RangeError);
          for (const base of SPHERE_BASES)
            expect(radiusPx * sphereError(base, 10)).toBeGreaterThan(maxErrorPx);
        }
      }
    }
  });

  it('property: any budget and any subset of bases, exhaustively cheapest', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1e4, noNaN: true }),
        fc.double({ min: 1e-3, max: 100, noNaN: true }),
        fc.subarray([...SPHERE_BASES], { minLength: 1 }),
        fc.integer({ min: 0, max: 12 }),
        (radiusPx, maxErrorPx, bases, maxLevel) => {
          const reachable = bases.some((b) => radiusPx * sphereError(b, maxLevel) <= maxErrorPx);
          if (reachable) expectCheapest(radiusPx, maxErrorPx, bases, maxLevel);
          else
            expect(() => chooseSphereDetail({ radiusPx, maxErrorPx, bases, maxLevel })).toThrow(RangeError);
        },
      ),
      { numRuns: 200 },
    );
  });

  it('a few worked cases: a tiny sphere needs the tetrahedron; a 300 px sphere at 0.5 px the icosahedron', () => {
    expect(chooseSphereDetail({ radiusPx: 0, maxErrorPx: 0.5 })).toEqual({
      base: 'tetrahedron',
      level: 0,
      triangles: 4,
      errorPx: 0,
    });
    expect(chooseSphereDetail({ radiusPx: 1, maxErrorPx: 1 })).toMatchObject({
      base: 'tetrahedron',
      level: 0,
    });
    expect(chooseSphereDetail({ radiusPx: 300, maxErrorPx: 0.5 })).toMatchObject({
      base: 'icosahedron',
      level: 4,
      triangles: 5120,
    });
  });

  it('an unreachable budget is a RangeError giving the smallest error reachable', () => {
    expect(() => chooseSphereDetail({ radiusPx: 1e6, maxErrorPx: 1e-3 })).toThrow(RangeError);
    expect(() => chooseSphereDetail({ radiusPx: 1e6, maxErrorPx: 1e-3 })).toThrow(
      /up to maxLevel 10 .*the smallest is/,
    );
    expect(chooseSphereDetail({ radiusPx: 1e6, maxErrorPx: 1e-3, maxLevel: 20 }).errorPx).toBeLessThanOrEqual(
      1e-3,
    );
  });

  it('bad options: RangeError / TypeError naming the option, the value and the allowed range', () => {
    const cases: [object, ErrorConstructor, string][] = [
      [{ radiusPx: -1, maxErrorPx: 1 }, RangeError, 'radiusPx must be a finite number ≥ 0; got -1'],
      [{ radiusPx: Number.NaN, maxErrorPx: 1 }, RangeError, 'radiusPx must be a finite number ≥ 0; got NaN'],
      [{ radiusPx: Number.POSITIVE_INFINITY, maxErrorPx: 1 }, RangeError, 'radiusPx'],
      [{ radiusPx: '5', maxErrorPx: 1 }, TypeError, "radiusPx must be a finite number ≥ 0; got '5'"],
      [{ radiusPx: 5, maxErrorPx: 0 }, RangeError, 'maxErrorPx must be a finite number > 0; got 0'],
      [{ radiusPx: 5, maxErrorPx: Number.NaN }, RangeError, 'maxErrorPx'],
      [{ radiusPx: 5 }, TypeError, 'maxErrorPx must be a finite number > 0; got undefined'],
      [{ radiusPx: 5, maxErrorPx: 1, bases: [] }, RangeError, 'bases must name at least one base'],
      [{ radiusPx: 5, maxErrorPx: 1, bases: ['cube'] }, RangeError, "bases[0] must be 'tetrahedron'"],
      [{ radiusPx: 5, maxErrorPx: 1, bases: 'icosahedron' }, TypeError, 'bases must be an array'],
      [
        { radiusPx: 5, maxErrorPx: 1, maxLevel: 21 },
        RangeError,
        'maxLevel must be an integer from 0 to 20; got 21',
      ],
      [{ radiusPx: 5, maxErrorPx: 1, maxLevel: 2.5 }, RangeError, 'maxLevel'],
    ];
    for (const [options, Kind, message] of cases) {
      expect(() => chooseSphereDetail(options as never)).toThrow(Kind);
      expect(() => chooseSphereDetail(options as never)).toThrow(message);
    }
    expect(() => chooseSphereDetail(undefined as never)).toThrow(TypeError);
  });
});
