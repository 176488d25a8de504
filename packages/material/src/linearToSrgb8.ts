// Linear → 8-bit sRGB exactly as three's output path and the canvas do it. Three-free.

/**
 * Convert one linear channel to its 8-bit sRGB code as the GPU writes it: clamp to [0, 1], the sRGB
 * transfer function three uses in `linearToOutputTexel` (12.92·x up to 0.0031308, else 1.055·x^(1/2.4) − 0.055),
 * then round to the nearest of 0 … 255.
 */
export function linearToSrgb8Channel(linear: number): number {
  const x = Number.isNaN(linear) ? 0 : Math.min(Math.max(linear, 0), 1);
  const srgb = x <= 0.0031308 ? x * 12.92 : 1.055 * x ** (1 / 2.4) - 0.055;
  return Math.round(srgb * 255);
}

/**
 * Convert a linear RGB colour (e.g. a result of `shade`) to 8-bit sRGB `[r, g, b]`, like a
 * `ShadingMaterial` drawing to an sRGB canvas (three's default `outputColorSpace`).
 * @param out receives the codes; a new array when omitted.
 */
export function linearToSrgb8(
  linear: ArrayLike<number>,
  out: [number, number, number] = [0, 0, 0],
): [number, number, number] {
  out[0] = linearToSrgb8Channel(linear[0]);
  out[1] = linearToSrgb8Channel(linear[1]);
  out[2] = linearToSrgb8Channel(linear[2]);
  return out;
}
