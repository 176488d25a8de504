/**
 * `ShadingMaterial`'s shading for three's `WebGPURenderer` (`three/webgpu`): a node material, on the WebGPU and
 * the WebGL2 backend, `SphereImpostorMaterial`'s ray-cast sphere and `OutlineMaterial`'s cel outline as node
 * materials. A separate entry point, so that apps on `WebGLRenderer` never load `three/webgpu`.
 * @module @shadelab/material/webgpu
 */
export { createOutlineNode } from './createOutlineNode.js';
export type { LightingSplit } from './nodeLighting.js';
export type { ShadowTerm, ShadowTerms } from './nodeShadows.js';
export { OutlineNodeMaterial, type OutlineNodeMaterialOptions } from './OutlineNodeMaterial.js';
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
