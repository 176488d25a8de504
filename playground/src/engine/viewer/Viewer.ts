/**
 * The playground's renderer: owns the three.js objects, applies a {@link PlaygroundState} to them (only what
 * changed), and renders on demand — after a change, trackball/camera events, a resize, a damped spin's step —
 * never in a loop. Each frame is React Three Fiber's ({@link SceneRoot.frame}).
 *
 * Its parts: `sphere.ts` (the lecture's sphere), `pickedScene.ts` (the scene picker's scene), `lightRig.ts` (the
 * lights and their gizmo), `input.ts` (trackball and keys), `applyState.ts` (state sections onto the packages'
 * objects), `layout.ts` (the compare view's cells), `stats.ts` and `gpuTimer.ts` (the stats panel),
 * `shaderEditing.ts` (the GLSL editor), and `../webgpu/` (WebGPU mode).
 */
import { Camera, CameraMovement, depthModeOf } from '@shadelab/camera';
import type { ShadingMaterial } from '@shadelab/material';
import type { Trackball } from '@shadelab/trackball';
import type * as THREE from 'three';
import type { DepthMode, PlaygroundState } from '../../state/schema';
import type { ShaderCheck, ShaderSource } from '../ShaderProbe';
import type { DemoScene } from '../scenes';
import { WebGPUSwitch } from '../webgpu/switch';
import { applyMovement, applyProjection, applyTrackball } from './applyState';
import { GpuTimer } from './gpuTimer';
import type { ViewerEvents, ViewerHost } from './host';
import { ViewInput } from './input';
import { type CellRenderer, canvasSize, cellAspect, fitToCanvas, type Layout, viewLayout } from './layout';
import { LightRig } from './lightRig';
import { ParityFrames } from './parity';
import { PickedScene } from './pickedScene';
import { SceneRoot } from './sceneRoot';
import { ShaderEditing } from './shaderEditing';
import { cappedErrorScalePx, LectureSphere } from './sphere';
import { capPrograms, FrameCounter, type FrameStats, WebGPUStats } from './stats';

/** Errors by state section (`camera`, `sphere`, `lights`, …); a section with an error keeps its last good value. */
export type SectionErrors = Partial<Record<string, string>>;

/** Most GPU programs kept alive before the shading materials' cached variants are freed. */
export const PROGRAM_CAP = 24;

const _pixel = /* @__PURE__ */ new Uint8Array(4);

export class Viewer implements ViewerHost {
  readonly renderer: THREE.WebGLRenderer;
  /** The depth mode the renderer really runs (without EXT_clip_control, 'reversed' falls back). */
  readonly depth: DepthMode;
  /** R3F's scene (its background black, as the lecture's). */
  readonly scene: THREE.Scene;
  readonly camera: Camera;
  /** The trackball turns this group; the sphere mesh sits in it. */
  readonly pivot: THREE.Group;
  readonly trackball: Trackball;
  readonly mover: CameraMovement;
  /** The lecture's sphere mesh (WebGPU mode draws it too) and its material (the shader editor's). */
  readonly mesh: THREE.Mesh;
  readonly material: ShadingMaterial;
  /** React Three Fiber's root: it made the renderer and mounted the sphere's JSX (sceneRoot.tsx). */
  private readonly root: SceneRoot;
  private readonly sphere: LectureSphere;
  private readonly picked: PickedScene;
  private readonly lightRig: LightRig;
  private readonly input: ViewInput;
  private readonly shader: ShaderEditing;
  private readonly gpuTimer: GpuTimer;
  private readonly frames: FrameCounter;
  /** WebGPU mode (the `renderer` field) or the parity view's WebGPU half: three/webgpu, loaded on first use. */
  private readonly webgpu: WebGPUSwitch;
  private readonly parity: ParityFrames;
  private readonly gpuStats: WebGPUStats;
  private applied: PlaygroundState | null = null;
  /** The pending animation frame of {@link requestRender}; 0 when none. */
  private scheduled = 0;
  private disposed = false;
  private contextLost = false;
  private renderError = false;

