// The error of an image against the reference as a picture. Interior pixels: dark grey where the colour is
// exact (or not compared: within 1 px of the silhouette), then olive (1 code) → yellow (8) → red (16 and
// above). Silhouette mismatches: cyan, brighter the farther the pixel is from the true edge. Background: black.
// The page's legend is drawn from these same colours.
import type { ImageError, ReferenceImage } from '@shadelab/reference';

/** An 8-bit RGB colour. */
export type Rgb8 = readonly [number, number, number];

/** Interior pixels with no colour error (or within 1 px of the edge, where colour is not compared). */
export const HEAT_EXACT: Rgb8 = [40, 40, 40];
/** Pixels that neither the reference nor the image covers. */
export const HEAT_BACKGROUND: Rgb8 = [0, 0, 0];
/** The interior errors the ramp names: 1 code (olive), 8 (yellow), 16 and above (red). */
export const HEAT_RAMP_STOPS = [1, 8, 16] as const;

/** The colour of an interior colour error of `e` 8-bit codes (0 gives {@link HEAT_EXACT}). */
export function heatColor(e: number): Rgb8 {
  if (e === 0) return HEAT_EXACT;
  const t = Math.min(e / 16, 1);
  const r = 255 * Math.min(1, 2 * t + 0.2);
  const g = Math.min(255, 255 * Math.max(0, 1 - Math.abs(2 * t - 1)) + (t < 0.5 ? 60 : 0));
  return [Math.round(r), Math.round(g), 0];
}

/** The colour of a silhouette mismatch `px` pixels from the exact edge (> 0): cyan, 35 % → 100 % at 2.6 px. */
export function silhouetteColor(px: number): Rgb8 {
  const v = Math.round(255 * Math.min(1, 0.35 + px / 4));
  return [0, v, v];
}

/** RGBA pixels, rows top-down (for `ImageData`), of the error heat map. */
export function errorHeatmap(error: ImageError, reference: ReferenceImage): Uint8ClampedArray<ArrayBuffer> {
  const { width, height, hit } = reference;
  const out = new Uint8ClampedArray(4 * width * height);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const k = j * width + i;
      const o = 4 * ((height - 1 - j) * width + i);
      const s = error.silhouetteError[k];
      const c = s > 0 ? silhouetteColor(s) : hit[k] ? heatColor(error.colorError[k]) : HEAT_BACKGROUND;
      out[o] = c[0];
      out[o + 1] = c[1];
      out[o + 2] = c[2];
      out[o + 3] = 255;
    }
  }
  return out;
}
