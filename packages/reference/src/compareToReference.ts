import type { ReferenceImage } from './renderReference.js';

/** Options of {@link compareToReference}. */
export interface CompareToReferenceOptions {
  /**
   * The background colour of the image under test as 8-bit sRGB codes: a pixel of exactly this colour is
   * "not covered". Pick a colour the shading never produces (e.g. pure blue). @default [0, 0, 255]
   */
  background?: readonly [number, number, number];
  /**
   * Interior pixels are those at least this far inside the exact silhouette (pixels, ≥ 0): their colour is
   * compared. @default 1
   */
  interiorMarginPx?: number;
}

/** How far an image is from the reference. */
export interface ImageError {
  /** Root mean square colour error over the interior, in 8-bit sRGB codes (all three channels). */
  readonly rmse: number;
  /** Largest channel error over the interior, in 8-bit sRGB codes. */
  readonly max: number;
  /** Interior pixels compared: reference interior (see `interiorMarginPx`) and covered in the image. */
  readonly interiorPixels: number;
  /**
   * Largest silhouette error in pixels: over the pixels whose coverage (centre inside or not) differs from
   * the reference, the largest distance of the pixel centre from the exact silhouette (`edgeDistance`); 0 when
   * every pixel agrees. A rasteriser sampling pixel centres of the exact shape scores 0.
   */
  readonly silhouettePx: number;
  /** Mean silhouette error in pixels: mismatched pixels divided by the silhouette's length in pixels. */
  readonly silhouetteMeanPx: number;
  /** Pixels whose coverage differs from the reference. */
  readonly mismatchedPixels: number;
  /** Per pixel: the interior colour error (largest channel, 8-bit codes), 0 elsewhere; rows as the images. */
  readonly colorError: Uint8Array;
  /** Per pixel: the silhouette error in pixels where coverage differs, 0 elsewhere. */
  readonly silhouetteError: Float32Array;
}

/**
 * Measure an image (e.g. `gl.readPixels` of a GPU render, RGBA, rows bottom-up) against a
 * {@link ReferenceImage} of the same size: colour error (RMSE and max, 8-bit sRGB) over the interior and
 * silhouette error in pixels.
 * @param pixels - The image under test: RGBA, 8-bit sRGB, rows bottom-up, width·height pixels.
 * @param reference - What {@link renderReference} returned for the same scene and size.
 * @param options - The background colour and the interior margin.
 *
 * @throws RangeError when `pixels` does not hold width·height RGBA pixels, or for a bad option.
 */
export function compareToReference(
  pixels: ArrayLike<number>,
  reference: ReferenceImage,
  { background = [0, 0, 255], interiorMarginPx = 1 }: CompareToReferenceOptions = {},
): ImageError {
  const { width, height, rgba, hit, edgeDistance } = reference;
  const n = width * height;
  if (pixels.length !== 4 * n) {
    throw new RangeError(
      `compareToReference: pixels must hold ${width}×${height} RGBA pixels (${4 * n} values), got ${pixels.length}`,
    );
  }
  if (!(interiorMarginPx >= 0) || !Number.isFinite(interiorMarginPx)) {
    throw new RangeError(
      `compareToReference: interiorMarginPx must be a finite number ≥ 0, got ${String(interiorMarginPx)}`,
    );
  }
  const colorError = new Uint8Array(n);
  const silhouetteError = new Float32Array(n);
  let sum = 0;
  let max = 0;
  let interior = 0;
  let silhouettePx = 0;
  let mismatched = 0;
  let edgePixels = 0;
  for (let k = 0; k < n; k++) {
    const r = pixels[4 * k];
    const g = pixels[4 * k + 1];
    const b = pixels[4 * k + 2];
    const covered = r !== background[0] || g !== background[1] || b !== background[2];
    const d = edgeDistance[k];
    if (Math.abs(d) <= 0.5) edgePixels++;
    if (covered !== (hit[k] === 1)) {
      mismatched++;
      const e = Number.isFinite(d) ? Math.abs(d) : 0;
      silhouetteError[k] = e;
      if (e > silhouettePx) silhouettePx = e;
      continue;
    }
    if (covered && d <= -interiorMarginPx) {
      const er = Math.abs(r - rgba[4 * k]);
      const eg = Math.abs(g - rgba[4 * k + 1]);
      const eb = Math.abs(b - rgba[4 * k + 2]);
      const e = Math.max(er, eg, eb);
      colorError[k] = e;
      if (e > max) max = e;
      sum += er * er + eg * eg + eb * eb;
      interior++;
    }
  }
  return {
    rmse: interior > 0 ? Math.sqrt(sum / (3 * interior)) : 0,
    max,
    interiorPixels: interior,
    silhouettePx,
    silhouetteMeanPx: edgePixels > 0 ? mismatched / edgePixels : 0,
    mismatchedPixels: mismatched,
    colorError,
    silhouetteError,
  };
}
