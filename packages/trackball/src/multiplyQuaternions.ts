import type { Quat } from './types.js';

/**
 * The Hamilton product `a · b` (rotate by `b`, then by `a`), three-free. `out` may alias `a` or `b`.
 *
 * @param a - Left factor `[x, y, z, w]`.
 * @param b - Right factor `[x, y, z, w]`.
 * @param out - Where to write the product. @defaultValue a new array
 * @returns `out`.
 */
export function multiplyQuaternions(a: Readonly<Quat>, b: Readonly<Quat>, out: Quat = [0, 0, 0, 1]): Quat {
  const ax = a[0];
  const ay = a[1];
  const az = a[2];
  const aw = a[3];
  const bx = b[0];
  const by = b[1];
  const bz = b[2];
  const bw = b[3];
  out[0] = ax * bw + aw * bx + ay * bz - az * by;
  out[1] = ay * bw + aw * by + az * bx - ax * bz;
  out[2] = az * bw + aw * bz + ax * by - ay * bx;
  out[3] = aw * bw - ax * bx - ay * by - az * bz;
  return out;
}
