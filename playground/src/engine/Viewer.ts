/**
 * The playground's renderer: owns the three.js objects, applies a {@link PlaygroundState} to them (only what
 * changed), and renders on demand — after a change, trackball/camera events, a resize — never in a loop.
 */
import * as THREE from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import type { DepthMode, LightState, PlaygroundState, SceneName, Vec3 } from '../state/schema';
import {
  activeDepth,
  applyImpostorMaterial,
  applyLight,
  applyMaterial,
  chooseDetail,
  createCamera,
  createImpostor,
  createLight,
  createMaterial,
  createMover,
  createOutlineMesh,
  createSphere,
  createTrackball,
  type Detail,
  depthParameters,
  getCameraEye,
  getCameraFrame,
  getTrackballRotation,
  type Light,
  type Material,
  type Mover,
  setCameraOrthographic,
  setCameraPerspective,
  setCameraView,
  setOutlineColor,
  setOutlineWidth,
  setTrackballMapping,
  setTrackballRadius,
  setTrackballRotation,
  setTrackballZoomLimits,
  sphereErrorPx,
  sphereErrorScalePx,
  sphereKey,
  type TrackballHandle,
  updateMaterialLights,
  type ViewCamera,
  variantKey,
} from './packages';
import { type ShaderCheck, ShaderProbe, type ShaderSource, tagLines } from './ShaderProbe';
import { createScene, type DemoScene } from './scenes';
import { type WebGPUEvents, WebGPUSwitch } from './webgpu/switch';

/** What the stats panel shows. */
export interface FrameStats {
  frames: number;
  /** CPU time of the last frame (submit + 1×1 readPixels), ms. */
  cpuMs: number;
  /** GPU time of a recent frame (EXT_disjoint_timer_query_webgl2), ms; null without the extension. */
  gpuMs: number | null;
  /** Triangles drawn in the frame (every cell of the compare view, outlines included; three's count). */
  triangles: number;
  /** Vertices drawn in the frame, summed like `triangles` over every draw of the sphere and its outline. */
  vertices: number;
  /** Bytes of the sphere's vertex and index buffers on the GPU (a buffer shared by several cells counts once). */
  bufferBytes: number;
  /** Cells drawn (4 in the compare view). */
  cells: number;
  programs: number;
  /** The depth mode the renderer runs. */
  depth: DepthMode;
  detail: Detail | null;
  /** The drawn sphere's silhouette error on screen, px (an upper bound); null when unknown. */
  errorPx: number | null;
}

/** Errors by state section (`camera`, `sphere`, `lights`, …); a section with an error keeps its last good value. */
export type SectionErrors = Partial<Record<string, string>>;

export interface ViewerEvents extends WebGPUEvents {
  /** The camera moved (movement keys) or the trackball turned; the new values for the state. */
  onView?: (view: {
    eye: Vec3;
    at: Vec3;
    up?: Vec3;
    zoom: number;
    rotation: [number, number, number, number];
  }) => void;
  /** The gizmo moved light `index` to `position`. */
  onLightMoved?: (index: number, position: Vec3) => void;
  /** Drawing failed (the message), or succeeded again (null). */
  onRenderError?: (message: string | null) => void;
  /** The compiled variant changed (its key and generated GLSL). */
  onVariant?: () => void;
  onStats?: (stats: FrameStats) => void;
  onContext?: (status: 'lost' | 'restored') => void;
  onFirstFrame?: (ms: number) => void;
}

/** The compare view's columns, as in the lecture's slide. */
export const COMPARE_COLUMNS = [
  { label: 'flat', shading: 'flat', cel: false },
  { label: 'Gouraud', shading: 'gouraud', cel: false },
  { label: 'Phong', shading: 'phong', cel: false },
  { label: 'cel', shading: 'phong', cel: true },
] as const;

/** Most GPU programs kept alive before the shading materials' cached variants are freed. */
export const PROGRAM_CAP = 24;

/** Cells of the compare view. */
export interface Layout {
  cols: number;
  rows: number;
}

/** The compare view in one row on wide canvases, 2 × 2 otherwise (cells as close to square as possible). */
export function compareLayout(width: number, height: number): Layout {
  return width / height >= 2 ? { cols: COMPARE_COLUMNS.length, rows: 1 } : { cols: 2, rows: 2 };
}

/**
 * Keys that turn the sphere (the keyboard's trackball), by `KeyboardEvent.code`: an axis of the camera's frame
 * and a sign. None is one of @shadelab/camera's MOVEMENT_KEYS (WASD, arrows, E/Q, PageUp/PageDown).
 */
