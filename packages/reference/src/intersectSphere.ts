/** The two ray parameters where a ray meets a sphere, t0 ≤ t1 (distances along a unit direction). */
export interface SphereHit {
  /** Entry parameter (the front surface when ≥ 0). */
  t0: number;
  /** Exit parameter. */
  t1: number;
}

/**
 * Where the ray o + t·d̂ meets the sphere |x − c| = r, with the numerically stable form of Ray Tracing Gems,
 * chapter 7 ("Precision Improvements for Ray/Sphere Intersection"): with f = o − c and a unit direction d̂,
 * b′ = f·d̂, the discriminant is computed as Δ = r² − |f − b′d̂|² (no cancellation between b′² and f·f − r²
 * when the origin is far away), c′ = f·f − r², q = −b′ − sign(b′)·√Δ, and the roots are t0 = c′/q,
 * t1 = q (a = 1), each without catastrophic cancellation.
 *
 * @param origin - ray origin o.
 * @param direction - ray direction; normalised here (any non-zero length).
 * @param centre - sphere centre c. @default [0, 0, 0]
 * @param radius - sphere radius r > 0. @default 1
 * @param out - receives the hit; a new object when omitted.
 * @returns the hit with t in units of world length along the normalised direction, or `null` when the ray
 * misses (Δ < 0) or the direction is zero or not finite.
 */
export function intersectSphere(
  origin: ArrayLike<number>,
  direction: ArrayLike<number>,
  centre: ArrayLike<number> = ORIGIN,
  radius = 1,
  out: SphereHit = { t0: 0, t1: 0 },
): SphereHit | null {
  const len = Math.hypot(direction[0], direction[1], direction[2]);
  if (!(len > 0) || !Number.isFinite(len)) return null;
  const dx = direction[0] / len;
  const dy = direction[1] / len;
  const dz = direction[2] / len;
  const fx = origin[0] - centre[0];
  const fy = origin[1] - centre[1];
  const fz = origin[2] - centre[2];
  const b = fx * dx + fy * dy + fz * dz;
  // f − b′d̂: the vector from the centre to the ray's closest point.
  const px = fx - b * dx;
  const py = fy - b * dy;
  const pz = fz - b * dz;
  const delta = radius * radius - (px * px + py * py + pz * pz);
  if (delta < 0) return null;
  const c = fx * fx + fy * fy + fz * fz - radius * radius;
  const q = -b - (b >= 0 ? 1 : -1) * Math.sqrt(delta);
  if (q === 0) {
    // b′ = 0 and Δ = 0: the ray grazes the sphere at its closest point.
    out.t0 = 0;
    out.t1 = 0;
    return out;
  }
  const ta = c / q;
  const tb = q;
  out.t0 = Math.min(ta, tb);
  out.t1 = Math.max(ta, tb);
  return out;
}

const ORIGIN: readonly number[] = [0, 0, 0];
