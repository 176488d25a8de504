// Benchmark page for bench/scene.bench.mjs (issue 14's measurements):
// - realistic: 1,000 instanced level-3 spheres lit by three PointLights and a DirectionalLight, with fog, at
//   1280×720: ShadingMaterial (flat, gouraud, phong) against MeshPhongMaterial and MeshLambertMaterial;
// - lecture: the lecture's scene (the material bench's level-6 sphere and light) with the ShadingMaterial of
//   the commit before issue 14 ('before', a bundle the bench builds from git and hands to loadModule) and of
//   this checkout ('after');
// - flat: flat shading of an indexed mesh prepared (flatShadingGeometry), as a non-indexed soup, and as the
//   indexed mesh itself, timed, with its error against shade() per face and its bytes.
// Every frame is followed by a 1×1 readPixels (SwiftShader's gl.finish() does not wait); GPU time from
// EXT_disjoint_timer_query_webgl2 when the browser has it.
import * as material from '@shadelab/material';
import { linearToSrgb8, PhongLight, type Shading, ShadingMaterial, shade } from '@shadelab/material';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import * as THREE from 'three';
import {
  type BufferGeometry,
  Color,
  Float32BufferAttribute,
  GLSL3,
  type Material,
  Mesh,
  MeshLambertMaterial,
  MeshPhongMaterial,
  type Object3D,
  PerspectiveCamera,
  Scene,
  ShaderMaterial,
  TorusKnotGeometry,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { sphereGeometry } from '../../tests/harness/material-sphere';
import { buildRealisticScene, realisticGeometries } from './realistic-scene';

/** A variant of the realistic scene. */
export interface RealisticVariant {
  kind: 'shadelab' | 'three-phong' | 'three-lambert';
  shading?: Shading;
  /**
   * What flat shading draws: the prepared `flatShadingGeometry` (default), the non-indexed sphere, or the
   * indexed sphere as it is (no preparation). Gouraud, phong and three's materials draw the indexed sphere.
   */
  geometry?: 'prepared' | 'non-indexed' | 'indexed';
  /** A ShadingMaterial from a bundle given to loadModule instead of this checkout's. */
  module?: string;
}

/** A variant of the lecture's scene. */
export interface LectureVariant {
  /** 'before': the material of the commit before issue 14 (see loadModule); 'after': this checkout's. */
  build: 'before' | 'after';
  shading: Shading;
}

/** The meshes and modes of the flat-shading trade-off. */
export type FlatMesh = 'torus-knot' | 'sphere-3' | 'sphere-6';
export type FlatMode = 'prepared' | 'non-indexed' | 'indexed';

export interface TimedResult {
  /** Every timed frame, ms (the 1×1 readPixels included). */
  frames: number[];
  /** GPU time of every timed frame, ms; empty without EXT_disjoint_timer_query_webgl2. */
  gpu: number[];
  programs: number;
  /** Set when the variant cannot render (the material threw); nothing was timed. */
  error?: string;
}

/** What a module of @shadelab/material has to offer here, in its version before issue 14 as in this one. */
interface MaterialModule {
  ShadingMaterial: new (options: {
    shading: Shading;
    lights?: readonly Object3D[];
    ka?: readonly [number, number, number];
    kd?: readonly [number, number, number];
    ks?: number;
    shininess?: number;
  }) => Material;
  PhongLight: new () => Object3D;
  flatShadingGeometry: (geometry: BufferGeometry) => BufferGeometry;
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

/** One scene of this page to time: the realistic scene, the lecture's, or a flat-shading one. */
export type TimedScene =
  | { scene: 'realistic'; variant: RealisticVariant }
  | { scene: 'lecture'; variant: LectureVariant }
  | { scene: 'flat'; mesh: FlatMesh; mode: FlatMode };

function sceneOf(spec: TimedScene): { scene: Scene; camera: PerspectiveCamera } {
  if (spec.scene === 'realistic') return realisticScene(spec.variant);
  if (spec.scene === 'lecture') return lectureScene(spec.variant);
  return flatScene(spec.mesh, spec.mode);
}

/**
 * Time `specs` interleaved frame by frame: `warmup` untimed frames of each, then `frames` cycles that render
 * one timed frame of every spec in turn (each followed by a 1×1 readPixels), so that a change of the machine's
 * load hits every spec of a cycle alike. A spec that throws is left out with its error.
 */
async function cycle(specs: TimedScene[], frames: number, warmup: number): Promise<TimedResult[]> {
  const built = specs.map(sceneOf);
  const results: TimedResult[] = specs.map(() => ({ frames: [], gpu: [], programs: 0 }));
  const frame = (k: number) => {
    renderer.render(built[k].scene, built[k].camera);
    gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  };
  for (let k = 0; k < specs.length; k++) {
    try {
      for (let i = 0; i < warmup; i++) frame(k);
    } catch (error) {
      results[k].error = error instanceof Error ? error.message : String(error);
    }
  }
  const queries: WebGLQuery[][] = specs.map(() => []);
  for (let i = 0; i < frames; i++) {
    for (let k = 0; k < specs.length; k++) {
      if (results[k].error !== undefined) continue;
      let query: WebGLQuery | null = null;
      if (timer !== null) {
        query = gl.createQuery();
        gl.beginQuery(timer.TIME_ELAPSED_EXT, query);
      }
      const t0 = performance.now();
      renderer.render(built[k].scene, built[k].camera);
      if (query !== null && timer !== null) {
        gl.endQuery(timer.TIME_ELAPSED_EXT);
        queries[k].push(query);
      }
      gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      results[k].frames.push(performance.now() - t0);
    }
  }
  for (let k = 0; k < specs.length; k++) {
    results[k].gpu = await gpuTimes(queries[k]);
    results[k].programs = renderer.info.programs?.length ?? 0;
  }
  return results;
}

async function gpuTimes(queries: WebGLQuery[]): Promise<number[]> {
  if (timer === null || queries.length === 0) return [];
  const times: number[] = [];
  for (const q of queries) {
    for (let tries = 0; tries < 200; tries++) {
      if (gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE)) break;
      await new Promise((r) => setTimeout(r, 5));
    }
    if (
      gl.getParameter(0x8fbb /* GPU_DISJOINT_EXT */) ||
      !gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE)
    ) {
      return [];
    }
    times.push(gl.getQueryParameter(q, gl.QUERY_RESULT) / 1e6);
    gl.deleteQuery(q);
  }
  return times;
}

