/**
 * The lecture's camera, `lookAt(eye, at, up)`, `setPerspective`, `setOrthographic` and the frame e, u, v, w,
 * as a three.js `Camera`; `CameraMovement`, its keyboard and pointer handlers; the renderer's depth modes.
 * @module @shadelab/camera
 * @mergeModuleWith <project>
 */
export type { CameraOptions, ProjectionType } from './Camera.js';
export { Camera } from './Camera.js';
export type { CameraFrame } from './CameraFrame.js';
export type { CameraMovementEventMap, CameraMovementOptions } from './CameraMovement.js';
export { CameraMovement, MOVEMENT_KEYS } from './CameraMovement.js';
export type { DepthBufferParameters, DepthMode, DepthModeRequest } from './depthMode.js';
export { depthBufferParameters, depthModeOf } from './depthMode.js';
export type { PoleMemory } from './lookAtFrame.js';
export { createPoleMemory, lookAtFrame, POLE_CAP_RAD } from './lookAtFrame.js';
export type { Vec3Input } from './readVector3.js';
