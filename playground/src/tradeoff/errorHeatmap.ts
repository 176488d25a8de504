// The error of an image against the reference as a picture: interior colour error on a black → yellow → red
// ramp (0 … 16 codes and above), silhouette mismatches in cyan (brighter = farther from the true edge).
import type { ImageError, ReferenceImage } from '@shadelab/reference';

/** RGBA pixels, rows top-down (for `ImageData`), of the error heat map. */
export function errorHeatmap(error: ImageError, reference: ReferenceImage): Uint8ClampedArray<ArrayBuffer> {
  const { width, height, hit } = reference;
  const out = new Uint8ClampedArray(4 * width * height);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const k = j * width + i;
      const o = 4 * ((height - 1 - j) * width + i);
      const s = error.silhouetteError[k];
      if (s > 0) {
        const v = Math.min(1, 0.35 + s / 4);
        out.set([0, 255 * v, 255 * v, 255], o);
        continue;
      }
      const e = error.colorError[k];
      const t = Math.min(e / 16, 1);
      if (hit[k]) {
        // black (0) → yellow (8) → red (16+); a faint grey marks the compared area.
        const r = e === 0 ? 40 : 255 * Math.min(1, 2 * t + 0.2);
        const g = e === 0 ? 40 : 255 * Math.max(0, 1 - Math.abs(2 * t - 1)) + (t < 0.5 ? 60 : 0);
        out.set([r, g, e === 0 ? 40 : 0, 255], o);
      } else out.set([0, 0, 0, 255], o);
    }
  }
  return out;
}
