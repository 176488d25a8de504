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

  it('names each setting WebGPU mode does not draw, and only those', () => {
    const state = defaultState();
    expect(webgpuNotes(state)).toEqual([expect.stringMatching(/GLSL editing is WebGL-only/)]);
    state.scene = 'skinned';
    state.view = 'compare';
    state.sphere.render = 'impostor';
    state.material.outline = true;
    state.camera.depth = 'logarithmic';
    const notes = webgpuNotes(state);
    expect(notes).toHaveLength(5);
    expect(notes[0]).toContain('"skinned" scene');
    // The outline is drawn only with cel bands (WebGL mode too): no note without them.
    expect(notes.some((n) => n.includes('outline'))).toBe(false);
    state.material.celBands = 3;
    expect(webgpuNotes(state).some((n) => n.includes('outline'))).toBe(true);
  });
});
