import type { ExpectMatcherState, Page } from '@playwright/test';
import { describe, expect, it } from 'vitest';
import { type BackendProof, rasteriserOf } from './rendererNames.js';
import { describeProof, toMatchAcrossRenderers } from './toMatchAcrossRenderers.js';

const state = { isNot: false, timeout: 100 } as ExpectMatcherState;
/** A page that must not be reached: option errors are thrown before the page is asked for anything. */
const page = new Proxy(
  {},
  { get: () => () => Promise.reject(new Error('the page was used')) },
) as unknown as Page;
const run = (scene: unknown, options: object) =>
  toMatchAcrossRenderers.call(state, page, scene as string, options as never);

describe('toMatchAcrossRenderers: its arguments', () => {
  it('refuses fewer than two renderers, unknown ones and repeats, naming them', async () => {
    await expect(run('s', { renderers: ['webgl'] })).rejects.toThrow(
      new RangeError(
        'toMatchAcrossRenderers: renderers must list at least two of webgl, webgpu, webgpu-webgl2, got ["webgl"]',
      ),
    );
    await expect(run('s', { renderers: ['webgl', 'vulkan'] })).rejects.toThrow(
      new TypeError(
        "toMatchAcrossRenderers: renderers may hold 'webgl', 'webgpu', 'webgpu-webgl2', got \"vulkan\"",
      ),
    );
    await expect(run('s', { renderers: ['webgl', 'webgl'] })).rejects.toThrow(
      'toMatchAcrossRenderers: renderers has a repeat: ["webgl","webgl"]',
    );
  });

  it('refuses a size or tolerance out of range, and a scene that is neither a function nor a name', async () => {
    for (const [options, message] of [
      [{ width: 0 }, 'width must be an integer 1 … 4096 pixels, got 0'],
      [{ height: 1.5 }, 'height must be an integer 1 … 4096 pixels, got 1.5'],
      [{ maxChannelDiff: 256 }, 'maxChannelDiff must be a number of 8-bit codes 0 … 255, got 256'],
      [{ radiusPx: 9 }, 'radiusPx must be an integer 0 … 8, got 9'],
      [{ maxDiffPixels: -1 }, 'maxDiffPixels must be an integer ≥ 0, got -1'],
    ] as const) {
      await expect(run('s', options)).rejects.toThrow(`toMatchAcrossRenderers: ${message}`);
    }
    await expect(run('', {})).rejects.toThrow(
      new TypeError(
        "toMatchAcrossRenderers: scene must be a scene factory function or a registered scene's name, got ",
      ),
    );
  });
});

describe('the backends, as the report names them', () => {
  const proof = (p: Partial<BackendProof>): BackendProof => ({
    renderer: 'webgpu',
    api: 'none',
    isWebGPUBackend: false,
    isWebGLBackend: false,
    gpuDevice: false,
    adapter: null,
    glRenderer: null,
    ...p,
  });
  it('names the API, the device and what draws it; the rasteriser follows from the name', () => {
    const gpu = describeProof(
      proof({
        api: 'webgpu',
        isWebGPUBackend: true,
        gpuDevice: true,
        adapter: { vendor: 'google', architecture: 'swiftshader', description: '' },
      }),
      'webgpu',
    );
    expect(gpu).toBe('WebGPURenderer, WebGPU backend (GPUDevice; google swiftshader)');
    expect(rasteriserOf(gpu)).toBe('swiftshader');
    const fallback = describeProof(
      proof({
        api: 'webgl2',
        isWebGLBackend: true,
        glRenderer: 'ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL 4.5)',
      }),
      'webgpu',
    );
    expect(fallback).toBe(
      'WebGPURenderer, WebGL2 backend: ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL 4.5)',
    );
    expect(rasteriserOf(fallback)).toBe('llvmpipe');
    expect(
      rasteriserOf(
        describeProof(
          proof({ renderer: 'webgl', api: 'webgl2', glRenderer: 'ANGLE (NVIDIA, Vulkan 1.3)' }),
          'webgl',
        ),
      ),
    ).toBe('gpu');
    expect(describeProof(null, 'webgpu')).toBe('WebGPURenderer (not initialised)');
  });
});
