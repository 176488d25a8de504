/**
 * Reads a Mach-band profile back from the canvas: the same view drawn in flat, Gouraud and Phong shading, one
 * after the other in one task (the page shows only the last draw, the current state's), and the pixels along the
 * line read from each draw with `readPixels`. Loaded with the plot, on the first profile (not in the first frame).
 */
import { SHADINGS } from '@shadelab/material';
import type { Viewer } from '../engine/viewer/Viewer';
import type { Shading } from '../state/schema';
import type { Rgb8 } from './profileLine';

/** Each shading's displayed colour at each pixel of the line, in the line's order. */
export type ProfileSamples = Record<Shading, Rgb8[]>;

/** The part of the viewer a profile reads: its state, its draw and its WebGL canvas. */
export type ProfileViewer = Pick<Viewer, 'state' | 'apply' | 'render' | 'renderer' | 'canvas'>;

/**
 * Draws the viewer's state in each shading and reads `pixels` (`[column, row]`, row 0 at the top, inside the
 * canvas) back from each draw; then draws the state as it was. Throws a RangeError for a pixel outside the canvas.
 *
 * @param viewer - The playground's viewer, in WebGL mode, with a state applied.
 * @param pixels - The line's pixels ({@link linePixels}).
 */
export function sampleProfile(
  viewer: ProfileViewer,
  pixels: readonly (readonly [number, number])[],
): ProfileSamples {
  const base = viewer.state;
  if (!base) throw new Error('sampleProfile: the viewer has no state yet');
  const { width, height } = viewer.canvas;
  let [x0, y0, x1, y1] = [width, height, -1, -1];
  for (const [x, y] of pixels) {
    if (!(x >= 0 && x < width && y >= 0 && y < height)) {
      throw new RangeError(`sampleProfile: pixel (${x}, ${y}) is outside the ${width} × ${height} canvas`);
    }
    [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x), Math.max(y1, y)];
  }
  const [w, h] = [x1 - x0 + 1, y1 - y0 + 1];
  const gl = viewer.renderer.getContext();
  const buffer = new Uint8Array(Math.max(0, w * h * 4));
  const out = {} as ProfileSamples;
  try {
    for (const shading of SHADINGS) {
      viewer.apply({ ...base, material: { ...base.material, shading } });
      viewer.render();
      if (pixels.length > 0) gl.readPixels(x0, height - 1 - y1, w, h, gl.RGBA, gl.UNSIGNED_BYTE, buffer);
      out[shading] = pixels.map(([x, y]) => {
        const i = ((y1 - y) * w + (x - x0)) * 4;
        return [buffer[i]!, buffer[i + 1]!, buffer[i + 2]!] as const;
      });
    }
  } finally {
    viewer.apply(base);
    viewer.render();
  }
  return out;
}
