/**
 * WebGPU mode's renderer: three's WebGPURenderer on a canvas of its own laid over the viewer's WebGL canvas (which
 * keeps the pointer and keyboard input: the trackball, the camera keys and the gizmo work unchanged), drawing the
 * viewer's scene and camera with the mesh's ShadingMaterial mirrored into a ShadingNodeMaterial. Loaded only by
 * dynamic import (switch.ts), so that WebGL mode never loads three/webgpu.
 *
 * The WebGPU backend runs when `navigator.gpu` gives an adapter, else the WebGL2 backend (`forceWebGL`). A lost
 * WebGPU device (a canvas presented headless loses it) falls back to the WebGL2 backend on a fresh canvas (a
 * canvas keeps its first context type) and says so.
 */
import { ShadingMaterial } from '@shadelab/material';
import { provokingVertexOf, ShadingNodeMaterial } from '@shadelab/material/webgpu';
import * as THREE from 'three';
import { WebGPURenderer } from 'three/webgpu';
import { drawnAsWebGPU, flatFor, mirrorMaterial } from './scene';
import type { FallbackReason, GeneratedShader, WebGPUStatus } from './status';

/** What the view needs of the viewer: its canvas (the overlay's size and place), scene, camera and mesh. */
export interface GpuHost {
  readonly canvas: HTMLCanvasElement;
  readonly scene: THREE.Scene;
  readonly camera: THREE.Camera;
  /** The lecture's sphere: drawn with the node material (its siblings, the impostor and a picked scene, hidden). */
  readonly mesh: THREE.Mesh;
  requestRender(): void;
}

/** What WebGPU mode reports to the app. */
export interface WebGPUEvents {
  /** The backend that runs (and why), or null when WebGPU mode is left. */
  onStatus?: (status: WebGPUStatus | null) => void;
  /** The mesh material's generated shader, after a variant change or a backend change. */
  onShader?: (shader: GeneratedShader | null) => void;
}

type Backend = {
  isWebGPUBackend?: boolean;
  device?: { lost: Promise<{ message: string; reason: string | null }> };
};
type GpuNavigator = { gpu?: { requestAdapter(): Promise<unknown> } };

export class WebGPUView {
  private renderer: WebGPURenderer | null = null;
  private canvas: HTMLCanvasElement | null = null;
  private readonly material = new ShadingNodeMaterial();
  private ready = false;
  private disposed = false;
  private frames = 0;
  private shaderKey = '';

  constructor(
    private readonly host: GpuHost,
    private readonly events: WebGPUEvents,
  ) {
    window.addEventListener('unhandledrejection', this.onRejection);
    host.canvas.addEventListener('webglcontextrestored', this.onHostRestored);
    void this.start();
  }

  /** Opens the WebGPU backend where an adapter exists, else the WebGL2 backend (and says why). */
  private async start(): Promise<void> {
    const gpu = (navigator as GpuNavigator).gpu;
    let reason: FallbackReason | null = gpu ? null : 'no-webgpu';
    if (gpu) {
      try {
        if ((await gpu.requestAdapter()) === null) reason = 'no-adapter';
      } catch {
        reason = 'no-adapter';
      }
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
    this.host.canvas.after(canvas);
    this.canvas = canvas;
    const renderer = new WebGPURenderer({ canvas, antialias: false, forceWebGL: reason !== null });
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
    await this.readShader(renderer);
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

  /** Draws the viewer's scene; false when no backend is ready yet (nothing drawn). */
  render(): boolean {
    const { renderer, canvas } = this;
    if (!renderer || !canvas || !this.ready || this.disposed) return false;
    const { host } = this;
    const w = Math.max(1, host.canvas.clientWidth || host.canvas.width);
    const h = Math.max(1, host.canvas.clientHeight || host.canvas.height);
    if (canvas.width !== w || canvas.height !== h) renderer.setSize(w, h, false);
    const source = host.mesh.material;
    if (source instanceof ShadingMaterial) mirrorMaterial(source, this.material);
    drawnAsWebGPU(host, this.material, provokingVertexOf(renderer), () =>
      renderer.render(host.scene, host.camera),
    );
    // The WebGL canvas stays below for the input; it shows again when WebGPU mode is left.
    host.canvas.style.opacity = '0';
    this.frames += 1;
    canvas.dataset['frames'] = String(this.frames);
    const key = this.variantKey();
    if (key !== this.shaderKey) {
      this.shaderKey = key;
      void this.readShader(renderer);
    }
    return true;
  }

  /** What the generated shader depends on: the compiled variant and the geometry. */
  private variantKey(): string {
    const m = this.material;
    return `${m.shading}|${m.lighting}|${m.celBands}|${m.phongLights.length}|${this.host.mesh.geometry.uuid}`;
  }

  /** The node material's generated code as the running backend compiled it (a scene of the mesh alone). */
  private async readShader(renderer: WebGPURenderer) {
    const { mesh } = this.host;
    const probe = new THREE.Mesh(flatFor(mesh.geometry, provokingVertexOf(renderer)), this.material);
    probe.matrixWorld.copy(mesh.matrixWorld);
    probe.matrixAutoUpdate = false;
    probe.matrixWorldAutoUpdate = false;
    const scene = new THREE.Scene();
    scene.add(probe);
    const camera = this.host.camera;
    const saved = camera.coordinateSystem;
    const language = (renderer.backend as Backend).isWebGPUBackend === true ? 'WGSL' : 'GLSL';
    try {
      const { vertexShader, fragmentShader } = await renderer.debug.getShaderAsync(scene, camera, probe);
      if (this.renderer !== renderer || this.disposed) return;
      this.events.onShader?.({
        language,
        vertexShader: vertexShader ?? '',
        fragmentShader: fragmentShader ?? '',
      });
    } catch (error) {
      if (this.renderer === renderer && !this.disposed) {
        const text = `// The generated shader could not be read: ${error instanceof Error ? error.message : error}`;
        this.events.onShader?.({ language, vertexShader: text, fragmentShader: text });
      }
    } finally {
      camera.coordinateSystem = saved;
      (camera as THREE.PerspectiveCamera).updateProjectionMatrix?.();
      scene.remove(probe);
    }
  }

  /** Drops the renderer and its canvas (the WebGL canvas shows again). */
  private close() {
    this.ready = false;
    const { renderer, canvas } = this;
    this.renderer = null;
    this.canvas = null;
    // dispose() is async (it awaits init(): a failed init rejects it) and a lost device may refuse to free what
    // it no longer has: nothing to report either way.
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
