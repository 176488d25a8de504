import { Vector3 } from 'three';
import type { CameraFrame } from './CameraFrame.js';
import { readVector3, safeNormalize, type Vec3Input } from './readVector3.js';
import { finite } from './validateProjection.js';

/**
 * Half-angle of the cap around the gaze line (radians) inside which `up` no longer decides the frame on its own.
 *
 * Outside the cap, `u = normalize(up × w)` exactly as three.js's `Matrix4.lookAt`. Inside it (`up` within
 * 1e-4 rad of the gaze or of its opposite) the exact projection turns by 180° across the pole, so the frame
 * instead turns smoothly from a remembered anchor towards it (see {@link PoleMemory}).
 */
export const POLE_CAP_RAD = 1e-4;

const POLE_CAP_SIN = Math.sin(POLE_CAP_RAD);

/**
 * What {@link lookAtFrame} remembers between calls so that the frame turns continuously while `up` passes the
 * gaze line. A camera keeps one of these; a fresh one (`createPoleMemory()`) is always valid.
 */
export interface PoleMemory {
  /** Last right vector `u` computed outside the pole cap (world space, unit). */
  anchor: Vector3;
  /** Last signed turn (radians, about `w`) from the anchor to the exact up-projection, unwrapped across ±π. */
  turn: number;
}

/** A fresh {@link PoleMemory}: anchor +x, no turn. */
export function createPoleMemory(): PoleMemory {
  return { anchor: new Vector3(1, 0, 0), turn: 0 };
}

const _d = /* @__PURE__ */ new Vector3();
const _up = /* @__PURE__ */ new Vector3();
const _c = /* @__PURE__ */ new Vector3();
const _a = /* @__PURE__ */ new Vector3();
const _b = /* @__PURE__ */ new Vector3();
const _t = /* @__PURE__ */ new Vector3();

/** A unit vector perpendicular to unit `w`, chosen from the world axis least aligned with it. */
function stablePerpendicular(w: Vector3, target: Vector3): Vector3 {
  const ax = Math.abs(w.x);
  const ay = Math.abs(w.y);
  const az = Math.abs(w.z);
  if (ax <= ay && ax <= az) target.set(0, -w.z, w.y);
  else if (ay <= az) target.set(w.z, 0, -w.x);
  else target.set(-w.y, w.x, 0);
  return target.normalize();
}

/**
 * The lecture's `lookAt(eye, at, up)` frame: `w = normalize(eye − at)`, `u = normalize(up × w)`, `v = w × u`,
 * `e = eye` — the same basis three.js's `Matrix4.lookAt` / `Object3D.lookAt` build for a camera.
 *
 * When `up` is parallel to the gaze, or within {@link POLE_CAP_RAD} of it, `up × w` is (nearly) zero and its
 * direction flips as `up` passes the pole. The frame then stays finite and orthonormal, and turns continuously:
 * `u` is the memory's anchor (the last `u` before the cap, projected onto the plane ⊥ `w`) rotated about `w`
 * towards the exact projection by `turn · sin(angle(up, gaze line)) / sin(POLE_CAP_RAD)`, so it meets the exact
 * frame at the cap's rim and equals the anchor on the pole. Without `memory` a stable perpendicular of `w` is the
 * anchor (finite and orthonormal, but a sweep through the pole may then jump).
 *
 * @param eye - Camera position (world units, finite).
 * @param at - Point looked at (world units, finite, ≠ `eye`).
 * @param up - Up direction (any non-zero finite length; only its direction matters).
 * @param target - Frame to write (its vectors are overwritten).
 * @param memory - Pole memory to read and update; see {@link PoleMemory}.
 * @throws RangeError when `eye` = `at`, `up` is zero, or any component is NaN or infinite.
 * @throws TypeError when an argument is not a vector.
 */
export function lookAtFrame(
  eye: Vec3Input,
  at: Vec3Input,
  up: Vec3Input,
  target: CameraFrame,
  memory?: PoleMemory,
): CameraFrame {
  const e = readVector3(eye, 'eye', _b);
  readVector3(at, 'at', _d);
  readVector3(up, 'up', _up);
  const w = target.w.subVectors(e, _d);
  if (!safeNormalize(w)) {
    throw new RangeError(`eye and at must differ, both are (${e.x}, ${e.y}, ${e.z}); allowed: eye ≠ at`);
  }
  if (!finite(w.x + w.y + w.z)) {
    throw new RangeError(`eye − at overflows: eye (${e.x}, ${e.y}, ${e.z}); allowed: |eye − at| finite`);
  }
  if (!safeNormalize(_up)) throw new RangeError('up must be a non-zero vector, got (0, 0, 0)');
  target.e.copy(e);
  const u = target.u;
  const c = _c.crossVectors(_up, w);
  const s = c.length();
  if (s >= POLE_CAP_SIN) {
    u.copy(c).divideScalar(s);
    if (memory) {
      memory.anchor.copy(u);
      memory.turn = 0;
    }
  } else {
    // Anchor projected onto the plane ⊥ w (or a stable perpendicular when the anchor is along w).
    const a = _a.copy(memory ? memory.anchor : w).addScaledVector(w, -(memory ? memory.anchor.dot(w) : 1));
    if (!memory || a.length() < 1e-6) stablePerpendicular(w, a);
    else a.normalize();
    const wa = _t.crossVectors(w, a);
    let angle = 0;
    if (s > 0) {
      const ch = c.divideScalar(s);
      let phi = Math.atan2(wa.dot(ch), a.dot(ch));
      const previous = memory ? memory.turn : 0;
      phi += 2 * Math.PI * Math.round((previous - phi) / (2 * Math.PI));
      if (memory) memory.turn = phi;
      angle = (phi * s) / POLE_CAP_SIN;
    }
    u.copy(a).multiplyScalar(Math.cos(angle)).addScaledVector(wa, Math.sin(angle)).normalize();
  }
  target.v.crossVectors(w, u).normalize();
  return target;
}
