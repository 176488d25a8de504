/**
 * The page side of `toMatchAcrossRenderers`: a script of the page under test imports this entry and calls
 * {@link exposeRenderers}, which gives the test one `WebGLRenderer` and one `WebGPURenderer` per backend (made
 * once, shared by every scene), the page's own modules for scene factories written in the test, and any scenes
 * the page registers by name ({@link registerScene}). Runs in the browser; imports `three` and `three/webgpu`.
 * @module @shadelab/playwright/page
 */
import {
  type ColorRepresentation,
  type ColorSpace,
  NoToneMapping,
  type Object3D,
  SRGBColorSpace,
  type ToneMapping,
  WebGLRenderer,
} from 'three';
import * as THREE from 'three/webgpu';
import type { BackendProof, RendererName } from './rendererNames.js';

export type { BackendProof, RendererName } from './rendererNames.js';

/** What a scene factory is given: which renderer the scene is for, three, the page's modules and the test's argument. */
export interface SceneContext {
  /** The renderer that will draw the scene. */
  readonly renderer: RendererName;
  /**
   * `'webgl'` for `WebGLRenderer` (GLSL materials such as `ShadingMaterial`), `'webgpu'` for `WebGPURenderer` on
   * either backend (node materials such as `ShadingNodeMaterial`; three's own materials work on both).
   */
  readonly kind: 'webgl' | 'webgpu';
  /** `three/webgpu`: everything of `three`'s core, the node materials and `WebGPURenderer`. */
  readonly THREE: typeof THREE;
  /** The modules the page passed to {@link exposeRenderers} (its own classes), by name. */
  readonly modules: Readonly<Record<string, unknown>>;
  /** The test's argument (`arg` of the matcher's options; JSON-serialisable), or undefined. */
  readonly arg: unknown;
  /** The picture's width in pixels (with `height`, the camera's aspect). */
  readonly width: number;
  /** The picture's height in pixels. */
  readonly height: number;
}

/** What a scene factory returns: what to draw, from where, and how the renderer outputs it. */
export interface SceneSetup {
  /** The scene (usually a `Scene`); its `background`, when set, is drawn as three draws it. */
  readonly scene: Object3D;
  /** The camera. */
  readonly camera: THREE.Camera;
  /** The renderer's tone mapping. @default NoToneMapping */
  readonly toneMapping?: ToneMapping;
  /** The renderer's tone mapping exposure. @default 1 */
  readonly toneMappingExposure?: number;
  /** The renderer's output colour space. @default SRGBColorSpace */
  readonly outputColorSpace?: ColorSpace;
  /** The clear colour where the scene has no background. @default black */
  readonly clearColor?: ColorRepresentation;
  /** The clear alpha (0 … 1). @default 1 */
  readonly clearAlpha?: number;
  /**
   * Frees what the factory made, called after the picture is read. @default every geometry and material in
   * `scene` is disposed (the factory made them for this picture)
   */
  readonly dispose?: () => void;
}

/**
 * A scene factory: called once for each renderer, in the page, it builds the scene that renderer draws. A
 * factory passed from a test is serialised into the page as `page.evaluate`'s functions are (it cannot use the
 * test file's variables: pass data as `arg`, classes through {@link exposeRenderers}' modules).
 */
export type SceneFactory = (context: SceneContext) => SceneSetup | Promise<SceneSetup>;

/** One renderer's picture, as the page returns it to the test. */
export type RenderedPicture =
  | {
      readonly renderer: RendererName;
      readonly ok: true;
      readonly proof: BackendProof;
      /** RGBA8, rows top-down, base64. */
      readonly pixels: string;
    }
  | {
      readonly renderer: RendererName;
      readonly ok: false;
      readonly proof: BackendProof | null;
      readonly error: string;
    };

/** What the test asks the page for. */
export interface RenderRequest {
  /** The renderers, in order. */
  readonly renderers: readonly RendererName[];
  /** Picture width in pixels. */
  readonly width: number;
  /** Picture height in pixels. */
  readonly height: number;
  /** The factory's `context.arg`. */
  readonly arg?: unknown;
}

/** The page API that {@link exposeRenderers} installs (under `Symbol.for('shadelab.renderers')`). */
export interface PageRenderers {
  /** The contract's version: 1. */
  readonly version: 1;
  /** Draw the scene of `factory` (a function, or the name of a registered scene) with each renderer asked for. */
  render(factory: SceneFactory | string, request: RenderRequest): Promise<RenderedPicture[]>;
}

const KEY = Symbol.for('shadelab.renderers');
const scenes = new Map<string, SceneFactory>();
let pageModules: Readonly<Record<string, unknown>> = {};

