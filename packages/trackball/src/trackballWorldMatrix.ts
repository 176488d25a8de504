import { Matrix4, type Object3D, Quaternion, Vector3 } from 'three';

const _camera = /* @__PURE__ */ new Quaternion();
const _world = /* @__PURE__ */ new Quaternion();
const _pivot = /* @__PURE__ */ new Vector3();

/** What {@link trackballWorldMatrix} reads from a trackball. */
export interface TrackballState {
  /** The trackball rotation in camera coordinates (unit quaternion). */
  readonly rotation: Quaternion;
  /** The pivot in world coordinates. */
  readonly target: Vector3;
}

/**
 * The lecture's `trackballWorldMatrix(trackball, camera)`: the trackball rotation R, which is expressed in
 * the camera's frame, turned into a world transform about the pivot:
 * `T(target) · C · R · C⁻¹ · T(−target)`, where C is the camera's current world orientation (only its
 * rotation: the pivot, not the eye, stays fixed). Without a camera C is the identity (camera frame = world).
 *
 * The whole rotation is turned about the camera's axes as they are now, so after the camera turns this no
 * longer matches a Trackball's object, whose every drag stays about the axes of its time: use
 * `Trackball.getWorldMatrix` for that (the two agree while the camera has not turned since the first drag).
 *
 * @param trackball - The rotation and the pivot (a {@link Trackball} will do).
 * @param camera - The camera whose frame the rotation is expressed in, or null.
 * @param out - Where to write the matrix. @defaultValue a new Matrix4
 * @returns `out`, a rigid transform (rotation about `target`).
 */
export function trackballWorldMatrix(
  trackball: TrackballState,
  camera: Object3D | null,
  out: Matrix4 = new Matrix4(),
): Matrix4 {
  if (camera) camera.getWorldQuaternion(_camera);
  else _camera.identity();
  // C · R · C⁻¹
  _world.copy(_camera).multiply(trackball.rotation).multiply(_camera.invert());
  out.makeRotationFromQuaternion(_world);
  const t = trackball.target;
  _pivot.copy(t).applyQuaternion(_world);
  out.setPosition(t.x - _pivot.x, t.y - _pivot.y, t.z - _pivot.z);
  return out;
}
