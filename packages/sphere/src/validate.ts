// Validation shared by every entry point: one message format, one throw.

/** A value as shown in error messages: strings quoted, numbers as written, objects by kind. */
function describeValue(value: unknown): string {
  if (typeof value === 'string') return `'${value}'`;
  if (typeof value === 'bigint') return `${value}n`;
  if (typeof value === 'number' || typeof value === 'boolean' || value == null) return String(value);
  if (Array.isArray(value)) return 'an array';
  return `a ${typeof value}`;
}

/**
 * The message of every validation error: `${caller}: ${name} must be ${allowed}; got <value>`, which names the
 * function, the parameter, what is allowed and what was given.
 * @internal
 */
export function mustBe(caller: string, name: string, allowed: string, value: unknown): string {
  return `${caller}: ${name} must be ${allowed}; got ${describeValue(value)}`;
}

/**
 * Throw the {@link mustBe} message for a bad `value`: a TypeError when `type` is given and `typeof value` is not
 * `type` (the wrong kind of value), else a RangeError (the right kind, out of range).
 * @internal
 */
export function fail(caller: string, name: string, allowed: string, value: unknown, type?: string): never {
  const message = mustBe(caller, name, allowed, value);
  throw type !== undefined && typeof value !== type ? new TypeError(message) : new RangeError(message);
}

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
