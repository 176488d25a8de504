/** @internal Throws a RangeError naming `name`, its value and the allowed range unless `ok`. */
function check(ok: boolean, name: string, value: number, allowed: string): void {
  if (!ok) throw new RangeError(`${name} must be ${allowed}, got ${value}`);
}

/**
 * Validate perspective parameters.
 * @throws RangeError naming the first bad parameter: fovy ∉ (0, 180) degrees, aspect ≤ 0, near ≤ 0, far ≤ near,
 * zoom ≤ 0, or any of them NaN/infinite.
 * @internal
 */
export function validatePerspective(fovy: number, aspect: number, near: number, far: number, zoom = 1): void {
  check(fovy > 0 && fovy < 180, 'fovy', fovy, 'in (0, 180) degrees');
  check(aspect > 0 && Number.isFinite(aspect), 'aspect', aspect, 'finite and > 0');
  check(near > 0 && Number.isFinite(near), 'near', near, 'finite and > 0');
  check(far > near && Number.isFinite(far), 'far', far, `finite and > near (${near})`);
  check(zoom > 0 && Number.isFinite(zoom), 'zoom', zoom, 'finite and > 0');
}

/**
 * Validate orthographic parameters (any finite near, including ≤ 0, is allowed: orthographic depth is linear).
 * @throws RangeError naming the first bad parameter: r = l, t = b, far ≤ near, zoom ≤ 0, or any NaN/infinite.
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
  check(Number.isFinite(right), 'right', right, 'finite');
  check(Number.isFinite(left) && left !== right, 'left', left, `finite and ≠ right (${right})`);
  check(Number.isFinite(top), 'top', top, 'finite');
  check(Number.isFinite(bottom) && bottom !== top, 'bottom', bottom, `finite and ≠ top (${top})`);
  check(Number.isFinite(near), 'near', near, 'finite');
  check(far > near && Number.isFinite(far), 'far', far, `finite and > near (${near})`);
  check(zoom > 0 && Number.isFinite(zoom), 'zoom', zoom, 'finite and > 0');
}
