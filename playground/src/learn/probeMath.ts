/**
 * The probe's pure arithmetic (no three.js, no DOM): which device pixel a click lands on and the NDC of its
 * centre, the barycentric weights with which the GPU blends a triangle's vertex values at a point, and the
 * 8-bit colour the canvas keeps (sRGB, after three's fog), and whether a cel-lit point is at a band's edge.
 */
import type { ShadeExplanation } from '@shadelab/material/explain';

/** A 3-vector. */
export type V3 = [number, number, number];

/**
 * The device pixel (x from the left, y from the top, integers) under a pointer at (`clientX`, `clientY`) on a
 * canvas drawn at `rect` (CSS pixels) with a drawing buffer of `width` × `height` pixels; null outside it.
 */
export function devicePixelOf(
  clientX: number,
  clientY: number,
  rect: { left: number; top: number; width: number; height: number },
  width: number,
  height: number,
): [number, number] | null {
  if (!(rect.width > 0 && rect.height > 0)) return null;
  const x = Math.floor(((clientX - rect.left) * width) / rect.width);
  const y = Math.floor(((clientY - rect.top) * height) / rect.height);
  return x >= 0 && y >= 0 && x < width && y < height ? [x, y] : null;
}

/** Normalised device coordinates (−1 … 1, y up) of the centre of device pixel (`x`, `y`), y from the top. */
export function ndcOfPixel(x: number, y: number, width: number, height: number): [number, number] {
  return [((x + 0.5) / width) * 2 - 1, 1 - ((y + 0.5) / height) * 2];
}

/**
 * The device pixel whose centre is nearest to NDC (`nx`, `ny`), y from the top; null off the canvas. The
 * inverse of {@link ndcOfPixel} (how a followed point's pixel is found after the view moved).
 */
export function pixelOfNdc(nx: number, ny: number, width: number, height: number): [number, number] | null {
  if (!(Math.abs(nx) <= 1 && Math.abs(ny) <= 1)) return null;
  const x = Math.min(Math.floor(((nx + 1) / 2) * width), width - 1);
  const y = Math.min(Math.floor(((1 - ny) / 2) * height), height - 1);
  return [x, y];
}

const sub = (a: ArrayLike<number>, b: ArrayLike<number>): V3 => [a[0]! - b[0]!, a[1]! - b[1]!, a[2]! - b[2]!];
const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * The barycentric weights (wa, wb, wc), summing to 1, of point `p` (on the plane of triangle a, b, c) such that
 * p = wa·a + wb·b + wc·c: what the GPU's perspective-correct interpolation blends the vertices' values with at
 * the pixel whose ray meets the triangle at p. A degenerate triangle (no area) gives (1/3, 1/3, 1/3).
 */
export function barycentric(
  p: ArrayLike<number>,
  a: ArrayLike<number>,
  b: ArrayLike<number>,
  c: ArrayLike<number>,
): V3 {
  const v0 = sub(b, a);
  const v1 = sub(c, a);
  const v2 = sub(p, a);
  const d00 = dot(v0, v0);
  const d01 = dot(v0, v1);
  const d11 = dot(v1, v1);
  const d20 = dot(v2, v0);
  const d21 = dot(v2, v1);
  const denom = d00 * d11 - d01 * d01;
  if (!(Math.abs(denom) > 1e-30 * Math.max(d00 * d11, 1e-300))) return [1 / 3, 1 / 3, 1 / 3];
  const wb = (d11 * d20 - d01 * d21) / denom;
  const wc = (d00 * d21 - d01 * d20) / denom;
  return [1 - wb - wc, wb, wc];
}

/** Σ weights[i] · values[i]: three vertex values blended as the GPU blends them. */
export function blend(values: readonly [V3, V3, V3], weights: V3): V3 {
  const out: V3 = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    for (let k = 0; k < 3; k++) out[k] += weights[i]! * values[i]![k]!;
  }
  return out;
}

/** three's sRGB transfer function (`sRGBTransferOETF`) of a linear value ≥ 0, not clamped. */
export function srgbEncode(linear: number): number {
  const x = Math.max(linear, 0);
  return x <= 0.0031308 ? x * 12.92 : 1.055 * x ** (1 / 2.4) - 0.055;
}

/**
 * The 8-bit colour the canvas keeps for a linear colour: sRGB encoded, then (with fog) mixed with the fog colour
 * (linear; three encodes it too) by `fog.factor` as three's fog chunk does, clamped to 0 … 1 and rounded.
 */
export function displayed8(
  linear: ArrayLike<number>,
  fog?: { color: ArrayLike<number>; factor: number },
): V3 {
  const out: V3 = [0, 0, 0];
  for (let k = 0; k < 3; k++) {
    let c = srgbEncode(Number.isNaN(linear[k]!) ? 0 : linear[k]!);
    if (fog) c = c + (srgbEncode(fog.color[k]!) - c) * fog.factor;
    out[k] = Math.round(Math.min(Math.max(c, 0), 1) * 255);
  }
  return out;
}

/** The 8-bit codes of values written as they are (no colour space): a term view's attenuation or normal. */
export function raw8(value: ArrayLike<number>): V3 {
  const code = (x: number) => Math.round(Math.min(Math.max(Number.isNaN(x) ? 0 : x, 0), 1) * 255);
  return [code(value[0]!), code(value[1]!), code(value[2]!)];
}

/** The largest difference between two colours' channels (8-bit codes). */
export function maxChannelDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  return Math.max(Math.abs(a[0]! - b[0]!), Math.abs(a[1]! - b[1]!), Math.abs(a[2]! - b[2]!));
}

/** How near (in the cosine) a cel threshold counts as on it: float32 normals and positions move that much. */
const CEL_EDGE = 2e-3;

/**
 * Whether a cel-lit explanation has a light at a band's edge: max(l·n, 0)·N within {@link CEL_EDGE} of an inner
 * band threshold, or the highlight's power within as much of its 0.5 threshold (scaled by its slope).
 */
export function nearCelEdge(e: ShadeExplanation, bands: number, shininess: number): boolean {
  if (bands <= 0) return false;
  return e.lights.some((light) => {
    if (light.lDotN === null) return false;
    const x = Math.max(light.lDotN, 0) * bands;
    const threshold = Math.round(x);
    if (threshold > 0 && threshold < bands && Math.abs(x - threshold) < CEL_EDGE * bands) return true;
    const cosine = Math.max(light.cosine, 0);
    const power = cosine ** shininess;
    const slope = cosine > 0 ? (shininess * power) / cosine : 0;
    return Math.abs(power - 0.5) < CEL_EDGE * Math.max(slope, 1);
  });
}
