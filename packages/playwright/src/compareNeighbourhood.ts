import type { RgbaImage } from './png.js';

/** What {@link compareNeighbourhood} measured between two pictures of the same size. */
export interface NeighbourhoodComparison {
  /**
   * Per pixel (rows as the images), in 8-bit codes: how far the pixel of one picture lies outside the range
   * its neighbourhood spans in the other, per channel, the larger of both directions and of R, G, B.
   */
  readonly excess: Uint8Array;
  /** The largest excess, in 8-bit codes. */
  readonly maxExcess: number;
  /** Pixels whose excess is above `maxChannelDiff`. */
  readonly failingPixels: number;
  /** The pixel of the largest excess (x right, y as the images' rows), or null when every excess is 0. */
  readonly worst: { readonly x: number; readonly y: number } | null;
}

/** Per-channel minimum and maximum of each pixel's (2r + 1)² neighbourhood (clamped at the borders). */
function neighbourhoodRange(
  { width, height, data }: RgbaImage,
  r: number,
): { lo: Uint8Array; hi: Uint8Array } {
  const n = width * height;
  const rowLo = new Uint8Array(n * 3);
  const rowHi = new Uint8Array(n * 3);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      for (let c = 0; c < 3; c++) {
        let lo = 255;
        let hi = 0;
        for (let dx = Math.max(0, x - r); dx <= Math.min(width - 1, x + r); dx++) {
          const v = data[4 * (y * width + dx) + c];
          if (v < lo) lo = v;
          if (v > hi) hi = v;
        }
        rowLo[3 * (y * width + x) + c] = lo;
        rowHi[3 * (y * width + x) + c] = hi;
      }
    }
  }
  const lo = new Uint8Array(n * 3);
  const hi = new Uint8Array(n * 3);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      for (let c = 0; c < 3; c++) {
        let l = 255;
        let h = 0;
        for (let dy = Math.max(0, y - r); dy <= Math.min(height - 1, y + r); dy++) {
          const k = 3 * (dy * width + x) + c;
          if (rowLo[k] < l) l = rowLo[k];
          if (rowHi[k] > h) h = rowHi[k];
        }
        lo[3 * (y * width + x) + c] = l;
        hi[3 * (y * width + x) + c] = h;
      }
    }
  }
  return { lo, hi };
}

/**
 * Compare two pictures of one scene from different rasterisers (or GPUs): each pixel of either picture must
 * lie, per channel, within the range the other picture spans over the pixel's neighbourhood of radius
 * `radiusPx` (a (2r + 1)² square), widened by `maxChannelDiff` codes. An edge moved by up to `radiusPx`
 * pixels, a pixel covered by the other triangle of a shared edge, a shifted smooth gradient and an
 * antialiased edge (a blend of the two sides) all pass; a colour off by more than `maxChannelDiff` codes, or
 * geometry moved farther, fails.
 *
 * @param a - One picture.
 * @param b - The other picture, of the same size.
 * @param options - The comparison's tolerances.
 * @param options.radiusPx - Neighbourhood radius in pixels, an integer 0 … 8. Default 1.
 * @param options.maxChannelDiff - Codes a pixel may lie outside the range, 0 … 255 (only counts `failingPixels`).
 *   Default 0.
 * @throws RangeError when the sizes differ or a parameter is out of range.
 */
export function compareNeighbourhood(
  a: RgbaImage,
  b: RgbaImage,
  { radiusPx = 1, maxChannelDiff = 0 }: { radiusPx?: number; maxChannelDiff?: number } = {},
): NeighbourhoodComparison {
  if (a.width !== b.width || a.height !== b.height) {
    throw new RangeError(
      `compareNeighbourhood: the pictures must have the same size, got ${a.width}×${a.height} and ${b.width}×${b.height}`,
    );
  }
  if (!Number.isInteger(radiusPx) || radiusPx < 0 || radiusPx > 8) {
    throw new RangeError(`compareNeighbourhood: radiusPx must be an integer 0 … 8, got ${String(radiusPx)}`);
  }
  if (!(maxChannelDiff >= 0 && maxChannelDiff <= 255)) {
    throw new RangeError(
      `compareNeighbourhood: maxChannelDiff must be 0 … 255, got ${String(maxChannelDiff)}`,
    );
  }
  const n = a.width * a.height;
  const ra = neighbourhoodRange(a, radiusPx);
  const rb = neighbourhoodRange(b, radiusPx);
  const excess = new Uint8Array(n);
  let maxExcess = 0;
  let failing = 0;
  let worst = -1;
  for (let k = 0; k < n; k++) {
    let e = 0;
    for (let c = 0; c < 3; c++) {
      const va = a.data[4 * k + c];
      const vb = b.data[4 * k + c];
      e = Math.max(
        e,
        rb.lo[3 * k + c] - va,
        va - rb.hi[3 * k + c],
        ra.lo[3 * k + c] - vb,
        vb - ra.hi[3 * k + c],
      );
    }
    excess[k] = e;
    if (e > maxChannelDiff) failing++;
    if (e > maxExcess) {
      maxExcess = e;
      worst = k;
    }
  }
  return {
    excess,
    maxExcess,
    failingPixels: failing,
    worst: worst < 0 ? null : { x: worst % a.width, y: Math.floor(worst / a.width) },
  };
}
