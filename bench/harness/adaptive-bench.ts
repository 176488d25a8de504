// Benchmark page for bench/adaptive.bench.mjs (issue 25's measurement): the realistic scene (realistic-scene.ts:
// 1,000 instanced level-3 tetrahedron spheres, three's PointLights and DirectionalLight, fog, 1280×720) as an app
// has it (MeshPhongMaterial), and after swapMaterials (ShadingMaterial): all-Phong, fixed Gouraud, fixed flat, and
// AdaptiveShading at a budget (maxError) choosing per instance; in the published view and a deeper one (camera
// farther, narrower field of view, the fog moved back by as much as the camera).
// - frame(k): one frame of variant k (AdaptiveShading's update included: the camera is still, so it is the cached
//   update an app pays every frame), then a 1×1 readPixels (SwiftShader's gl.finish() does not wait); wall ms;
// - errors(): each variant's picture against all-Phong's (ShadingMaterial, Phong shading, full detail) over the
//   drawn pixels: the 99th percentile and the largest per-pixel max |Δ| over RGB (8-bit sRGB levels), the fraction
//   over 2, 8 and 32;
// - updateCost(k, n): AdaptiveShading.update alone when everything moved (the camera nudged each call: every
//   instance computed again and the allowance spent again), ms;
// - choices(k): how many instances took each shading and level; model(k): what its error model predicted.
import { type Shading, ShadingMaterial, swapMaterials } from '@shadelab/material';
import {
  type AdaptiveChoice,
  AdaptiveShading,
  overFraction,
  pictureError,
} from '@shadelab/material/adaptive';
import {
  Color,
  Fog,
  type InstancedMesh,
  type Material,
  MeshBasicMaterial,
  MeshPhongMaterial,
  type PerspectiveCamera,
  type Scene,
  WebGLRenderer,
} from 'three';
import { buildRealisticScene } from './realistic-scene';

/** A variant of the realistic scene. */
export type AdaptiveVariant =
  | { kind: 'three-phong' }
  | { kind: 'fixed'; shading: Shading }
  | { kind: 'adaptive'; maxError: number };

/** The view: the published camera, or farther back with a narrower field of view. */
export type AdaptiveView = 'published' | 'deep';

/** How far the deep view's camera is from the centre, relative to the published one's, and its field of view. */
export const DEEP = { distance: 3, fov: 30 } as const;

export interface PictureError {
  /** Drawn pixels: covered by the spheres at full detail, or different from all-Phong's picture. */
  drawn: number;
  /** 99th percentile of the per-pixel max |Δ| over RGB against all-Phong's picture, 8-bit sRGB levels. */
  p99: number;
  /** The largest per-pixel difference. */
  max: number;
  /** Fractions of the drawn pixels over 2, 8 and 32 levels. */
  over2: number;
  over8: number;
  over32: number;
}

const width = 1280;
const height = 720;
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(width, height, false);
const gl = renderer.getContext() as WebGL2RenderingContext;
const pixel = new Uint8Array(4);

/** The scene's material as an app has it (the scene and swap benches' MeshPhongMaterial). */
const phongMaterial = () =>
  new MeshPhongMaterial({
    color: new Color(0.6, 0.6, 0.6),
    specular: new Color(0.5, 0.5, 0.5),
    shininess: 32,
  });

interface Built {
  scene: Scene;
  camera: PerspectiveCamera;
  mesh: InstancedMesh;
  adaptive: AdaptiveShading | null;
}

function place(camera: PerspectiveCamera, scene: Scene, view: AdaptiveView): void {
  if (view === 'published') return;
  const before = camera.position.length();
  camera.position.multiplyScalar(DEEP.distance);
  camera.fov = DEEP.fov;
  camera.updateProjectionMatrix();
  camera.lookAt(0, 0, 0);
  const fog = scene.fog as Fog;
  const back = camera.position.length() - before;
  scene.fog = new Fog(fog.color, fog.near + back, fog.far + back);
}

function build(variant: AdaptiveVariant, view: AdaptiveView): Built {
  const s = buildRealisticScene(phongMaterial(), undefined, width / height);
  place(s.camera, s.scene, view);
  let adaptive: AdaptiveShading | null = null;
  if (variant.kind !== 'three-phong') {
    const swap = swapMaterials(s.scene);
    if (!(s.mesh.material instanceof ShadingMaterial)) throw new Error('the swap left no ShadingMaterial');
    if (variant.kind === 'fixed' && variant.shading !== 'phong') swap.update({ shading: variant.shading });
    if (variant.kind === 'adaptive') {
      adaptive = new AdaptiveShading({ maxError: variant.maxError });
      adaptive.add(s.mesh);
    }
  }
  s.camera.updateMatrixWorld();
  return { ...s, adaptive };
}

const prepared: Built[] = [];
let currentView: AdaptiveView = 'published';

