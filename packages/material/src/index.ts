/**
 * ShadingMaterial (flat, Gouraud, Phong shading × Phong, Blinn-Phong, cel lighting), PhongLight, the cel
 * outline, and `shade()`, the same equations on the CPU. The ray-cast sphere is in `@shadelab/material/impostor`.
 * @module @shadelab/material
 */
export { computeNormalMatrix } from './computeNormalMatrix.js';
export { createOutline } from './createOutline.js';
export { eyeOf } from './eyeOf.js';
export { linearToSrgb8, linearToSrgb8Channel } from './linearToSrgb8.js';
export { OutlineMaterial, type OutlineMaterialOptions } from './OutlineMaterial.js';
export { PhongLight, type PhongLightOptions } from './PhongLight.js';
export {
  MAX_CEL_BANDS,
  SHADINGS,
  type Shading,
  ShadingMaterial,
  type ShadingMaterialOptions,
  SPHERE_FLAG,
} from './ShadingMaterial.js';
export {
  type Attenuation,
  celDiffuse,
  celSpecular,
  LIGHTINGS,
  type Lighting,
  MIN_ATTENUATION_DENOMINATOR,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeSample,
  shade,
  specularPower,
} from './shade.js';
export type { ColorInput } from './validate.js';
export type { Vec3, Vec3Like, Vec4Like } from './vec3.js';
