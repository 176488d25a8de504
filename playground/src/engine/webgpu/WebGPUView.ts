/**
 * WebGPU mode's renderer: three's WebGPURenderer drawing the viewer's own scene and camera (every view: the
 * viewer's draw code runs on it through `gpuCells.ts`, the WebGL-only materials swapped for node materials by
 * `nodeMirror.ts`). Output `'canvas'`: on a canvas of its own laid over the viewer's WebGL canvas (which keeps the
 * pointer and keyboard input: the trackball, the camera keys and the gizmo work unchanged). Output `'offscreen'`
 * (the parity view): into a render target through three's output pass, read back ({@link WebGPUView.read}),
 * never presented (headless Chromium loses a WebGPU device that presents a canvas). Loaded only by dynamic import
 * (switch.ts), so that WebGL mode never loads three/webgpu.
 *
 * The WebGPU backend runs when `navigator.gpu` gives an adapter, else the WebGL2 backend (`forceWebGL`). A lost
 * WebGPU device (a canvas presented headless loses it) falls back to the WebGL2 backend on a fresh canvas (a
 * canvas keeps its first context type) and says so.
 */
import { ShadingMaterial } from '@shadelab/material';
import { provokingVertexOf, ShadingNodeMaterial } from '@shadelab/material/webgpu';
import type * as THREE from 'three';
import { RenderTarget, WebGPURenderer } from 'three/webgpu';
import { GpuCells } from './gpuCells';
import { NodeMirror } from './nodeMirror';
import { readBack } from './readBack';
import { mirrorMaterial } from './scene';
import { generatedShader } from './shaderReader';
import type {
  FallbackReason,
  GpuDraw,
  GpuFrame,
  GpuHost,
  GpuOutput,
  WebGPUEvents,
  WebGPUStatus,
} from './status';
import { timestamps } from './timing';

export type { GpuHost, WebGPUEvents } from './status';

type Backend = {
  isWebGPUBackend?: boolean;
  device?: { lost: Promise<{ message: string; reason: string | null }> };
};
type GpuNavigator = { gpu?: { requestAdapter(): Promise<unknown> } };

/** This browser gave no WebGPU adapter (it will not give one later in the page's life). */
let noAdapter = false;

export class WebGPUView {
  private renderer: WebGPURenderer | null = null;
  private canvas: HTMLCanvasElement | null = null;
  private readonly material = new ShadingNodeMaterial();
  private mirror: NodeMirror | null = null;
  private target: RenderTarget | null = null;
  private ready = false;
  /** When the backend opened (performance.now(), ms). */
  private openedAt = 0;
  private disposed = false;
  private frames = 0;
  private shaderKey = '';

  constructor(
    private readonly host: GpuHost,
    private readonly events: WebGPUEvents,
    private readonly output: GpuOutput = 'canvas',
  ) {
    window.addEventListener('unhandledrejection', this.onRejection);
    host.canvas.addEventListener('webglcontextrestored', this.onHostRestored);
    void this.start();
  }

  /** Opens the WebGPU backend where an adapter exists, else the WebGL2 backend (and says why). */
  private async start(): Promise<void> {
    const gpu = (navigator as GpuNavigator).gpu;
    let reason: FallbackReason | null = gpu ? null : 'no-webgpu';
    if (gpu && (noAdapter || (await gpu.requestAdapter().catch(() => null)) === null)) {
      // Chromium warns "No available adapters." at each request that finds none: asked once per page.
      noAdapter = true;
      reason = 'no-adapter';
    }
    await this.open(reason);
  }

  /** Why the current backend was opened (for reopening it). */
  private opened: { reason: FallbackReason | null; message: string | undefined } | null = null;

  /**
   * The viewer's WebGL context came back after a loss: the GPU process restarted (as it does after a lost WebGPU
   * device here), and a WebGL2 backend opened before that may draw to a canvas the page no longer shows. Opened
   * again on a fresh canvas.
   */
  private readonly onHostRestored = () => {
    const opened = this.opened;
    if (this.disposed || !this.ready || opened?.reason == null) return;
    void this.fallBack(opened.reason, opened.message);
  };

