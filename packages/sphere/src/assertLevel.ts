import { describeValue } from './describeValue.js';

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
  const allowed = max === Infinity ? 'an integer ≥ 0' : `an integer from 0 to ${max}`;
  if (typeof level !== 'number') {
    throw new TypeError(`${caller}: ${name} must be ${allowed}; got ${describeValue(level)}`);
  }
  if (!Number.isInteger(level) || level < 0 || level > max) {
    throw new RangeError(`${caller}: ${name} must be ${allowed}; got ${level}`);
  }
}
