import { describe, expect, it } from 'vitest';
import { defaultState } from '../../state/schema';
import { backendLabel, webgpuNotes } from './status';

describe('WebGPU mode’s status', () => {
  it('names the backend that runs and why', () => {
    expect(backendLabel({ state: 'running', backend: 'webgpu', reason: null })).toBe('WebGPU');
    expect(backendLabel({ state: 'running', backend: 'webgl2', reason: 'no-adapter' })).toBe(
      "WebGL2 (WebGPU's fallback: no WebGPU adapter)",
    );
    expect(backendLabel({ state: 'running', backend: 'webgl2', reason: 'no-webgpu' })).toBe(
      "WebGL2 (WebGPU's fallback: this browser has no WebGPU)",
    );
    expect(
      backendLabel({
        state: 'running',
        backend: 'webgl2',
        reason: 'device-lost',
        message: 'Device was destroyed.',
      }),
    ).toBe("WebGL2 (WebGPU's fallback: the WebGPU device was lost: Device was destroyed.)");
    expect(backendLabel({ state: 'loading' })).toMatch(/loading three\/webgpu/);
    expect(backendLabel({ state: 'failed', message: 'no WebGL2 context' })).toBe(
      'WebGPU mode failed (no WebGL2 context); switch the renderer back to WebGL',
    );
  });

  it('names what WebGPU mode draws differently, and only that', () => {
    const state = defaultState();
    expect(webgpuNotes(state)).toEqual([expect.stringMatching(/GLSL editing is WebGL-only/)]);
    // Every scene, the compare view, the impostor and the outline are drawn: no note.
    state.scene = 'skinned';
    state.view = 'compare';
    state.sphere.render = 'impostor';
    state.material.outline = true;
    state.material.celBands = 3;
    expect(webgpuNotes(state)).toHaveLength(1);
    state.camera.depth = 'logarithmic';
    expect(webgpuNotes(state)[0]).toContain('"logarithmic" depth buffer');
    state.camera.depth = 'standard';
    // The textured scene (its normal map too) draws as in WebGL mode.
    state.scene = 'textured';
    expect(webgpuNotes(state)).toHaveLength(1);
    state.scene = 'lights';
    expect(webgpuNotes(state)[0]).toMatch(/node fog/);
    state.scene = 'model';
    expect(webgpuNotes(state)[0]).toMatch(/swapNodeMaterials/);
  });
});
