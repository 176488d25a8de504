/**
 * The one place the playground touches the shadelab packages. Everything else calls these functions, so a
 * package's API change (or swapping a stand-in for the real package) is a change to this file only.
 */
import * as THREE from 'three';
import type { LightState, PlaygroundState, SphereBase, TrackballMapping, Vec3 } from '../state/schema';
import {
  StandInCamera,
  StandInLight,
  StandInMaterial,
  StandInMover,
  StandInTrackball,
  standInSphere,
  vec,
} from './standins';

/** Which packages are real (false = a three.js stand-in is used); shown on the page. */
export const REAL_PACKAGES = { sphere: false, camera: false, trackball: false, material: false };

// ---- sphere ------------------------------------------------------------------------------------------------

export function createSphere(base: SphereBase, level: number): THREE.BufferGeometry {
  if (!Number.isInteger(level) || level < 0) throw new RangeError(`level: ${level} is not an integer ≥ 0`);
  return standInSphere(base, level);
}

export interface Detail {
  base: SphereBase;
  level: number;
  triangles: number;
  errorPx: number;
}

/** The cheapest sphere whose radial error stays under `maxErrorPx` for a sphere `radiusPx` pixels across. */
export function chooseDetail(radiusPx: number, maxErrorPx: number): Detail {
  // Stand-in: the tetrahedron level whose error (≈ edge sagitta) meets the budget.
  for (let level = 0; level <= 10; level++) {
    const edge = 1.63 / 2 ** level;
    const errorPx = radiusPx * (1 - Math.sqrt(Math.max(0, 1 - (edge * edge) / 3)));
    if (errorPx <= maxErrorPx) return { base: 'tetrahedron', level, triangles: 4 * 4 ** level, errorPx };
  }
  return { base: 'tetrahedron', level: 10, triangles: 4 * 4 ** 10, errorPx: 0 };
}

// ---- camera -------------------------------------------------------------------------------------------------

export type ViewCamera = StandInCamera;

export function createCamera(): ViewCamera {
  return new StandInCamera();
}

export function setCameraView(camera: ViewCamera, eye: Vec3, at: Vec3, up: Vec3): void {
  if (eye.every((x, i) => x === at[i])) throw new RangeError(`lookAt: eye (${eye}) equals at`);
  camera.position.copy(vec(eye));
  camera.up.copy(vec(up));
  camera.lookAt(vec(at));
  camera.updateMatrixWorld(true);
}

export function setCameraPerspective(
  camera: ViewCamera,
  fovy: number,
  aspect: number,
  near: number,
  far: number,
) {
  if (!(fovy > 0 && fovy < 180)) throw new RangeError(`fovy: ${fovy} is outside (0, 180) degrees`);
  if (!(near > 0)) throw new RangeError(`near: ${near} is not > 0`);
  if (!(far > near)) throw new RangeError(`far: ${far} is not > near (${near})`);
  const top = near * Math.tan(THREE.MathUtils.degToRad(fovy / 2));
  camera.projectionMatrix.makePerspective(-top * aspect, top * aspect, top, -top, near, far);
  camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
  camera.isOrthographic = false;
}

export function setCameraOrthographic(
  camera: ViewCamera,
  r: number,
  l: number,
  t: number,
  b: number,
  n: number,
  f: number,
) {
  if (r === l) throw new RangeError(`r: ${r} equals l`);
  if (t === b) throw new RangeError(`t: ${t} equals b`);
  if (!(f > n)) throw new RangeError(`far: ${f} is not > near (${n})`);
  camera.projectionMatrix.makeOrthographic(l, r, t, b, n, f);
  camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
  camera.isOrthographic = true;
}

/** The camera's eye, and an `at` on its gaze at `distance`, after the movement keys moved it. */
export function getCameraEye(camera: ViewCamera, distance: number): { eye: Vec3; at: Vec3 } {
  camera.updateMatrixWorld(true);
  const e = camera.matrixWorld.elements;
  const eye: Vec3 = [e[12]!, e[13]!, e[14]!];
  const at: Vec3 = [eye[0] - e[8]! * distance, eye[1] - e[9]! * distance, eye[2] - e[10]! * distance];
  return { eye, at };
}

export interface Mover extends THREE.EventDispatcher<{ change: object }> {
  speed: number;
  connect(element: HTMLElement): void;
  disconnect(): void;
  dispose(): void;
}

/** Keys that move the camera (documented on the page). */
export const MOVE_KEYS = 'W/S forward/back, A/D left/right, R/F up/down';

export function createMover(camera: ViewCamera): Mover {
  return new StandInMover(camera);
}

// ---- trackball ----------------------------------------------------------------------------------------------

export interface TrackballHandle
  extends THREE.EventDispatcher<{ change: object; start: object; end: object }> {
  rotateSpeed: number;
  zoomSpeed: number;
  enabled: boolean;
  connect(element: HTMLElement): void;
  disconnect(): void;
  dispose(): void;
}

export function createTrackball(object: THREE.Object3D, camera: ViewCamera): TrackballHandle {
  return new StandInTrackball(object, camera);
}

export function setTrackballMapping(_trackball: TrackballHandle, _mapping: TrackballMapping): void {
  // The stand-in has one mapping.
}

/** The trackball's accumulated rotation as [x, y, z, w]. */
export function getTrackballRotation(object: THREE.Object3D): [number, number, number, number] {
  return object.quaternion.toArray() as [number, number, number, number];
}

export function setTrackballRotation(object: THREE.Object3D, q: [number, number, number, number]): void {
  object.quaternion.fromArray(q).normalize();
  object.updateMatrixWorld(true);
}

// ---- material -----------------------------------------------------------------------------------------------

export type Light = StandInLight;
export type Material = StandInMaterial;

export function createLight(): Light {
  return new StandInLight();
}

export function applyLight(light: Light, state: LightState): void {
  const { a, b, c } = state.attenuation;
  if (a === 0 && b === 0 && c === 0) throw new RangeError('attenuation: a = b = c = 0 would divide by zero');
  light.position.set(...state.position);
  light.ambient.setRGB(...state.ambient);
  light.diffuse.setRGB(...state.diffuse);
  light.specular.setRGB(...state.specular);
  light.attenuation = { a, b, c };
  light.updateMatrixWorld(true);
}

export type MaterialOptions = PlaygroundState['material'];

export function createMaterial(): Material {
  return new StandInMaterial();
}

export function applyMaterial(material: Material, options: MaterialOptions, lights: Light[]): void {
  material.shading = options.shading;
  material.lighting = options.lighting;
  material.celBands = options.celBands;
  material.phongLights = lights;
  material.setColors(options.ka, options.kd, options.ks, options.shininess);
  material.syncDefines();
}

/** Called before each render: light positions are read every frame. */
export function updateMaterialLights(material: Material): void {
  material.syncLights();
}

/** A key naming the compiled variant, so per-variant shader edits are kept apart. */
export function variantKey(material: Material): string {
  return JSON.stringify(material.defines ?? {});
}

/** An outline for cel shading, or null when the material package offers none. */
export function createOutline(_material: Material): THREE.Material | null {
  return null;
}
