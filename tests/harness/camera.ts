// Bare page for tests/camera.spec.ts and bench/camera-depth.bench.mjs.
// 1. A small scene seen through @shadelab/camera's Camera, moved by CameraMovement (keys/drag on the canvas);
//    renders only on `change`, and reports the frame on the canvas's data attributes.
// 2. `window.cameraDepth`: renders two overlapping quads (red near, green farther, drawn last) in each depth mode
//    and reads the centre pixel, to measure which separations stay in the right order; the quads are drawn with
//    three's MeshBasicMaterial, @shadelab/material's ShadingMaterial, or one of each.
// 3. `window.cameraCompare`: a MeshPhongMaterial sphere with a specular highlight rendered through Camera and
//    through three's own OrthographicCamera / PerspectiveCamera with the same parameters, pixels compared.
import {
  Camera,
  CameraMovement,
  type DepthMode,
  type DepthModeRequest,
  depthBufferParameters,
  depthModeOf,
} from '@shadelab/camera';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import {
  AmbientLight,
  BoxGeometry,
  Color,
  DepthTexture,
  DirectionalLight,
  FloatType,
  GridHelper,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshNormalMaterial,
  MeshPhongMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  PlaneGeometry,
  Scene,
  SphereGeometry,
  Camera as ThreeCamera,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { readCanvas } from './lib/pixels';

// ── 1. the movement scene ────────────────────────────────────────────────────────────────────────────────────
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(400, 300, false);

const scene = new Scene();
scene.background = new Color(0x202020);
const colours = [0xd04040, 0x40b040, 0x4060d0, 0xd0b040, 0xb040d0];
colours.forEach((colour, i) => {
  const box = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial({ color: colour }));
  box.position.set((i - 2) * 1.6, 0.5, -((i * 3) % 5));
  scene.add(box);
});
scene.add(new Mesh(new BoxGeometry(0.6, 0.6, 0.6), new MeshNormalMaterial()));
scene.add(new GridHelper(20, 20, 0x888888, 0x444444));

const camera = new Camera({ fovy: 50, aspect: 400 / 300, near: 0.1, far: 100 });
camera.lookAt([0, 2, 6], [0, 0.5, 0], [0, 1, 0]);
const movement = new CameraMovement(camera, canvas, { moveSpeed: 0.5, turnSpeed: 0.005 });

let frames = 0;
function render(): void {
  renderer.render(scene, camera);
  frames++;
  const { e, w } = camera.getFrame();
  canvas.dataset.frames = String(frames);
  canvas.dataset.eye = JSON.stringify(e.toArray());
  canvas.dataset.w = JSON.stringify(w.toArray());
}
movement.addEventListener('change', render);
render();

// ── 2. depth-order probe ─────────────────────────────────────────────────────────────────────────────────────
/**
 * Depth modes probed: every DepthModeRequest into the canvas's default depth buffer, and standard/reversed into a
 * render target with an explicit 32-bit float depth texture (`-float`). (Headless Chromium's SwiftShader stores
 * every depth format, the canvas's 24-bit one included, as 32-bit float; a 24-bit fixed-point depth texture
 * measured the same as the float one, so it is not probed.)
 */
type ProbeMode = DepthModeRequest | `${'standard' | 'reversed'}-float`;

interface Probe {
  renderer: WebGLRenderer;
  target: WebGLRenderTarget | null;
  active: DepthMode;
}

const SIZE = 8;
const probes = new Map<ProbeMode, Probe>();
const depthScene = new Scene();
depthScene.background = new Color(0x000000);
const quad = new PlaneGeometry(1, 1);
const nearQuad = new Mesh<PlaneGeometry, Material>(quad, new MeshBasicMaterial({ color: 0xff0000 }));
const farQuad = new Mesh<PlaneGeometry, Material>(quad, new MeshBasicMaterial({ color: 0x00ff00 }));
nearQuad.renderOrder = 0;
farQuad.renderOrder = 1; // the farther quad is drawn last: only the depth test can keep it hidden
depthScene.add(nearQuad, farQuad);
// The same colours from ShadingMaterial: ambient only (ka · Ia), unlit otherwise.
const ambientLight = new PhongLight({ ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0] });
depthScene.add(ambientLight);
const shaded = (ka: [number, number, number]) =>
  new ShadingMaterial({ ka, kd: [0, 0, 0], ks: [0, 0, 0], lights: [ambientLight] });
