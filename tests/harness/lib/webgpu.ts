// What the WebGPU harness pages share: one initialised WebGPURenderer per backend (and depth mode), which backend
// really runs, and reading a render target back in GL's row order on either backend.
import type { RenderTarget } from 'three';
import { WebGPURenderer } from 'three/webgpu';

/** WebGPURenderer's WebGPU backend, or its WebGL2 backend (`forceWebGL`). */
export type Backend = 'webgpu' | 'webgl2';

/** The renderer's depth buffer: standard, logarithmic (`logarithmicDepthBuffer`) or reversed-Z (`reversedDepthBuffer`). */
export type DepthMode = 'standard' | 'logarithmic' | 'reversed';

const renderers = new Map<string, Promise<WebGPURenderer>>();

/** The page's WebGPURenderer for `backend` and `mode` (no antialiasing), created and initialised once. */
export function gpuRenderer(backend: Backend, mode: DepthMode = 'standard'): Promise<WebGPURenderer> {
  const key = `${backend} ${mode}`;
  let r = renderers.get(key);
  if (r === undefined) {
    const renderer = new WebGPURenderer({
      antialias: false,
      forceWebGL: backend === 'webgl2',
      logarithmicDepthBuffer: mode === 'logarithmic',
      reversedDepthBuffer: mode === 'reversed',
    });
    r = renderer.init().then(() => renderer);
    renderers.set(key, r);
  }
  return r;
}

/** Which backend `renderer` runs (three's flags on it): proof that WebGPU is not a silent fallback to WebGL2. */
export function backendFlags(renderer: WebGPURenderer): {
  isWebGPUBackend: boolean;
  isWebGLBackend: boolean;
} {
  const b = renderer.backend as unknown as { isWebGPUBackend?: boolean; isWebGLBackend?: boolean };
  return { isWebGPUBackend: b.isWebGPUBackend === true, isWebGLBackend: b.isWebGLBackend === true };
}

/**
 * The `size` × `size` pixels of `target`, RGBA8, rows bottom-up on either backend: the WebGPU backend reads rows
 * top-down (texture space), the WebGL2 backend bottom-up (GL), so the WebGPU backend's rows are flipped.
 */
export async function readTarget(
  renderer: WebGPURenderer,
  target: RenderTarget,
  size: number,
): Promise<Uint8Array> {
  const data = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, size, size)) as Uint8Array;
  const pixels = new Uint8Array(data);
  if (backendFlags(renderer).isWebGPUBackend) {
    const row = 4 * size;
    for (let y = 0; y < size; y++) pixels.set(data.subarray((size - 1 - y) * row, (size - y) * row), y * row);
  }
  return pixels;
}
