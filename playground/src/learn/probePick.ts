/**
 * Probing a pixel: the ray through its centre meets the front-most ShadingMaterial surface (the sphere, or a part
 * of the picked scene), explained there as the material's shading lights it (probeExplain.ts); a probed point is
 * followed when the view moves, and the GPU's pixel read back.
 */
import type { ShadingMaterial } from '@shadelab/material';
import * as THREE from 'three';
import { explainHit, type ProbeHit } from './probeExplain';
import { modelOf } from './probeInputs';
import { ndcOfPixel, pixelOfNdc, type V3 } from './probeMath';

export type { ProbeHit, ProbeVertex } from './probeExplain';

/** A probe that met no shaded surface, and why. */
export interface ProbeMiss {
  readonly hit: false;
  readonly pixel: [number, number];
  readonly reason: string;
}

/** What a probe found. */
export type ProbeResult = ProbeHit | ProbeMiss;

const isShading = (m: unknown): m is ShadingMaterial =>
  (m as { isShadingMaterial?: boolean } | null)?.isShadingMaterial === true;
const MARKER = /^light marker/;
const raycaster = new THREE.Raycaster();

/** Whether a world point survives the material's clipping planes (three drops the negative side). */
const unclipped = (material: THREE.Material, point: THREE.Vector3) =>
  (material.clippingPlanes ?? []).every((plane) => plane.distanceToPoint(point) >= 0);

/**
 * Probes device pixel (`x`, `y`) (y from the top) of a `width` × `height` canvas showing `scene` through `camera`:
 * the front-most visible ShadingMaterial surface under the pixel's centre, explained as its shading lights it.
 */
export function probePixel(
  scene: THREE.Scene,
  camera: THREE.Camera,
  x: number,
  y: number,
  width: number,
  height: number,
): ProbeResult {
  const pixel: [number, number] = [x, y];
  const [nx, ny] = ndcOfPixel(x, y, width, height);
  raycaster.setFromCamera(new THREE.Vector2(nx, ny), camera);
  const candidates: THREE.Object3D[] = [];
  scene.traverseVisible((o) => {
    const mesh = o as THREE.Mesh;
    if (mesh.isMesh && (isShading(mesh.material) || MARKER.test(mesh.name))) candidates.push(mesh);
  });
  const found = raycaster
    .intersectObjects(candidates, false)
    .find((h) => unclipped((h.object as THREE.Mesh).material as THREE.Material, h.point));
  if (!found?.face) {
    return { hit: false, pixel, reason: 'No object under this pixel: the probe is off the object.' };
  }
  const mesh = found.object as THREE.Mesh;
  if (!isShading(mesh.material)) {
    return { hit: false, pixel, reason: `The ${mesh.name} hides the surface at this pixel.` };
  }
  return explainHit(scene, camera, mesh, mesh.material, found, raycaster.ray.direction, pixel, [
    width,
    height,
  ]);
}

/**
 * Where a followed point is now: the device pixel of `local` (in `mesh`'s, or its instance's, own space) after the
 * view moved; null when it left the canvas or is behind the camera.
 */
export function pixelOfFollowed(
  camera: THREE.Camera,
  mesh: THREE.Mesh,
  instanceId: number | null,
  local: V3,
  width: number,
  height: number,
): [number, number] | null {
  const world = new THREE.Vector3(...local).applyMatrix4(modelOf(mesh, instanceId));
  const view = world.clone().applyMatrix4(camera.matrixWorldInverse);
  if ((camera as THREE.PerspectiveCamera).isPerspectiveCamera && view.z >= 0) return null;
  const ndc = world.project(camera);
  return pixelOfNdc(ndc.x, ndc.y, width, height);
}

/** The canvas's pixel (`x`, `y`), y from the top, as 8-bit RGB: what the GPU drew last (the buffer is kept). */
export function readCanvasPixel(renderer: THREE.WebGLRenderer, x: number, y: number): V3 {
  const gl = renderer.getContext();
  const out = new Uint8Array(4);
  gl.readPixels(x, gl.drawingBufferHeight - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return [out[0]!, out[1]!, out[2]!];
}
