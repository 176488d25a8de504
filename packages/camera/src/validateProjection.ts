/**
 * @internal Throws a TypeError naming `name` unless `value` is a number, and a RangeError naming it, its value and
 * the allowed range unless `ok(value)`.
 */
export function check(value: unknown, ok: (v: number) => boolean, name: string, allowed: string): void {
  if (typeof value !== 'number')
    throw new TypeError(`${name} must be a number ${allowed}, got ${typeof value}`);
  if (!ok(value)) throw new RangeError(`${name} must be ${allowed}, got ${value}`);
}

/** @internal `Number.isFinite`. */
export const finite = Number.isFinite;

/** @internal `v` is finite and > 0 (aspect, perspective near, zoom). */
export const positive = (v: number): boolean => v > 0 && finite(v);

/**
 * Validate perspective parameters.
 * @throws TypeError naming the first parameter that is not a number; RangeError naming the first bad parameter:
 * fovy ∉ (0, 180) degrees, aspect ≤ 0, near ≤ 0, far ≤ near, zoom ≤ 0, or any of them NaN/infinite.
 * @internal
 */
export function validatePerspective(fovy: number, aspect: number, near: number, far: number, zoom = 1): void {
  check(fovy, (v) => v > 0 && v < 180, 'fovy', 'in (0, 180) degrees');
  check(aspect, positive, 'aspect', 'finite and > 0');
  check(near, positive, 'near', 'finite and > 0');
  check(far, (v) => v > near && finite(v), 'far', `finite and > near (${near})`);
  check(zoom, positive, 'zoom', 'finite and > 0');
}

/**
 * Validate orthographic parameters (any finite near, including ≤ 0, is allowed: orthographic depth is linear).
 * @throws TypeError naming the first parameter that is not a number; RangeError naming the first bad parameter:
 * r = l, t = b, far ≤ near, zoom ≤ 0, or any NaN/infinite.
 * @internal
 */
export function validateOrthographic(
  right: number,
  left: number,
  top: number,
  bottom: number,
  near: number,
  far: number,
  zoom = 1,
): void {
  check(right, finite, 'right', 'finite');
  check(left, (v) => finite(v) && v !== right, 'left', `finite and ≠ right (${right})`);
  check(top, finite, 'top', 'finite');
  check(bottom, (v) => finite(v) && v !== top, 'bottom', `finite and ≠ top (${top})`);
  check(near, finite, 'near', 'finite');
  check(far, (v) => v > near && finite(v), 'far', `finite and > near (${near})`);
  check(zoom, positive, 'zoom', 'finite and > 0');
}
