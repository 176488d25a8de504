/**
 * ShadingMaterial (flat, Gouraud, Phong shading × Phong, Blinn-Phong, cel lighting), PhongLight, and `shade()`,
 * the same equations on the CPU. The cel outline is in `@shadelab/material/outline`, the ray-cast sphere in
 * `@shadelab/material/impostor`.
 * @module @shadelab/material
 * @mergeModuleWith <project>
 */
export { computeNormalMatrix } from './computeNormalMatrix.js';
export { eyeOf } from './eyeOf.js';
export {
  type FlatShadingGeometryOptions,
  flatShadingGeometry,
  type ProvokingVertex,
} from './flatShadingGeometry.js';
export { FLAT_CORNER_INDEX, FLAT_CORNERS, FLAT_PROVOKING_VERTEX, SPHERE_FLAG } from './geometryFlags.js';
export { linearToSrgb8, linearToSrgb8Channel } from './linearToSrgb8.js';
export {
  MAX_CEL_BANDS,
  NORMAL_MATRIX_MODES,
  type NormalMatrixMode,
  SHADING_OUTPUTS,
  SHADINGS,
  type Shading,
  type ShadingOptions,
  type ShadingOutput,
} from './options.js';
export { PhongLight, type PhongLightOptions } from './PhongLight.js';
export { ShadingMaterial, type ShadingMaterialOptions } from './ShadingMaterial.js';
export {
  type Attenuation,
  celDiffuse,
  celSpecular,
  type FogParameters,
  fogFactor,
  LIGHTINGS,
  type Lighting,
  MIN_ATTENUATION_DENOMINATOR,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeSample,
  type ShadeThreeLight,
  shade,
  specularPower,
  threeDistanceFalloff,
} from './shade.js';
export { SHADING_MATERIAL_OPTION_KEYS } from './shadingOptionsOf.js';
export type { ShadingProperties } from './shadingProperties.js';
export { type SwapMaterialsOptions, swapMaterials } from './swapMaterials.js';
export type { SkippedMaterial, SwappedMaterials } from './swapWith.js';
export { toShadingMaterial } from './toShadingMaterial.js';
export type { ColorInput } from './validate.js';
export type { Vec3, Vec3Like, Vec4Like } from './vec3.js';
