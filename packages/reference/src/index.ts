export {
  type CompareToReferenceOptions,
  compareToReference,
  type ImageError,
} from './compareToReference.js';
export { intersectSphere, type SphereHit } from './intersectSphere.js';
export type { Mat4Like } from './mat4.js';
export { type ReferenceImage, type RenderReferenceOptions, renderReference } from './renderReference.js';
