/**
 * How WebGPU mode draws the viewer's scene: the mesh with the node material mirroring the panel's material, what
 * only WebGL materials draw hidden for the frame, the camera's conventions put back after.
 */
import {
  FLAT_PROVOKING_VERTEX,
  flatShadingGeometry,
  type ProvokingVertex,
  type ShadingMaterial,
} from '@shadelab/material';
import type { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import * as THREE from 'three';
import type { GpuHost } from './WebGPUView';

/** The panel's options, as the viewer set them on the WebGL material (setters recompile only on a change). */
export function mirrorMaterial(source: ShadingMaterial, m: ShadingNodeMaterial): void {
  m.shading = source.shading;
  m.lighting = source.lighting;
  m.celBands = source.celBands;
  m.ka = source.ka;
  m.kd = source.kd;
  m.ks = source.ks;
  m.shininess = source.shininess;
  const lights = source.phongLights;
  if (lights.length !== m.phongLights.length || lights.some((l, i) => l !== m.phongLights[i])) {
    m.phongLights = lights;
  }
}

const _remade = new WeakMap<THREE.BufferGeometry, THREE.BufferGeometry>();

/**
 * `geometry`, or, when it is a flatShadingGeometry made for the other provoking vertex (the viewer's are made
 * for WebGL's, the last; WebGPU's is the first), one made for `provokingVertex` (once per geometry).
 */
export function flatFor(
  geometry: THREE.BufferGeometry,
  provokingVertex: ProvokingVertex,
): THREE.BufferGeometry {
  const made = geometry.userData[FLAT_PROVOKING_VERTEX];
  if (made === undefined || made === provokingVertex) return geometry;
  let remade = _remade.get(geometry);
  if (remade === undefined) {
    const g = flatShadingGeometry(geometry, { provokingVertex });
    geometry.addEventListener('dispose', () => g.dispose());
    _remade.set(geometry, g);
    remade = g;
  }
  return remade;
}

/**
 * Runs `draw` with the scene as WebGPU mode draws it: the mesh visible with the node material, what WebGL
 * materials draw beside it hidden (the mesh's outline, its siblings: the impostor, a picked scene), no fog,
 * a black background; the camera's projection conventions put back after (WebGPU's depth range differs).
 */
export function drawnAsWebGPU(
  host: GpuHost,
  material: ShadingNodeMaterial,
  provokingVertex: ProvokingVertex,
  draw: () => void,
): void {
  const { scene, camera, mesh } = host;
  const hidden = [...(mesh.parent?.children ?? []), ...mesh.children].filter((o) => o !== mesh && o.visible);
  const saved = {
    geometry: mesh.geometry,
    material: mesh.material,
    visible: mesh.visible,
    fog: scene.fog,
    background: scene.background,
    coordinateSystem: camera.coordinateSystem,
    reversedDepth: (camera as { _reversedDepth?: boolean })._reversedDepth,
  };
  for (const o of hidden) o.visible = false;
  mesh.geometry = flatFor(mesh.geometry, provokingVertex);
  mesh.material = material;
  mesh.visible = true;
  scene.fog = null;
  scene.background = BLACK;
  // The standard depth buffer: a projection the viewer's WebGLRenderer reversed is made standard again.
  if (saved.reversedDepth) {
    (camera as { _reversedDepth?: boolean })._reversedDepth = false;
    (camera as THREE.PerspectiveCamera).updateProjectionMatrix?.();
  }
  try {
    draw();
  } finally {
    for (const o of hidden) o.visible = true;
    mesh.geometry = saved.geometry;
    mesh.material = saved.material;
    mesh.visible = saved.visible;
    scene.fog = saved.fog;
    scene.background = saved.background;
    camera.coordinateSystem = saved.coordinateSystem;
    (camera as { _reversedDepth?: boolean })._reversedDepth = saved.reversedDepth;
    (camera as THREE.PerspectiveCamera).updateProjectionMatrix?.();
  }
}

const BLACK = /* @__PURE__ */ new THREE.Color(0x000000);
