import type { Vector3 } from 'three';

/**
 * The lecture's camera frame: an eye point and a right-handed orthonormal basis, in world space.
 *
 * The camera looks down `−w`; `u × v = w`.
 */
export interface CameraFrame {
  /** The eye (camera position), world units. */
  e: Vector3;
  /** Unit vector to the camera's right. */
  u: Vector3;
  /** Unit vector in the camera's up direction (the component of `up` perpendicular to the gaze). */
  v: Vector3;
  /** Unit vector opposite the gaze direction (the camera looks down `−w`). */
  w: Vector3;
}