export const TURN_KEYS: Readonly<Record<string, readonly [axis: 'u' | 'v', sign: 1 | -1]>> = {
  KeyJ: ['v', -1],
  KeyL: ['v', 1],
  KeyI: ['u', -1],
  KeyK: ['u', 1],
};

/** The turn keys as the page documents them. */
export const TURN_KEYS_TEXT = 'J/L, I/K';

/** One turn key press, radians (times the trackball's rotate speed). */
export const TURN_STEP = Math.PI / 36;

const _size = /* @__PURE__ */ new THREE.Vector2();
const _axis = /* @__PURE__ */ new THREE.Vector3();
const _turn = /* @__PURE__ */ new THREE.Quaternion();
const _pixel = /* @__PURE__ */ new Uint8Array(4);

export class Viewer {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly camera: ViewCamera;
  /** The trackball turns this group; the sphere mesh sits in it. */
  readonly pivot = new THREE.Group();
  readonly mesh: THREE.Mesh;
  readonly material: Material;
  readonly trackball: TrackballHandle;
  readonly mover: Mover;
  /** Moves the selected light's marker (three's TransformControls); the trackball pauses while it drags. */
  readonly gizmo: TransformControls;
  private gizmoLight: number | null = null;

  private readonly compareMaterials: Material[];
  private readonly outline: ReturnType<typeof createOutlineMesh>;
  /** The ray-cast sphere, drawn instead of the mesh when `sphere.render` is 'impostor' (single view). */
  private readonly impostor: THREE.Mesh;
  private lights: Light[] = [];
  private markers: THREE.Mesh[] = [];
  private readonly markerGeometry = new THREE.SphereGeometry(0.08, 12, 8);
  private readonly markerMaterial = new THREE.MeshBasicMaterial({ color: 0xffee88 });
  /** Sphere geometries of the current base and level, by {@link sphereKey}. */
  private geometries = new Map<string, THREE.BufferGeometry>();
  private sphere: { base: PlaygroundState['sphere']['base']; level: number; radius: number } | null = null;
  /** The picked scene when it is not the lecture's sphere (in the pivot, in place of the sphere). */
  private demo: { name: SceneName; scene: DemoScene } | null = null;
  private reportedVariant = '';
  private state: PlaygroundState | null = null;
  private errors: SectionErrors = {};
  private frames = 0;
  private readonly startedAt = performance.now();
  private firstFrameReported = false;
  private lastDetail: Detail | null = null;
  private gpuMs: number | null = null;
  private pendingQuery: WebGLQuery | null = null;
  private readonly timer: { TIME_ELAPSED_EXT: number; GPU_DISJOINT_EXT: number } | null;
  private readonly probe: ShaderProbe;
  private shaderOverride: (ShaderSource & { key: string }) | null = null;
  private generated: ShaderSource = { vertexShader: '', fragmentShader: '' };
  private scheduled = 0;
  private disposed = false;
  private contextLost = false;
  private renderError = false;
  /** WebGPU mode (the `renderer` field): three/webgpu on a canvas over this one, loaded on first use. */
  private readonly webgpu: WebGPUSwitch;

  /** The depth mode the renderer really runs (see {@link activeDepth}). */
  readonly depth: DepthMode;

  /** @param depth - The renderer's depth mode; a different one needs a new canvas and Viewer. */
  constructor(
    readonly canvas: HTMLCanvasElement,
    private readonly events: ViewerEvents = {},
    depth: DepthMode = 'standard',
  ) {
    this.renderer = new THREE.WebGLRenderer({
      canvas,
      antialias: false,
      preserveDrawingBuffer: true,
      ...depthParameters(depth),
    });
    this.depth = activeDepth(this.renderer);
    this.renderer.setPixelRatio(1);
    this.renderer.info.autoReset = false;
    this.scene.background = new THREE.Color(0x000000);
    this.camera = createCamera();
    this.material = createMaterial();
    this.compareMaterials = COMPARE_COLUMNS.map(() => createMaterial());
    this.mesh = new THREE.Mesh(new THREE.BufferGeometry(), this.material);
    this.outline = createOutlineMesh(this.mesh);
    this.outline.visible = false;
    this.impostor = createImpostor();
    this.impostor.visible = false;
    this.pivot.add(this.mesh, this.impostor);
    this.scene.add(this.pivot);
    // The gizmo listens first, so that grabbing a handle disables the trackball before it sees the press.
    this.gizmo = new TransformControls(this.camera, canvas);
    this.gizmo.setSize(0.8);
    this.gizmo.addEventListener('dragging-changed', this.onGizmoDragging);
    this.gizmo.addEventListener('change', this.onGizmoChange);
    this.gizmo.addEventListener('objectChange', this.onGizmoMove);
    this.gizmo.addEventListener('mouseUp', this.onGizmoDone);
    this.scene.add(this.gizmo.getHelper());
    this.trackball = createTrackball(this.pivot, this.camera);
    this.mover = createMover(this.camera);
    this.trackball.addEventListener('change', this.onTrackballChange);
    this.trackball.addEventListener('end', this.onTrackballEnd);
    this.mover.addEventListener('change', this.onMoverChange);
    this.mover.addEventListener('start', this.onMoverStart);
    this.mover.addEventListener('end', this.onMoverEnd);
    this.trackball.connect(canvas);
    this.mover.connect(canvas);
    this.timer = this.renderer.getContext().getExtension('EXT_disjoint_timer_query_webgl2');
    this.probe = new ShaderProbe(this.renderer);
    canvas.addEventListener('webglcontextlost', this.onContextLost);
    canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    canvas.addEventListener('keydown', this.onKeyDown);
    this.webgpu = new WebGPUSwitch(this, events);
  }

