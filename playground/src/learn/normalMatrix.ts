/**
 * The normal matrix, live (the lecture's slide): at a surface point of an object with model matrix M, a tangent
 * t and the normal n go to world space as M·t and, for n, either by the normal matrix (M⁻¹)ᵀ (right: it stays
 * perpendicular to M·t, since ((M⁻¹)ᵀn)·(Mt) = nᵀM⁻¹Mt = n·t = 0) or by M itself (wrong under a non-uniform
 * scale: (Mn)·(Mt) = nᵀMᵀMt, not 0 in general). The tangent drawn is the one the error is largest for: t along
 * the part of MᵀM·n in the tangent plane.
 */
import { computeNormalMatrix } from '@shadelab/material';
import * as THREE from 'three';

/** A 3-vector `[x, y, z]`. */
export type Vec3 = [number, number, number];

/** The vectors drawn at the point, world space, unit length. */
export interface NormalMatrixVectors {
  /** The surface point, world space. */
  point: Vec3;
  /** M·t, the tangent transformed (unit). */
  tangent: Vec3;
  /** (M⁻¹)ᵀ·n, normalised: the right normal. */
  inverseTranspose: Vec3;
  /** M·n, normalised: the lecture's wrong normal. */
  model: Vec3;
  /** Angle between each normal and the tangent, degrees (90 for the right one). */
  angles: { inverseTranspose: number; model: number };
}

const _m3 = /* @__PURE__ */ new THREE.Matrix3();
const _n3 = /* @__PURE__ */ new THREE.Matrix3();

const arr = (v: THREE.Vector3): Vec3 => [v.x, v.y, v.z];
const degrees = (a: THREE.Vector3, b: THREE.Vector3) =>
  THREE.MathUtils.radToDeg(Math.acos(THREE.MathUtils.clamp(a.dot(b), -1, 1)));

/**
 * The tangent and both normals at `point` (world space) of an object with model matrix `matrixWorld`, whose
 * object-space normal there is `objectNormal` (any length but 0).
 *
 * @throws RangeError when `objectNormal` or the transformed vectors are zero or not finite (a singular M).
 */
export function normalMatrixVectors(
  matrixWorld: THREE.Matrix4,
  point: readonly number[],
  objectNormal: readonly number[],
): NormalMatrixVectors {
  const n = new THREE.Vector3().fromArray(objectNormal as number[]);
  if (!(n.lengthSq() > 0) || !Number.isFinite(n.lengthSq())) {
    throw new RangeError(`objectNormal: [${objectNormal.join(', ')}] is not a finite non-zero vector`);
  }
  n.normalize();
  _m3.setFromMatrix4(matrixWorld);
  computeNormalMatrix(matrixWorld, _n3);
  // The tangent the wrong normal is furthest from perpendicular to: MᵀM·n minus its part along n.
  const mtmN = n.clone().applyMatrix3(_m3).applyMatrix3(_m3.clone().transpose());
  const full = mtmN.lengthSq();
  const t = mtmN.addScaledVector(n, -mtmN.dot(n));
  if (t.lengthSq() <= 1e-8 * full) {
    // MᵀM·n ∥ n (a uniform scale, or n along a principal axis): any tangent; M·n is right there too.
    t.set(1, 0, 0).cross(n);
    if (t.lengthSq() < 1e-6) t.set(0, 1, 0).cross(n);
  }
  t.normalize();
  t.addScaledVector(n, -t.dot(n)); // once more: the subtraction above can leave a rounding error along n
  const tangent = t.normalize().applyMatrix3(_m3);
  const right = n.clone().applyMatrix3(_n3);
  const wrong = n.clone().applyMatrix3(_m3);
  for (const [name, v] of [
    ['M·t', tangent],
    ['(M⁻¹)ᵀ·n', right],
    ['M·n', wrong],
  ] as const) {
    if (!(v.lengthSq() > 0) || !Number.isFinite(v.lengthSq())) {
      throw new RangeError(`matrixWorld: ${name} is zero or not finite (a singular model matrix)`);
    }
    v.normalize();
  }
  return {
    point: [point[0]!, point[1]!, point[2]!],
    tangent: arr(tangent),
    inverseTranspose: arr(right),
    model: arr(wrong),
    angles: { inverseTranspose: degrees(right, tangent), model: degrees(wrong, tangent) },
  };
}

/**
 * The object-space normal behind a world normal drawn with the normal matrix: n ∝ Mᵀ·n_world (since
 * n_world ∝ (M⁻¹)ᵀ·n). For a probe, which publishes the world normal it was lit with.
 */
export function objectNormalOf(matrixWorld: THREE.Matrix4, worldNormal: readonly number[]): Vec3 {
  const n = new THREE.Vector3()
    .fromArray(worldNormal as number[])
    .applyMatrix3(_m3.setFromMatrix4(matrixWorld).transpose());
  return arr(n);
}
