/**
 * The renderers `toMatchAcrossRenderers` draws a scene with:
 * - `'webgl'`: three's `WebGLRenderer` (a WebGL2 context);
 * - `'webgpu'`: `WebGPURenderer` on its WebGPU backend (a real `GPUDevice`; a silent fallback to WebGL2 fails);
 * - `'webgpu-webgl2'`: `WebGPURenderer` on its WebGL2 backend (`forceWebGL: true`).
 */
export type RendererName = 'webgl' | 'webgpu' | 'webgpu-webgl2';

/** Every {@link RendererName}, in the order `toMatchAcrossRenderers` draws them by default. */
export const RENDERER_NAMES: readonly RendererName[] = ['webgl', 'webgpu', 'webgpu-webgl2'];

/** What a renderer really ran on, seen in the page: the proof that WebGPU was not a silent fallback. */
export interface BackendProof {
  /** The renderer asked for. */
  readonly renderer: RendererName;
  /** The graphics API that drew: `'webgpu'` only with `isWebGPUBackend` and a real `GPUDevice`. */
  readonly api: 'webgl2' | 'webgpu' | 'none';
  /** `renderer.backend.isWebGPUBackend` of a WebGPURenderer (false for WebGLRenderer). */
  readonly isWebGPUBackend: boolean;
  /** `renderer.backend.isWebGLBackend` of a WebGPURenderer (false for WebGLRenderer). */
  readonly isWebGLBackend: boolean;
  /** Whether the WebGPU backend's device is a `GPUDevice` (the browser's own class). */
  readonly gpuDevice: boolean;
  /** The WebGPU adapter (the device's `adapterInfo`), for the WebGPU backend; null otherwise. */
  readonly adapter: {
    /** `GPUAdapterInfo.vendor`, such as `'google'`. */
    readonly vendor: string;
    /** `GPUAdapterInfo.architecture`, such as `'swiftshader'`. */
    readonly architecture: string;
    /** `GPUAdapterInfo.description` (often empty). */
    readonly description: string;
  } | null;
  /** The WebGL renderer string (`UNMASKED_RENDERER_WEBGL`), for WebGL contexts; null otherwise. */
  readonly glRenderer: string | null;
}

/** A software rasteriser the kit can launch Chromium with (see `shadelabPreset`), or `'gpu'` for anything else. */
export type Rasteriser = 'swiftshader' | 'llvmpipe' | 'gpu';

/**
 * Which rasteriser a WebGL renderer string or a WebGPU adapter's architecture names: SwiftShader, Mesa's
 * llvmpipe, or (anything else) a GPU.
 */
export function rasteriserOf(description: string): Rasteriser {
  const d = description.toLowerCase();
  if (d.includes('swiftshader')) return 'swiftshader';
  if (d.includes('llvmpipe')) return 'llvmpipe';
  return 'gpu';
}
