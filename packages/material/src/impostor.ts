/**
 * The analytic ray-cast sphere: a screen-aligned quad whose fragment shader intersects the sphere, writes
 * exact depth and shades with ShadingMaterial's equations. A separate entry point, so that apps that draw
 * meshes only do not load it.
 * @module @shadelab/material/impostor
 */
export { createImpostorQuad, SphereImpostor } from './SphereImpostor.js';
export {
  projectedBounds,
  SphereImpostorMaterial,
  type SphereImpostorMaterialOptions,
} from './SphereImpostorMaterial.js';
