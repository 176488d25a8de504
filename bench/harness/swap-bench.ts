// Benchmark page for bench/swap.bench.mjs (issue 22's measurement): the realistic scene (realistic-scene.ts:
// 1,000 instanced spheres, three's PointLights and DirectionalLight, fog) as an app has it, with
// MeshPhongMaterial, against the same scene after `swapMaterials(scene)` (phong shading, the swap's default; gouraud
// and flat after `update({ shading })`), and against a ShadingMaterial built by hand with the options the swap
// carried over (what tells the swap's own cost from the material's). Each variant is its own scene, built once.
// - cycle: frame times, interleaved frame by frame, each frame followed by a 1×1 readPixels (SwiftShader's
//   gl.finish() does not wait); GPU time from EXT_disjoint_timer_query_webgl2 when the browser has it;
// - luminance: the mean Rec. 709 luma of the 8-bit sRGB read-back, over the whole frame and over the pixels the
//   spheres cover (three's MeshBasicMaterial draws the coverage), and each picture against the first's;
// - describe: what each variant's material is (options, defines, the compiled program's parameters), and how
//   two variants' programs differ.
import {
  type Lighting,
  type Shading,
  ShadingMaterial,
  type ShadingMaterialOptions,
  type SwappedMaterials,
  swapMaterials,
  toShadingMaterial,
} from '@shadelab/material';
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

/** A variant of the realistic scene. */
export type SwapVariant =
  /** The scene as an app has it: MeshPhongMaterial (`specular`: its grey level; default 0.5). */
  | { kind: 'three-phong'; specular?: number }
  /** The same scene after swapMaterials(scene), then update({ shading }) unless it is 'phong'. */
  | { kind: 'swapped'; shading: Shading; specular?: number }
  /**
   * A ShadingMaterial made with `new ShadingMaterial(…)` from the options the swap carried over (its phong
   * scene's), with `lighting` in place of the carried one when given (and the shininess the swap carries over
   * for that lighting).
   */
  | { kind: 'by-hand'; shading: Shading; lighting?: Lighting };

export interface TimedResult {
  /** Every timed frame, ms (the 1×1 readPixels included). */
  frames: number[];
  /** GPU time of every timed frame, ms; empty without EXT_disjoint_timer_query_webgl2. */
  gpu: number[];
  programs: number;
  /** Set when the variant cannot render (building it or drawing it threw); nothing was timed. */
  error?: string;
}

