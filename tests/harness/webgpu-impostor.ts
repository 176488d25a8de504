// Harness for tests/material-webgpu-impostor.spec.ts: SphereImpostorNodeMaterial under WebGPURenderer (its WebGPU
// backend and, with forceWebGL, its WebGL2 backend), rendered offscreen into a RenderTarget and read back, against
// SphereImpostorMaterial under WebGLRenderer in the same scene (the WebGL impostor is tested against shade() and
// renderReference() by its own spec), and against a subdivided mesh sphere for the depth it writes.
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { createImpostorQuad, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { ShadingNodeMaterial, SphereImpostorNodeMaterial } from '@shadelab/material/webgpu';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  BoxGeometry,
  type BufferGeometry,
  Color,
  Fog,
  InstancedMesh,
  type Material,
  Matrix4,
  Mesh,
  Object3D,
  OrthographicCamera,
  PerspectiveCamera,
  Plane,
  Scene,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { ClippingGroup, RenderTarget } from 'three/webgpu';
import { thrown } from './lib/errors';
import { hasRgb, maxRgbDelta } from './lib/pixels';
import { type Backend, backendFlags, type DepthMode, gpuRenderer, readTarget } from './lib/webgpu';

export type { Backend, DepthMode };
export interface Variant {
  lighting: 'phong' | 'blinn-phong';
  celBands: number;
}
/**
 * 'ellipsoid' (the lecture's 2, 1, 2 scale, rotated), 'sphere' (a unit sphere off the axis), 'instanced' (both as
 * two instances of one InstancedMesh, with instance colours), 'mirrored' (the ellipsoid with a negative x scale: det < 0),
 * 'orthographic' (the ellipsoid and the sphere through an orthographic camera), 'inside' (a perspective eye
 * inside the ellipsoid: nothing drawn), 'fog' (the ellipsoid in three's range Fog), 'clipped' (the ellipsoid
 * cut by a clipping plane), 'clip-intersection' (by two planes with clipIntersection), 'huge' and 'tiny' (the
 * ellipsoid and the sphere, the light and the camera scaled by 1e15 and 1e-18: the cofactors of 32-bit matrices
 * would overflow or underflow unscaled; 'unit' is that scene unscaled, its light without attenuation too), 'extreme' (the ellipsoid beside a sphere scaled by 1e-20, one by 1e20
 * beyond the far plane and one by 1e20 around the eye: neither of these three draws anything), 'box' (a unit sphere with a box through it: depth against a mesh),
 * 'box-alone' and 'sphere-alone' (each of the two without the other).
 */
export type Scenario =
  | 'ellipsoid'
  | 'sphere'
  | 'instanced'
  | 'mirrored'
  | 'orthographic'
  | 'inside'
  | 'fog'
  | 'clipped'
  | 'clip-intersection'
  | 'unit'
  | 'huge'
  | 'tiny'
  | 'extreme'
  | 'box'
  | 'box-alone'
  | 'sphere-alone';
/** What draws the sphere: an impostor, or (WebGPURenderer only) a level-6 subdivided mesh sphere. */
export type SphereKind = 'impostor' | 'mesh';

const SIZE = 112;
const BACKGROUND = [0, 0, 255] as const;
const meshSphere: BufferGeometry = new SubdivisionSphereGeometry({ level: 6, base: 'octahedron' });
const box: BufferGeometry = new BoxGeometry(2.4, 0.5, 1.2);

function transforms(): { ellipsoid: Matrix4; sphere: Matrix4 } {
  const o = new Object3D();
  o.position.set(-0.4, 0.4, -0.5);
  o.rotation.set(0.3, 0.5, 0.1);
  o.scale.set(2, 1, 2);
  o.updateMatrix();
  const ellipsoid = o.matrix.clone();
  o.position.set(1.3, -1.2, 0.8);
  o.rotation.set(0, 0, 0);
  o.scale.set(1, 1, 1);
  o.updateMatrix();
  return { ellipsoid, sphere: o.matrix.clone() };
}

/** The scene; `gpu` picks the node materials (WebGPURenderer) or the GLSL ones (WebGLRenderer). */
function scene(gpu: boolean, v: Variant, scenario: Scenario, kind: SphereKind = 'impostor') {
  // The whole scene scaled by k (the light without attenuation: its distance is scaled too). At 1e18 the
  // lighting's squared distances (about 1e37) come near float32's largest and the highlight drifts by up to
  // 22/255: 1e15 keeps the lighting exact while the model-view matrix's cofactors (1e30, its determinant 1e45)
  // would still overflow unscaled.
  const k = scenario === 'huge' ? 1e15 : scenario === 'tiny' ? 1e-18 : 1;
  const light = new PhongLight({ ambient: 0.2, diffuse: [1, 0.95, 0.85], specular: 0.9 });
  light.position.set(-2, 3, 4).multiplyScalar(k);
  if (scenario !== 'unit' && k === 1) light.attenuation = { a: 0.6, b: 0.1, c: 0.02 };
  const options = { ...v, lights: [light], shininess: 24 };
  const impostorMaterial: Material = gpu
    ? new SphereImpostorNodeMaterial(options)
    : new SphereImpostorMaterial(options);
  const s = new Scene();
  s.add(light);
  const { ellipsoid, sphere } = transforms();
  const quad = createImpostorQuad();
  const add = (matrix: Matrix4) => {
    let mesh: Mesh;
    if (kind === 'mesh') {
      mesh = new Mesh(meshSphere, new ShadingNodeMaterial({ ...options, shading: 'phong' }));
    } else mesh = new Mesh(quad, impostorMaterial);
    mesh.applyMatrix4(new Matrix4().makeScale(k, k, k).multiply(matrix));
    s.add(mesh);
  };
  if (
    scenario === 'ellipsoid' ||
    scenario === 'orthographic' ||
    scenario === 'inside' ||
    scenario === 'fog' ||
    scenario === 'clipped' ||
    scenario === 'clip-intersection' ||
    scenario === 'unit' ||
    scenario === 'huge' ||
    scenario === 'tiny' ||
    scenario === 'extreme'
  )
    add(ellipsoid);
  if (scenario === 'extreme') {
    add(new Matrix4().makeTranslation(-1, 1.8, 0).scale(new Vector3(1e-20, 1e-20, 1e-20)));
    add(new Matrix4().makeTranslation(0, 0, -3e20).scale(new Vector3(1e20, 1e20, 1e20)));
    add(new Matrix4().makeScale(1e20, 1e20, 1e20));
  }
  // The same planes (world space): WebGLRenderer reads a material's clippingPlanes, WebGPURenderer a ClippingGroup's.
  const planes =
    scenario === 'clipped'
      ? [new Plane(new Vector3(1, 0.4, 0.3).normalize(), 0.3)]
      : scenario === 'clip-intersection'
        ? [
            new Plane(new Vector3(1, 0.2, 0).normalize(), 0.2),
            new Plane(new Vector3(-0.3, 1, 0.2).normalize(), 0),
          ]
        : [];
  if (planes.length > 0) {
    const intersection = scenario === 'clip-intersection';
    if (gpu) {
      const group = new ClippingGroup();
      group.clippingPlanes = planes;
      group.clipIntersection = intersection;
      group.add(...s.children.filter((o) => o instanceof Mesh));
      s.add(group);
    } else {
      impostorMaterial.clippingPlanes = planes;
      impostorMaterial.clipIntersection = intersection;
    }
  }
  if (scenario === 'fog') s.fog = new Fog(new Color(0.2, 0.4, 0.6), 4.5, 7.5);
  if (['sphere', 'orthographic', 'unit', 'huge', 'tiny'].includes(scenario)) add(sphere);
  if (scenario === 'mirrored') add(ellipsoid.clone().multiply(new Matrix4().makeScale(-1, 1, 1)));
  if (scenario === 'instanced') {
    const instanced = new InstancedMesh(quad, impostorMaterial, 2);
    instanced.setMatrixAt(0, ellipsoid);
    instanced.setMatrixAt(1, sphere);
    instanced.position.set(0.1, 0.2, -0.3); // the mesh's own matrix multiplies the instances'
    // instanceColor multiplies ka and kd (not ks).
    instanced.setColorAt(0, new Color(0.5, 1, 0.8));
    instanced.setColorAt(1, new Color(1, 0.6, 1));
    s.add(instanced);
  }
  if (scenario === 'box' || scenario === 'sphere-alone') add(new Matrix4());
  if (scenario === 'box' || scenario === 'box-alone') {
    const boxOptions = { ...options, ka: [0.1, 0.5, 0.2], kd: [0.1, 0.6, 0.2] } as const;
    const m = new Mesh(box, gpu ? new ShadingNodeMaterial(boxOptions) : new ShadingMaterial(boxOptions));
    m.rotation.set(0.4, 0.6, 0.2);
    m.position.set(0.1, 0, 0.45);
    s.add(m);
  }
  const camera =
    scenario === 'orthographic'
      ? new OrthographicCamera(-3, 3, 3, -3, 0.5, 20)
      : new PerspectiveCamera(50, 1, 0.5 * k, 20 * k);
  camera.position.set(0.5, 0.8, 6).multiplyScalar(k);
  camera.lookAt(0, 0, 0);
  if (scenario === 'inside') camera.position.set(-0.2, 0.5, -0.2);
  s.updateMatrixWorld();
  camera.updateMatrixWorld();
  return { scene: s, camera };
}

function dispose(s: Scene): void {
  s.traverse((o) => {
    if (o instanceof Mesh) (o.material as Material).dispose();
  });
}

/** Rows bottom-up, RGBA8, linear (a render target has no output colour space conversion). */
async function renderGpu(
  backend: Backend,
  v: Variant,
  scenario: Scenario,
  kind: SphereKind = 'impostor',
  mode: DepthMode = 'standard',
) {
  const renderer = await gpuRenderer(backend, mode);
  const setup = scene(true, v, scenario, kind);
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(setup.scene, setup.camera);
  const pixels = await readTarget(renderer, target, SIZE);
  renderer.setRenderTarget(null);
  target.dispose();
  dispose(setup.scene);
  return pixels;
}

let gl: WebGLRenderer | null = null;
function renderGl(v: Variant, scenario: Scenario): Uint8Array {
  gl ??= new WebGLRenderer({ antialias: false });
  gl.localClippingEnabled = true;
  const setup = scene(false, v, scenario);
  const target = new WebGLRenderTarget(SIZE, SIZE);
  gl.setRenderTarget(target);
  gl.setClearColor(0x0000ff, 1);
  gl.clear();
  gl.render(setup.scene, setup.camera);
  const pixels = new Uint8Array(4 * SIZE * SIZE);
  gl.readRenderTargetPixels(target, 0, 0, SIZE, SIZE, pixels);
  gl.setRenderTarget(null);
  target.dispose();
  dispose(setup.scene);
  return pixels;
}

const isBackground = (p: Uint8Array, i: number): boolean => hasRgb(p, i, BACKGROUND);

/**
 * A pixel on an edge of the reference picture: one of its 8 neighbours is background where it is not (or the
 * reverse), or differs from it by more than `jump`/255 (the box/sphere boundary, a cel band's edge).
 */
function edgeMask(p: Uint8Array, jump: number): boolean[] {
  const mask: boolean[] = [];
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const i = 4 * (y * SIZE + x);
      let edge = false;
      for (let dy = -1; dy <= 1 && !edge; dy++) {
        for (let dx = -1; dx <= 1 && !edge; dx++) {
          const nx = x + dx;
          const ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= SIZE || ny >= SIZE) continue;
          const j = 4 * (ny * SIZE + nx);
          edge = isBackground(p, i) !== isBackground(p, j) || maxRgbDelta(p, p, i, j) > jump;
        }
      }
      mask.push(edge);
    }
  }
  return mask;
}

