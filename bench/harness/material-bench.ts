// Benchmark page for bench/material.bench.mjs: frame time (a 1×1 readPixels after each frame) and GPU time
// (EXT_disjoint_timer_query_webgl2) of a sphere filling most of a 1280×720 canvas, ShadingMaterial variants
// against three's MeshPhongMaterial, MeshLambertMaterial and MeshToonMaterial on the same geometry, and
// MeshBasicMaterial (no lighting) as the floor.
import { type Lighting, PhongLight, type Shading, ShadingMaterial } from '@shadelab/material';
import {
  AmbientLight,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshPhongMaterial,
  MeshToonMaterial,
  PerspectiveCamera,
  PointLight,
  Scene,
  WebGLRenderer,
} from 'three';
import { flatSphereGeometry, sphereGeometry } from '../../tests/harness/material-sphere';

export interface BenchVariant {
  /** 'shadelab' or one of three's materials. */
  kind: 'shadelab' | 'three-phong' | 'three-lambert' | 'three-toon' | 'three-basic';
  shading?: Shading;
  lighting?: Lighting;
  celBands?: number;
  lights?: number;
  /** Flat shading of the triangle soup (face positions from a texture) instead of flatShadingGeometry. */
  soup?: boolean;
}

export interface BenchResult {
  /** Every timed frame, ms (1×1 readPixels included). */
  frames: number[];
  /** GPU time of every timed frame, ms; empty without EXT_disjoint_timer_query_webgl2. */
  gpu: number[];
  programs: number;
}

const width = 1280;
const height = 720;
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(width, height, false);
const gl = renderer.getContext() as WebGL2RenderingContext;
const timer = gl.getExtension('EXT_disjoint_timer_query_webgl2') as { TIME_ELAPSED_EXT: number } | null;
const pixel = new Uint8Array(4);

function material(variant: BenchVariant, scene: Scene): Material {
  const n = variant.lights ?? 1;
  const positions: Array<[number, number, number]> = [
    [-5, 10, 20],
    [8, -3, 10],
    [0, 12, 6],
    [-9, -6, 8],
  ];
  if (variant.kind === 'shadelab') {
    const lights = Array.from({ length: n }, (_, i) => {
      const light = new PhongLight();
      light.position.set(...positions[i % positions.length]);
      scene.add(light);
      return light;
    });
    return new ShadingMaterial({
      shading: variant.shading ?? 'phong',
      lighting: variant.lighting ?? 'phong',
      celBands: variant.celBands ?? 0,
      lights,
    });
  }
  scene.add(new AmbientLight(0xffffff, 0.2));
  for (let i = 0; i < n; i++) {
    const light = new PointLight(0xffffff, 1, 0, 0);
    light.position.set(...positions[i % positions.length]);
    scene.add(light);
  }
  const color = 0xc89664;
  if (variant.kind === 'three-phong') return new MeshPhongMaterial({ color, shininess: 32 });
  if (variant.kind === 'three-lambert') return new MeshLambertMaterial({ color });
  // No lighting at all: the floor that transforming and rasterising the sphere costs.
  if (variant.kind === 'three-basic') return new MeshBasicMaterial({ color });
  return new MeshToonMaterial({ color });
}

async function gpuTimes(queries: WebGLQuery[]): Promise<number[]> {
  if (timer === null || queries.length === 0) return [];
  const times: number[] = [];
  for (const q of queries) {
    for (let tries = 0; tries < 200; tries++) {
      if (gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE)) break;
      await new Promise((r) => setTimeout(r, 5));
    }
    if (gl.getParameter(0x8fbb /* GPU_DISJOINT_EXT */)) return [];
    if (!gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE)) return [];
    times.push(gl.getQueryParameter(q, gl.QUERY_RESULT) / 1e6);
    gl.deleteQuery(q);
  }
  return times;
}

/** Render `frames` timed frames (after `warmup`), each followed by a 1×1 readPixels. */
async function run(variant: BenchVariant, level: number, frames = 25, warmup = 5): Promise<BenchResult> {
  const scene = new Scene();
  const mat = material(variant, scene);
  // Each draws the geometry it needs and no more: ours reads positions only (analytic sphere normals), three's
  // need normals; flat shading draws flatShadingGeometry (each face on its own last vertex: V′ = T) or the
  // triangle soup, everything else the indexed sphere (shared vertices: V = 2 + T/2).
  const geometry =
    variant.shading !== 'flat'
      ? sphereGeometry(level, variant.kind !== 'shadelab', true)
      : variant.soup
        ? sphereGeometry(level, false)
        : flatSphereGeometry(level);
  const mesh = new Mesh(geometry, mat);
  mesh.scale.setScalar(2);
  scene.add(mesh);
  const camera = new PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  const frame = () => {
    renderer.render(scene, camera);
    gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  };
  for (let i = 0; i < warmup; i++) frame();
  const times: number[] = [];
  const queries: WebGLQuery[] = [];
  for (let i = 0; i < frames; i++) {
    let query: WebGLQuery | null = null;
    if (timer !== null) {
      query = gl.createQuery();
      gl.beginQuery(timer.TIME_ELAPSED_EXT, query!);
    }
    const t0 = performance.now();
    renderer.render(scene, camera);
    if (query !== null) {
      gl.endQuery(timer!.TIME_ELAPSED_EXT);
      queries.push(query);
    }
    gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    times.push(performance.now() - t0);
  }
  const gpu = await gpuTimes(queries);
  const programs = renderer.info.programs?.length ?? 0;
  mat.dispose();
  return { frames: times, gpu, programs };
}

/** Bytes each mode's geometry needs on the GPU at `level`: attributes, index, and flat shading's texture. */
function memory(level: number): {
  flat: { vertices: number; positionsBytes: number; cornersBytes: number; indexBytes: number };
  flatSoup: { vertices: number; positionsBytes: number; flatTextureBytes: number };
  indexed: { vertices: number; positionsBytes: number; indexBytes: number; normalsBytes: number };
} {
  const soup = sphereGeometry(level, false).getAttribute('position').count;
  const flat = flatSphereGeometry(level);
  const flatVertices = flat.getAttribute('position').count;
  const shared = sphereGeometry(level, false, true);
  const vertices = shared.getAttribute('position').count;
  return {
    flat: {
      vertices: flatVertices,
      positionsBytes: flatVertices * 12,
      cornersBytes: flatVertices * 24,
      indexBytes: flat.index!.array.byteLength,
    },
    flatSoup: {
      vertices: soup,
      positionsBytes: soup * 12,
      flatTextureBytes: 2048 * Math.ceil(soup / 2048) * 12,
    },
    indexed: {
      vertices,
      positionsBytes: vertices * 12,
      indexBytes: shared.index!.array.byteLength,
      normalsBytes: vertices * 12,
    },
  };
}

const api = { run, memory, hasTimer: timer !== null };
declare global {
  interface Window {
    materialBench: typeof api;
  }
}
window.materialBench = api;
document.body.dataset.ready = '1';
