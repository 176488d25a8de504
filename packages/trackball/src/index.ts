/**
 * A virtual trackball as three.js `Controls` (Shoemake's arcball or Bell's mapping), with zoom for both
 * projections, and its three-free core: `projectToBall` and `arcRotation`.
 * @module @shadelab/trackball
 * @mergeModuleWith <project>
 */
export { arcRotation } from './arcRotation.js';
export { projectToBall } from './projectToBall.js';
export type { TrackballCamera, TrackballEventMap, TrackballOptions } from './Trackball.js';
export { Trackball } from './Trackball.js';
export type { TrackballState } from './trackballWorldMatrix.js';
export { trackballWorldMatrix } from './trackballWorldMatrix.js';
export type { BallMapping, Quat, Vec3 } from './types.js';
