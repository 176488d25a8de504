import type { RgbaImage } from './png.js';

/**
 * A diff picture for a report: `picture` in dim grey (a third of its luma), with the pixels `mark` colours
 * drawn over it (`mark(k)` for pixel k in the picture's row order returns RGB, or null for none).
 */
export function diffImage(
  picture: RgbaImage,
  mark: (k: number) => readonly [number, number, number] | null,
): RgbaImage {
  const { width, height, data } = picture;
  const out = new Uint8Array(width * height * 4);
  for (let k = 0; k < width * height; k++) {
    const m = mark(k);
    if (m === null) {
      const luma = (0.299 * data[4 * k] + 0.587 * data[4 * k + 1] + 0.114 * data[4 * k + 2]) / 3;
      out[4 * k] = out[4 * k + 1] = out[4 * k + 2] = Math.round(luma);
    } else {
      [out[4 * k], out[4 * k + 1], out[4 * k + 2]] = m;
    }
    out[4 * k + 3] = 255;
  }
  return { width, height, data: out };
}

/** A mark's colour for an error of `e` against an allowance of `allowed`: orange within it, red above. */
export function errorColour(e: number, allowed: number): readonly [number, number, number] {
  if (e <= allowed) return [255, 170, 0];
  return [255, 0, 0];
}