  /** @param depth - The renderer's depth mode; a different one needs a new canvas and Viewer. */
  constructor(
    readonly canvas: HTMLCanvasElement,
    private readonly events: ViewerEvents = {},
    depth: DepthMode = 'standard',
  ) {
    this.camera = new Camera({ fovy: 90, aspect: 1, near: 0.1, far: 10 });
    this.root = new SceneRoot(canvas, depth, this.camera);
    this.renderer = this.root.renderer;
    this.scene = this.root.scene;
    this.depth = depthModeOf(this.renderer);
    this.renderer.info.autoReset = false;
    // The gizmo listens first, so that grabbing a handle disables the trackball before it sees the press.
    this.lightRig = new LightRig(this, events);
    const sphere = this.root.mountLectureSphere();
    this.pivot = sphere.pivot;
    this.trackball = sphere.trackball;
    this.sphere = new LectureSphere(sphere);
    this.mesh = this.sphere.mesh;
    this.material = this.sphere.material;
    this.mover = new CameraMovement(this.camera, null, { turnSpeed: 0 });
    this.input = new ViewInput(this, events);
    this.gpuTimer = new GpuTimer(this.renderer.getContext() as WebGL2RenderingContext, this.onGpuTime);
    this.shader = new ShaderEditing(this);
    const mount = (picked: DemoScene | null) => this.root.setLectureSphere({ picked });
    this.picked = new PickedScene(mount, this.scene, this.renderer, () => this.requestRender());
    this.frames = new FrameCounter(canvas, (ms) => this.events.onFirstFrame?.(ms));
    canvas.addEventListener('webglcontextlost', this.onContextLost);
    canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    this.gpuStats = new WebGPUStats(this.frames, events.onStats);
    this.webgpu = new WebGPUSwitch(this, { ...events, onGpuTime: this.gpuStats.gpuTime });
    this.parity = new ParityFrames(this.renderer, this.webgpu, this.drawViews, (r) => events.onParity?.(r));
  }

  /** The state applied last; null before the first. */
  get state(): PlaygroundState | null {
    return this.applied;
  }

  /** Applies a state: rebuilds only what changed; returns an error message per section that was refused. */
  apply(state: PlaygroundState): SectionErrors {
    const previous = this.applied;
    const errors: SectionErrors = {};
    const changed = (key: keyof PlaygroundState) =>
      !previous || JSON.stringify(previous[key]) !== JSON.stringify(state[key]);
    const attempt = (section: string, run: () => void) => {
      try {
        run();
      } catch (error) {
        errors[section] = error instanceof Error ? error.message : String(error);
      }
    };
    const { lights } = this.lightRig;
    if (changed('lights')) attempt('lights', () => this.lightRig.apply(state.lights));
    if (changed('material') || changed('lights')) {
      attempt('material', () => {
        this.sphere.applyMaterial(state.material, lights);
        this.shader.capture();
      });
    }
    this.applied = state;
    this.webgpu.set(state.view === 'parity' ? 'offscreen' : state.renderer === 'webgpu' ? 'canvas' : null);
    if (this.webgpu.output !== 'canvas') this.gpuStats.reset();
    if (changed('scene')) attempt('scene', () => this.picked.pick(state.scene));
    if (this.picked.active) this.sphere.hide();
    if (this.picked.active && (changed('scene') || changed('material') || changed('lights'))) {
      attempt('material', () => this.picked.applyMaterial(state.material, lights));
    }
    this.root.setLectureSphere({ scale: state.model.scale, radius: state.sphere.radius });
    attempt('camera', () => {
      const c = state.camera;
      this.camera.lookAt(c.eye, c.at, c.up);
      applyProjection(this.camera, c, cellAspect(this.canvas, this.layout()));
    });
    attempt('sphere', () => this.sphere.applySphere(state, this.errorScalePx));
    attempt('trackball', () => applyTrackball(this.trackball, state.trackball));
    attempt('camera movement', () => applyMovement(this, state.camera, this.lightRig.gizmo.dragging));
    this.requestRender();
    return errors;
  }

  /** The user's model (`scene: 'model'`), built by the app from the file; null frees it (pickedScene.ts). */
  setModel = (model: DemoScene | null): void => this.picked.setModel(model);
  /** The model shown or waiting to be shown; null when there is none (freed when another scene is picked). */
  model = (): DemoScene | null => this.picked.modelScene;
  /** Puts the move gizmo on light `index` (0-based), or removes it (null). */
  selectLight = (index: number | null) => this.lightRig.select(index);
  /** The current variant's key and its generated GLSL (before any edit). */
  getShaderSource = (): ShaderSource & { key: string; defines: Record<string, unknown> } =>
    this.shader.source();
  /** Compiles an edited program off-screen first; only one that compiles and links replaces the rendered one. */
  tryShader = (edited: ShaderSource): ShaderCheck => this.shader.tryEdit(edited);
  /** Drops the edit and goes back to the generated program. */
  clearShaderOverride = () => this.shader.clear();

  /** Renders at the next animation frame (coalesces many requests into one frame; see FrameCounter.pending). */
  requestRender() {
    if (this.scheduled || this.disposed) return;
    this.frames.pending(true);
    this.scheduled = requestAnimationFrame(() => {
      this.scheduled = 0;
      this.frames.pending(false);
      this.render();
    });
  }

  /**
   * Renders now: one R3F frame ({@link SceneRoot.frame}). Its `useFrame`s run first (`useTrackball` steps a
   * damped spin, whose `change` asks for the next frame), then it draws with WebGL or, in WebGPU mode, WebGPU.
   */
  render() {
    if (this.disposed || this.contextLost || !this.applied) return;
    this.root.frame(this.webgpu.output === 'canvas' ? this.drawWebGPU : this.drawWebGL);
  }

