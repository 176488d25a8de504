export { type AutoDetail, AutoDetailSphere, type AutoDetailSphereOptions } from './AutoDetailSphere.js';
export {
  type ChooseSphereDetailOptions,
  chooseSphereDetail,
  type SphereDetail,
} from './chooseSphereDetail.js';
export { computeVertexNormals, type NormalWeighting } from './computeVertexNormals.js';
export { estimateSphereBytes } from './estimateSphereBytes.js';
export { type ProjectedRadiusOptions, projectedRadiusPx } from './projectedRadiusPx.js';
export { SPHERE_BASES, type SphereBase } from './SphereBase.js';
export {
  DEFAULT_SPHERE_MAX_BYTES,
  MAX_SPHERE_RADIUS,
  MIN_SPHERE_RADIUS,
  type SphereNormals,
  type SphereParameters,
  type SubdivideSphereOptions,
} from './SphereOptions.js';
export { SubdivisionSphereGeometry } from './SubdivisionSphereGeometry.js';
export { type SphereCounts, sphereCounts } from './sphereCounts.js';
export { MAX_SPHERE_ERROR_LEVEL, sphereError } from './sphereError.js';
export { type SphereMesh, subdivideSphere } from './subdivideSphere.js';