  /**
   * J/L turn the sphere about the camera's up axis v, I/K about its right axis u (as a drag right or down
   * would), {@link TURN_STEP} · rotate speed per press.
   */
  private readonly onKeyDown = (event: KeyboardEvent) => {
    const key = TURN_KEYS[event.code];
    if (!key || event.ctrlKey || event.metaKey || event.altKey || !this.state) return;
    event.preventDefault();
    // The camera's u or v axis in camera coordinates, through the trackball (as a drag): its rotation and
    // matrices stay those of the picture, and the next drag continues from here.
    _axis.set(key[0] === 'u' ? 1 : 0, key[0] === 'u' ? 0 : 1, 0);
    this.trackball.rotate(
      _turn.setFromAxisAngle(_axis, key[1] * TURN_STEP * this.state.trackball.rotateSpeed),
    );
    this.onViewEnd();
  };

  private readonly onGizmoDragging = (event: { value: unknown }) => {
    this.trackball.enabled = !event.value && !this.state?.camera.dragTurns;
    this.mover.enabled = !event.value;
  };
  private readonly onGizmoChange = () => this.requestRender();
  private readonly onGizmoMove = () => {
    const i = this.gizmoLight;
    if (i === null) return;
    this.lights[i]?.position.copy(this.markers[i]!.position);
    this.lights[i]?.updateMatrixWorld(true);
    this.requestRender();
  };
  private readonly onGizmoDone = () => {
    const i = this.gizmoLight;
    if (i === null || !this.markers[i]) return;
    const p = this.markers[i]!.position;
    this.events.onLightMoved?.(i, [p.x, p.y, p.z]);
  };

  /** Puts the move gizmo on light `index` (0-based), or removes it (null). */
  selectLight(index: number | null) {
    this.gizmoLight = index !== null && this.markers[index] ? index : null;
    if (this.gizmoLight === null) this.gizmo.detach();
    else this.gizmo.attach(this.markers[this.gizmoLight]!);
    this.requestRender();
  }

  private viewTimer = 0;
  private readonly onTrackballChange = () => {
    this.requestRender();
    // Wheel zoom has no drag to end: report the view once the wheel rests.
    window.clearTimeout(this.viewTimer);
    this.viewTimer = window.setTimeout(this.onViewEnd, 250);
  };
  /**
   * A drag ended: report the view, and with damping on keep the trackball spinning, one `update` per
   * animation frame until it rests (each step's `change` renders; the view is reported once it is quiet).
   */
  private spinFrame = 0;
  private readonly onTrackballEnd = () => {
    this.onViewEnd();
    if (!this.trackball.enableDamping || this.spinFrame !== 0) return;
    let last = performance.now();
    const step = (now: number) => {
      const dt = Math.min(0.1, Math.max(0, (now - last) / 1000));
      last = now;
      this.spinFrame = !this.disposed && this.trackball.update(dt) ? requestAnimationFrame(step) : 0;
    };
    this.spinFrame = requestAnimationFrame(step);
  };
  /** The movement keys translate the camera: `at` moves with the eye. */
  private moverDragging = false;
  private readonly onMoverStart = () => {
    this.moverDragging = true;
  };
  private readonly onMoverEnd = () => {
    this.moverDragging = false;
    this.reportCamera();
  };
  private readonly onMoverChange = () => {
    this.requestRender();
    if (!this.moverDragging) this.reportCamera();
  };
  /** The movement keys moved the camera or a drag turned its gaze: `at` stays at the same distance ahead. */
  private reportCamera() {
    if (!this.state) return;
    const { eye, w, v } = getCameraFrame(this.camera);
    const c = this.state.camera;
    const distance = Math.hypot(...c.eye.map((x, i) => x - c.at[i]!)) || 1;
    const at = eye.map((x, i) => x - w[i]! * distance) as Vec3;
    this.events.onView?.({
      eye,
      at,
      up: c.dragTurns ? v : c.up,
      zoom: c.zoom,
      rotation: getTrackballRotation(this.pivot),
    });
  }
  /** The trackball turned the sphere or zoomed (perspective: the eye moves towards `at`; orthographic: zoom). */
  private readonly onViewEnd = () => {
    window.clearTimeout(this.viewTimer);
    if (!this.state) return;
    const { eye, zoom } = getCameraEye(this.camera);
    const c = this.state.camera;
    const ortho = c.projection === 'orthographic';
    this.events.onView?.({
      eye: ortho ? c.eye : eye,
      at: c.at,
      zoom: ortho ? zoom : c.zoom,
      rotation: getTrackballRotation(this.pivot),
    });
  };
  private readonly onContextLost = () => {
    this.contextLost = true;
    this.pendingQuery = null;
    this.events.onContext?.('lost');
  };
  private readonly onContextRestored = () => {
    this.contextLost = false;
    this.events.onContext?.('restored');
    this.render();
  };

