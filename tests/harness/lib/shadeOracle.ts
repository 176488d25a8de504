// What the harnesses that compare a picture with shade() per pixel share (material.ts for ShadingMaterial on
// WebGLRenderer, webgpu-material.ts for ShadingNodeMaterial on WebGPURenderer): the pixels too near a triangle's
// edge to say which triangle the rasteriser gave them, and the points too near a jump of the lighting to say on
// which side float32 rounds.
import { type ShadeLight, type ShadeMaterial, type ShadeThreeLight, shade } from '@shadelab/material';
import { type Camera, Vector3 } from 'three';

/**
 * For the world-space triangle soup `world` (3 corners a triangle, 3 numbers a corner) seen by `camera` on a
 * `size`-pixel square picture: a function giving the distance in pixels from (x, y) to the nearest edge line of
 * screen triangle t (0 for a degenerate triangle).
 */
export function screenEdgeDistance(
  world: ArrayLike<number>,
  camera: Camera,
  size: number,
): (t: number, x: number, y: number) => number {
  const corners = world.length / 3;
  const screen = new Float64Array(2 * corners);
  const v = new Vector3();
  for (let i = 0; i < corners; i++) {
    v.fromArray(world, 3 * i).project(camera);
    screen[2 * i] = ((v.x + 1) / 2) * size;
    screen[2 * i + 1] = ((v.y + 1) / 2) * size;
  }
  return (t, x, y) => {
    let d = Number.POSITIVE_INFINITY;
    for (let k = 0; k < 3; k++) {
      const i = 3 * t + k;
      const j = 3 * t + ((k + 1) % 3);
      const ex = screen[2 * j] - screen[2 * i];
      const ey = screen[2 * j + 1] - screen[2 * i + 1];
      const len = Math.hypot(ex, ey);
      if (!(len > 0)) return 0;
      d = Math.min(d, Math.abs((x - screen[2 * i]) * ey - (y - screen[2 * i + 1]) * ex) / len);
    }
    return d;
  };
}

/** The unit direction from `p` to `light`; null for a light without one (ambient, hemisphere). */
function toLight(light: ShadeLight | ShadeThreeLight, p: Vector3): Vector3 | null {
  if (!('type' in light)) return new Vector3().fromArray(light.position).sub(p).normalize();
  if (light.type === 'directional') return new Vector3().fromArray(light.direction ?? [0, 1, 0]).normalize();
  if (light.type === 'point' || light.type === 'spot')
    return new Vector3()
      .fromArray(light.position ?? [0, 0, 0])
      .sub(p)
      .normalize();
  return null;
}

/**
 * For `material` under `lights` seen from `eye`: whether the point `position` with normal `normal` lies near a
 * discontinuity of the lighting, where the GPU (float32) and shade() (float64) may round to either side: the
 * terminator (l·n = 0) when the specular jumps there (shininess 0: 0⁰ = 1, or cel), a cel band's edge, or the cel
 * highlight's edge, for any light.
 */
export function lightingDiscontinuity(
  material: ShadeMaterial,
  lights: readonly (ShadeLight | ShadeThreeLight)[],
  eye: readonly number[],
): (position: ArrayLike<number>, normal: ArrayLike<number>) => boolean {
  const bands = material.celBands ?? 0;
  const p = new Vector3();
  const n = new Vector3();
  return (position, normal) => {
    if (bands === 0 && material.shininess !== 0) return false;
    p.fromArray(position);
    n.fromArray(normal).normalize();
    for (const light of lights) {
      const l = toLight(light, p);
      if (l === null) continue;
      const ndl = n.dot(l);
      if (Math.abs(ndl) < 0.01) return true;
      if (bands === 0) continue;
      const scaled = Math.max(ndl, 0) * bands;
      const edge = Math.round(scaled);
      if (Math.abs(scaled - edge) < 0.02 && edge > 0 && edge < bands) return true;
      // The cel highlight: the specular alone, white, of a light far along l (no attenuation), at its 0.5 step.
      const far = p.clone().addScaledVector(l, 1e6).toArray();
      const raw = shade(
        { position: p.toArray(), normal: n.toArray(), eye },
        { ...material, celBands: 0, ka: [0, 0, 0], kd: [0, 0, 0], ks: [1, 1, 1] },
        [{ position: far, ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [1, 1, 1] }],
      );
      if (Math.abs(raw[0] - 0.5) < 0.02) return true;
    }
    return false;
  };
}
