// What the harness pages (tests/harness/, bench/harness/) share to read a picture back and compare two: reading a
// WebGLRenderer's canvas, a pixel's coverage against the clear colour, and the per-pixel max |Δ| over RGB.
// Pictures are RGBA8, rows bottom-up (GL's order), 4 bytes a pixel; `i` is a byte offset (4 × the pixel index).
import type { WebGLRenderer } from 'three';

/** The `width` × `height` pixels at the origin of what `renderer` last drew on its canvas, rows bottom-up. */
export function readCanvas(renderer: WebGLRenderer, width: number, height = width): Uint8Array {
  const gl = renderer.getContext();
  const pixels = new Uint8Array(4 * width * height);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

/** Whether the pixel at byte `i` of `p` has the RGB `rgb` (0 … 255): the clear colour where nothing was drawn. */
export const hasRgb = (p: Uint8Array, i: number, rgb: readonly [number, number, number]): boolean =>
  p[i] === rgb[0] && p[i + 1] === rgb[1] && p[i + 2] === rgb[2];

/** max |a − b| over R, G and B (1/255) between the pixel at byte `i` of `a` and byte `j` of `b`. */
export const maxRgbDelta = (a: Uint8Array, b: Uint8Array, i: number, j = i): number =>
  Math.max(Math.abs(a[i] - b[j]), Math.abs(a[i + 1] - b[j + 1]), Math.abs(a[i + 2] - b[j + 2]));