  /** Applies a state: rebuilds only what changed; returns an error message per section that was refused. */
  apply(state: PlaygroundState): SectionErrors {
    const previous = this.state;
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
    if (changed('lights')) attempt('lights', () => this.applyLights(state.lights));
    if (changed('material') || changed('lights')) {
      attempt('material', () => {
        applyMaterial(this.material, state.material, this.lights);
        COMPARE_COLUMNS.forEach((column, i) => {
          applyMaterial(
            this.compareMaterials[i]!,
            {
              ...state.material,
              shading: column.shading,
              celBands: column.cel ? Math.max(3, state.material.celBands) : 0,
            },
            this.lights,
          );
        });
        applyImpostorMaterial(this.impostor, state.material, this.lights);
        setOutlineWidth(this.outline, state.material.outlineWidth);
        setOutlineColor(this.outline, state.material.outlineColor);
        this.captureGenerated();
      });
    }
    this.state = state;
    if (changed('renderer')) this.webgpu.set(state.renderer === 'webgpu');
    if (changed('scene')) attempt('scene', () => this.applyScene(state.scene));
    if (this.demo && (changed('scene') || changed('material') || changed('lights'))) {
      attempt('material', () => {
        for (const part of this.demo!.scene.parts) {
          applyMaterial(part.material, state.material, this.lights);
          setOutlineWidth(part.outline, state.material.outlineWidth);
          setOutlineColor(part.outline, state.material.outlineColor);
        }
      });
    }
    attempt('model', () => {
      const [x, y, z] = state.model.scale;
      const r = state.sphere.radius;
      this.mesh.scale.set(x, y, z);
      // The impostor is a unit sphere: the radius is part of its scale (the mesh's is in its geometry).
      this.impostor.scale.set(x * r, y * r, z * r);
    });
    attempt('camera', () => this.applyCamera(state));
    attempt('sphere', () => this.applySphere(state));
    attempt('trackball', () => {
      setTrackballMapping(this.trackball, state.trackball.mapping);
      this.trackball.rotateSpeed = state.trackball.rotateSpeed;
      this.trackball.zoomSpeed = state.trackball.zoomSpeed;
      setTrackballZoomLimits(this.trackball, state.trackball.minZoom, state.trackball.maxZoom);
      this.trackball.dampingFactor = state.trackball.dampingFactor;
      this.trackball.enableDamping = state.trackball.damping;
      setTrackballRadius(this.trackball, state.trackball.radius);
      const current = getTrackballRotation(this.pivot);
      if (current.some((c, i) => Math.abs(c - state.trackball.rotation[i]!) > 1e-12)) {
        setTrackballRotation(this.trackball, state.trackball.rotation);
      }
    });
    attempt('camera movement', () => {
      this.mover.moveSpeed = state.camera.moveSpeed;
      this.mover.turnSpeed = state.camera.dragTurns ? state.camera.turnSpeed : 0;
      this.trackball.enabled = !state.camera.dragTurns && !this.gizmo.dragging;
    });
    this.errors = errors;
    this.requestRender();
    return errors;
  }

