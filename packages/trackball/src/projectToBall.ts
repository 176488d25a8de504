import type { BallMapping, Vec3 } from './types.js';

const SQRT1_2_SQ = 0.5;

/**
 * Lift a pointer position onto the virtual ball (three-free, allocation-free with `out`).
 *
 * Coordinates are in ball radii, measured from the ball's centre with y up: (0, 0) is the centre and
 * x² + y² = 1 the rim. The result is a point on the ball's surface in the camera frame (x right, y up,
 * z toward the viewer, z ≥ 0):
 *
 * - `'arcball'`: inside the rim (x² + y² ≤ 1) `(x, y, √(1 − x² − y²))`, unit length; on and beyond the rim
 *   `(x, y) / r` on the equator (z = 0), unit length.
 * - `'bell'`: inside r ≤ 1/√2 the same sphere point; beyond it `(x, y, 1 / (2r))` on the hyperbolic sheet,
 *   not unit length (use its direction). Continuous with a continuous slope at r = 1/√2.
 *
 * @param x - Horizontal position in ball radii (right is positive). Any finite number.
 * @param y - Vertical position in ball radii (up is positive). Any finite number.
 * @param mapping - Which surface to use. @defaultValue `'bell'`
 * @param out - Where to write the point. @defaultValue a new array
 * @returns `out`, the point on the ball.
 * @throws RangeError if `x` or `y` is not finite; TypeError if `mapping` is unknown.
 */
export function projectToBall(
  x: number,
  y: number,
  mapping: BallMapping = 'bell',
  out: Vec3 = [0, 0, 0],
): Vec3 {
  if (!Number.isFinite(x)) throw new RangeError(`projectToBall: x must be a finite number, got ${x}`);
  if (!Number.isFinite(y)) throw new RangeError(`projectToBall: y must be a finite number, got ${y}`);
  // The plain square root is several times faster than Math.hypot; hypot only when the squares overflow.
  const r2 = x * x + y * y;
  const r = r2 < Number.POSITIVE_INFINITY ? Math.sqrt(r2) : Math.hypot(x, y);
  if (mapping === 'arcball') {
    if (r <= 1) {
      out[0] = x;
      out[1] = y;
      out[2] = Math.sqrt(Math.max(0, 1 - r2));
    } else {
      // Halved first: |(x, y)| itself can overflow (x = 1e308, y = 1.5e308).
      const h = Math.hypot(x / 2, y / 2);
      out[0] = x / 2 / h;
      out[1] = y / 2 / h;
      out[2] = 0;
    }
    return out;
  }
  if (mapping === 'bell') {
    out[0] = x;
    out[1] = y;
    out[2] = r2 <= SQRT1_2_SQ ? Math.sqrt(1 - r2) : 0.5 / r;
    return out;
  }
  throw new TypeError(`projectToBall: mapping must be 'arcball' or 'bell', got ${String(mapping)}`);
}