/**
 * WebGLRenderer + SphereImpostorMaterial against WebGPURenderer + SphereImpostorNodeMaterial in the same scene:
 * covered pixels, pixels covered by one only (and how many of those are on the reference's silhouette), and
 * max |Δ| in 1/255 over the pixels covered by both away from the reference's edges.
 */
async function crossRenderer(backend: Backend, v: Variant, scenario: Scenario) {
  const a = renderGl(v, scenario);
  const b = await renderGpu(backend, v, scenario);
  // Cel bands and where two surfaces meet (the box and the sphere, the ellipsoid and the sphere) are edges within
  // the picture.
  const oneSurface = ['ellipsoid', 'sphere', 'mirrored', 'fog', 'clipped', 'clip-intersection'].includes(
    scenario,
  );
  const edges = edgeMask(a, v.celBands > 0 || !oneSurface ? 24 : 255);
  let covered = 0;
  let coverageMismatch = 0;
  let coverageMismatchOffEdge = 0;
  let compared = 0;
  let maxDelta = 0;
  let differing = 0;
  let worst: unknown = null;
  for (let k = 0; k < SIZE * SIZE; k++) {
    const i = 4 * k;
    const ca = !isBackground(a, i);
    const cb = !isBackground(b, i);
    if (ca) covered++;
    if (ca !== cb) {
      coverageMismatch++;
      if (!edges[k]) coverageMismatchOffEdge++;
    }
    if (!ca || !cb || edges[k]) continue;
    compared++;
    const d = maxRgbDelta(a, b, i);
    if (d > maxDelta) {
      maxDelta = d;
      worst = {
        x: k % SIZE,
        y: Math.floor(k / SIZE),
        gl: [...a.subarray(i, i + 3)],
        gpu: [...b.subarray(i, i + 3)],
      };
    }
    if (d > 2) differing++;
  }
  return { covered, coverageMismatch, coverageMismatchOffEdge, compared, maxDelta, differing, worst };
}

