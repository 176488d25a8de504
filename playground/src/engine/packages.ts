/**
 * The one place the playground touches the shadelab packages. Everything else calls these functions, so a
 * package's API change (or swapping a stand-in for the real package) is a change to this file only.
 */

import { Camera, CameraMovement, depthBufferParameters, depthModeOf } from '@shadelab/camera';
import { flatShadingGeometry, PhongLight, ShadingMaterial } from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline, type OutlineMaterial } from '@shadelab/material/outline';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  chooseSphereDetail,
  type SphereDetail,
  silhouetteErrorScalePx,
  sphereError,
} from '@shadelab/sphere/detail';
import { Trackball } from '@shadelab/trackball';
import type * as THREE from 'three';
import { Quaternion } from 'three';
import type {
  DepthMode,
  LightState,
  PlaygroundState,
  Shading,
  SphereBase,
  TrackballMapping,
  Vec3,
} from '../state/schema';

// ---- sphere ------------------------------------------------------------------------------------------------

/**
 * The unit sphere for `shading`, indexed with no normal attribute (analytic normals); for flat shading
 * prepared by `flatShadingGeometry` (each face lit once, on a last vertex of its own).
 */
export function createSphere(
  base: SphereBase,
  level: number,
  shading: Shading,
  radius = 1,
): THREE.BufferGeometry {
  const sphere = new SubdivisionSphereGeometry({ base, level, radius, normals: 'none' });
  if (shading !== 'flat') return sphere;
  const flat = flatShadingGeometry(sphere);
  sphere.dispose();
  return flat;
}

/** The geometry a shading needs differs only between flat and the others. */
export function sphereKey(base: SphereBase, level: number, shading: Shading, radius = 1): string {
  return `${base}:${level}:${radius}:${shading === 'flat' ? 'faces' : 'shared'}`;
}

export type Detail = SphereDetail;

/**
 * Pixels of silhouette error on screen per unit of the sphere's relative radial error: an upper bound for
 * this camera and model matrix, near the camera and off axis too (@shadelab/sphere's
 * `silhouetteErrorScalePx`). Capped at sixteen viewport heights: with the eye inside the sphere, or its outline
 * reaching behind the eye, it is Infinity, and no detail is needed beyond the finest level there.
 */
export function sphereErrorScalePx(
  camera: ViewCamera,
  matrixWorld: THREE.Matrix4,
  viewportHeightPx: number,
  radius = 1,
): number {
  const px = silhouetteErrorScalePx({ camera, matrixWorld, viewportHeightPx, radius });
  return Math.min(px, 16 * viewportHeightPx);
}

/** The sphere's silhouette error on screen in pixels (at most; from the exact `sphereError`). */
export function sphereErrorPx(base: SphereBase, level: number, errorScalePx: number): number {
  return sphereError(base, level) * errorScalePx;
}

/** The cheapest sphere whose silhouette error on screen stays within `maxErrorPx` (levels 0 … 10). */
export function chooseDetail(errorScalePx: number, maxErrorPx: number): Detail {
  return chooseSphereDetail({ radiusPx: errorScalePx, maxErrorPx });
}

// ---- camera -------------------------------------------------------------------------------------------------

export type ViewCamera = Camera;

/** `WebGLRenderer` parameters for a depth mode (fixed for the renderer's life). */
export function depthParameters(depth: DepthMode): {
  logarithmicDepthBuffer: boolean;
  reversedDepthBuffer: boolean;
} {
  return depthBufferParameters(depth);
}

/**
 * The depth mode a renderer really runs (without EXT_clip_control, 'reversed' falls back to standard and
 * 'reversed-or-logarithmic' to logarithmic).
 */
export function activeDepth(renderer: THREE.WebGLRenderer): DepthMode {
  return depthModeOf(renderer);
}

export function createCamera(): ViewCamera {
  return new Camera({ fovy: 90, aspect: 1, near: 0.1, far: 10 });
}

/** The lecture's `lookAt(eye, at, up)`; throws a RangeError naming the bad argument. */
export function setCameraView(camera: ViewCamera, eye: Vec3, at: Vec3, up: Vec3): void {
  camera.lookAt(eye, at, up);
}

