// Benchmark page for bench/lighting.bench.mjs (issue 23's "the lighting itself"): the vertex-heavy variant of
// the realistic scene (realistic-scene.ts with the level-3 icosahedron sphere, 1,280 triangles, in place of the
// level-3 tetrahedron: 1,000 instances, three's three PointLights and DirectionalLight, fog, 1280×720) wearing
// MeshBasicMaterial (the unlit floor: the same vertices, instancing, fog and output, no lighting),
// MeshPhongMaterial or ShadingMaterial. Each variant is its own scene, built once; a cycle renders one frame of
// every variant in turn (the bench script calls `frame` for each), each followed by a 1×1 readPixels
// (SwiftShader's gl.finish() does not wait), so that a change of the machine's load hits every variant of a cycle
// alike.
import { type Lighting, type Shading, ShadingMaterial } from '@shadelab/material';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  Color,
  type Material,
  MeshBasicMaterial,
  MeshPhongMaterial,
  type PerspectiveCamera,
  type Scene,
  WebGLRenderer,
} from 'three';
import { buildRealisticScene } from './realistic-scene';

/** A material of the scene: three's unlit floor, three's Phong, or ShadingMaterial with a shading and lighting. */
export type LightingVariant =
  | { kind: 'three-basic' }
  | { kind: 'three-phong' }
  | { kind: 'shadelab'; shading: Shading; lighting: Lighting };

const width = 1280;
const height = 720;
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(width, height, false);
const gl = renderer.getContext() as WebGL2RenderingContext;
const pixel = new Uint8Array(4);

/** The vertex-heavy sphere: icosahedron level 3 (1,280 triangles, 642 vertices, indexed, smooth normals). */
const geometry = new SubdivisionSphereGeometry({
  base: 'icosahedron',
  level: 3,
  normals: 'smooth',
  indexed: true,
});

/** The same grey for every material: ka = kd = colour 0.6, ks = specular 0.5, α = shininess 32. */
function materialOf(variant: LightingVariant): Material {
  const color = new Color(0.6, 0.6, 0.6);
  if (variant.kind === 'three-basic') return new MeshBasicMaterial({ color });
  if (variant.kind === 'three-phong') {
    return new MeshPhongMaterial({ color, specular: new Color(0.5, 0.5, 0.5), shininess: 32 });
  }
  return new ShadingMaterial({
    shading: variant.shading,
    lighting: variant.lighting,
    ka: [0.6, 0.6, 0.6],
    kd: [0.6, 0.6, 0.6],
    ks: 0.5,
    shininess: 32,
  });
}

const scenes = new Map<string, { scene: Scene; camera: PerspectiveCamera }>();

function sceneOf(variant: LightingVariant): { scene: Scene; camera: PerspectiveCamera } {
  const key = JSON.stringify(variant);
  let built = scenes.get(key);
  if (built === undefined) {
    const { scene, camera } = buildRealisticScene(materialOf(variant), geometry, width / height);
    built = { scene, camera };
    scenes.set(key, built);
  }
  return built;
}

let prepared: Array<{ scene: Scene; camera: PerspectiveCamera }> = [];

/**
 * Build the variants' scenes (once each) and draw `warmup` untimed frames of each; returns the triangles three
 * drew in each variant's last frame.
 */
function prepare(variants: LightingVariant[], warmup: number): number[] {
  prepared = variants.map(sceneOf);
  return variants.map((_, k) => {
    for (let i = 0; i < warmup; i++) frame(k);
    return renderer.info.render.triangles;
  });
}

/** One frame of prepared variant `k`, followed by a 1×1 readPixels; its wall time, ms. */
function frame(k: number): number {
  const t0 = performance.now();
  renderer.render(prepared[k].scene, prepared[k].camera);
  gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return performance.now() - t0;
}

const api = { prepare, frame };
declare global {
  interface Window {
    lightingBench: typeof api;
  }
}
window.lightingBench = api;
document.body.dataset.ready = '1';