  /** A WebGL frame: the view drawn, timed on the CPU and GPU, counted, its stats reported. */
  private readonly drawWebGL = () => {
    const t0 = performance.now();
    const { renderer, canvas } = this;
    const { w, h } = fitToCanvas(renderer, canvas);
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const query = this.gpuTimer.begin();
    renderer.info.reset();
    const layout = this.layout();
    try {
      applyProjection(this.camera, this.applied!.camera, cellAspect(canvas, layout));
    } catch {
      // The camera section already reported the error; keep the last good projection.
    }
    try {
      if (this.applied!.view === 'parity') this.parity.frame(w, h, layout);
      else this.drawViews(renderer, w, h, layout);
      if (this.renderError) this.events.onRenderError?.(null);
      this.renderError = false;
    } catch (error) {
      // A throw from inside three (e.g. a material's onBeforeRender) must not stop the next frames.
      this.renderError = true;
      this.renderer.setScissorTest(false);
      this.events.onRenderError?.(error instanceof Error ? error.message : String(error));
    }
    this.gpuTimer.end(query);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, _pixel);
    const cpuMs = performance.now() - t0;
    this.frames.count();
    capPrograms(this.renderer, PROGRAM_CAP, [this.sphere, this.picked]);
    this.events.onStats?.(this.stats(cpuMs));
    // The material settles some defines while drawing (analytic sphere normals, attenuation).
    if (this.shader.variantChanged()) this.events.onVariant?.();
  };

  /**
   * Draws the picked scene (the sphere is hidden then) or the sphere, in `layout`'s cells of a `w` × `h` canvas,
   * with `renderer` (WebGL's, WebGPU mode's, a parity cell's); each draw recorded.
   */
  private readonly drawViews = (renderer: CellRenderer, w: number, h: number, layout: Layout) => {
    const [state, cells] = [this.applied!, { layout, w, h }];
    this.frames.drawn = [];
    if (this.picked.active) this.picked.draw(this.camera, state.material, cells, this.frames.drawn, renderer);
    else this.sphere.draw(renderer, this.scene, this.camera, state, cells, this.frames.drawn);
  };

  /** WebGPU mode's frame (webgpu/WebGPUView.ts): the same views, camera and scene on WebGPURenderer. */
  private readonly drawWebGPU = () => {
    try {
      const layout = this.layout();
      applyProjection(this.camera, this.applied!.camera, cellAspect(this.canvas, layout));
      const frame = this.webgpu.render((r, w, h) => this.drawViews(r, w, h, layout));
      this.gpuStats.frame(frame, this.extras(0, null));
      if (this.renderError) this.events.onRenderError?.(null);
      this.renderError = false;
    } catch (error) {
      this.renderError = true;
      this.events.onRenderError?.(error instanceof Error ? error.message : String(error));
    }
  };

  /** The cells drawn: the compare view's and the parity view's (WebGL, WebGPU, difference, numbers), or one. */
  private layout(): Layout {
    return viewLayout(this.canvas, this.applied?.view);
  }

  /** Pixels of silhouette error per unit of relative radial error (an upper bound), for automatic detail. */
  private readonly errorScalePx = (): number => {
    const { h } = canvasSize(this.canvas);
    const { rows } = this.layout();
    this.pivot.updateMatrixWorld(true);
    return cappedErrorScalePx(this.camera, this.mesh.matrixWorld, h / rows, this.applied!.sphere.radius);
  };

  private extras(cpuMs: number, gpuMs: number | null) {
    const errorPx = this.applied && !this.picked.active ? this.sphere.errorPx(this.errorScalePx) : null;
    return { cpuMs, gpuMs, depth: this.depth, detail: this.sphere.detail, errorPx };
  }

  private stats(cpuMs: number): FrameStats {
    return this.frames.stats(this.renderer.info, this.extras(cpuMs, this.gpuTimer.gpuMs));
  }

  private readonly onGpuTime = () => this.applied && this.events.onStats?.(this.stats(Number.NaN));
  private readonly onContextLost = () => {
    this.contextLost = true;
    this.events.onContext?.('lost');
  };
  private readonly onContextRestored = () => {
    this.contextLost = false;
    this.events.onContext?.('restored');
    this.render();
  };

  dispose() {
    this.disposed = true;
    this.webgpu.dispose();
    if (this.scheduled) cancelAnimationFrame(this.scheduled);
    this.canvas.removeEventListener('webglcontextlost', this.onContextLost);
    this.canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.input.dispose();
    this.lightRig.dispose();
    this.trackball.dispose();
    this.mover.dispose();
    this.gpuTimer.dispose();
    this.shader.dispose();
    this.picked.leave();
    this.sphere.dispose();
    this.root.unmount();
  }
}