  /** Swaps the picked scene in (built anew) and the previous one out (disposed); the sphere is `null`. */
  private applyScene(name: SceneName) {
    if (this.demo?.name === name) return;
    const next = name === 'sphere' ? null : { name, scene: createScene(name) };
    this.leaveScene();
    this.demo = next;
    if (next) {
      this.pivot.add(next.scene.root);
      next.scene.enter?.(this.scene, this.renderer);
    }
  }

  private leaveScene() {
    if (!this.demo) return;
    this.demo.scene.leave?.(this.scene, this.renderer);
    this.pivot.remove(this.demo.scene.root);
    this.demo.scene.dispose();
    this.demo = null;
  }

  private applyLights(states: LightState[]) {
    while (this.lights.length < states.length) {
      const light = createLight();
      const marker = new THREE.Mesh(this.markerGeometry, this.markerMaterial);
      marker.name = `light marker ${this.lights.length + 1}`;
      this.scene.add(light, marker);
      this.lights.push(light);
      this.markers.push(marker);
    }
    while (this.lights.length > states.length) {
      const marker = this.markers.pop()!;
      if (this.gizmo.object === marker) this.selectLight(null);
      this.scene.remove(this.lights.pop()!, marker);
    }
    states.forEach((s, i) => {
      applyLight(this.lights[i]!, s);
      this.markers[i]!.position.set(...s.position);
    });
  }

  private applyCamera(state: PlaygroundState) {
    const c = state.camera;
    setCameraView(this.camera, c.eye, c.at, c.up);
    this.updateProjection(this.aspect(this.layout()));
  }

  private layout(): Layout {
    const w = Math.max(1, this.canvas.clientWidth || this.canvas.width);
    const h = Math.max(1, this.canvas.clientHeight || this.canvas.height);
    // WebGPU mode draws the single view only.
    return this.state?.view === 'compare' && !this.webgpu.active ? compareLayout(w, h) : { cols: 1, rows: 1 };
  }

  private aspect({ cols, rows }: Layout) {
    const w = Math.max(1, this.canvas.clientWidth || this.canvas.width);
    const h = Math.max(1, this.canvas.clientHeight || this.canvas.height);
    return w / cols / (h / rows);
  }

  private updateProjection(aspect: number) {
    const c = this.state!.camera;
    if (c.projection === 'perspective') {
      setCameraPerspective(this.camera, c.fovy, aspect, c.near, c.far);
    } else if (c.fitAspect) {
      const half = ((c.top - c.bottom) / 2) * aspect;
      const mid = (c.right + c.left) / 2;
      setCameraOrthographic(this.camera, mid + half, mid - half, c.top, c.bottom, c.near, c.far, c.zoom);
    } else {
      setCameraOrthographic(this.camera, c.right, c.left, c.top, c.bottom, c.near, c.far, c.zoom);
    }
  }

  private errorPx(): number | null {
    if (!this.sphere || !this.state || this.demo) return null;
    try {
      return sphereErrorPx(this.sphere.base, this.sphere.level, this.errorScalePx());
    } catch {
      return null;
    }
  }

  /** Pixels of silhouette error per unit of relative radial error (an upper bound), for automatic detail. */
  private errorScalePx(): number {
    const h = Math.max(1, this.canvas.clientHeight || this.canvas.height);
    const { rows } = this.layout();
    this.pivot.updateMatrixWorld(true);
    return sphereErrorScalePx(this.camera, this.mesh.matrixWorld, h / rows, this.state!.sphere.radius);
  }

  private applySphere(state: PlaygroundState) {
    let { base, level } = state.sphere;
    const { radius } = state.sphere;
    this.lastDetail = null;
    if (state.sphere.auto) {
      this.lastDetail = chooseDetail(this.errorScalePx(), state.sphere.maxErrorPx);
      ({ base, level } = this.lastDetail);
    }
    const shadings =
      state.view === 'compare' ? COMPARE_COLUMNS.map((c) => c.shading) : [state.material.shading];
    // Build first (a refused level throws here and the previous sphere stays), then swap.
    const wanted = new Map<string, THREE.BufferGeometry>();
    for (const shading of shadings) {
      const key = sphereKey(base, level, shading, radius);
      if (wanted.has(key)) continue;
      wanted.set(key, this.geometries.get(key) ?? createSphere(base, level, shading, radius));
    }
    for (const [key, geometry] of this.geometries) if (!wanted.has(key)) geometry.dispose();
    this.geometries = wanted;
    this.sphere = { base, level, radius };
    this.applyGeometry(state.material.shading);
  }

  /** Puts the sphere geometry for `shading` on the mesh (and its outline). */
  private applyGeometry(shading: PlaygroundState['material']['shading']) {
    if (!this.sphere) return;
    const { base, level, radius } = this.sphere;
    const geometry = this.geometries.get(sphereKey(base, level, shading, radius));
    if (!geometry) return;
    this.mesh.geometry = geometry;
    this.outline.geometry = geometry;
  }

