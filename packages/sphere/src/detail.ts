/**
 * Detail from a screen-space error budget: the exact radial error of a subdivision sphere, the cheapest base
 * and level that meets a budget in pixels, the projected radius of a sphere, and `AutoDetailSphere`, a mesh
 * that keeps its detail at the budget as the camera and canvas change.
 * @module @shadelab/sphere/detail
 */
export { type AutoDetail, AutoDetailSphere, type AutoDetailSphereOptions } from './AutoDetailSphere.js';
export {
  type ChooseSphereDetailOptions,
  chooseSphereDetail,
  type SphereDetail,
} from './chooseSphereDetail.js';
export {
  type ProjectedRadiusOptions,
  projectedRadiusPx,
  silhouetteErrorScalePx,
} from './projectedRadiusPx.js';
export { MAX_SPHERE_ERROR_LEVEL, sphereError } from './sphereError.js';
