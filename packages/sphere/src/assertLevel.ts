import { fail } from './fail.js';

/**
 * Throw unless `level` is a subdivision level: a TypeError for a non-number, a RangeError for NaN, a
 * negative or fractional number, or one above `max`.
 * @internal
 */
export function assertLevel(
  caller: string,
  name: string,
  level: unknown,
  max = Infinity,
): asserts level is number {
  if (!Number.isInteger(level) || (level as number) < 0 || (level as number) > max) {
    fail(caller, name, max === Infinity ? 'an integer ≥ 0' : `an integer from 0 to ${max}`, level, 'number');
  }
}