  // ---- shader editing ------------------------------------------------------------------------------------

  private captureGenerated() {
    const key = variantKey(this.material);
    if (this.shaderOverride && this.shaderOverride.key !== key) this.clearShaderOverride();
    if (!this.shaderOverride) {
      this.generated = {
        vertexShader: this.material.vertexShader,
        fragmentShader: this.material.fragmentShader,
      };
    } else {
      this.material.vertexShader = this.shaderOverride.vertexShader;
      this.material.fragmentShader = this.shaderOverride.fragmentShader;
      this.material.needsUpdate = true;
    }
  }

  /** The current variant's key and its generated GLSL (before any edit). */
  getShaderSource(): ShaderSource & { key: string; defines: Record<string, unknown> } {
    return {
      ...this.generated,
      key: variantKey(this.material),
      defines: { ...(this.material.defines ?? {}) },
    };
  }

  /**
   * Compiles an edited program for the current variant off-screen first; only a program that compiles and
   * links replaces the rendered one, so a broken edit leaves the last good program rendering.
   */
  tryShader(edited: ShaderSource): ShaderCheck {
    const source = {
      vertexShader: tagLines(edited.vertexShader),
      fragmentShader: tagLines(edited.fragmentShader),
    };
    const check = this.probe.check(this.material, this.mesh, this.camera, source);
    if (check.ok) {
      this.material.vertexShader = source.vertexShader;
      this.material.fragmentShader = source.fragmentShader;
      this.material.needsUpdate = true;
      this.shaderOverride = { ...source, key: variantKey(this.material) };
      this.requestRender();
    }
    return check;
  }

  /** Drops the edit and goes back to the generated program. */
  clearShaderOverride() {
    if (!this.shaderOverride) return;
    this.shaderOverride = null;
    this.material.vertexShader = this.generated.vertexShader;
    this.material.fragmentShader = this.generated.fragmentShader;
    this.material.needsUpdate = true;
    this.requestRender();
  }

  // ---- rendering -----------------------------------------------------------------------------------------

  /** Renders at the next animation frame (coalesces many requests into one frame). */
  requestRender() {
    if (this.scheduled || this.disposed) return;
    this.scheduled = requestAnimationFrame(() => {
      this.scheduled = 0;
      this.render();
    });
  }

