import { expect } from 'vitest';

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