const quadMaterials = {
  basic: [nearQuad.material, farQuad.material],
  shading: [shaded([1, 0, 0]), shaded([0, 1, 0])],
};
/** Which materials draw the near and the far quad. */
type QuadMaterials = 'basic' | 'shading' | 'shading-near' | 'shading-far';
function setQuadMaterials(which: QuadMaterials): void {
  nearQuad.material =
    quadMaterials[which === 'shading' || which === 'shading-near' ? 'shading' : 'basic'][0]!;
  farQuad.material = quadMaterials[which === 'shading' || which === 'shading-far' ? 'shading' : 'basic'][1]!;
}
const depthCamera = new Camera({ fovy: 60, aspect: 1, near: 0.01, far: 100 });
const pixel = new Uint8Array(4);

function probe(mode: ProbeMode): Probe {
  let p = probes.get(mode);
  if (p) return p;
  const float = mode.endsWith('-float');
  const base = (float ? mode.slice(0, -'-float'.length) : mode) as DepthModeRequest;
  const c = document.createElement('canvas');
  c.width = SIZE;
  c.height = SIZE;
  const r = new WebGLRenderer({ canvas: c, antialias: false, ...depthBufferParameters(base) });
  r.setPixelRatio(1);
  r.setSize(SIZE, SIZE, false);
  r.sortObjects = false;
  let target: WebGLRenderTarget | null = null;
  if (float) {
    target = new WebGLRenderTarget(SIZE, SIZE, {
      depthBuffer: true,
      depthTexture: new DepthTexture(SIZE, SIZE, FloatType),
    });
  }
  p = { renderer: r, target, active: depthModeOf(r) };
  probes.set(mode, p);
  return p;
}

/** Which colour wins the centre: 'near' (order kept), 'far' (order lost) or 'none'. */
function centre(p: Probe): 'near' | 'far' | 'none' {
  const { renderer: r, target } = p;
  // One camera serves every renderer: a reversed-depth renderer switches reversedDepth on and never off.
  depthCamera.reversedDepth = p.active === 'reversed';
  r.setRenderTarget(target);
  r.render(depthScene, depthCamera);
  if (target) r.readRenderTargetPixels(target, SIZE / 2, SIZE / 2, 1, 1, pixel);
  else
    r.getContext().readPixels(
      SIZE / 2,
      SIZE / 2,
      1,
      1,
      WebGL2RenderingContext.RGBA,
      WebGL2RenderingContext.UNSIGNED_BYTE,
      pixel,
    );
  r.setRenderTarget(null);
  if (pixel[0] > 128 && pixel[1] < 64) return 'near';
  if (pixel[1] > 128 && pixel[0] < 64) return 'far';
  return 'none';
}

function place(near: number, far: number, z: number, dzRel: number): void {
  depthCamera.setPerspective(60, 1, near, far);
  // Quads facing the camera (which looks down −z from the origin), 4× wider than the view at their distance.
  nearQuad.position.set(0, 0, -z);
  nearQuad.scale.setScalar(4 * z);
  const zf = z * (1 + dzRel);
  farQuad.position.set(0, 0, -zf);
  farQuad.scale.setScalar(4 * zf);
}

/** Does `mode` draw the red quad at distance z in front of the green one at z·(1 + dzRel)? */
function kept(
  mode: ProbeMode,
  near: number,
  far: number,
  z: number,
  dzRel: number,
  materials: QuadMaterials = 'basic',
): 'near' | 'far' | 'none' {
  place(near, far, z, dzRel);
  setQuadMaterials(materials);
  try {
    return centre(probe(mode));
  } finally {
    setQuadMaterials('basic');
  }
}

/**
 * Smallest Δz/z on a log grid (`perDecade` steps per decade, from 1 down to 1e-9) such that the nearer quad wins
 * at it and at every larger grid separation (rounding makes the order flicker just above the limit: this is the
 * limit below which order is no longer guaranteed). `Infinity` when even Δz/z = 1 is lost, 1e-9 when nothing is
 * lost, null when the case is invalid (z outside (near, far/2), or the far quad alone does not show).
 */
function threshold(mode: ProbeMode, near: number, far: number, z: number, perDecade = 20): number | null {
  if (z * 2 >= far || z <= near) return null;
  const p = probe(mode);
  place(near, far, z, 1);
  nearQuad.visible = false;
  const farShows = centre(p) === 'far';
  nearQuad.visible = true;
  if (!farShows) return null;
  let smallest = Number.POSITIVE_INFINITY;
  for (let i = 0; i <= 9 * perDecade; i++) {
    const separation = 10 ** (-i / perDecade);
    if (kept(mode, near, far, z, separation) !== 'near') break;
    smallest = separation;
  }
  return smallest;
}

