/**
 * How the state's sections are set on the packages' objects: the materials and lights, the trackball's options
 * and rotation, the camera's projection. The viewer calls these for the sections that changed.
 *
 * Imperative on purpose, not JSX props: the packages' setters refuse a bad value by throwing, and the playground
 * must report it for its section while the last good value stays on screen. As a prop, the throw would come
 * from inside R3F's commit, which unmounts the whole tree; here each section is tried on its own (Viewer.apply).
 */
import type { Camera, CameraMovement } from '@shadelab/camera';
import type { PhongLight, ShadingMaterial } from '@shadelab/material';
import type { SphereImpostorMaterial } from '@shadelab/material/impostor';
import type { Trackball } from '@shadelab/trackball';
import { Quaternion } from 'three';
import type { LightState, PlaygroundState } from '../../state/schema';
import type { Outline } from '../meshes';
import { rotationOf } from './input';
import type { CompareColumn } from './layout';

export type MaterialOptions = PlaygroundState['material'];

/** Sets every material option (shading included) and the lights on a ShadingMaterial. */
export function applyMaterial(
  material: ShadingMaterial,
  options: MaterialOptions,
  lights: PhongLight[],
): void {
  material.shading = options.shading;
  material.output = options.output;
  material.normalMatrix = options.normalMatrix;
  applyLighting(material, options, lights);
}

/** Every option but `shading` (what the mesh's material and the impostor's have in common), and the lights. */
export function applyLighting(
  material: ShadingMaterial | SphereImpostorMaterial,
  options: MaterialOptions,
  lights: PhongLight[],
): void {
  material.lighting = options.lighting;
  material.celBands = options.celBands;
  material.ka = options.ka;
  material.kd = options.kd;
  material.ks = options.ks;
  material.shininess = options.shininess;
  material.phongLights = lights;
}

/** The panel's options as a compare column draws them: its shading, and cel bands (at least 3) only in cel's. */
export function columnOptions(options: MaterialOptions, column: CompareColumn): MaterialOptions {
  return {
    ...options,
    shading: column.shading,
    celBands: column.cel ? Math.max(3, options.celBands) : 0,
  };
}

/** The outline's width (model units) and colour (CSS); the material names a bad value. */
export function applyOutline(outline: Outline, options: MaterialOptions): void {
  outline.material.thickness = options.outlineWidth;
  outline.material.color = options.outlineColor;
}

export function applyLight(light: PhongLight, state: LightState): void {
  light.position.set(...state.position);
  light.ambient = state.ambient;
  light.diffuse = state.diffuse;
  light.specular = state.specular;
  light.attenuation = state.attenuation;
  light.updateMatrixWorld(true);
}

/** The trackball's options, and its rotation when the state's differs from the object's (a link, a reset). */
export function applyTrackball(trackball: Trackball, options: PlaygroundState['trackball']): void {
  trackball.mapping = options.mapping;
  trackball.rotateSpeed = options.rotateSpeed;
  trackball.zoomSpeed = options.zoomSpeed;
  // In an order the trackball accepts (it keeps minZoom ≤ maxZoom at every step).
  if (options.minZoom > trackball.maxZoom) {
    trackball.maxZoom = options.maxZoom;
    trackball.minZoom = options.minZoom;
  } else {
    trackball.minZoom = options.minZoom;
    trackball.maxZoom = options.maxZoom;
  }
  trackball.dampingFactor = options.dampingFactor;
  trackball.enableDamping = options.damping;
  trackball.radius = options.radius;
  const current = rotationOf(trackball.object);
  if (current.some((c, i) => Math.abs(c - options.rotation[i]!) > 1e-12)) {
    setTrackballRotation(trackball, options.rotation);
  }
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
export function setTrackballRotation(trackball: Trackball, q: [number, number, number, number]): void {
  if (trackball.camera) trackball.camera.getWorldQuaternion(_cameraRotation);
  else _cameraRotation.identity();
  _rotation.fromArray(q).multiply(_cameraRotation); // q · C
  trackball.setRotation(_rotation.premultiply(_cameraRotation.invert())); // C⁻¹ · q · C
  trackball.object.updateMatrixWorld(true);
}

/** The movement keys' speeds, and gaze turns by drag (the trackball is off while they are on, or the gizmo drags). */
export function applyMovement(
  { mover, trackball }: { mover: CameraMovement; trackball: Trackball },
  c: PlaygroundState['camera'],
  gizmoDragging: boolean,
): void {
  mover.moveSpeed = c.moveSpeed;
  mover.turnSpeed = c.dragTurns ? c.turnSpeed : 0;
  trackball.enabled = !c.dragTurns && !gizmoDragging;
}

/**
 * The camera's projection for a cell of width/height `aspect`: perspective, or orthographic with its zoom
 * (with `fitAspect`, the box widened or narrowed about its middle to the cell's aspect).
 */
export function applyProjection(camera: Camera, c: PlaygroundState['camera'], aspect: number): void {
  if (c.projection === 'perspective') {
    camera.zoom = 1;
    camera.setPerspective(c.fovy, aspect, c.near, c.far);
    return;
  }
  camera.zoom = c.zoom;
  if (c.fitAspect) {
    const half = ((c.top - c.bottom) / 2) * aspect;
    const mid = (c.right + c.left) / 2;
    camera.setOrthographic(mid + half, mid - half, c.top, c.bottom, c.near, c.far);
  } else {
    camera.setOrthographic(c.right, c.left, c.top, c.bottom, c.near, c.far);
  }
}
