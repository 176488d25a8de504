import type { RgbaImage } from './png.js';

/** What {@link summarisePicture} found in a picture. */
export interface PictureSummary {
  /** Width in pixels. */
  readonly width: number;
  /** Height in pixels. */
  readonly height: number;
  /**
   * The background: the colour given, or else the most frequent colour of the picture, as RGBA bytes.
   */
  readonly background: readonly [number, number, number, number];
  /** Pixels whose RGB differs from the background's. */
  readonly drawnPixels: number;
}

/**
 * Count the pixels drawn over the background: those whose RGB differs from `background`, or, when it is not
 * given, from the picture's most frequent colour. A blank (flat) picture has none.
 *
 * @param background 8-bit RGB of the background, 0 … 255 each. @default the most frequent colour
 * @throws RangeError for a background that is not three integers 0 … 255.
 */
export function summarisePicture(
  { width, height, data }: RgbaImage,
  background?: readonly number[],
): PictureSummary {
  const n = width * height;
  let bg: [number, number, number, number];
  if (background !== undefined) {
    if (background.length !== 3 || !background.every((c) => Number.isInteger(c) && c >= 0 && c <= 255)) {
      throw new RangeError(
        `background must be three integers 0 … 255 (8-bit RGB), got [${Array.from(background).join(', ')}]`,
      );
    }
    bg = [background[0], background[1], background[2], 255];
  } else {
    bg = mostFrequent(data, n);
  }
  let drawn = 0;
  for (let k = 0; k < n; k++) {
    if (data[4 * k] !== bg[0] || data[4 * k + 1] !== bg[1] || data[4 * k + 2] !== bg[2]) drawn++;
  }
  return { width, height, background: bg, drawnPixels: drawn };
}

function mostFrequent(data: Uint8Array, n: number): [number, number, number, number] {
  if (n === 0) return [0, 0, 0, 0];
  const counts = new Map<number, number>();
  let best = 0;
  let bestCount = 0;
  for (let k = 0; k < n; k++) {
    const rgb = (data[4 * k] << 16) | (data[4 * k + 1] << 8) | data[4 * k + 2];
    const c = (counts.get(rgb) ?? 0) + 1;
    counts.set(rgb, c);
    if (c > bestCount) {
      bestCount = c;
      best = k;
    }
  }
  return [data[4 * best], data[4 * best + 1], data[4 * best + 2], data[4 * best + 3]];
}

/** `rgb(r, g, b)` of RGB bytes, for messages. */
export function rgbText(rgb: ArrayLike<number>): string {
  return `rgb(${rgb[0]}, ${rgb[1]}, ${rgb[2]})`;
}