  private async open(reason: FallbackReason | null, message?: string, attempt = 0): Promise<void> {
    if (this.disposed) return;
    const canvas = document.createElement('canvas');
    canvas.dataset['testid'] = 'viewport-webgpu';
    canvas.setAttribute('aria-hidden', 'true');
    canvas.style.cssText = 'position:absolute;left:0;top:0;width:100%;height:100%;pointer-events:none';
    if (this.output === 'canvas') this.host.canvas.after(canvas);
    this.canvas = canvas;
    const renderer = new WebGPURenderer({
      canvas,
      antialias: false,
      forceWebGL: reason !== null,
      trackTimestamp: true,
    });
    renderer.info.autoReset = false;
    this.renderer = renderer;
    renderer.setPixelRatio(1);
    // A lost WebGPU device: the WebGL2 backend takes over on a new canvas. (A lost WebGL2 context is reported.)
    // A lost WebGL2 context (the GPU process restarting): the same backend again on a fresh canvas.
    renderer.onDeviceLost = (info: { api: string; message: string }) => {
      if (info.api === 'WebGPU') this.lost(renderer, info.message);
      else if (!this.disposed && this.renderer === renderer)
        void this.fallBack(reason ?? 'no-adapter', message);
    };
    this.opened = { reason, message };
    try {
      await renderer.init();
    } catch (error) {
      if (this.renderer !== renderer) return;
      const text = error instanceof Error ? error.message : String(error);
      if (reason === null) return this.fallBack('init-failed', text);
      // After a lost device the browser may refuse a WebGL2 context until its GPU process is back: retry.
      if (reason === 'device-lost' && attempt < RETRIES) {
        this.close();
        await new Promise((resolve) => setTimeout(resolve, RETRY_MS));
        return this.open(reason, message, attempt + 1);
      }
      this.report({ state: 'failed', message: text });
      return;
    }
    if (this.disposed || this.renderer !== renderer) return;
    this.ready = true;
    this.openedAt = performance.now();
    this.mirror = new NodeMirror(provokingVertexOf(renderer));
    const webgpu = (renderer.backend as Backend).isWebGPUBackend === true;
    // three ignores a loss with reason 'destroyed' (its own dispose), but a dropped instance (the GPU process
    // gone) says 'destroyed' too; only this view's close() destroys the device on purpose.
    (renderer.backend as Backend).device?.lost.then((info) =>
      this.lost(renderer, info.message || info.reason || 'lost'),
    );
    this.report({
      state: 'running',
      backend: webgpu ? 'webgpu' : 'webgl2',
      reason: webgpu ? null : (reason ?? 'no-adapter'),
      ...(message === undefined ? {} : { message }),
    });
    // The shader is read before the first frame: a device lost by presenting that frame has shown its WGSL.
    const source = this.host.mesh.material;
    if (source instanceof ShadingMaterial) mirrorMaterial(source, this.material);
    this.shaderKey = this.variantKey();
    if (this.output === 'canvas') await this.readShader(renderer);
    if (!this.disposed && this.renderer === renderer) this.host.requestRender();
  }

  private async fallBack(reason: FallbackReason, message: string | undefined): Promise<void> {
    this.close();
    await this.open(reason, message);
  }

  /** `renderer`'s WebGPU device is gone: the WebGL2 backend takes over (once, whichever report comes first). */
  private lost(renderer: WebGPURenderer, message: string) {
    if (this.disposed || this.renderer !== renderer) return;
    void this.fallBack('device-lost', message.trim());
  }

  /**
   * three's pipeline creation pops a WebGPU error scope without a catch: once the device is gone, its rejection
   * ("Instance dropped in popErrorScope") would be uncaught. Taken here as the device loss it is.
   */
  private readonly onRejection = (event: PromiseRejectionEvent) => {
    const message = event.reason instanceof Error ? event.reason.message : String(event.reason);
    if (!/instance dropped|device (is |was )?lost/i.test(message)) return;
    event.preventDefault();
    const renderer = this.renderer;
    if (renderer && (renderer.backend as Backend).isWebGPUBackend === true) this.lost(renderer, message);
  };

  private report(status: WebGPUStatus) {
    if (!this.disposed) this.events.onStatus?.(status);
  }