/**
 * The 'huge' or 'tiny' scene (everything scaled by 1e15 or 1e-18) against the 'unit' scene drawn the same way
 * (the same directions, no attenuation: the same picture): by SphereImpostorNodeMaterial on a backend of
 * WebGPURenderer, or (`'webgl'`) by SphereImpostorMaterial on WebGLRenderer.
 */
async function scaleInvariance(on: Backend | 'webgl', v: Variant, scenario: 'huge' | 'tiny') {
  const render = async (s: Scenario) => (on === 'webgl' ? renderGl(v, s) : await renderGpu(on, v, s));
  const a = await render('unit');
  const b = await render(scenario);
  const edges = edgeMask(a, 24);
  let covered = 0;
  let coverageMismatch = 0;
  let coverageMismatchOffEdge = 0;
  let maxDelta = 0;
  let worst: unknown = null;
  for (let k = 0; k < SIZE * SIZE; k++) {
    const i = 4 * k;
    const ca = !isBackground(a, i);
    const cb = !isBackground(b, i);
    if (ca) covered++;
    if (ca !== cb) {
      coverageMismatch++;
      if (!edges[k]) coverageMismatchOffEdge++;
    }
    if (ca && cb && !edges[k] && maxRgbDelta(a, b, i) > maxDelta) {
      maxDelta = maxRgbDelta(a, b, i);
      worst = {
        x: k % SIZE,
        y: Math.floor(k / SIZE),
        unit: [...a.subarray(i, i + 3)],
        scaled: [...b.subarray(i, i + 3)],
      };
    }
  }
  return { covered, coverageMismatch, coverageMismatchOffEdge, maxDelta, worst };
}