/** What the page exposes as `window.cameraDepth` (typed for tests/camera.spec.ts and the bench). */
export interface CameraDepthProbe {
  /** Every probe mode, in table order. */
  modes: ProbeMode[];
  /** The depth mode the renderer behind a probe mode really runs. */
  activeMode(mode: ProbeMode): DepthMode;
  kept: typeof kept;
  threshold: typeof threshold;
}
export type { ProbeMode, QuadMaterials };

// ── 3. Camera vs three's cameras through three's shaders ──────────────────────────────────────────────────────
const COMPARE = 96;
const compareCanvas = document.createElement('canvas');
const compareRenderer = new WebGLRenderer({ canvas: compareCanvas, antialias: false });
compareRenderer.setPixelRatio(1);
compareRenderer.setSize(COMPARE, COMPARE, false);
const sphereScene = new Scene();
sphereScene.background = new Color(0x000000);
sphereScene.add(
  new Mesh(
    new SphereGeometry(1, 64, 32),
    new MeshPhongMaterial({ color: 0x3060c0, specular: 0xffffff, shininess: 40 }),
  ),
);
const sun = new DirectionalLight(0xffffff, 2);
sun.position.set(-2, 3, 4);
sphereScene.add(sun, new AmbientLight(0xffffff, 0.1));
const EYE = [2.5, 1.5, 3] as const;

/** Render the sphere scene through `camera` and read every pixel back. */
function pixels(camera: ThreeCamera): Uint8Array {
  compareRenderer.render(sphereScene, camera);
  return readCanvas(compareRenderer, COMPARE);
}

const differing = (a: Uint8Array, b: Uint8Array) => a.reduce((n, x, i) => n + (x === b[i] ? 0 : 1), 0);

/**
 * The sphere through Camera and through three's camera of the same kind and parameters (the lecture's
 * `setOrthographic(r, l, t, b, n, f)` = three's `OrthographicCamera(l, r, t, b, n, f)`), both placed with
 * lookAt(eye, origin, +y). `flagless` renders three's camera's matrices through a bare THREE.Camera (neither
 * isPerspectiveCamera nor isOrthographicCamera), to show that the flag changes the shading (three's `isOrthographic`
 * uniform: the view direction of the specular term).
 */
function compare(kind: 'orthographic' | 'perspective'): {
  differing: number;
  flaglessDiffering: number;
  brightest: number;
  lit: number;
  isOrthographicCamera: boolean;
} {
  const ours = new Camera();
  let three: OrthographicCamera | PerspectiveCamera;
  if (kind === 'orthographic') {
    ours.setOrthographic(1.6, -1.4, 1.3, -1.5, 0.5, 10);
    three = new OrthographicCamera(-1.4, 1.6, 1.3, -1.5, 0.5, 10);
  } else {
    ours.setPerspective(35, 1, 0.5, 10);
    three = new PerspectiveCamera(35, 1, 0.5, 10);
  }
  ours.lookAt(EYE, [0, 0, 0], [0, 1, 0]);
  three.position.set(...EYE);
  three.lookAt(0, 0, 0);
  three.updateMatrixWorld();
  const flagless = new ThreeCamera();
  flagless.matrixAutoUpdate = false;
  flagless.matrixWorld.copy(three.matrixWorld);
  flagless.matrixWorldInverse.copy(three.matrixWorldInverse);
  flagless.projectionMatrix.copy(three.projectionMatrix);
  flagless.projectionMatrixInverse.copy(three.projectionMatrixInverse);
  const a = pixels(ours);
  const b = pixels(three);
  const c = pixels(flagless);
  let brightest = 0;
  let lit = 0;
  for (let i = 0; i < a.length; i += 4) {
    brightest = Math.max(brightest, Math.min(a[i], a[i + 1], a[i + 2])); // white highlight: all channels high
    if (a[i] + a[i + 1] + a[i + 2] > 0) lit++;
  }
  return {
    differing: differing(a, b),
    flaglessDiffering: differing(b, c),
    brightest,
    lit,
    isOrthographicCamera: ours.isOrthographicCamera,
  };
}

declare global {
  interface Window {
    cameraDepth: CameraDepthProbe;
    cameraCompare: typeof compare;
  }
}
window.cameraCompare = compare;

window.cameraDepth = {
  modes: [
    'standard',
    'logarithmic',
    'reversed',
    'reversed-or-logarithmic',
    'standard-float',
    'reversed-float',
  ],
  activeMode: (mode) => probe(mode).active,
  kept,
  threshold,
};
canvas.dataset.ready = 'true';