  /**
   * Draws a frame with `draw` (the viewer's views, on a `w` × `h` target: the canvas's size, or `size` offscreen);
   * null when no backend is ready yet (nothing drawn), else what the frame drew and cost.
   */
  render(draw: GpuDraw, size?: { w: number; h: number }): GpuFrame | null {
    const { renderer, canvas, mirror, host } = this;
    if (!renderer || !canvas || !mirror || !this.ready || this.disposed) return null;
    const t0 = performance.now();
    const w = size?.w ?? Math.max(1, host.canvas.clientWidth || host.canvas.width);
    const h = size?.h ?? Math.max(1, host.canvas.clientHeight || host.canvas.height);
    if (canvas.width !== w || canvas.height !== h) renderer.setSize(w, h, false);
    if (this.output === 'offscreen') {
      if (!this.target || this.target.width !== w || this.target.height !== h) {
        this.target?.dispose();
        // No depth buffer: the frame is drawn in three's frame-buffer target (with its own), and only its output
        // pass (a quad) comes here. (With one, clear() recurses in three 0.187: the output pass clears its depth.)
        this.target = new RenderTarget(w, h, { depthBuffer: false });
      }
      // The canvas path (three's output pass: sRGB, as on screen) into the target.
      renderer.setOutputRenderTarget(this.target);
    }
    renderer.setRenderTarget(null);
    renderer.info.reset();
    const camera = host.camera as THREE.PerspectiveCamera & { _reversedDepth?: boolean };
    const saved = { coordinateSystem: camera.coordinateSystem, reversedDepth: camera._reversedDepth };
    // The standard depth buffer: a projection the viewer's WebGLRenderer reversed is made standard again.
    if (saved.reversedDepth) {
      camera._reversedDepth = false;
      camera.updateProjectionMatrix?.();
    }
    try {
      draw(new GpuCells(renderer, h, mirror), w, h);
    } finally {
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      if (this.output === 'offscreen') renderer.setOutputRenderTarget(null);
      camera.coordinateSystem = saved.coordinateSystem;
      camera._reversedDepth = saved.reversedDepth;
      camera.updateProjectionMatrix?.();
    }
    // The WebGL canvas stays below for the input; it shows again when WebGPU mode is left.
    if (this.output === 'canvas') host.canvas.style.opacity = '0';
    this.frames += 1;
    canvas.dataset['frames'] = String(this.frames);
    const key = this.variantKey();
    if (this.output === 'canvas' && key !== this.shaderKey) {
      this.shaderKey = key;
      void this.readShader(renderer);
    }
    const { render, memory } = renderer.info;
    return {
      cpuMs: performance.now() - t0,
      // Not read in the first second of a presenting WebGPU backend: a device lost by presenting (headless
      // Chromium loses it) would fail the read-back, which three reports as a console error.
      gpuMs:
        this.output === 'canvas' && performance.now() - this.openedAt < 1000
          ? { ms: null, note: 'GPU time: waiting for the first timestamps' }
          : timestamps(renderer, (ms) => this.events.onGpuTime?.(ms)),
      triangles: render.triangles,
      programs: memory.programs,
    };
  }

  /** The last offscreen frame's pixels (RGBA8 sRGB, rows bottom-up as gl.readPixels gives them); null if none. */
  async read(): Promise<{ pixels: Uint8Array; w: number; h: number } | null> {
    const { renderer, target } = this;
    if (!renderer || !target || !this.ready) return null;
    const read = await readBack(renderer, target);
    return this.renderer === renderer ? read : null;
  }

  /** What the generated shader depends on: the compiled variant and the geometry. */
  private variantKey(): string {
    const m = this.material;
    return `${m.shading}|${m.lighting}|${m.celBands}|${m.output}|${m.normalMatrix}|${m.phongLights.length}|${this.host.mesh.geometry.uuid}`;
  }

  /** The node material's generated code as the running backend compiled it (a scene of the mesh alone). */
  private async readShader(renderer: WebGPURenderer) {
    const shader = await generatedShader(renderer, this.host, this.material);
    if (this.renderer === renderer && !this.disposed) this.events.onShader?.(shader);
  }

  /** Drops the renderer and its canvas (the WebGL canvas shows again). */
  private close() {
    this.ready = false;
    const { renderer, canvas } = this;
    this.renderer = null;
    this.canvas = null;
    // dispose() is async (it awaits init(): a failed init rejects it) and a lost device may refuse to free what
    // it no longer has: nothing to report either way.
    this.mirror?.dispose();
    this.mirror = null;
    this.target?.dispose();
    this.target = null;
    renderer?.dispose().catch(() => {});
    canvas?.remove();
    this.host.canvas.style.opacity = '';
  }

  dispose() {
    if (this.disposed) return;
    this.close();
    this.disposed = true;
    window.removeEventListener('unhandledrejection', this.onRejection);
    this.host.canvas.removeEventListener('webglcontextrestored', this.onHostRestored);
    this.material.dispose();
    this.events.onShader?.(null);
  }
}

/** Tries at a WebGL2 context after a lost WebGPU device, and the pause between two, ms. */
const RETRIES = 20;
const RETRY_MS = 250;