// ── The realistic scene ─────────────────────────────────────────────────────────────────────────────────

/** The prepared geometry of flat shading, built on first use by the module of the first variant that asks. */
let preparedGeometry: BufferGeometry | null = null;

const realisticScenes = new Map<string, { scene: Scene; camera: PerspectiveCamera }>();

/** The realistic scene (realistic-scene.ts) wearing the variant's material; built once per variant. */
function realisticScene(variant: RealisticVariant): { scene: Scene; camera: PerspectiveCamera } {
  const key = JSON.stringify(variant);
  let built = realisticScenes.get(key);
  if (built !== undefined) return built;
  let mat: Material;
  let geometry: BufferGeometry = realisticGeometries.indexed;
  if (variant.kind === 'shadelab') {
    const shading = variant.shading ?? 'phong';
    const module = moduleNamed(variant.module);
    mat = new module.ShadingMaterial({
      shading,
      ka: [0.6, 0.6, 0.6],
      kd: [0.6, 0.6, 0.6],
      ks: 0.5,
      shininess: 32,
    });
    if (shading === 'flat') {
      const kind = variant.geometry ?? 'prepared';
      if (kind === 'prepared') {
        preparedGeometry ??= module.flatShadingGeometry(realisticGeometries.indexed);
        geometry = preparedGeometry;
      } else geometry = realisticGeometries[kind];
    }
  } else {
    const color = new Color(0.6, 0.6, 0.6);
    mat =
      variant.kind === 'three-phong'
        ? new MeshPhongMaterial({ color, specular: new Color(0.5, 0.5, 0.5), shininess: 32 })
        : new MeshLambertMaterial({ color });
  }
  const { scene, camera } = buildRealisticScene(mat, geometry, width / height);
  built = { scene, camera };
  realisticScenes.set(key, built);
  return built;
}

// ── The lecture's scene, before and after issue 14 ──────────────────────────────────────────────────────