export function setCameraPerspective(
  camera: ViewCamera,
  fovy: number,
  aspect: number,
  near: number,
  far: number,
  zoom = 1,
) {
  camera.zoom = zoom;
  camera.setPerspective(fovy, aspect, near, far);
}

export function setCameraOrthographic(
  camera: ViewCamera,
  r: number,
  l: number,
  t: number,
  b: number,
  n: number,
  f: number,
  zoom = 1,
) {
  camera.zoom = zoom;
  camera.setOrthographic(r, l, t, b, n, f);
}

/** The camera's eye (after movement keys or a perspective zoom) and its zoom (after an orthographic zoom). */
export function getCameraEye(camera: ViewCamera): { eye: Vec3; zoom: number } {
  const { e } = camera.getFrame();
  return { eye: [e.x, e.y, e.z], zoom: camera.zoom };
}

export interface Mover extends THREE.EventDispatcher<{ change: object; start: object; end: object }> {
  moveSpeed: number;
  turnSpeed: number;
  enabled: boolean;
  connect(element: HTMLElement): void;
  disconnect(): void;
  dispose(): void;
}

/** Keys that move the camera (documented on the page; @shadelab/camera's MOVEMENT_KEYS). */
export const MOVE_KEYS = 'W/S or ↑/↓ forward/back, A/D or ←/→ left/right, E/Q up/down';

/** Keyboard movement, and a pointer drag that turns the gaze when `turnSpeed` > 0 (0: the drag is the trackball's). */
export function createMover(camera: ViewCamera): Mover {
  return new CameraMovement(camera, null, { turnSpeed: 0 });
}

/** The camera's frame: eye, gaze-opposite w and up v (after movement keys or a gaze turn). */
export function getCameraFrame(camera: ViewCamera): { eye: Vec3; w: Vec3; v: Vec3 } {
  const { e, v, w } = camera.getFrame();
  return { eye: [e.x, e.y, e.z], w: [w.x, w.y, w.z], v: [v.x, v.y, v.z] };
}

// ---- trackball ----------------------------------------------------------------------------------------------

export type TrackballHandle = Trackball;

/** The trackball with the package's own defaults (Bell's mapping, speeds, limits, radius). */
export function createTrackball(object: THREE.Object3D, camera: ViewCamera): TrackballHandle {
  return new Trackball(object, null, { camera });
}

/** Ball radius, a fraction of half the canvas's shorter side (the trackball refuses ≤ 0 or non-finite). */
export function setTrackballRadius(trackball: TrackballHandle, radius: number): void {
  trackball.radius = radius;
}

export function setTrackballMapping(trackball: TrackballHandle, mapping: TrackballMapping): void {
  trackball.mapping = mapping;
}

/** Sets the zoom limits in an order the trackball accepts (it keeps minZoom ≤ maxZoom at every step). */
export function setTrackballZoomLimits(trackball: TrackballHandle, minZoom: number, maxZoom: number): void {
  if (minZoom > trackball.maxZoom) {
    trackball.maxZoom = maxZoom;
    trackball.minZoom = minZoom;
  } else {
    trackball.minZoom = minZoom;
    trackball.maxZoom = maxZoom;
  }
}

/** The object's rotation (what the trackball turned) as [x, y, z, w]. */
export function getTrackballRotation(object: THREE.Object3D): [number, number, number, number] {
  return object.quaternion.toArray() as [number, number, number, number];
}

const _rotation = /* @__PURE__ */ new Quaternion();
const _cameraRotation = /* @__PURE__ */ new Quaternion();

/**
 * Puts the trackball's object at rotation `q` (world orientation, as the URL keeps it; a restored link, "reset
 * rotation") through the trackball's own `setRotation`, so its `rotation`, `getMatrix()` and `getWorldMatrix()`
 * agree with the picture and the next drag continues from it. The trackball works in camera coordinates:
 * `setRotation(C⁻¹ · q · C)` (C the camera's orientation now) puts the object, which starts unrotated, at q.
 * The zoom is kept.
 */