/**
 * Depth (in the renderer's depth mode `mode`): in the 'box' scene on WebGPURenderer, the pixels of the box's colour (green dominant) and of the
 * sphere's (red dominant) with the sphere drawn as an impostor and as a level-6 mesh sphere, and in the scenes
 * of each alone: the box is partly hidden by the sphere and the sphere partly by the box, as with the mesh.
 */
async function occlusion(backend: Backend, v: Variant, mode: DepthMode = 'standard') {
  const count = (p: Uint8Array) => {
    let boxPixels = 0;
    let spherePixels = 0;
    for (let i = 0; i < p.length; i += 4) {
      if (isBackground(p, i)) continue;
      if (p[i + 1] > p[i]) boxPixels++;
      else spherePixels++;
    }
    return { boxPixels, spherePixels };
  };
  const impostor = await renderGpu(backend, v, 'box', 'impostor', mode);
  const mesh = await renderGpu(backend, v, 'box', 'mesh', mode);
  const renderer = await gpuRenderer(backend, mode);
  // Where the two pictures disagree on what is seen (box or sphere), away from the mesh picture's edges.
  const edges = edgeMask(mesh, 24);
  let disagree = 0;
  let disagreeOffEdge = 0;
  for (let k = 0; k < SIZE * SIZE; k++) {
    const i = 4 * k;
    const kindOf = (p: Uint8Array) => (isBackground(p, i) ? 0 : p[i + 1] > p[i] ? 1 : 2);
    if (kindOf(impostor) !== kindOf(mesh)) {
      disagree++;
      if (!edges[k]) disagreeOffEdge++;
    }
  }
  return {
    impostor: count(impostor),
    mesh: count(mesh),
    boxAlone: count(await renderGpu(backend, v, 'box-alone', 'impostor', mode)),
    sphereAlone: count(await renderGpu(backend, v, 'sphere-alone', 'impostor', mode)),
    // The depth mode the renderer really runs (a backend without the extension falls back to standard depth).
    logarithmic: renderer.logarithmicDepthBuffer === true,
    reversed: renderer.reversedDepthBuffer === true,
    disagree,
    disagreeOffEdge,
  };
}

/** Which backend runs: proof that WebGPU is not a silent fallback to WebGL2. */
async function backendInfo(backend: Backend) {
  return backendFlags(await gpuRenderer(backend));
}

/** The message each impostor material throws for the same bad input. */
function errors() {
  const cases: Record<string, unknown>[] = [
    { shading: 'flat' },
    { shading: 'smooth' },
    { lighting: 'toon' },
    { celBands: 1 },
    { celBands: 2.5 },
    { celBands: 256 },
    { celBands: '4' },
    { ka: -1 },
    { kd: [1, Number.NaN, 0] },
    { ks: 'not a colour' },
    { shininess: Number.NaN },
    { shininess: -1 },
    { lights: [{}] },
    { lights: 'none' },
  ];
  const setters = (m: SphereImpostorNodeMaterial) => [
    thrown(() => {
      m.shading = 'gouraud';
    }),
    thrown(() => {
      m.lighting = 'x' as never;
    }),
  ];
  return {
    rows: cases.map((options) => ({
      options: JSON.stringify(options),
      webgl: thrown(() => new SphereImpostorMaterial(options as never)),
      node: thrown(() => new SphereImpostorNodeMaterial(options as never)),
    })),
    setters: setters(new SphereImpostorNodeMaterial()),
    valid: thrown(() => new SphereImpostorNodeMaterial({ lighting: 'blinn-phong', celBands: 4, ka: 0.3 })),
  };
}

const api = { backendInfo, crossRenderer, errors, occlusion, scaleInvariance };
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
