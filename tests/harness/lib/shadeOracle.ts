// What the harnesses that compare a picture with shade() per pixel share (material.ts for ShadingMaterial on
// WebGLRenderer, webgpu-material.ts for ShadingNodeMaterial on WebGPURenderer): the pixels too near a triangle's
// edge to say which triangle the rasteriser gave them, the points too near a jump of the lighting to say on which
// side float32 rounds, and the triangle each pixel's centre sees.
import { type ShadeLight, type ShadeMaterial, type ShadeThreeLight, shade } from '@shadelab/material';
import { type Camera, Raycaster, Triangle, Vector2, Vector3 } from 'three';

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

/** What each pixel's centre sees of a triangle soup (the nearest triangle drawn there). */
export interface PixelHits {
  /** Per pixel (row by row from the bottom), the triangle's index; −1 where the ray hits none. */
  triangle: Int32Array;
  /** 3 per pixel: the hit's barycentrics in that triangle. */
  bary: Float32Array;
  /** 3 per pixel: the hit point, world space. */
  point: Float64Array;
}

/** The hits already found, by everything they depend on ({@link hitsKey}). */
const hitCache = new Map<string, PixelHits>();

/** A key for the inputs of {@link pixelHits}: the camera's matrices, the options and a hash of the soup. */
function hitsKey(world: Float64Array, camera: Camera, size: number, mirrored: boolean, side: string): string {
  // Two FNV-1a hashes of the soup's bytes, one from each end: a collision would need both to collide.
  const bytes = new Uint8Array(world.buffer, world.byteOffset, world.byteLength);
  let h1 = 0x811c9dc5;
  let h2 = 0x811c9dc5;
  for (let i = 0, j = bytes.length - 1; i < bytes.length; i++, j--) {
    h1 = Math.imul(h1 ^ bytes[i], 0x01000193);
    h2 = Math.imul(h2 ^ bytes[j], 0x01000193);
  }
  return [
    size,
    mirrored,
    side,
    world.length,
    h1 >>> 0,
    h2 >>> 0,
    camera.matrixWorld.elements.join(),
    camera.projectionMatrix.elements.join(),
  ].join('/');
}

/**
 * For the world-space triangle soup `world` (9 numbers a triangle) seen by `camera` on a `size`-pixel square
 * picture: the nearest triangle at each pixel's centre (three's Raycaster, each ray testing the triangles whose
 * screen box covers its tile), culled as three draws it (`side`; front faces swap when the model matrix is
 * `mirrored`, as three's renderer swaps them), with its barycentrics and point. The same soup, camera and options
 * give the same hits, found once: the variants a harness compares share them.
 */
export function pixelHits(
  world: Float64Array,
  camera: Camera,
  size: number,
  mirrored: boolean,
  side: 'front' | 'back' | 'double' = 'front',
): PixelHits {
  const key = hitsKey(world, camera, size, mirrored, side);
  const found = hitCache.get(key);
  if (found !== undefined) return found;
  const triangles = world.length / 9;
  const tile = 8;
  const tiles = Math.ceil(size / tile);
  const bins: number[][] = Array.from({ length: tiles * tiles }, () => []);
  const v = new Vector3();
  const px = new Float64Array(6);
  for (let t = 0; t < triangles; t++) {
    let minX = Number.POSITIVE_INFINITY;
    let minY = Number.POSITIVE_INFINITY;
    let maxX = Number.NEGATIVE_INFINITY;
    let maxY = Number.NEGATIVE_INFINITY;
    for (let k = 0; k < 3; k++) {
      v.set(world[9 * t + 3 * k], world[9 * t + 3 * k + 1], world[9 * t + 3 * k + 2]).project(camera);
      px[2 * k] = ((v.x + 1) / 2) * size;
      px[2 * k + 1] = ((v.y + 1) / 2) * size;
      minX = Math.min(minX, px[2 * k]);
      maxX = Math.max(maxX, px[2 * k]);
      minY = Math.min(minY, px[2 * k + 1]);
      maxY = Math.max(maxY, px[2 * k + 1]);
    }
    if (!Number.isFinite(minX + maxX + minY + maxY)) continue;
    const x0 = Math.max(0, Math.floor((minX - 1) / tile));
    const x1 = Math.min(tiles - 1, Math.floor((maxX + 1) / tile));
    const y0 = Math.max(0, Math.floor((minY - 1) / tile));
    const y1 = Math.min(tiles - 1, Math.floor((maxY + 1) / tile));
    for (let ty = y0; ty <= y1; ty++) for (let tx = x0; tx <= x1; tx++) bins[ty * tiles + tx].push(t);
  }
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  const a = new Vector3();
  const b = new Vector3();
  const c = new Vector3();
  const hit = new Vector3();
  const best = new Vector3();
  const bc = new Vector3();
  const triangle = new Int32Array(size * size).fill(-1);
  const bary = new Float32Array(3 * size * size);
  const point = new Float64Array(3 * size * size);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const bin = bins[Math.floor(y / tile) * tiles + Math.floor(x / tile)];
      if (bin.length === 0) continue;
      ndc.set(((x + 0.5) / size) * 2 - 1, ((y + 0.5) / size) * 2 - 1);
      raycaster.setFromCamera(ndc, camera);
      let bestT = -1;
      let bestD = Number.POSITIVE_INFINITY;
      for (const t of bin) {
        a.fromArray(world, 9 * t);
        b.fromArray(world, 9 * t + 3);
        c.fromArray(world, 9 * t + 6);
        // Cull back faces as three does (its front face flips when the determinant is negative).
        // BackSide draws only the back faces; DoubleSide both.
        const hitTriangle =
          side === 'double'
            ? raycaster.ray.intersectTriangle(a, b, c, false, hit)
            : mirrored !== (side === 'back')
              ? raycaster.ray.intersectTriangle(a, c, b, true, hit)
              : raycaster.ray.intersectTriangle(a, b, c, true, hit);
        if (hitTriangle === null) continue;
        const dist = hit.distanceTo(raycaster.ray.origin);
        if (dist < bestD) {
          bestD = dist;
          bestT = t;
          best.copy(hit);
        }
      }
      if (bestT < 0) continue;
      const i = y * size + x;
      triangle[i] = bestT;
      a.fromArray(world, 9 * bestT);
      b.fromArray(world, 9 * bestT + 3);
      c.fromArray(world, 9 * bestT + 6);
      Triangle.getBarycoord(best, a, b, c, bc);
      bary[3 * i] = bc.x;
      bary[3 * i + 1] = bc.y;
      bary[3 * i + 2] = bc.z;
      point[3 * i] = best.x;
      point[3 * i + 1] = best.y;
      point[3 * i + 2] = best.z;
    }
  }
  const hits = { triangle, bary, point };
  hitCache.set(key, hits);
  return hits;
}