export function setTrackballRotation(trackball: TrackballHandle, q: [number, number, number, number]): void {
  if (trackball.camera) trackball.camera.getWorldQuaternion(_cameraRotation);
  else _cameraRotation.identity();
  _rotation.fromArray(q).multiply(_cameraRotation); // q · C
  trackball.setRotation(_rotation.premultiply(_cameraRotation.invert())); // C⁻¹ · q · C
  trackball.object.updateMatrixWorld(true);
}

// ---- material -----------------------------------------------------------------------------------------------

export type Light = PhongLight;
export type Material = ShadingMaterial;

export function createLight(): Light {
  return new PhongLight();
}

export function applyLight(light: Light, state: LightState): void {
  light.position.set(...state.position);
  light.ambient = state.ambient;
  light.diffuse = state.diffuse;
  light.specular = state.specular;
  light.attenuation = state.attenuation;
  light.updateMatrixWorld(true);
}

export type MaterialOptions = PlaygroundState['material'];

export function createMaterial(): Material {
  return new ShadingMaterial();
}

export function applyMaterial(material: Material, options: MaterialOptions, lights: Light[]): void {
  material.shading = options.shading;
  applyLighting(material, options, lights);
}

/** Every option but `shading`: what the mesh's material and the impostor's have in common. */
function applyLighting(
  material: Material | SphereImpostorMaterial,
  options: MaterialOptions,
  lights: Light[],
): void {
  material.lighting = options.lighting;
  material.celBands = options.celBands;
  material.ka = options.ka;
  material.kd = options.kd;
  material.ks = options.ks;
  material.shininess = options.shininess;
  material.phongLights = lights;
}

/**
 * The ray-cast sphere (exact silhouette and normals on two triangles; always per-fragment shading), with its
 * own material taking the same options as the mesh's but `shading`.
 */
export function createImpostor(): THREE.Mesh {
  return new SphereImpostor(new SphereImpostorMaterial());
}

export function applyImpostorMaterial(impostor: THREE.Mesh, options: MaterialOptions, lights: Light[]): void {
  applyLighting((impostor as SphereImpostor).material, options, lights);
}

/** Light positions are read by the material itself every frame (onBeforeRender). */
export function updateMaterialLights(_material: Material): void {}

/** A key naming the compiled variant (its defines), so per-variant shader edits are kept apart. */
export function variantKey(material: Material): string {
  const defines = material.defines ?? {};
  return Object.keys(defines)
    .sort()
    .map((k) => `${k}=${String(defines[k])}`)
    .join(',');
}

/** Outline thickness along the normal, in model units (before the model scale). */
export const OUTLINE_THICKNESS = 0.03;

/**
 * The material package's inverted-hull outline for cel shading, as a child of `mesh` sharing its geometry;
 * drawn light so that it shows on the lecture's black background.
 */
export function createOutlineMesh(mesh: THREE.Mesh): THREE.Mesh<THREE.BufferGeometry, OutlineMaterial> {
  return createOutline(mesh, { thickness: OUTLINE_THICKNESS, color: '#f2f2f2' });
}

/** Sets the outline's colour (a CSS colour such as `#rrggbb`, sRGB; the material names a bad one). */
export function setOutlineColor(
  outline: THREE.Mesh<THREE.BufferGeometry, OutlineMaterial>,
  color: string,
): void {
  outline.material.color = color;
}

/** Sets the outline's thickness (model units; the material refuses negative or non-finite values). */
export function setOutlineWidth(
  outline: THREE.Mesh<THREE.BufferGeometry, OutlineMaterial>,
  width: number,
): void {
  outline.material.thickness = width;
}

// ---- scenes -------------------------------------------------------------------------------------------------

/**
 * The copy of an indexed geometry on which flat shading lights each face once (the material's
 * `flatShadingGeometry`; it keeps skinning and position morph targets, not uv).
 */
export function flatGeometry(geometry: THREE.BufferGeometry): THREE.BufferGeometry {
  return flatShadingGeometry(geometry);
}
