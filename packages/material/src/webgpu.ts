/**
 * `ShadingMaterial`'s shading for three's `WebGPURenderer` (`three/webgpu`): a node material, on the WebGPU and
 * the WebGL2 backend, and `SphereImpostorMaterial`'s ray-cast sphere as a node material. A separate entry
 * point, so that apps on `WebGLRenderer` never load `three/webgpu`.
 * @module @shadelab/material/webgpu
 */
export { provokingVertexOf } from './provokingVertexOf.js';
export {
  ShadingNodeMaterial,
  type ShadingNodeMaterialOptions,
  type Surface,
} from './ShadingNodeMaterial.js';
export {
  SphereImpostorNodeMaterial,
  type SphereImpostorNodeMaterialOptions,
} from './SphereImpostorNodeMaterial.js';
export { swapNodeMaterials } from './swapNodeMaterials.js';
export type { SkippedMaterial, SwappedMaterials } from './swapWith.js';
export { toShadingNodeMaterial } from './toShadingNodeMaterial.js';