export interface Luminance {
  /** Mean Rec. 709 luma (0.2126 R' + 0.7152 G' + 0.0722 B') of the 8-bit sRGB codes, whole frame, 0 … 255. */
  frame: number;
  /** The same over the covered pixels. */
  covered: number;
  coveredPixels: number;
  pixels: number;
  /** Against the first variant's picture: the largest channel difference (codes) and the RMS of the luma difference over covered pixels. */
  vsFirst: { maxChannel: number; rmsLuma: number; over2Codes: number };
  error?: string;
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

/**
 * The scene's material as an app has it (the scene bench's MeshPhongMaterial); `specular` 0 leaves the diffuse
 * term alone (what tells a difference in the diffuse term from one in the highlights).
 */
const phongMaterial = (specular = 0.5) =>
  new MeshPhongMaterial({
    color: new Color(0.6, 0.6, 0.6),
    specular: new Color(specular, specular, specular),
    shininess: 32,
  });

interface Built {
  scene: Scene;
  camera: PerspectiveCamera;
  material: Material;
  swap?: SwappedMaterials;
}
const built = new Map<string, Built>();

/** The options the swap carried over, read back from its phong scene's material. */
function carriedOver(): ShadingMaterialOptions {
  const m = swappedMaterial(sceneOf({ kind: 'swapped', shading: 'phong' }));
  return {
    lighting: m.lighting as Lighting,
    celBands: m.celBands,
    ka: m.ka.clone(),
    kd: m.kd.clone(),
    ks: m.ks.clone(),
    shininess: m.shininess,
    emissive: m.emissive.clone(),
    opacity: m.opacity,
    transparent: m.transparent,
    vertexColors: m.vertexColors,
    alphaTest: m.alphaTest,
  };
}

function swappedMaterial(b: Built): ShadingMaterial {
  if (!(b.material instanceof ShadingMaterial)) {
    throw new Error(`the swap left a ${b.material.type} on the instanced mesh`);
  }
  return b.material;
}

function sceneOf(variant: SwapVariant): Built {
  const key = JSON.stringify(variant);
  let b = built.get(key);
  if (b !== undefined) return b;
  if (variant.kind === 'three-phong') {
    const s = buildRealisticScene(phongMaterial(variant.specular), undefined, width / height);
    b = { ...s, material: s.mesh.material as Material };
  } else if (variant.kind === 'swapped') {
    const s = buildRealisticScene(phongMaterial(variant.specular), undefined, width / height);
    const swap = swapMaterials(s.scene);
    if (variant.shading !== 'phong') swap.update({ shading: variant.shading });
    b = { ...s, material: s.mesh.material as Material, swap };
    swappedMaterial(b);
  } else {
    const options = carriedOver();
    if (variant.lighting !== undefined) {
      // The other lighting, with the shininess the swap carries over for it.
      const other = toShadingMaterial(phongMaterial(), { lighting: variant.lighting });
      options.lighting = other.lighting as Lighting;
      options.shininess = other.shininess;
      other.dispose();
    }
    const material = new ShadingMaterial({ ...options, shading: variant.shading });
    const s = buildRealisticScene(material, undefined, width / height);
    b = { ...s, material };
  }
  built.set(key, b);
  return b;
}

const message = (error: unknown) => (error instanceof Error ? error.message : String(error));

/**
 * Time `variants` interleaved frame by frame: `warmup` untimed frames of each, then `frames` cycles that render
 * one timed frame of every variant in turn (each followed by a 1×1 readPixels), so that a change of the machine's
 * load hits every variant of a cycle alike. A variant that throws is left out with its error.
 */
async function cycle(variants: SwapVariant[], frames: number, warmup: number): Promise<TimedResult[]> {
  const results: TimedResult[] = variants.map(() => ({ frames: [], gpu: [], programs: 0 }));
  const scenes: Array<Built | null> = variants.map((v, k) => {
    try {
      return sceneOf(v);
    } catch (error) {
      results[k].error = message(error);
      return null;
    }
  });
  const frame = (b: Built) => {
    renderer.render(b.scene, b.camera);
    gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  };
  for (let k = 0; k < variants.length; k++) {
    const b = scenes[k];
    if (b === null) continue;
    try {
      for (let i = 0; i < warmup; i++) frame(b);
    } catch (error) {
      results[k].error = message(error);
    }
  }
  const queries: WebGLQuery[][] = variants.map(() => []);
  for (let i = 0; i < frames; i++) {
    for (let k = 0; k < variants.length; k++) {
      const b = scenes[k];
      if (b === null || results[k].error !== undefined) continue;
      let query: WebGLQuery | null = null;
      if (timer !== null) {
        query = gl.createQuery();
        gl.beginQuery(timer.TIME_ELAPSED_EXT, query);
      }
      const t0 = performance.now();
      renderer.render(b.scene, b.camera);
      if (query !== null && timer !== null) {
        gl.endQuery(timer.TIME_ELAPSED_EXT);
        queries[k].push(query);
      }
      gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      results[k].frames.push(performance.now() - t0);
    }
  }
  for (let k = 0; k < variants.length; k++) {
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

// ── Luminance ──────────────────────────────────────────────────────────────────────────────────────────────

/** The whole frame of `b`, read back as 8-bit sRGB RGBA (rows bottom-up). */
function picture(b: Built): Uint8Array {
  renderer.render(b.scene, b.camera);
  const out = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return out;
}

let coverageMask: Uint8Array | null = null;

/** 1 where the spheres are drawn: the MeshPhong scene drawn white on black by three's MeshBasicMaterial, no fog. */
function coverage(): Uint8Array {
  if (coverageMask !== null) return coverageMask;
  const b = sceneOf({ kind: 'three-phong' });
  const { background, fog } = b.scene;
  const white = new MeshBasicMaterial({ color: 0xffffff, fog: false });
  b.scene.background = new Color(0, 0, 0);
  b.scene.fog = null;
  b.scene.overrideMaterial = white;
  const rgba = picture(b);
  b.scene.background = background;
  b.scene.fog = fog;
  b.scene.overrideMaterial = null;
  white.dispose();
  coverageMask = new Uint8Array(width * height);
  for (let i = 0; i < coverageMask.length; i++) {
    coverageMask[i] = rgba[4 * i] | rgba[4 * i + 1] | rgba[4 * i + 2] ? 1 : 0;
  }
  return coverageMask;
}

const luma = (p: Uint8Array, i: number) => 0.2126 * p[4 * i] + 0.7152 * p[4 * i + 1] + 0.0722 * p[4 * i + 2];

/**
 * The mean luma of each variant's frame (after `warmup` untimed frames), whole and over the covered pixels, and
 * how each picture differs from the first variant's.
 */
function luminance(variants: SwapVariant[], warmup: number): Luminance[] {
  const mask = coverage();
  let first: Uint8Array | null = null;
  return variants.map((variant, k) => {
    let p: Uint8Array;
    try {
      const b = sceneOf(variant);
      for (let i = 0; i < warmup; i++) renderer.render(b.scene, b.camera);
      p = picture(b);
    } catch (error) {
      const nan = Number.NaN;
      return {
        frame: nan,
        covered: nan,
        coveredPixels: 0,
        pixels: 0,
        vsFirst: { maxChannel: nan, rmsLuma: nan, over2Codes: nan },
        error: message(error),
      };
    }
    if (k === 0) first = p;
    let sum = 0;
    let sumCovered = 0;
    let covered = 0;
    let maxChannel = 0;
    let squares = 0;
    let over2 = 0;
    for (let i = 0; i < width * height; i++) {
      const y = luma(p, i);
      sum += y;
      if (first !== null) {
        for (let c = 0; c < 3; c++) {
          const d = Math.abs(p[4 * i + c] - first[4 * i + c]);
          if (d > maxChannel) maxChannel = d;
        }
      }
      if (!mask[i]) continue;
      covered++;
      sumCovered += y;
      if (first !== null) {
        const d = y - luma(first, i);
        squares += d * d;
        if (Math.abs(d) > 2) over2++;
      }
    }
    return {
      frame: sum / (width * height),
      covered: sumCovered / covered,
      coveredPixels: covered,
      pixels: width * height,
      vsFirst: { maxChannel, rmsLuma: Math.sqrt(squares / covered), over2Codes: over2 / covered },
    };
  });
}

// ── What each variant draws with ───────────────────────────────────────────────────────────────────────────

export interface Description {
  material: string;
  /** The ShadingMaterial's options (none for three's material). */
  options?: Record<string, unknown>;
  defines?: Record<string, unknown>;
  /** The materials the swap made and what it left in place. */
  swap?: { materials: number; skipped: string[] };
  /** The parameters three compiled the material's program with (its cache key, split at commas), after a frame. */
  program: string[] | null;
  error?: string;
}

const rgb = (c: Color) => [c.r, c.g, c.b].map((x) => Math.round(x * 1e6) / 1e6);

/** What `variant` draws with: its material's options and defines and its compiled program's parameters. */
function describe(variant: SwapVariant): Description {
  let b: Built;
  try {
    b = sceneOf(variant);
    renderer.render(b.scene, b.camera);
  } catch (error) {
    return { material: 'none', program: null, error: message(error) };
  }
  const m = b.material;
  const props = renderer.properties.get(m) as { currentProgram?: { cacheKey?: string } };
  const key = props.currentProgram?.cacheKey;
  const out: Description = { material: m.type, program: key === undefined ? null : key.split(',') };
  if (m instanceof ShadingMaterial) {
    out.options = {
      shading: m.shading,
      lighting: m.lighting,
      celBands: m.celBands,
      ka: rgb(m.ka),
      kd: rgb(m.kd),
      ks: rgb(m.ks),
      shininess: m.shininess,
      emissive: rgb(m.emissive),
      opacity: m.opacity,
      transparent: m.transparent,
      vertexColors: m.vertexColors,
      alphaTest: m.alphaTest,
      map: m.map !== null,
      fog: m.fog,
      side: m.side,
    };
    out.defines = { ...m.defines };
  }
  if (b.swap !== undefined) {
    out.swap = { materials: b.swap.materials.length, skipped: b.swap.skipped.map((s) => s.reason) };
  }
  return out;
}

const api = { cycle, luminance, describe, hasTimer: timer !== null };
declare global {
  interface Window {
    swapBench: typeof api;
  }
}
window.swapBench = api;
document.body.dataset.ready = '1';
