// Benchmark page for bench/webgpu.bench.mjs (issue 15's measurements, and issue 23's realistic scene) and
// bench/lecture-refactor.bench.mjs (issue 23's lecture scene before and after its refactor): the lecture's scene
// (the material bench's level-6 sphere and one PhongLight) or the realistic scene (realistic-scene.ts: 1,000
// instanced spheres, three's lights, fog) drawn by ShadingNodeMaterial on both backends of three's
// WebGPURenderer (WebGPU; WebGL2 with forceWebGL) against three's MeshPhongNodeMaterial on the same backend, and
// by ShadingMaterial and MeshPhongMaterial under WebGLRenderer, all in one page so that one cycle times them all.
// Another build of @shadelab/material (an older commit's, bundled by bench/lib/materialAt.mjs) can be loaded
// beside this checkout's (loadModule) and drawn in the lecture's scene through the same three.js.
//
// Every renderer draws offscreen into a linear RGBA8 render target of the same size (a WebGPU canvas loses its
// device when presented headless), each frame followed by a 1×1 read-back so that the GPU work is waited for:
// readRenderTargetPixelsAsync on the WebGPU backend, a synchronous readPixels on the WebGL2 backend (three's
// asynchronous read-back there polls once per animation frame) and under WebGLRenderer. GPU time: three's
// trackTimestamp (WebGPU 'timestamp-query'; EXT_disjoint_timer_query_webgl2 on the WebGL2 backend) and the same
// extension under WebGLRenderer, when the browser has them.
import { flatShadingGeometry, PhongLight, ShadingMaterial } from '@shadelab/material';
import { provokingVertexOf, ShadingNodeMaterial } from '@shadelab/material/webgpu';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import * as THREE from 'three';
import {
  AmbientLight,
  type BufferGeometry,
  Color,
  DirectionalLight,
  type Material,
  Mesh,
  MeshLambertMaterial,
  MeshPhongMaterial,
  type Object3D,
  PerspectiveCamera,
  PointLight,
  Scene,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import * as TSL from 'three/tsl';
import { normalView, positionLocal, positionView, property, transformNormalToView } from 'three/tsl';
import * as THREE_WEBGPU from 'three/webgpu';
import {
  ConditionalNode,
  MeshLambertNodeMaterial,
  MeshPhongNodeMaterial,
  NodeMaterial,
  RenderTarget,
  WebGPURenderer,
} from 'three/webgpu';
import { buildRealisticScene, realisticGeometries } from './realistic-scene';

/** Where a spec is drawn: WebGPURenderer's WebGPU or WebGL2 backend, or three's WebGLRenderer. */
export type Backend = 'webgpu' | 'webgl2' | 'webgl';
type Shading = 'flat' | 'gouraud' | 'phong';
type Lighting = 'phong' | 'blinn-phong';

/** One timed scene. */
export interface BenchSpec {
  backend: Backend;
  /**
   * 'lecture' (default): the material bench's level-6 sphere and the lights of `lights`; 'realistic': the
   * realistic scene (realistic-scene.ts: 1,000 instances of the level-3 sphere with instance colours, three
   * PointLights and a DirectionalLight, Fog), ka = kd = 0.6 grey (three's: colour), ks = 0.5, α = 32; `lights`
   * and `build` do not apply to it.
   */
  scene?: 'lecture' | 'realistic';
  /**
   * 'shadelab': ShadingNodeMaterial (WebGPURenderer) or ShadingMaterial (WebGLRenderer); 'three-phong':
   * MeshPhongNodeMaterial (WebGPURenderer) or MeshPhongMaterial (WebGLRenderer), shininess 32; 'three-lambert'
   * (realistic scene only): MeshLambertNodeMaterial or MeshLambertMaterial.
   */
  material: 'shadelab' | 'three-phong' | 'three-lambert';
  /**
   * Flat shading in the realistic scene: the indexed sphere as it is (default), or its flatShadingGeometry made
   * for the backend's provoking vertex.
   */
  flatGeometry?: 'indexed' | 'prepared';
  /**
   * 'shadelab' in the lecture's scene: the name of a build of @shadelab/material given to loadModule (an older
   * commit's) whose ShadingMaterial / ShadingNodeMaterial and PhongLight draw it; default: this checkout's.
   */
  build?: string;
  shading?: Shading;
  lighting?: Lighting;
  celBands?: number;
  /**
   * 'phong': the lecture's PhongLight at (−5, 10, 20) (Ia 0.2, Id 1, Is 0.8); three's materials get the
   * equivalent AmbientLight(0.2) and PointLight(1, decay 0) there. 'three': three's AmbientLight(0.2), a
   * PointLight (400, decay 2) at (−5, 10, 20) and a DirectionalLight (0.8) from (5, 10, 7), for every material.
   */
  lights?: 'phong' | 'three';
  /** A/B: a patched copy of ShadingNodeMaterial's lighting (see experimentalMaterial), WebGPURenderer only. */
  experiment?: Experiment;
}

export interface TimedResult {
  /** Every timed frame, ms: the render call and the 1×1 read-back. */
  frames: number[];
  /** GPU time of every timed frame, ms; empty without a GPU timer on this backend. */
  gpu: number[];
  /** Set when the spec cannot render (it threw); nothing was timed. */
  error?: string;
}

const params = new URLSearchParams(location.search);
const width = Number(params.get('width') ?? 1280);
const height = Number(params.get('height') ?? 720);
const LEVEL = 6;
const pixel = new Uint8Array(4);

// ── Renderers ───────────────────────────────────────────────────────────────────────────────────────────────

interface GpuRenderer {
  renderer: WebGPURenderer;
  target: RenderTarget;
  /** Whether three tracks GPU time on this backend (timestamp-query, or the WebGL2 timer extension). */
  timestamps: boolean;
  /** The 1×1 read-back after a frame. */
  read: () => Promise<unknown> | undefined;
}

async function gpuRenderer(backend: 'webgpu' | 'webgl2'): Promise<GpuRenderer> {
  const renderer = new WebGPURenderer({
    antialias: false,
    forceWebGL: backend === 'webgl2',
    trackTimestamp: true,
  });
  await renderer.init();
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  const target = new RenderTarget(width, height, { depthBuffer: true });
  renderer.setRenderTarget(target);
  // biome-ignore lint/suspicious/noExplicitAny: the backends' internals (three's types do not describe them).
  const b = renderer.backend as any;
  const isWebGPU = b.isWebGPUBackend === true;
  if (isWebGPU !== (backend === 'webgpu')) throw new Error(`asked for ${backend}, got another backend`);
  let read: () => Promise<unknown> | undefined;
  if (isWebGPU) {
    read = () => renderer.readRenderTargetPixelsAsync(target, width >> 1, height >> 1, 1, 1);
  } else {
    // A synchronous readPixels from the target's texture (three's async read-back polls per animation frame).
    const gl = b.gl as WebGL2RenderingContext;
    let fb: WebGLFramebuffer | null = null;
    read = () => {
      if (fb === null) {
        fb = gl.createFramebuffer();
        b.state.bindFramebuffer(gl.READ_FRAMEBUFFER, fb);
        const texture = b.get(target.texture).textureGPU as WebGLTexture;
        gl.framebufferTexture2D(gl.READ_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      } else b.state.bindFramebuffer(gl.READ_FRAMEBUFFER, fb);
      gl.readPixels(width >> 1, height >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      b.state.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
      return undefined;
    };
  }
  return { renderer, target, timestamps: b.trackTimestamp === true, read };
}

const gpu: Partial<Record<'webgpu' | 'webgl2', GpuRenderer>> = {};
const initErrors: Partial<Record<Backend, string>> = {};
for (const backend of ['webgpu', 'webgl2'] as const) {
  try {
    gpu[backend] = await gpuRenderer(backend);
  } catch (error) {
    initErrors[backend] = error instanceof Error ? error.message : String(error);
  }
}

const gl = new WebGLRenderer({ antialias: false });
gl.setPixelRatio(1);
gl.setSize(width, height, false);
const glTarget = new WebGLRenderTarget(width, height);
gl.setRenderTarget(glTarget);
const glContext = gl.getContext() as WebGL2RenderingContext;
const timer = glContext.getExtension('EXT_disjoint_timer_query_webgl2') as {
  TIME_ELAPSED_EXT: number;
} | null;

/** What each backend is and offers, for the results' meta. */
async function info() {
  const adapter =
    'gpu' in navigator
      ? await (
          navigator as unknown as { gpu: { requestAdapter(): Promise<{ features: Set<string> } | null> } }
        ).gpu.requestAdapter()
      : null;
  const adapterInfo = adapter as unknown as { info?: Record<string, string> } | null;
  return {
    width,
    height,
    adapter:
      adapter === null
        ? null
        : {
            timestampQuery: adapter.features.has('timestamp-query'),
            features: [...adapter.features].sort(),
            vendor: adapterInfo?.info?.vendor ?? null,
            architecture: adapterInfo?.info?.architecture ?? null,
            description: adapterInfo?.info?.description ?? null,
          },
    webgpu: gpu.webgpu ? { timestamps: gpu.webgpu.timestamps } : { error: initErrors.webgpu },
    webgl2: gpu.webgl2
      ? {
          timestamps: gpu.webgl2.timestamps,
          renderer: String(
            (gpu.webgl2.renderer.backend as unknown as { gl: WebGL2RenderingContext }).gl.getParameter(
              0x1f01 /* RENDERER */,
            ),
          ),
        }
      : { error: initErrors.webgl2 },
    webgl: { timer: timer !== null, renderer: String(glContext.getParameter(glContext.RENDERER)) },
  };
}

// ── A/B experiments ─────────────────────────────────────────────────────────────────────────────────────────

/**
 * A named change to ShadingNodeMaterial's phong shading, measured against it (subclasses of this checkout's
 * ShadingNodeMaterial, so that a proposed change can be timed before it is made). three compiles a `select()` to
 * an if/else block, and a node first used inside a block is computed there, again in every block that uses it:
 * - 'hoist-v': in phong shading (the fragment stage), the unit vector towards the eye given to the lighting model as a var
 *   computed once in the main flow (on the stack) before the lighting, instead of again inside each light's
 *   specular branch;
 * - 'plain-normalize': n and v as plain `normalize()`, no zero-length fallbacks (a bound on what the fallbacks
 *   cost; not a proposal: the fallbacks are the material's contract);
 * - 'branch-free': every scalar or vector `select()` of the material compiled to one assignment of a ternary
 *   (WGSL `select`, GLSL `?:`) in the flow it is in, both operands computed, instead of an if/else block
 *   (three's ConditionalNode patched for this material only; three's own `uniformFlow` context does the same
 *   but drops the parentheses and leaves reused selects unassigned in three 0.187);
 * - 'branch-free-mix': the same with `mix(b, a, float(cond))`, what plain TSL can write (exact when both
 *   operands are finite: weight 0 or 1);
 * - 'static-bindings': three's own observer (NodeMaterial.setupObserver), without the material's `hasNode`, so
 *   that three does not refresh the material's bindings on every frame (a bound on what that refresh costs;
 *   not a proposal as it stands: ka/kd edited in place would no longer be uploaded).
 */
export type Experiment =
  | 'hoist-v'
  | 'plain-normalize'
  | 'branch-free'
  | 'branch-free-mix'
  | 'static-bindings';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes and three's node builder are dynamically typed.
type N = any;

const conditional = ConditionalNode.prototype as N;
const generateConditional = conditional.generate as (this: N, builder: N, output: string) => string;
conditional.generate = function (this: N, builder: N, output: string): string {
  const mode = builder.material?.userData?.benchBranchFree as 'ternary' | 'mix' | undefined;
  if (mode === undefined || output === 'void') {
    return generateConditional.call(this, builder, output);
  }
  const { condNode, ifNode, elseNode } = builder.getNodeProperties(this);
  if (elseNode === null || builder.getTypeLength(condNode.getNodeType(builder)) > 1) {
    return generateConditional.call(this, builder, output);
  }
  const type = this.getNodeType(builder);
  const data = builder.getDataFromNode(this);
  if (data.propertyName !== undefined) return builder.format(data.propertyName, type, output);
  const cond = condNode.build(builder, 'bool');
  const a = ifNode.build(builder, type);
  const b = elseNode.build(builder, type);
  const name = (property(type) as N).build(builder);
  data.propertyName = name;
  const float = builder.getType('float');
  const picked =
    mode === 'mix'
      ? `mix( ${b}, ${a}, ${builder.getType(type) === float ? '' : `${builder.getType(type)}`}( ${float}( ${cond} ) ) )`
      : builder.getTernary(`( ${cond} )`, `( ${a} )`, `( ${b} )`);
  builder.addLineFlowCode(`${name} = ${picked}`, this);
  return builder.format(name, type, output);
};

function experimentalMaterial(name: Experiment, options: object): Material {
  class Experimental extends ShadingNodeMaterial {
    override setupObserver(builder: N): N {
      return name === 'static-bindings'
        ? (NodeMaterial.prototype as N).setupObserver.call(this, builder)
        : super.setupObserver(builder);
    }
    override setupLighting(builder: N): N {
      if (name !== 'plain-normalize' || this.shading !== 'phong' || builder.camera?.isOrthographicCamera) {
        return super.setupLighting(builder);
      }
      const normal: N =
        builder.geometry.getAttribute('normal') === undefined
          ? (transformNormalToView(positionLocal) as N).toVarying()
          : normalView;
      const v = (positionView as N).negate().normalize();
      return (this as N).lightSurface(builder, { n: normal.normalize(), v });
    }
  }
  if (name === 'hoist-v') {
    // ShadingNodeMaterial.lightSurface (protected; the checker sees the webgpu entry's built declarations):
    // in the fragment stage, v becomes a var computed on the stack before the lighting.
    const base = (ShadingNodeMaterial.prototype as N).lightSurface as (...args: N[]) => N;
    (Experimental.prototype as N).lightSurface = function (this: N, builder: N, surface: N, at?: N): N {
      // Phong shading lights in the fragment stage (setup runs before any stage is set: no shaderStage yet).
      if (this.shading !== 'phong') return base.call(this, builder, surface, at);
      const v = surface.v.toVar('towardsEye');
      v.toStack();
      return base.call(this, builder, { n: surface.n, v }, at);
    };
  }
  const material = new Experimental(options as never) as unknown as Material;
  if (name === 'branch-free') material.userData.benchBranchFree = 'ternary';
  if (name === 'branch-free-mix') material.userData.benchBranchFree = 'mix';
  return material;
}

// ── Scenes ──────────────────────────────────────────────────────────────────────────────────────────────────

const geometries = new Map<string, BufferGeometry>();
function sphere(normals: boolean, indexed: boolean): BufferGeometry {
  const key = `${normals}/${indexed}`;
  let g = geometries.get(key);
  if (g === undefined) {
    g = new SubdivisionSphereGeometry({
      level: LEVEL,
      base: 'tetrahedron',
      normals: normals ? 'smooth' : 'none',
      indexed,
    });
    geometries.set(key, g);
  }
  return g;
}
/** flatShadingGeometry of the lecture's sphere per build of @shadelab/material ('' = this checkout's), and of the realistic scene's sphere per provoking vertex ('realistic/first', 'realistic/last'). */
const flatPrepared = new Map<string, BufferGeometry>();

/**
 * The geometry each material draws: ours read positions only (the analytic sphere normal); three's need
 * normals. Flat shading: ShadingNodeMaterial's exact per-face path draws the triangle soup, ShadingMaterial the
 * prepared flatShadingGeometry (as in the material bench); everything else the indexed sphere.
 */
function geometryOf(spec: BenchSpec): BufferGeometry {
  if (spec.material !== 'shadelab') return sphere(true, true);
  if ((spec.shading ?? 'phong') !== 'flat') return sphere(false, true);
  if (spec.backend !== 'webgl') return sphere(false, false);
  const key = spec.build ?? '';
  let prepared = flatPrepared.get(key);
  if (prepared === undefined) {
    prepared = buildOf(spec.build).flatShadingGeometry(sphere(false, true));
    flatPrepared.set(key, prepared);
  }
  return prepared;
}

const LIGHT_POSITION = [-5, 10, 20] as const;

function materialOf(spec: BenchSpec, scene: Scene): Material {
  const lights = spec.lights ?? 'phong';
  const build = buildOf(spec.build);
  const phongLights: Object3D[] = [];
  if (lights === 'phong' && spec.material === 'shadelab') {
    const light = new build.PhongLight();
    light.position.set(...LIGHT_POSITION);
    scene.add(light);
    phongLights.push(light);
  } else if (lights === 'phong') {
    scene.add(new AmbientLight(0xffffff, 0.2));
    const point = new PointLight(0xffffff, 1, 0, 0);
    point.position.set(...LIGHT_POSITION);
    scene.add(point);
  } else {
    scene.add(new AmbientLight(0xffffff, 0.2));
    const point = new PointLight(0xffffff, 400, 0, 2);
    point.position.set(...LIGHT_POSITION);
    scene.add(point);
    const sun = new DirectionalLight(0xffffff, 0.8);
    sun.position.set(5, 10, 7);
    scene.add(sun);
  }
  if (spec.material === 'three-phong') {
    const options = {
      color: new Color(0.6, 0.35, 0.2),
      specular: new Color(0.5, 0.5, 0.5),
      shininess: 32,
    };
    return spec.backend === 'webgl' ? new MeshPhongMaterial(options) : new MeshPhongNodeMaterial(options);
  }
  const options = {
    shading: spec.shading ?? 'phong',
    lighting: spec.lighting ?? 'phong',
    celBands: spec.celBands ?? 0,
    lights: phongLights,
  };
  if (spec.backend === 'webgl') return new build.ShadingMaterial(options);
  if (spec.experiment !== undefined) return experimentalMaterial(spec.experiment, options);
  return new build.ShadingNodeMaterial(options);
}

// ── Builds of @shadelab/material ────────────────────────────────────────────────────────────────────────────

/** What the lecture's scene takes from a build of @shadelab/material (this checkout's, or an older commit's). */
interface MaterialBuild {
  ShadingMaterial: new (options: object) => Material;
  ShadingNodeMaterial: new (options: object) => Material;
  PhongLight: new () => Object3D;
  flatShadingGeometry: (geometry: BufferGeometry) => BufferGeometry;
}

// tsconfig.test.json maps @shadelab/material to its sources but not @shadelab/material/webgpu (its dist): two
// PhongLight types for the checker, one class at run time (Vite resolves both to the sources).
const checkout = {
  ShadingMaterial,
  ShadingNodeMaterial,
  PhongLight,
  flatShadingGeometry,
} as unknown as MaterialBuild;
const builds = new Map<string, MaterialBuild>();

/**
 * Load another build of @shadelab/material under `name`: `code` is one ES module (bench/lib/materialAt.mjs)
 * exporting its main and webgpu entries, whose imports of `three`, `three/webgpu` and `three/tsl` read this
 * page's (globalThis.__shadelabThree, __shadelabThreeWebGPU, __shadelabTSL), so that both builds draw through
 * one three.js. Returns the module's export names.
 */
async function loadModule(name: string, code: string): Promise<string[]> {
  Object.assign(globalThis, {
    __shadelabThree: THREE,
    __shadelabThreeWebGPU: THREE_WEBGPU,
    __shadelabTSL: TSL,
  });
  const url = URL.createObjectURL(new Blob([code], { type: 'text/javascript' }));
  const module = (await import(/* @vite-ignore */ url)) as MaterialBuild;
  URL.revokeObjectURL(url);
  for (const key of [
    'ShadingMaterial',
    'ShadingNodeMaterial',
    'PhongLight',
    'flatShadingGeometry',
  ] as const) {
    if (typeof module[key] !== 'function') throw new Error(`loadModule('${name}'): no ${key} in the build`);
  }
  builds.set(name, module);
  return Object.keys(module);
}

/** The build loaded under `name`, or this checkout's. */
function buildOf(name: string | undefined): MaterialBuild {
  if (name === undefined) return checkout;
  const build = builds.get(name);
  if (build === undefined) throw new Error(`loadModule('${name}', …) first`);
  return build;
}

// ── The realistic scene ─────────────────────────────────────────────────────────────────────────────────────

/** The realistic scene wearing `spec`'s material (the indexed sphere, or for flat shading with `flatGeometry: 'prepared'` its flatShadingGeometry for the backend's provoking vertex). */
function realisticOf(spec: BenchSpec): Built {
  const grey = new Color(0.6, 0.6, 0.6);
  const node = spec.backend !== 'webgl';
  let material: Material;
  if (spec.material === 'shadelab') {
    const options = {
      shading: spec.shading ?? 'phong',
      lighting: spec.lighting ?? 'phong',
      ka: [0.6, 0.6, 0.6],
      kd: [0.6, 0.6, 0.6],
      ks: 0.5,
      shininess: 32,
    };
    material = !node
      ? new ShadingMaterial(options as never)
      : spec.experiment !== undefined
        ? experimentalMaterial(spec.experiment, options)
        : new ShadingNodeMaterial(options as never);
  } else if (spec.material === 'three-phong') {
    const options = { color: grey, specular: new Color(0.5, 0.5, 0.5), shininess: 32 };
    material = node ? new MeshPhongNodeMaterial(options) : new MeshPhongMaterial(options);
  } else {
    material = node ? new MeshLambertNodeMaterial({ color: grey }) : new MeshLambertMaterial({ color: grey });
  }
  let geometry: BufferGeometry = realisticGeometries.indexed;
  if (spec.material === 'shadelab' && spec.shading === 'flat' && spec.flatGeometry === 'prepared') {
    const provokingVertex = node
      ? provokingVertexOf(gpu[spec.backend as 'webgpu' | 'webgl2']?.renderer ?? {})
      : 'last';
    const key = `realistic/${provokingVertex}`;
    let prepared = flatPrepared.get(key);
    if (prepared === undefined) {
      prepared = flatShadingGeometry(realisticGeometries.indexed, { provokingVertex });
      flatPrepared.set(key, prepared);
    }
    geometry = prepared;
  }
  const { scene, camera, mesh } = buildRealisticScene(material, geometry, width / height);
  return { scene, camera, mesh };
}

interface Built {
  scene: Scene;
  camera: PerspectiveCamera;
  mesh: Mesh;
}
const scenes = new Map<string, Built>();

/** The material bench's lecture scene: the sphere (radius 2) filling most of the canvas, camera 90° at z = 3. */
function sceneOf(spec: BenchSpec): Built {
  const key = JSON.stringify(spec);
  let built = scenes.get(key);
  if (built !== undefined) return built;
  if (spec.scene === 'realistic') {
    built = realisticOf(spec);
    scenes.set(key, built);
    return built;
  }
  const scene = new Scene();
  scene.background = new Color(0, 0, 0);
  const mesh = new Mesh(geometryOf(spec), materialOf(spec, scene));
  mesh.scale.setScalar(2);
  scene.add(mesh);
  const camera = new PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  built = { scene, camera, mesh };
  scenes.set(key, built);
  return built;
}

// ── Timing ──────────────────────────────────────────────────────────────────────────────────────────────────

/** One frame of `spec`, timed: render and 1×1 read-back; then its GPU time when there is a timer (untimed). */
async function frame(spec: BenchSpec, built: Built): Promise<{ ms: number; gpu: number | null }> {
  if (spec.backend === 'webgl') {
    let query: WebGLQuery | null = null;
    if (timer !== null) {
      query = glContext.createQuery();
      glContext.beginQuery(timer.TIME_ELAPSED_EXT, query);
    }
    const t0 = performance.now();
    gl.render(built.scene, built.camera);
    if (query !== null && timer !== null) glContext.endQuery(timer.TIME_ELAPSED_EXT);
    gl.readRenderTargetPixels(glTarget, width >> 1, height >> 1, 1, 1, pixel);
    const ms = performance.now() - t0;
    return { ms, gpu: query === null ? null : await queryMs(query) };
  }
  const r = gpu[spec.backend];
  if (r === undefined) throw new Error(`no ${spec.backend} backend: ${initErrors[spec.backend]}`);
  const t0 = performance.now();
  r.renderer.render(built.scene, built.camera);
  await r.read();
  const ms = performance.now() - t0;
  if (!r.timestamps) return { ms, gpu: null };
  const duration = await r.renderer.resolveTimestampsAsync('render');
  return { ms, gpu: typeof duration === 'number' ? duration : null };
}

async function queryMs(q: WebGLQuery): Promise<number | null> {
  for (let tries = 0; tries < 200; tries++) {
    if (glContext.getQueryParameter(q, glContext.QUERY_RESULT_AVAILABLE)) break;
    await new Promise((r) => setTimeout(r, 1));
  }
  const ok =
    !glContext.getParameter(0x8fbb /* GPU_DISJOINT_EXT */) &&
    glContext.getQueryParameter(q, glContext.QUERY_RESULT_AVAILABLE);
  const ms = ok ? glContext.getQueryParameter(q, glContext.QUERY_RESULT) / 1e6 : null;
  glContext.deleteQuery(q);
  return ms;
}

/**
 * Time `specs` interleaved frame by frame: `warmup` untimed frames of each (the first compiles it), then
 * `frames` cycles that render one timed frame of every spec in turn, so that a change of the machine's load
 * hits every spec of a cycle alike. A spec that throws is left out with its error.
 */
async function cycle(specs: BenchSpec[], frames: number, warmup: number): Promise<TimedResult[]> {
  const results: TimedResult[] = specs.map(() => ({ frames: [], gpu: [] }));
  const built: Array<Built | null> = specs.map((spec, k) => {
    try {
      return sceneOf(spec);
    } catch (error) {
      results[k].error = error instanceof Error ? error.message : String(error);
      return null;
    }
  });
  for (let k = 0; k < specs.length; k++) {
    const b = built[k];
    if (b === null) continue;
    // three reports a node material it cannot build with console.error and draws on without it: such a spec
    // is left out with that error, as one that throws.
    const logged: string[] = [];
    const consoleError = console.error;
    console.error = (...args: unknown[]) => {
      logged.push(args.map(String).join(' '));
      consoleError.apply(console, args);
    };
    try {
      for (let i = 0; i < warmup; i++) await frame(specs[k], b);
    } catch (error) {
      results[k].error = error instanceof Error ? error.message : String(error);
    } finally {
      console.error = consoleError;
    }
    if (results[k].error === undefined && logged.length > 0) results[k].error = logged[0].slice(0, 300);
  }
  for (let i = 0; i < frames; i++) {
    for (let k = 0; k < specs.length; k++) {
      const b = built[k];
      if (b === null || results[k].error !== undefined) continue;
      const { ms, gpu: g } = await frame(specs[k], b);
      results[k].frames.push(ms);
      if (g !== null) results[k].gpu.push(g);
    }
  }
  return results;
}

/** The generated shaders of `spec` (WebGPURenderer: WGSL or GLSL ES 3.0), for comparing variants. */
async function shader(
  spec: BenchSpec,
): Promise<{ vertexShader: string | null; fragmentShader: string | null }> {
  if (spec.backend === 'webgl') throw new Error('shader(): WebGPURenderer backends only');
  const r = gpu[spec.backend];
  if (r === undefined) throw new Error(`no ${spec.backend} backend`);
  const built = sceneOf(spec);
  return r.renderer.debug.getShaderAsync(built.scene, built.camera, built.mesh);
}

/** The colour at the canvas centre of one frame of `spec` (linear RGBA8), to check that a variant draws. */
async function centre(spec: BenchSpec): Promise<number[]> {
  const built = sceneOf(spec);
  if (spec.backend === 'webgl') {
    gl.render(built.scene, built.camera);
    gl.readRenderTargetPixels(glTarget, width >> 1, height >> 1, 1, 1, pixel);
    return [...pixel];
  }
  const r = gpu[spec.backend];
  if (r === undefined) throw new Error(`no ${spec.backend} backend`);
  r.renderer.render(built.scene, built.camera);
  const data = await r.renderer.readRenderTargetPixelsAsync(r.target, width >> 1, height >> 1, 1, 1);
  return [...(data as Uint8Array)];
}

const api = { info, cycle, shader, centre, loadModule };
declare global {
  interface Window {
    webgpuBench: typeof api;
  }
}
window.webgpuBench = api;
document.body.dataset.ready = '1';
