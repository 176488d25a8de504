// The error `AdaptiveShading`'s budget bounds, measured on two pictures: what the tests, the bench and the
// playground's adaptive tool measure, and an app can measure on its own frames.

/** How a picture differs from the reference picture of the same scene (see {@link pictureError}). */
export interface PictureError {
  /** Pixels compared: those `drawn` says are drawn (in either picture). */
  readonly drawn: number;
  /** The 99th percentile of the per-pixel largest |Δ| over R, G and B across the compared pixels, 8-bit levels. */
  readonly p99: number;
  /** The largest per-pixel |Δ|, 8-bit levels. */
  readonly max: number;
  /** The fraction (0 … 1) of the compared pixels whose |Δ| exceeds `maxError`. */
  readonly over: number;
}

/**
 * The error of `picture` against `reference` (two RGBA8 pictures of one size, e.g. read back from the renderer):
 * per pixel the largest |Δ| over R, G and B in 8-bit levels, over the pixels `drawn` names (by default those
 * whose alpha is not 0 in either picture). `AdaptiveShading({ maxError })` keeps the picture's `p99` within
 * `maxError` of the all-Phong, full-detail picture, with `over` at most 0.5 % (its honesty tests).
 *
 * @param reference - The reference picture (Phong shading at full detail), RGBA, 4 bytes a pixel.
 * @param picture - The picture measured, the same size.
 * @param maxError - The budget `over` counts against, 8-bit levels.
 * @param drawn - Whether pixel `i` (its index, not its byte offset) is compared.
 * @returns `drawn` 0 and errors 0 when no pixel is compared.
 * @throws RangeError when the two pictures differ in length or it is not a multiple of 4.
 */
export function pictureError(
  reference: ArrayLike<number>,
  picture: ArrayLike<number>,
  maxError: number,
  drawn: (i: number) => boolean = (i) => reference[4 * i + 3] !== 0 || picture[4 * i + 3] !== 0,
): PictureError {
  if (reference.length !== picture.length || reference.length % 4 !== 0) {
    throw new RangeError(
      `pictureError: reference and picture must be RGBA pictures of one size, got ${reference.length} and ${picture.length} bytes`,
    );
  }
  const deltas: number[] = [];
  for (let i = 0; i < reference.length / 4; i++) {
    if (!drawn(i)) continue;
    const k = 4 * i;
    deltas.push(
      Math.max(
        Math.abs(reference[k] - picture[k]),
        Math.abs(reference[k + 1] - picture[k + 1]),
        Math.abs(reference[k + 2] - picture[k + 2]),
      ),
    );
  }
  const n = deltas.length;
  if (n === 0) return { drawn: 0, p99: 0, max: 0, over: 0 };
  deltas.sort((a, b) => a - b);
  let over = 0;
  for (const d of deltas) if (d > maxError) over++;
  return { drawn: n, p99: deltas[Math.min(n - 1, Math.floor(0.99 * n))], max: deltas[n - 1], over: over / n };
}