  /** Renders now. */
  render() {
    if (this.disposed || this.contextLost || !this.state) return;
    if (this.webgpu.active) return this.renderWebGPU();
    const t0 = performance.now();
    const { renderer, canvas } = this;
    const w = Math.max(1, canvas.clientWidth || canvas.width);
    const h = Math.max(1, canvas.clientHeight || canvas.height);
    renderer.getSize(_size);
    if (_size.x !== w || _size.y !== h) renderer.setSize(w, h, false);
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const query = this.beginGpuQuery(gl);
    renderer.info.reset();
    const layout = this.layout();
    try {
      this.updateProjection(this.aspect(layout));
    } catch {
      // The camera section already reported the error; keep the last good projection.
    }
    try {
      this.draw(w, h, layout);
      if (this.renderError) this.events.onRenderError?.(null);
      this.renderError = false;
    } catch (error) {
      // A throw from inside three (e.g. a material's onBeforeRender) must not stop the next frames.
      this.renderError = true;
      this.renderer.setScissorTest(false);
      this.mesh.material = this.material;
      this.events.onRenderError?.(error instanceof Error ? error.message : String(error));
    }
    this.endGpuQuery(gl, query);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, _pixel);
    const cpuMs = performance.now() - t0;
    this.countFrame();
    this.capPrograms();
    this.events.onStats?.(this.stats(cpuMs));
    // The material settles some defines while drawing (analytic sphere normals, attenuation).
    const key = variantKey(this.material);
    if (key !== this.reportedVariant) {
      this.reportedVariant = key;
      this.captureGenerated();
      this.events.onVariant?.();
    }
  }

  private countFrame() {
    this.frames += 1;
    this.canvas.dataset['frames'] = String(this.frames);
    if (!this.firstFrameReported) {
      this.firstFrameReported = true;
      const ms = performance.now();
      this.canvas.dataset['firstFrameMs'] = ms.toFixed(1);
      this.events.onFirstFrame?.(ms);
    }
  }

  /** WebGPU mode's frame (webgpu/WebGPUView.ts): the same camera and scene on WebGPURenderer. */
  private renderWebGPU() {
    try {
      this.updateProjection(this.aspect(this.layout()));
      if (this.webgpu.render()) this.countFrame();
      if (this.renderError) this.events.onRenderError?.(null);
      this.renderError = false;
    } catch (error) {
      this.renderError = true;
      this.events.onRenderError?.(error instanceof Error ? error.message : String(error));
    }
  }

  private draw(w: number, h: number, { cols, rows }: Layout) {
    const { renderer } = this;
    const state = this.state!;
    this.drawn = [];
    if (this.demo) {
      this.drawScene(this.demo.scene, w, h, { cols, rows });
      return;
    }
    this.outline.visible = state.material.outline && state.material.celBands > 0;
    const impostor = state.sphere.render === 'impostor';
    this.mesh.visible = !impostor || cols * rows > 1;
    this.impostor.visible = impostor && cols * rows === 1;
    if (cols * rows === 1) {
      this.mesh.material = this.material;
      this.applyGeometry(state.material.shading);
      this.drawn.push(
        impostor
          ? { geometry: this.impostor.geometry, outline: false }
          : { geometry: this.mesh.geometry, outline: this.outline.visible },
      );
      updateMaterialLights(this.material);
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      renderer.render(this.scene, this.camera);
    } else {
      renderer.setScissorTest(true);
      const cw = w / cols;
      const ch = h / rows;
      for (let i = 0; i < COMPARE_COLUMNS.length; i++) {
        const material = this.compareMaterials[i]!;
        this.mesh.material = material;
        this.applyGeometry(COMPARE_COLUMNS[i]!.shading);
        this.outline.visible = COMPARE_COLUMNS[i]!.cel && state.material.outline;
        this.drawn.push({ geometry: this.mesh.geometry, outline: this.outline.visible });
        updateMaterialLights(material);
        const col = i % cols;
        const row = Math.floor(i / cols);
        const x = Math.round(col * cw);
        const width = Math.round((col + 1) * cw) - x;
        const y = Math.round(h - (row + 1) * ch);
        const height = Math.round(h - row * ch) - y;
        renderer.setViewport(x, y, width, height);
        renderer.setScissor(x, y, width, height);
        renderer.render(this.scene, this.camera);
      }
      renderer.setScissorTest(false);
      this.mesh.material = this.material;
      this.applyGeometry(state.material.shading);
    }
  }

  /**
   * Draws a picked scene in place of the sphere: in one view with the panel's shading, or in the compare view's
   * cells with each column's shading and cel bands set on its materials for that cell (and put back after).
   */
  private drawScene(scene: DemoScene, w: number, h: number, { cols, rows }: Layout) {
    const { renderer } = this;
    const { material } = this.state!;
    this.mesh.visible = false;
    this.impostor.visible = false;
    this.outline.visible = false;
    const setShading = (
      shading: PlaygroundState['material']['shading'],
      celBands: number,
      outline: boolean,
    ) => {
      for (const part of scene.parts) {
        part.material.shading = shading;
        part.material.celBands = celBands;
        part.mesh.geometry = part.geometry(shading);
        part.outline.visible = outline;
      }
    };
    const drawnParts = () => {
      for (const part of scene.parts) {
        this.drawn.push({ geometry: part.mesh.geometry, outline: part.outline.visible });
      }
    };
    const outline = material.outline && material.celBands > 0;
    if (cols * rows === 1) {
      setShading(material.shading, material.celBands, outline);
      drawnParts();
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      renderer.render(this.scene, this.camera);
      return;
    }
    renderer.setScissorTest(true);
    const cw = w / cols;
    const ch = h / rows;
    try {
      COMPARE_COLUMNS.forEach((column, i) => {
        setShading(
          column.shading,
          column.cel ? Math.max(3, material.celBands) : 0,
          column.cel && material.outline,
        );
        drawnParts();
        const x = Math.round((i % cols) * cw);
        const width = Math.round(((i % cols) + 1) * cw) - x;
        const y = Math.round(h - (Math.floor(i / cols) + 1) * ch);
        const height = Math.round(h - Math.floor(i / cols) * ch) - y;
        renderer.setViewport(x, y, width, height);
        renderer.setScissor(x, y, width, height);
        renderer.render(this.scene, this.camera);
      });
    } finally {
      renderer.setScissorTest(false);
      setShading(material.shading, material.celBands, outline);
    }
  }

  /**
   * three keeps every program a material ever used until the material is disposed; a long session visiting
   * many variants would grow without bound. Past {@link PROGRAM_CAP}, free them all: the next frame
   * recompiles only the variants on screen.
   */
  private capPrograms() {
    if ((this.renderer.info.programs?.length ?? 0) <= PROGRAM_CAP) return;
    this.material.dispose();
    for (const material of this.compareMaterials) material.dispose();
    for (const part of this.demo?.scene.parts ?? []) {
      part.material.dispose();
      part.outline.material.dispose();
    }
  }

  /** The geometries of the last frame's sphere draws (one per cell), and whether each cell drew an outline. */
  private drawn: { geometry: THREE.BufferGeometry; outline: boolean }[] = [];

  private stats(cpuMs: number): FrameStats {
    const buffers = new Set<ArrayBufferLike | THREE.TypedArray>();
    let bufferBytes = 0;
    let vertices = 0;
    for (const { geometry, outline } of this.drawn) {
      const arrays = Object.values(geometry.attributes).map((a) => (a as THREE.BufferAttribute).array);
      if (geometry.index) arrays.push(geometry.index.array);
      for (const array of arrays) {
        if (buffers.has(array)) continue;
        buffers.add(array);
        bufferBytes += array.byteLength;
      }
      // The outline draws the same geometry again.
      vertices += (geometry.attributes['position']?.count ?? 0) * (outline ? 2 : 1);
    }
    const info = this.renderer.info;
    return {
      frames: this.frames,
      cpuMs,
      gpuMs: this.gpuMs,
      triangles: info.render.triangles,
      vertices,
      bufferBytes,
      cells: this.drawn.length,
      programs: info.programs?.length ?? 0,
      depth: this.depth,
      detail: this.lastDetail,
      errorPx: this.errorPx(),
    };
  }

  private beginGpuQuery(gl: WebGL2RenderingContext): WebGLQuery | null {
    if (!this.timer || this.pendingQuery) return null;
    const query = gl.createQuery();
    if (!query) return null;
    gl.beginQuery(this.timer.TIME_ELAPSED_EXT, query);
    return query;
  }

  private endGpuQuery(gl: WebGL2RenderingContext, query: WebGLQuery | null) {
    if (!query || !this.timer) return;
    gl.endQuery(this.timer.TIME_ELAPSED_EXT);
    this.pendingQuery = query;
    const poll = (tries: number) => {
      if (this.disposed || this.pendingQuery !== query) return;
      const available = gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE);
      const disjoint = gl.getParameter(this.timer!.GPU_DISJOINT_EXT);
      if (available && !disjoint) {
        this.gpuMs = gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6;
      }
      if (available || disjoint || tries > 100) {
        gl.deleteQuery(query);
        this.pendingQuery = null;
        if (available && this.state) this.events.onStats?.(this.stats(Number.NaN));
        return;
      }
      setTimeout(() => poll(tries + 1), 16);
    };
    setTimeout(() => poll(0), 0);
  }

  /** Frames rendered so far. */
  get frameCount() {
    return this.frames;
  }

  /** Milliseconds from navigation start to this viewer's construction. */
  get createdAt() {
    return this.startedAt;
  }

  /** The errors of the last {@link apply}. */
  get sectionErrors() {
    return this.errors;
  }

  dispose() {
    this.disposed = true;
    this.webgpu.dispose();
    if (this.scheduled) cancelAnimationFrame(this.scheduled);
    this.canvas.removeEventListener('webglcontextlost', this.onContextLost);
    this.canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.canvas.removeEventListener('keydown', this.onKeyDown);
    this.trackball.removeEventListener('change', this.onTrackballChange);
    this.trackball.removeEventListener('end', this.onTrackballEnd);
    cancelAnimationFrame(this.spinFrame);
    this.mover.removeEventListener('change', this.onMoverChange);
    this.mover.removeEventListener('start', this.onMoverStart);
    this.mover.removeEventListener('end', this.onMoverEnd);
    this.gizmo.removeEventListener('dragging-changed', this.onGizmoDragging);
    this.gizmo.removeEventListener('change', this.onGizmoChange);
    this.gizmo.removeEventListener('objectChange', this.onGizmoMove);
    this.gizmo.removeEventListener('mouseUp', this.onGizmoDone);
    this.gizmo.dispose();
    this.trackball.dispose();
    this.mover.dispose();
    this.probe.dispose();
    this.leaveScene();
    window.clearTimeout(this.viewTimer);
    for (const geometry of this.geometries.values()) geometry.dispose();
    this.markerGeometry.dispose();
    this.markerMaterial.dispose();
    this.material.dispose();
    for (const m of this.compareMaterials) m.dispose();
    (this.outline.material as THREE.Material).dispose();
    this.impostor.geometry.dispose();
    (this.impostor.material as THREE.Material).dispose();
    this.renderer.dispose();
  }
}
