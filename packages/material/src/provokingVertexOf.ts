import type { ProvokingVertex } from './flatShadingGeometry.js';

/**
 * The provoking vertex of `renderer`'s flat varyings, for {@link flatShadingGeometry}'s `provokingVertex`:
 * `'first'` on `WebGPURenderer`'s WebGPU backend, `'last'` on its WebGL2 backend (and on `WebGLRenderer`).
 * Call it after `await renderer.init()`: before, `WebGPURenderer` has not chosen its backend.
 *
 * @example
 * await renderer.init();
 * const mesh = new Mesh(flatShadingGeometry(geometry, { provokingVertex: provokingVertexOf(renderer) }), material);
 */
export function provokingVertexOf(renderer: object): ProvokingVertex {
  const backend = (renderer as { backend?: { isWebGPUBackend?: boolean } }).backend;
  return backend?.isWebGPUBackend === true ? 'first' : 'last';
}
