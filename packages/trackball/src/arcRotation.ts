import type { Quat, Vec3 } from './types.js';

/** |v|: a plain square root (fast), Math.hypot only where the squares overflow or underflow. */
function length(v: Readonly<Vec3>): number {
  const s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  return s > 1e-300 && s < Number.POSITIVE_INFINITY ? Math.sqrt(s) : Math.hypot(v[0], v[1], v[2]);
}

/**
 * The rotation that carries ball point `a` toward ball point `b` (three-free, allocation-free with `out`).
 *
 * With θ = atan2(|â × b̂|, â · b̂), the angle between the directions of `a` and `b` (exact for tiny drags,
 * unlike `acos`), the result is the unit quaternion of a rotation by `2 · speed · θ` radians about
 * â × b̂. With `speed = 1` this is Shoemake's convention: the rotation is twice the arc, so a drag from the
 * centre of the ball to its rim (θ = 90°) turns the object by 180°, and arcs compose exactly
 * (q(b→c) · q(a→b) = q(a→c)).
 *
 * `a` and `b` need not be unit length (only their directions matter). When they are antiparallel the
 * axis is any direction perpendicular to `a`; when they are parallel the result is the identity.
 *
 * @param a - Start point on the ball (camera frame). Finite, non-zero.
 * @param b - End point on the ball (camera frame). Finite, non-zero.
 * @param speed - Multiplies the angle; 0 gives the identity. Finite, ≥ 0. @defaultValue 1
 * @param out - Where to write `[x, y, z, w]`. @defaultValue a new array
 * @returns `out`, a unit quaternion.
 * @throws RangeError if `a` or `b` is zero or not finite, or `speed` is negative or not finite.
 */
export function arcRotation(a: Readonly<Vec3>, b: Readonly<Vec3>, speed = 1, out: Quat = [0, 0, 0, 1]): Quat {
  if (!(speed >= 0 && speed < Number.POSITIVE_INFINITY)) {
    throw new RangeError(`arcRotation: speed must be a finite number ≥ 0, got ${speed}`);
  }
  const la = length(a);
  const lb = length(b);
  if (!(la > 0 && la < Number.POSITIVE_INFINITY)) {
    throw new RangeError(`arcRotation: a must be a finite non-zero vector, got [${a.join(', ')}]`);
  }
  if (!(lb > 0 && lb < Number.POSITIVE_INFINITY)) {
    throw new RangeError(`arcRotation: b must be a finite non-zero vector, got [${b.join(', ')}]`);
  }
  const ax = a[0] / la;
  const ay = a[1] / la;
  const az = a[2] / la;
  const bx = b[0] / lb;
  const by = b[1] / lb;
  const bz = b[2] / lb;
  let cx = ay * bz - az * by;
  let cy = az * bx - ax * bz;
  let cz = ax * by - ay * bx;
  const sin = Math.sqrt(cx * cx + cy * cy + cz * cz);
  const cos = ax * bx + ay * by + az * bz;
  const theta = Math.atan2(sin, cos);
  // speed · θ overflows only for speeds near 1.8e308, where the angle means nothing: any finite angle keeps
  // the result a unit quaternion.
  const half = speed * theta < Number.POSITIVE_INFINITY ? speed * theta : (speed % Math.PI) * theta;
  if (sin > 0) {
    cx /= sin;
    cy /= sin;
    cz /= sin;
  } else if (cos < 0) {
    // Antiparallel: any axis perpendicular to a. Cross a with the coordinate axis it is least aligned with.
    const mx = Math.abs(ax);
    const my = Math.abs(ay);
    const mz = Math.abs(az);
    if (mx <= my && mx <= mz) {
      cx = 0;
      cy = az;
      cz = -ay;
    } else if (my <= mz) {
      cx = -az;
      cy = 0;
      cz = ax;
    } else {
      cx = ay;
      cy = -ax;
      cz = 0;
    }
    const l = Math.sqrt(cx * cx + cy * cy + cz * cz);
    cx /= l;
    cy /= l;
    cz /= l;
  } else {
    out[0] = 0;
    out[1] = 0;
    out[2] = 0;
    out[3] = 1;
    return out;
  }
  const s = Math.sin(half);
  out[0] = cx * s;
  out[1] = cy * s;
  out[2] = cz * s;
  out[3] = Math.cos(half);
  return out;
}
