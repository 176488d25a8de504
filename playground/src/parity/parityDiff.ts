/**
 * The parity view's numbers and heat map: WebGL mode's and WebGPU mode's pictures of the same state, both read
 * back (RGBA8 sRGB, rows bottom-up, as gl.readPixels gives them), compared pixel by pixel. A pixel's difference
 * is its largest channel difference (R, G or B) in 8-bit codes; the numbers are over every pixel of the picture:
 * the largest, the mean, and how many pixels differ by more than 1/255 and by more than 3/255. The heat map is
 * the trade-off page's (`tradeoff/errorHeatmap.ts`): a pixel lit in one picture only (a channel above 8, as the
 * tests count coverage) is a silhouette mismatch (cyan), a pixel lit in both is coloured by its difference, a
 * pixel dark in both is background.
 */
import type { ImageError, ReferenceImage } from '@shadelab/reference';
import { errorHeatmap } from '../tradeoff/errorHeatmap';

/** The numbers of one comparison. */
export interface ParityNumbers {
  /** Pixels compared (the picture's width × height). */
  readonly pixels: number;
  /** Largest difference, 8-bit codes. */
  readonly max: number;
  /** Mean difference over every pixel, 8-bit codes. */
  readonly mean: number;
  /** Pixels whose difference is more than 1 code (1/255). */
  readonly over1: number;
  /** Pixels whose difference is more than 3 codes (3/255). */
  readonly over3: number;
  /** Pixels lit in one picture only. */
  readonly coverage: number;
}

/** A pixel is lit (not background) when a channel is above 8. */
const lit = (p: Uint8Array, o: number) => p[o]! > 8 || p[o + 1]! > 8 || p[o + 2]! > 8;

/** Compares `webgl` with `webgpu` (`w` × `h`, RGBA, rows bottom-up): the numbers, and the heat map's pixels. */
export function parityDiff(
  webgl: Uint8Array,
  webgpu: Uint8Array,
  w: number,
  h: number,
): { numbers: ParityNumbers; heatmap: Uint8ClampedArray<ArrayBuffer> } {
  const n = w * h;
  if (webgl.length < 4 * n || webgpu.length < 4 * n) {
    throw new RangeError(`parityDiff: both pictures must hold ${w} × ${h} RGBA pixels`);
  }
  const colorError = new Uint8Array(n);
  const silhouetteError = new Float32Array(n);
  const hit = new Uint8Array(n);
  let max = 0;
  let sum = 0;
  let over1 = 0;
  let over3 = 0;
  let coverage = 0;
  for (let k = 0; k < n; k++) {
    const o = 4 * k;
    const d = Math.max(
      Math.abs(webgl[o]! - webgpu[o]!),
      Math.abs(webgl[o + 1]! - webgpu[o + 1]!),
      Math.abs(webgl[o + 2]! - webgpu[o + 2]!),
    );
    if (d > max) max = d;
    sum += d;
    if (d > 1) over1++;
    if (d > 3) over3++;
    const a = lit(webgl, o);
    const b = lit(webgpu, o);
    if (a !== b) {
      coverage++;
      silhouetteError[k] = 1;
    }
    hit[k] = a || b ? 1 : 0;
    colorError[k] = d;
  }
  const error = { colorError, silhouetteError } as unknown as ImageError;
  const reference = { width: w, height: h, hit } as unknown as ReferenceImage;
  return {
    numbers: { pixels: n, max, mean: n > 0 ? sum / n : 0, over1, over3, coverage },
    heatmap: errorHeatmap(error, reference),
  };
}

/** RGBA rows bottom-up (a read-back) as `ImageData`'s rows top-down. */
export function topDown(pixels: Uint8Array, w: number, h: number): Uint8ClampedArray<ArrayBuffer> {
  const out = new Uint8ClampedArray(4 * w * h);
  const row = 4 * w;
  for (let y = 0; y < h; y++) out.set(pixels.subarray((h - 1 - y) * row, (h - y) * row), y * row);
  return out;
}