const modules = new Map<string, MaterialModule>();

/**
 * Load another build of @shadelab/material under `name` ('before': the commit before issue 14, for the
 * lecture scene): `code` is an ES module bundle of its sources whose `import … from 'three'` reads
 * `globalThis.__shadelabThree` (this page's three), so every material renders through one three.js.
 */
async function loadModule(name: string, code: string): Promise<string[]> {
  (globalThis as { __shadelabThree?: unknown }).__shadelabThree = THREE;
  const url = URL.createObjectURL(new Blob([code], { type: 'text/javascript' }));
  const module = (await import(/* @vite-ignore */ url)) as MaterialModule;
  URL.revokeObjectURL(url);
  modules.set(name, module);
  return Object.keys(module);
}

/** The module loaded under `name`, or this checkout's. */
function moduleNamed(name: string | undefined): MaterialModule {
  if (name === undefined) return material as unknown as MaterialModule;
  const module = modules.get(name);
  if (module === undefined) throw new Error(`loadModule('${name}', …) first`);
  return module;
}

const lectureScenes = new Map<string, { scene: Scene; camera: PerspectiveCamera }>();

/** The material bench's lecture scene at level 6: the sphere (radius 2) filling most of the canvas, one light. */
function lectureScene(variant: LectureVariant): { scene: Scene; camera: PerspectiveCamera } {
  const key = JSON.stringify(variant);
  let built = lectureScenes.get(key);
  if (built !== undefined) return built;
  const module = moduleNamed(variant.build === 'after' ? undefined : 'before');
  const scene = new Scene();
  const light = new module.PhongLight();
  light.position.set(-5, 10, 20);
  scene.add(light);
  const mat = new module.ShadingMaterial({ shading: variant.shading, lights: [light] });
  const indexed = sphereGeometry(6, false, true);
  const mesh = new Mesh(variant.shading === 'flat' ? module.flatShadingGeometry(indexed) : indexed, mat);
  mesh.scale.setScalar(2);
  scene.add(mesh);
  const camera = new PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  built = { scene, camera };
  lectureScenes.set(key, built);
  return built;
}

// ── Flat shading without preparation: error, time, bytes ───────────────────────────────────────────────

const flatSources = new Map<FlatMesh, BufferGeometry>();

/** The indexed source mesh: three's default TorusKnotGeometry, or the lecture's sphere at level 3 or 6. */
function flatSource(name: FlatMesh): BufferGeometry {
  let g = flatSources.get(name);
  if (g === undefined) {
    g =
      name === 'torus-knot'
        ? new TorusKnotGeometry()
        : new SubdivisionSphereGeometry({
            level: name === 'sphere-3' ? 3 : 6,
            normals: 'smooth',
            indexed: true,
          });
    flatSources.set(name, g);
  }
  return g;
}

const flatGeometries = new Map<string, BufferGeometry>();

function flatGeometry(name: FlatMesh, mode: FlatMode): BufferGeometry {
  const key = `${name}/${mode}`;
  let g = flatGeometries.get(key);
  if (g === undefined) {
    const source = flatSource(name);
    g =
      mode === 'prepared'
        ? material.flatShadingGeometry(source)
        : mode === 'non-indexed'
          ? source.toNonIndexed()
          : source;
    flatGeometries.set(key, g);
  }
  return g;
}

const flatLight = { position: [-5, 10, 20] as const, ambient: 0.2, diffuse: 1, specular: 1 };
const flatMaterial = {
  ka: [0.6, 0.35, 0.2],
  kd: [0.6, 0.35, 0.2],
  ks: [0.5, 0.5, 0.5],
  shininess: 32,
} as const;
/** Scale of each mesh so that it fills most of the canvas, and its rotation (a generic view of the faces). */
const flatScale: Record<FlatMesh, number> = { 'torus-knot': 1.4, 'sphere-3': 2, 'sphere-6': 2 };

const flatScenes = new Map<string, { scene: Scene; camera: PerspectiveCamera; mesh: Mesh }>();

