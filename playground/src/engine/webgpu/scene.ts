/**
 * What WebGPU mode copies from WebGL mode's objects: a ShadingMaterial's options onto its ShadingNodeMaterial, an
 * impostor's onto its SphereImpostorNodeMaterial, and a flatShadingGeometry remade for the backend's provoking
 * vertex.
 */
import {
  FLAT_PROVOKING_VERTEX,
  flatShadingGeometry,
  type ProvokingVertex,
  type ShadingMaterial,
} from '@shadelab/material';
import type { SphereImpostorMaterial } from '@shadelab/material/impostor';
import type { ShadingNodeMaterial, SphereImpostorNodeMaterial } from '@shadelab/material/webgpu';
import type * as THREE from 'three';

/** The surface properties (textures and three's Material flags) whose change rebuilds the node graph. */
const REBUILT = [
  'map',
  'alphaMap',
  'emissiveMap',
  'normalMap',
  'vertexColors',
  'transparent',
  'side',
] as const;
/** Plain properties copied as they are. */
const COPIED = ['fog', 'depthTest', 'depthWrite', 'blending', 'visible', 'opacity', 'alphaTest'] as const;

/**
 * The panel's options and the surface, as the viewer (or a scene) set them on the WebGL material (setters
 * recompile only on a change).
 */
export function mirrorMaterial(source: ShadingMaterial, m: ShadingNodeMaterial): void {
  mirrorLighting(source, m);
  m.shading = source.shading;
  m.output = source.output;
  m.normalMatrix = source.normalMatrix;
  const s = source as unknown as Record<string, unknown>;
  const t = m as unknown as Record<string, unknown>;
  let rebuild = false;
  for (const key of REBUILT) {
    if (t[key] === s[key]) continue;
    t[key] = s[key];
    rebuild = true;
  }
  for (const key of COPIED) if (t[key] !== s[key]) t[key] = s[key];
  if (!m.emissive.equals(source.emissive)) m.emissive = source.emissive;
  m.normalScale.copy(source.normalScale);
  if (rebuild) m.needsUpdate = true;
}

/** The options a ShadingMaterial and an impostor's material have in common (all but shading and the surface). */
export function mirrorLighting(
  source: ShadingMaterial | SphereImpostorMaterial,
  m: ShadingNodeMaterial | SphereImpostorNodeMaterial,
): void {
  m.lighting = source.lighting;
  m.celBands = source.celBands;
  if (!m.ka.equals(source.ka)) m.ka = source.ka;
  if (!m.kd.equals(source.kd)) m.kd = source.kd;
  if (!m.ks.equals(source.ks)) m.ks = source.ks;
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
