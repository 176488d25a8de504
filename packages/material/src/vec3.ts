// Tiny three-free vec3 helpers for the CPU lighting (`shade`). Internal: not re-exported.

/** A 3-vector as any indexable of numbers: a tuple, an array or a typed array. */
export type Vec3Like = ArrayLike<number>;

/** A homogeneous 4-vector as any indexable of numbers. */
export type Vec4Like = ArrayLike<number>;

/** A mutable 3-vector. */
export type Vec3 = [number, number, number];

/** a · b */
export function dot(a: Vec3Like, b: Vec3Like): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/** |a| (Euclidean length), computed with `Math.hypot` so tiny and huge vectors neither underflow nor overflow. */
export function length(a: Vec3Like): number {
  return Math.hypot(a[0], a[1], a[2]);
}

/** out = a − b */
export function sub(out: Vec3, a: Vec3Like, b: Vec3Like): Vec3 {
  out[0] = a[0] - b[0];
  out[1] = a[1] - b[1];
  out[2] = a[2] - b[2];
  return out;
}

/** out = a · s */
export function scale(out: Vec3, a: Vec3Like, s: number): Vec3 {
  out[0] = a[0] * s;
  out[1] = a[1] * s;
  out[2] = a[2] * s;
  return out;
}

/** out = a + b · s */
export function addScaled(out: Vec3, a: Vec3Like, b: Vec3Like, s: number): Vec3 {
  out[0] = a[0] + b[0] * s;
  out[1] = a[1] + b[1] * s;
  out[2] = a[2] + b[2] * s;
  return out;
}

/** out = a × b */
export function cross(out: Vec3, a: Vec3Like, b: Vec3Like): Vec3 {
  const x = a[1] * b[2] - a[2] * b[1];
  const y = a[2] * b[0] - a[0] * b[2];
  const z = a[0] * b[1] - a[1] * b[0];
  out[0] = x;
  out[1] = y;
  out[2] = z;
  return out;
}

/**
 * out = a / |a|, or `fallback` when |a| is 0 (or not finite).
 * @returns whether `a` had a usable length.
 */
export function normalizeOr(out: Vec3, a: Vec3Like, fallback: Vec3Like): boolean {
  // Divide by the largest component first: denormal and huge vectors normalise without under/overflow.
  const m = Math.max(Math.abs(a[0]), Math.abs(a[1]), Math.abs(a[2]));
  if (m > 0 && Number.isFinite(m)) {
    out[0] = a[0] / m;
    out[1] = a[1] / m;
    out[2] = a[2] / m;
    scale(out, out, 1 / length(out));
    return true;
  }
  out[0] = fallback[0];
  out[1] = fallback[1];
  out[2] = fallback[2];
  return false;
}