function flatScene(name: FlatMesh, mode: FlatMode): { scene: Scene; camera: PerspectiveCamera; mesh: Mesh } {
  const key = `${name}/${mode}`;
  let built = flatScenes.get(key);
  if (built !== undefined) return built;
  const scene = new Scene();
  const light = new PhongLight({
    ambient: flatLight.ambient,
    diffuse: flatLight.diffuse,
    specular: flatLight.specular,
  });
  light.position.set(...flatLight.position);
  scene.add(light);
  const mat = new ShadingMaterial({ shading: 'flat', lights: [light], ...flatMaterial });
  const mesh = new Mesh(flatGeometry(name, mode), mat);
  mesh.scale.setScalar(flatScale[name]);
  mesh.rotation.set(0.3, 0.5, 0.1);
  scene.add(mesh);
  const camera = new PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  built = { scene, camera, mesh };
  flatScenes.set(key, built);
  return built;
}

/** Renders the face index + 1 of every pixel (0: background) as 24-bit RGB, from a non-indexed geometry. */
const idMaterial = new ShaderMaterial({
  glslVersion: GLSL3,
  vertexShader: /* glsl */ `
    in float faceId;
    flat out float vFaceId;
    void main() {
      vFaceId = faceId + 1.0;
      gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
    }`,
  fragmentShader: /* glsl */ `
    flat in float vFaceId;
    out vec4 colour;
    void main() {
      colour = vec4(mod(vFaceId, 256.0), mod(floor(vFaceId / 256.0), 256.0), floor(vFaceId / 65536.0), 255.0) / 255.0;
    }`,
});

export interface FlatError {
  /** Pixels compared: covered, and with all 8 neighbours on the same face (edges are left out). */
  pixels: number;
  /** Faces with at least one compared pixel. */
  faces: number;
  /** Largest channel difference against shade() of the pixel's face, 1/255. */
  max: number;
  /** Root mean square of the channel differences over the compared pixels, 1/255. */
  rms: number;
  /** Share of compared pixels off by more than 1/255 in some channel. */
  over1: number;
  error?: string;
}

/**
 * Compare flat shading of `name` in `mode` with the lecture's flat shading, computed on the CPU: shade() at each
 * face's centroid with its face normal (world space), as 8-bit sRGB, for every pixel inside a face.
 */
