import type { Quat } from './types.js';

/**
 * Rescale a quaternion to unit length in place, so that accumulated rotations never drift from a rotation.
 * A zero or non-finite quaternion becomes the identity (never NaN).
 *
 * @param q - The quaternion `[x, y, z, w]`, modified in place.
 * @returns `q`.
 */
export function normalizeQuaternion(q: Quat): Quat {
  const s = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  const l = s > 1e-300 && s < Number.POSITIVE_INFINITY ? Math.sqrt(s) : Math.hypot(q[0], q[1], q[2], q[3]);
  if (!(l > 0 && l < Number.POSITIVE_INFINITY)) {
    q[0] = 0;
    q[1] = 0;
    q[2] = 0;
    q[3] = 1;
    return q;
  }
  q[0] /= l;
  q[1] /= l;
  q[2] /= l;
  q[3] /= l;
  return q;
}
