/**
 * The exact answer: a CPU ray-cast renderer of the lit analytic sphere (an ellipsoid under the model matrix)
 * and the image metrics that score a render against it. Three-free.
 * @module @shadelab/reference
 * @mergeModuleWith <project>
 */
export {
  type CompareToReferenceOptions,
  compareToReference,
  type ImageError,
} from './compareToReference.js';
export { intersectSphere, type SphereHit } from './intersectSphere.js';
export type { Mat4Like } from './mat4.js';
export { type ReferenceImage, type RenderReferenceOptions, renderReference } from './renderReference.js';