function flatError(name: FlatMesh, mode: FlatMode): FlatError {
  const { scene, camera, mesh } = flatScene(name, mode);
  mesh.updateMatrixWorld(true);
  camera.updateMatrixWorld(true);
  const picture = new Uint8Array(width * height * 4);
  try {
    renderer.render(scene, camera);
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    return { pixels: 0, faces: 0, max: Number.NaN, rms: Number.NaN, over1: Number.NaN, error: message };
  }
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, picture);

  // Face ids from the non-indexed geometry (the same vertex positions in the same order of faces).
  const soup = flatGeometry(name, 'non-indexed');
  const faces = soup.getAttribute('position').count / 3;
  if (soup.getAttribute('faceId') === undefined) {
    const ids = new Float32Array(faces * 3);
    for (let f = 0; f < faces; f++) ids.fill(f, 3 * f, 3 * f + 3);
    soup.setAttribute('faceId', new Float32BufferAttribute(ids, 1));
  }
  const idScene = new Scene();
  const idMesh = new Mesh(soup, idMaterial);
  idMesh.matrixAutoUpdate = false;
  idMesh.matrix.copy(mesh.matrixWorld);
  idScene.add(idMesh);
  const target = new WebGLRenderTarget(width, height);
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x000000, 0);
  renderer.clear();
  renderer.render(idScene, camera);
  const idPixels = new Uint8Array(width * height * 4);
  renderer.readRenderTargetPixels(target, 0, 0, width, height, idPixels);
  renderer.setRenderTarget(null);
  target.dispose();
  const id = new Int32Array(width * height);
  for (let i = 0; i < id.length; i++) {
    id[i] = idPixels[4 * i] + 256 * idPixels[4 * i + 1] + 65536 * idPixels[4 * i + 2] - 1;
  }

  // The expected colour of each face: shade() at its world centroid with its world face normal.
  const pos = soup.getAttribute('position');
  const m = mesh.matrixWorld;
  const eye = [camera.position.x, camera.position.y, camera.position.z, 1] as const;
  const light = { ...flatLight, position: [...flatLight.position] as [number, number, number] };
  const a = new Vector3();
  const b = new Vector3();
  const c = new Vector3();
  const expected = new Uint8Array(faces * 3);
  const rgb: [number, number, number] = [0, 0, 0];
  for (let f = 0; f < faces; f++) {
    a.fromBufferAttribute(pos, 3 * f).applyMatrix4(m);
    b.fromBufferAttribute(pos, 3 * f + 1).applyMatrix4(m);
    c.fromBufferAttribute(pos, 3 * f + 2).applyMatrix4(m);
    const centroid = [(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3] as const;
    const normal = new Vector3().subVectors(b, a).cross(new Vector3().subVectors(c, a));
    const linear = shade({ position: centroid, normal: [normal.x, normal.y, normal.z], eye }, flatMaterial, [
      { position: light.position, ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [1, 1, 1] },
    ]);
    linearToSrgb8(linear, rgb);
    expected.set(rgb, 3 * f);
  }

  let pixels = 0;
  let max = 0;
  let sum = 0;
  let over1 = 0;
  const seen = new Set<number>();
  for (let y = 1; y < height - 1; y++) {
    for (let x = 1; x < width - 1; x++) {
      const i = y * width + x;
      const f = id[i];
      if (f < 0 || f >= faces) continue;
      let inside = true;
      for (let dy = -1; dy <= 1 && inside; dy++) {
        for (let dx = -1; dx <= 1; dx++) {
          if (id[i + dy * width + dx] !== f) {
            inside = false;
            break;
          }
        }
      }
      if (!inside) continue;
      pixels++;
      seen.add(f);
      let worst = 0;
      for (let k = 0; k < 3; k++) {
        const d = Math.abs(picture[4 * i + k] - expected[3 * f + k]);
        sum += d * d;
        if (d > worst) worst = d;
      }
      if (worst > max) max = worst;
      if (worst > 1) over1++;
    }
  }
  return {
    pixels,
    faces: seen.size,
    max,
    rms: pixels ? Math.sqrt(sum / (3 * pixels)) : Number.NaN,
    over1: pixels ? over1 / pixels : Number.NaN,
  };
}

/** Bytes of a geometry's attributes and index (what three uploads for it). */
function geometryBytes(geometry: BufferGeometry): { total: number; attributes: Record<string, number> } {
  const attributes: Record<string, number> = {};
  let total = 0;
  for (const [name, attribute] of Object.entries(geometry.attributes)) {
    attributes[name] = attribute.array.byteLength;
    total += attribute.array.byteLength;
  }
  if (geometry.index !== null) {
    attributes.index = geometry.index.array.byteLength;
    total += geometry.index.array.byteLength;
  }
  return { total, attributes };
}

/**
 * The bytes each mode draws for `name`: its geometry's attributes and index, and what the GPU holds besides (the
 * non-indexed path's face-position texture: RGB32F, rows of 2048 texels).
 */
function flatBytes(
  name: FlatMesh,
): Record<
  FlatMode,
  { triangles: number; geometry: number; gpuExtra: number; attributes: Record<string, number> }
> {
  const out = {} as Record<
    FlatMode,
    { triangles: number; geometry: number; gpuExtra: number; attributes: Record<string, number> }
  >;
  const source = flatSource(name);
  const triangles =
    source.index !== null ? source.index.count / 3 : source.getAttribute('position').count / 3;
  for (const mode of ['prepared', 'non-indexed', 'indexed'] as const) {
    const g = flatGeometry(name, mode);
    // faceId is this page's own attribute (flatError's id pass), not part of what the material draws.
    const { attributes } = geometryBytes(g);
    delete attributes.faceId;
    const geometry = Object.values(attributes).reduce((s, v) => s + v, 0);
    const vertices = g.getAttribute('position').count;
    const gpuExtra = mode === 'non-indexed' ? 2048 * Math.ceil(vertices / 2048) * 12 : 0;
    out[mode] = { triangles, geometry, gpuExtra, attributes };
  }
  return out;
}

const api = { cycle, loadModule, flatError, flatBytes, hasTimer: timer !== null };
declare global {
  interface Window {
    sceneBench: typeof api;
  }
}
window.sceneBench = api;
document.body.dataset.ready = '1';
