export { estimateSphereBytes } from './estimateSphereBytes.js';
export { SPHERE_BASES, type SphereBase } from './SphereBase.js';
export {
  DEFAULT_SPHERE_MAX_BYTES,
  type SphereNormals,
  type SphereParameters,
  type SubdivideSphereOptions,
} from './SphereOptions.js';
export { type SphereCounts, sphereCounts } from './sphereCounts.js';
export { MAX_SPHERE_ERROR_LEVEL, sphereError } from './sphereError.js';
export { type SphereMesh, subdivideSphere } from './subdivideSphere.js';
