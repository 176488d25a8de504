import type { Page } from '@playwright/test';
import { type Rasteriser, rasteriserOf } from './rendererNames.js';

/** What {@link expectBackend} found: the backend the browser gives, and what draws it. */
export interface BackendInfo {
  /** The backend checked. */
  readonly backend: 'webgpu' | 'webgl2';
  /**
   * What draws it: the WebGL renderer string (`UNMASKED_RENDERER_WEBGL`), or the WebGPU adapter's vendor,
   * architecture and description.
   */
  readonly description: string;
  /** The rasteriser that description names: SwiftShader, Mesa's llvmpipe, or a GPU. */
  readonly rasteriser: Rasteriser;
  /** For WebGPU: whether the adapter is a fallback (software) adapter; false for WebGL2. */
  readonly isFallbackAdapter: boolean;
}

/** Options of {@link expectBackend}. */
export interface ExpectBackendOptions {
  /** Also require this rasteriser (`'swiftshader'`, `'llvmpipe'` or `'gpu'`). @default any */
  rasteriser?: Rasteriser;
}

type Probe = { ok: true; description: string; isFallbackAdapter: boolean } | { ok: false; problem: string };

/** Runs in the page: can it have `backend`, and what draws it. */
async function probe(backend: 'webgpu' | 'webgl2'): Promise<Probe> {
  if (backend === 'webgl2') {
    const canvas = document.createElement('canvas');
    const gl = canvas.getContext('webgl2');
    if (gl === null) {
      return {
        ok: false,
        problem:
          "canvas.getContext('webgl2') returned null: Chromium without a usable GPU gives no WebGL unless SwiftShader is allowed (shadelabPreset()'s flags) or a rasteriser is there (shadelabPreset({ rasteriser: 'llvmpipe' }) under Xvfb)",
      };
    }
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const description = String(gl.getParameter(info === null ? gl.RENDERER : info.UNMASKED_RENDERER_WEBGL));
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    return { ok: true, description, isFallbackAdapter: false };
  }
  if (!globalThis.isSecureContext) {
    return {
      ok: false,
      problem: `the page (${location.href}) is not a secure context: WebGPU needs https, localhost or 127.0.0.1`,
    };
  }
  type Adapter = {
    info?: { vendor?: string; architecture?: string; description?: string };
    isFallbackAdapter?: boolean;
    requestDevice(): Promise<{ destroy(): void }>;
  };
  const gpu = (navigator as Navigator & { gpu?: { requestAdapter(): Promise<Adapter | null> } }).gpu;
  if (gpu === undefined) {
    return {
      ok: false,
      problem:
        'navigator.gpu is undefined: this Chromium exposes no WebGPU. Launch it with --enable-unsafe-webgpu (shadelabPreset({ webgpu: true }) or test.use(shadelabUse({ webgpu: true })))',
    };
  }
  let adapter: Adapter | null;
  try {
    adapter = await gpu.requestAdapter();
  } catch (error) {
    return { ok: false, problem: `navigator.gpu.requestAdapter() threw: ${String(error)}` };
  }
  if (adapter === null) {
    return {
      ok: false,
      problem:
        'navigator.gpu.requestAdapter() returned null: no WebGPU adapter. Launch Chromium with --enable-unsafe-webgpu (shadelabPreset({ webgpu: true })); without a GPU it then gives SwiftShader’s',
    };
  }
  try {
    (await adapter.requestDevice()).destroy();
  } catch (error) {
    return { ok: false, problem: `adapter.requestDevice() failed: ${String(error)}` };
  }
  const i = adapter.info ?? {};
  const description =
    [i.vendor, i.architecture, i.description].filter((s) => s).join(' ') || 'unknown adapter';
  // Chromium reports a software adapter's fallback status on the info object (newer) or the adapter (older).
  const fallback =
    (i as { isFallbackAdapter?: boolean }).isFallbackAdapter ?? adapter.isFallbackAdapter ?? false;
  return { ok: true, description, isFallbackAdapter: fallback };
}

/**
 * Preflight: check that the browser of `page` can give `backend` (`'webgpu'`: `navigator.gpu`, an adapter and
 * a device; `'webgl2'`: a WebGL2 context), and resolve with what draws it. Throws, saying what is missing and
 * which launch flag gives it, when it cannot: run it first in a test whose pictures depend on the backend, so
 * that a missing flag fails there and not as a picture that differs.
 *
 * @throws Error when the backend is not available or is not drawn by `options.rasteriser`; TypeError for a
 * bad `backend`.
 */
export async function expectBackend(
  page: Page,
  backend: 'webgpu' | 'webgl2',
  options: ExpectBackendOptions = {},
): Promise<BackendInfo> {
  if (backend !== 'webgpu' && backend !== 'webgl2') {
    throw new TypeError(`expectBackend: backend must be 'webgpu' or 'webgl2', got ${String(backend)}`);
  }
  const { rasteriser } = options;
  if (rasteriser !== undefined && !['swiftshader', 'llvmpipe', 'gpu'].includes(rasteriser)) {
    throw new TypeError(
      `expectBackend: rasteriser must be 'swiftshader', 'llvmpipe' or 'gpu', got ${String(rasteriser)}`,
    );
  }
  const found = await page.evaluate(probe, backend);
  const hint = `expectBackend(page, '${backend}')`;
  if (!found.ok) throw new Error(`${hint}: the browser cannot give ${backend}: ${found.problem}.`);
  const info: BackendInfo = {
    backend,
    description: found.description,
    rasteriser: rasteriserOf(found.description),
    isFallbackAdapter: found.isFallbackAdapter,
  };
  if (rasteriser !== undefined && info.rasteriser !== rasteriser) {
    throw new Error(
      `${hint}: ${backend} is drawn by ${info.rasteriser} (${info.description}), not ${rasteriser}.`,
    );
  }
  return info;
}
