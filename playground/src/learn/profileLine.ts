/**
 * The Mach-band profile's pure part: the pixels a line dragged across the canvas crosses, the intensity of a
 * displayed pixel, and where an intensity profile's slope jumps (the places the eye sees bands).
 */

/** A point on the canvas in drawing-buffer pixels, x to the right and y down from the top left. */
export type CanvasPoint = readonly [x: number, y: number];

/** An 8-bit displayed colour `[r, g, b]`, each 0…255 (sRGB codes, as read back from the canvas). */
export type Rgb8 = readonly [r: number, g: number, b: number];

/**
 * The pixels (integer `[column, row]`, row 0 at the top) a segment crosses, one per pixel step along its longer
 * axis, from `from` to `to` inclusive, clipped to a `width` × `height` canvas. null when both ends are in the same
 * pixel: a zero-length line, which draws no profile.
 *
 * @param from - Start, drawing-buffer pixels (fractional: a pointer position).
 * @param to - End, drawing-buffer pixels.
 * @param width - Canvas width, pixels (integer ≥ 1).
 * @param height - Canvas height, pixels (integer ≥ 1).
 */
export function linePixels(
  from: CanvasPoint,
  to: CanvasPoint,
  width: number,
  height: number,
): [number, number][] | null {
  for (const [name, v] of [
    ['width', width],
    ['height', height],
  ] as const) {
    if (!Number.isInteger(v) || v < 1) throw new RangeError(`linePixels: ${name} ${v} is not an integer ≥ 1`);
  }
  for (const [name, p] of [
    ['from', from],
    ['to', to],
  ] as const) {
    if (!Number.isFinite(p[0]) || !Number.isFinite(p[1])) {
      throw new TypeError(`linePixels: ${name} (${p[0]}, ${p[1]}) is not a finite point`);
    }
  }
  const cell = (p: CanvasPoint) => [Math.floor(p[0]), Math.floor(p[1])] as const;
  const [a, b] = [cell(from), cell(to)];
  if (a[0] === b[0] && a[1] === b[1]) return null;
  const steps = Math.max(Math.abs(b[0] - a[0]), Math.abs(b[1] - a[1]));
  const out: [number, number][] = [];
  for (let i = 0; i <= steps; i++) {
    const x = Math.round(a[0] + ((b[0] - a[0]) * i) / steps);
    const y = Math.round(a[1] + ((b[1] - a[1]) * i) / steps);
    if (x >= 0 && x < width && y >= 0 && y < height) out.push([x, y]);
  }
  return out;
}

/**
 * The displayed intensity of a pixel: its luma Y′ = 0.2126 R′ + 0.7152 G′ + 0.0722 B′ (Rec. 709 weights on the
 * sRGB codes, as a display shows them), 0…255.
 *
 * @param rgb - The pixel's 8-bit codes.
 */
export function luma([r, g, b]: Rgb8): number {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

/**
 * Where a profile's slope jumps: the indices i (1 … n − 2) where the second difference
 * |v[i+1] − 2·v[i] + v[i−1]| is at least `threshold` and a local maximum. On a flat-shaded surface these are the
 * facet edges (the value itself jumps), on a Gouraud one the triangle edges (only the slope jumps); the eye
 * exaggerates both into bright and dark bands (Mach bands).
 *
 * @param values - The profile, one value per pixel step.
 * @param threshold - Smallest jump of the slope that counts, in the values' units per step². @default 2
 */
export function slopeBreaks(values: readonly number[], threshold = 2): number[] {
  if (!(threshold > 0)) throw new RangeError(`slopeBreaks: threshold ${threshold} is not > 0`);
  const jump = (i: number) => Math.abs(values[i + 1]! - 2 * values[i]! + values[i - 1]!);
  const out: number[] = [];
  for (let i = 1; i < values.length - 1; i++) {
    const j = jump(i);
    if (j < threshold) continue;
    const before = i > 1 ? jump(i - 1) : 0;
    const after = i < values.length - 2 ? jump(i + 1) : 0;
    if (j >= before && j > after) out.push(i);
  }
  return out;
}
