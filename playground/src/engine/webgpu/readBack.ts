/** Reading an offscreen frame of WebGPURenderer back, in gl.readPixels' row order on either backend. */
import type { RenderTarget, WebGPURenderer } from 'three/webgpu';

/**
 * The pixels of `target` (RGBA8, rows bottom-up): the WebGPU backend reads rows top-down (texture space), the
 * WebGL2 backend bottom-up (GL), so the WebGPU backend's rows are turned round.
 */
export async function readBack(
  renderer: WebGPURenderer,
  target: RenderTarget,
): Promise<{ pixels: Uint8Array; w: number; h: number }> {
  const { width: w, height: h } = target;
  const data = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, w, h)) as Uint8Array;
  const pixels = new Uint8Array(data);
  if ((renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true) {
    const row = 4 * w;
    for (let y = 0; y < h; y++) pixels.set(data.subarray((h - 1 - y) * row, (h - y) * row), y * row);
  }
  return { pixels, w, h };
}