interface Gpu {
  renderer: THREE.WebGPURenderer;
  target: THREE.RenderTarget | null;
}
let webgl: WebGLRenderer | null = null;
const gpus = new Map<RendererName, Promise<Gpu>>();

function base64(bytes: Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

function flip(data: Uint8Array, width: number, height: number): Uint8Array {
  const out = new Uint8Array(data.length);
  const row = 4 * width;
  for (let y = 0; y < height; y++)
    out.set(data.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return out;
}

function glRendererOf(gl: WebGLRenderingContext | WebGL2RenderingContext): string {
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return String(gl.getParameter(info === null ? gl.RENDERER : info.UNMASKED_RENDERER_WEBGL));
}

/** Why WebGPURenderer did not get a WebGPU device in this page. */
async function whyNoWebGpu(): Promise<string> {
  if (!globalThis.isSecureContext)
    return 'the page is not a secure context (WebGPU needs https or localhost)';
  const gpu = (navigator as Navigator & { gpu?: { requestAdapter(): Promise<unknown> } }).gpu;
  if (gpu === undefined) {
    return 'navigator.gpu is undefined: this Chromium exposes no WebGPU (launch it with --enable-unsafe-webgpu: shadelabPreset({ webgpu: true }))';
  }
  const adapter = await gpu.requestAdapter().catch(() => null);
  if (adapter === null) {
    return 'navigator.gpu.requestAdapter() returned null: no WebGPU adapter (launch Chromium with --enable-unsafe-webgpu: shadelabPreset({ webgpu: true }))';
  }
  return 'three chose its WebGL2 backend although an adapter exists (see the console)';
}

function proofOf(name: RendererName, renderer: WebGLRenderer | THREE.WebGPURenderer): BackendProof {
  if (renderer instanceof WebGLRenderer) {
    const gl = renderer.getContext();
    return {
      renderer: name,
      api: 'webgl2',
      isWebGPUBackend: false,
      isWebGLBackend: false,
      gpuDevice: false,
      adapter: null,
      glRenderer: glRendererOf(gl),
    };
  }
  const backend = renderer.backend as unknown as {
    isWebGPUBackend?: boolean;
    isWebGLBackend?: boolean;
    device?: { adapterInfo?: { vendor?: string; architecture?: string; description?: string } };
    gl?: WebGL2RenderingContext;
  };
  const isWebGPUBackend = backend.isWebGPUBackend === true;
  const Device = (globalThis as { GPUDevice?: new () => unknown }).GPUDevice;
  const gpuDevice = isWebGPUBackend && Device !== undefined && backend.device instanceof Device;
  const info = gpuDevice ? backend.device?.adapterInfo : undefined; // GPUDevice.adapterInfo
  return {
    renderer: name,
    api: gpuDevice ? 'webgpu' : backend.isWebGLBackend === true && backend.gl ? 'webgl2' : 'none',
    isWebGPUBackend,
    isWebGLBackend: backend.isWebGLBackend === true,
    gpuDevice,
    adapter:
      info === undefined
        ? null
        : {
            vendor: info.vendor ?? '',
            architecture: info.architecture ?? '',
            description: info.description ?? '',
          },
    glRenderer: backend.gl === undefined ? null : glRendererOf(backend.gl),
  };
}

function gpuRenderer(name: RendererName): Promise<Gpu> {
  let r = gpus.get(name);
  if (r === undefined) {
    const renderer = new THREE.WebGPURenderer({ antialias: false, forceWebGL: name === 'webgpu-webgl2' });
    renderer.setPixelRatio(1);
    r = renderer.init().then(() => ({ renderer, target: null }));
    gpus.set(name, r);
  }
  return r;
}

function disposeScene(scene: Object3D): void {
  scene.traverse((object) => {
    const o = object as Object3D & {
      geometry?: { dispose(): void };
      material?: { dispose(): void } | { dispose(): void }[];
    };
    o.geometry?.dispose();
    for (const m of Array.isArray(o.material) ? o.material : o.material ? [o.material] : []) m.dispose();
  });
}

async function renderOne(
  name: RendererName,
  factory: SceneFactory,
  { width, height, arg }: RenderRequest,
): Promise<RenderedPicture> {
  let proof: BackendProof | null = null;
  try {
    if (name === 'webgl' && webgl === null) webgl = new WebGLRenderer({ antialias: false });
    const renderer = name === 'webgl' ? webgl : null;
    const gpu = name === 'webgl' ? null : await gpuRenderer(name);
    const r = renderer ?? (gpu as Gpu).renderer;
    proof = proofOf(name, r);
    if (name === 'webgpu' && proof.api !== 'webgpu') {
      const why = proof.isWebGPUBackend ? 'its device is not a GPUDevice' : await whyNoWebGpu();
      return {
        renderer: name,
        ok: false,
        proof,
        error: `WebGPU was asked for, but WebGPURenderer fell back to its WebGL2 backend: ${why}`,
      };
    }
    const setup = await factory({
      renderer: name,
      kind: name === 'webgl' ? 'webgl' : 'webgpu',
      THREE,
      modules: pageModules,
      arg,
      width,
      height,
    });
    if (setup === null || typeof setup !== 'object' || !setup.scene || !setup.camera) {
      throw new TypeError(`the scene factory must return { scene, camera }, got ${String(setup)}`);
    }
    r.toneMapping = setup.toneMapping ?? NoToneMapping;
    r.toneMappingExposure = setup.toneMappingExposure ?? 1;
    r.outputColorSpace = setup.outputColorSpace ?? SRGBColorSpace;
    r.setClearColor(setup.clearColor ?? 0x000000, setup.clearAlpha ?? 1);
    r.setPixelRatio(1);
    r.setSize(width, height, false);
    let pixels: Uint8Array;
    try {
      if (renderer !== null) {
        // Drawn to the canvas, so that tone mapping and the output colour space apply; read in the same task.
        renderer.setRenderTarget(null);
        renderer.render(setup.scene, setup.camera);
        const gl = renderer.getContext();
        const bottomUp = new Uint8Array(width * height * 4);
        gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, bottomUp);
        pixels = flip(bottomUp, width, height);
      } else {
        const g = gpu as Gpu;
        if (g.target === null || g.target.width !== width || g.target.height !== height) {
          g.target?.dispose();
          g.target = new THREE.RenderTarget(width, height, { depthBuffer: true });
        }
        // The canvas path, offscreen: the scene into three's frame buffer, then its output pass (tone mapping,
        // colour space) into the output target, which is read back.
        g.renderer.setOutputRenderTarget(g.target);
        g.renderer.setRenderTarget(null);
        try {
          g.renderer.render(setup.scene as THREE.Object3D, setup.camera);
          const data = (await g.renderer.readRenderTargetPixelsAsync(
            g.target,
            0,
            0,
            width,
            height,
          )) as Uint8Array;
          const bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
          // The WebGPU backend reads rows top-down (texture space), the WebGL2 backend bottom-up (GL).
          pixels = proof.isWebGPUBackend ? new Uint8Array(bytes) : flip(bytes, width, height);
        } finally {
          g.renderer.setOutputRenderTarget(null);
        }
      }
    } finally {
      if (setup.dispose) setup.dispose();
      else disposeScene(setup.scene);
    }
    return { renderer: name, ok: true, proof, pixels: base64(pixels) };
  } catch (error) {
    const message = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
    return { renderer: name, ok: false, proof, error: message };
  }
}

const api: PageRenderers = {
  version: 1,
  async render(factory, request) {
    const resolved = typeof factory === 'string' ? scenes.get(factory) : factory;
    if (resolved === undefined) {
      const names = [...scenes.keys()].map((n) => JSON.stringify(n)).join(', ') || 'none';
      throw new Error(`no scene registered as ${JSON.stringify(factory)} (registered: ${names})`);
    }
    const out: RenderedPicture[] = [];
    for (const name of request.renderers) out.push(await renderOne(name, resolved, request));
    return out;
  },
};

/**
 * Give the tests of this page the renderers of `toMatchAcrossRenderers`: one `WebGLRenderer` and one
 * `WebGPURenderer` per backend, made on first use and shared by every scene (each draws offscreen, nothing is
 * added to the document). `modules` are handed to scene factories written in the test (`context.modules`), so
 * that they can build the page's own classes. Call it once, from a script of the page.
 */
export function exposeRenderers(modules: Readonly<Record<string, unknown>> = {}): void {
  if (modules === null || typeof modules !== 'object') {
    throw new TypeError(
      `exposeRenderers: modules must be an object of named modules, got ${String(modules)}`,
    );
  }
  pageModules = modules;
  (globalThis as unknown as Record<symbol, PageRenderers>)[KEY] = api;
}

/**
 * Register a scene factory under `name`, for `expect(page).toMatchAcrossRenderers(name)`: written in the page's
 * own code, it can import what it needs.
 */
export function registerScene(name: string, factory: SceneFactory): void {
  if (typeof name !== 'string' || name === '') {
    throw new TypeError(`registerScene: name must be a non-empty string, got ${String(name)}`);
  }
  if (typeof factory !== 'function') {
    throw new TypeError(`registerScene: factory must be a function, got ${String(factory)}`);
  }
  scenes.set(name, factory);
}