/** One frame of prepared variant `k` (its AdaptiveShading's update first), then a 1×1 readPixels; wall ms. */
function frame(k: number): number {
  const b = prepared[k];
  const t0 = performance.now();
  b.adaptive?.update(b.camera, renderer);
  renderer.render(b.scene, b.camera);
  gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return performance.now() - t0;
}

/**
 * Build the variants' scenes for `view` (disposing the last view's), time the error tables' measurement (at
 * `add`), draw `warmup` untimed frames of each; returns the triangles and draw calls of each one's last frame.
 */
function prepare(
  variants: AdaptiveVariant[],
  view: AdaptiveView,
  warmup: number,
): { triangles: number; calls: number; buildMs: number }[] {
  for (const b of prepared) {
    b.adaptive?.dispose();
    b.mesh.dispose();
    (b.mesh.material as Material).dispose();
  }
  currentView = view;
  return variants.map((variant, k) => {
    const t0 = performance.now();
    prepared[k] = build(variant, view);
    const buildMs = performance.now() - t0;
    for (let i = 0; i < warmup; i++) frame(k);
    return { triangles: renderer.info.render.triangles, calls: renderer.info.render.calls, buildMs };
  });
}

function picture(k: number): Uint8Array {
  frame(k);
  const out = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return out;
}

/** 1 where the full-detail spheres are: the view's scene drawn white on black by MeshBasicMaterial, no fog. */
function coverage(): Uint8Array {
  const b = build({ kind: 'three-phong' }, currentView);
  b.scene.background = new Color(0, 0, 0);
  b.scene.fog = null;
  const white = new MeshBasicMaterial({ color: 0xffffff, fog: false });
  b.scene.overrideMaterial = white;
  renderer.render(b.scene, b.camera);
  const rgba = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
  white.dispose();
  b.mesh.dispose();
  (b.mesh.material as Material).dispose();
  const mask = new Uint8Array(width * height);
  for (let i = 0; i < mask.length; i++) mask[i] = rgba[4 * i] | rgba[4 * i + 1] | rgba[4 * i + 2] ? 1 : 0;
  return mask;
}

/** Every prepared variant's picture against variant `reference`'s (all-Phong). */
function errors(reference: number): PictureError[] {
  const mask = coverage();
  const ref = picture(reference);
  return prepared.map((_, k) => {
    const p = picture(k);
    // Drawn: covered by the scene (the coverage mask), or different from the reference anywhere.
    const drawn = (i: number) =>
      mask[i] === 1 ||
      p[4 * i] !== ref[4 * i] ||
      p[4 * i + 1] !== ref[4 * i + 1] ||
      p[4 * i + 2] !== ref[4 * i + 2];
    const at = (budget: number) => pictureError(ref, p, budget, drawn);
    const { drawn: n, p99, max, over: over2 } = at(2);
    return { drawn: n, p99, max, over2, over8: at(8).over, over32: at(32).over };
  });
}

/** `n` updates of variant k's AdaptiveShading with the camera nudged each time (nothing cached); ms each. */
function updateCost(k: number, n: number): number[] {
  const b = prepared[k];
  if (!b.adaptive) return [];
  const times: number[] = [];
  const x = b.camera.position.x;
  for (let i = 0; i < n; i++) {
    b.camera.position.x = x + (i % 2 === 0 ? 1e-4 : -1e-4);
    const t0 = performance.now();
    b.adaptive.update(b.camera, renderer);
    times.push(performance.now() - t0);
  }
  b.camera.position.x = x;
  b.adaptive.update(b.camera, renderer);
  return times;
}

/** How many instances of variant k took each choice ("shading level", level "full" for the sphere as given). */
function choices(k: number): Record<string, number> {
  const b = prepared[k];
  const out: Record<string, number> = {};
  if (!b.adaptive) return out;
  for (let i = 0; i < 1000; i++) {
    const c: AdaptiveChoice | null = b.adaptive.choiceOf(b.mesh, i);
    const key = c ? `${c.shading} ${c.level ?? 'full'}${c.flatPath ? ` ${c.flatPath}` : ''}` : 'none';
    out[key] = (out[key] ?? 0) + 1;
  }
  return out;
}

/**
 * What variant k's error model says (its table, measured at add): per shading and level, the fraction of an
 * object's covered pixels over 8 and over 32 levels, the worst over the sampled directions; the silhouette term
 * of a coarser level is apart (relative radial error).
 */
function model(k: number): { choice: string; over8: number; over32: number; silhouetteError: number }[] {
  const b = prepared[k];
  const table = b.adaptive?.tableOf(b.mesh);
  if (!table) return [];
  return table.rows.map((row) => ({
    choice: `${row.shading} ${row.level ?? 'full'}`,
    over8: overFraction(table, row, 8),
    over32: overFraction(table, row, 32),
    silhouetteError: row.silhouetteError,
  }));
}

const api = { prepare, frame, errors, updateCost, choices, model, deep: DEEP };
declare global {
  interface Window {
    adaptiveBench: typeof api;
  }
}
window.adaptiveBench = api;
document.body.dataset.ready = '1';
