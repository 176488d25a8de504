/**
 * The sphere by recursive subdivision of a tetrahedron (the lecture's), an octahedron or an icosahedron: typed
 * arrays (`subdivideSphere`) or a three.js geometry (`SubdivisionSphereGeometry`), with their exact counts and
 * memory estimate. Detail from an error budget is in `@shadelab/sphere/detail`, vertex normals of any indexed
 * mesh in `@shadelab/sphere/normals`.
 * @module @shadelab/sphere
 * @mergeModuleWith <project>
 */
export { estimateSphereBytes } from './estimateSphereBytes.js';
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
export { type SphereMesh, subdivideSphere } from './subdivideSphere.js';
