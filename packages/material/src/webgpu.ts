/**
 * `ShadingMaterial`'s shading for three's `WebGPURenderer` (`three/webgpu`): a node material, on the WebGPU and
 * the WebGL2 backend. A separate entry point, so that apps on `WebGLRenderer` never load `three/webgpu`.
 * @module @shadelab/material/webgpu
 */
export { ShadingNodeMaterial, type ShadingNodeMaterialOptions } from './ShadingNodeMaterial.js';
