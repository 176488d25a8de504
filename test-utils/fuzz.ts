import fc from 'fast-check';
import { expect } from 'vitest';

/**
 * The seed every fast-check property of this run uses (set by test-utils/fastCheckSeed.ts), for a fuzz suite's
 * closing line: a failure seen in a log reproduces with `SHADELAB_FUZZ_SEED=<seed>`.
 */
export function fuzzSeed(): number {
  const { seed } = fc.readConfigureGlobal();
  if (seed === undefined)
    throw new Error('no fast-check seed: test-utils/fastCheckSeed.ts is not a setup file');
  return seed;
}

/** Calls made and calls refused, for a fuzz suite's closing line. */
export interface FuzzCounts {
  calls: number;
  threw: number;
}

/**
 * Run `fn`: it either works (true) or throws a TypeError/RangeError whose message names one of `names`
 * (false); anything else fails the test. Counts both in `counts`.
 */
export function worksOrNamedError(counts: FuzzCounts, names: readonly string[], fn: () => unknown): boolean {
  counts.calls++;
  try {
    fn();
    return true;
  } catch (error) {
    counts.threw++;
    expect(error).toSatisfy((e) => e instanceof TypeError || e instanceof RangeError);
    const message = (error as Error).message;
    expect(
      names.some((name) => message.includes(name)),
      message,
    ).toBe(true);
    return false;
  }
}

/** Numbers that break naive code: NaN, ±Infinity, ±0, the largest and smallest doubles, subnormals. */
export const HOSTILE_NUMBERS: readonly number[] = [
  Number.NaN,
  Number.POSITIVE_INFINITY,
  Number.NEGATIVE_INFINITY,
  0,
  -0,
  1e308,
  -1e308,
  1e-308,
  -1e-308,
  Number.MIN_VALUE,
  -Number.MIN_VALUE,
  Number.MAX_VALUE,
];

/** {@link HOSTILE_NUMBERS}, a package's own edge values, and any double. */
export function hostileNumbers(...edges: number[]): fc.Arbitrary<number> {
  return fc.oneof(fc.constantFrom(...HOSTILE_NUMBERS, ...edges), fc.double());
}

/**
 * Anything a caller might pass by mistake: hostile numbers (most often), wrong types, missing values, and a
 * package's own plausible-but-wrong `values` and `extra` arbitraries.
 */
export function hostileValue(
  numbers: fc.Arbitrary<number>,
  { values = [], extra = [] }: { values?: unknown[]; extra?: fc.Arbitrary<unknown>[] } = {},
): fc.Arbitrary<unknown> {
  return fc.oneof(
    { weight: 4, arbitrary: numbers as fc.Arbitrary<unknown> },
    fc.constantFrom<unknown>(undefined, null, true, false, '', [], {}, 10n, Symbol('s'), ...values),
    ...extra,
    fc.string({ maxLength: 6 }),
  );
}
