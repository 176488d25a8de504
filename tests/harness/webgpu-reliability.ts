// Harness for tests/material-webgpu-reliability.spec.ts: the extremes table (docs/design.md) and the reliability
// tests on WebGPURenderer, on its WebGPU backend and (forceWebGL) its WebGL2 backend, rendered offscreen into a
// RenderTarget and read back. ShadingNodeMaterial, OutlineNodeMaterial (createOutlineNode) and
// SphereImpostorNodeMaterial; three's own node materials (MeshPhongNodeMaterial, MeshBasicNodeMaterial) as the
// oracle of where and whether something is drawn, shade() for colours.
import { PhongLight, type ShadeThreeLight, shade } from '@shadelab/material';
import { createImpostorQuad } from '@shadelab/material/impostor';
import {
  createOutlineNode,
  ShadingNodeMaterial,
  SphereImpostorNodeMaterial,
} from '@shadelab/material/webgpu';
import {
  AmbientLight,
  BackSide,
  BoxGeometry,
  type BufferGeometry,
  type Camera,
  Color,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  Euler,
  Float32BufferAttribute,
  FloatType,
  Fog,
  FogExp2,
  FrontSide,
  HemisphereLight,
  IcosahedronGeometry,
  InstancedMesh,
  type Light,
  type Material,
  Matrix3,
  Matrix4,
  Mesh,
  type Object3D,
  PerspectiveCamera,
  PointLight,
  Quaternion,
  RGBAFormat,
  Scene,
  SpotLight,
  Vector3,
} from 'three';
import { MeshBasicNodeMaterial, MeshPhongNodeMaterial, RenderTarget, WebGPURenderer } from 'three/webgpu';
import { hasRgb, maxRgbDelta } from './lib/pixels';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';

export type { Backend };

/** The clear colour (RGB 0 … 255): where nothing was drawn. */
const CLEAR = [0, 0, 255] as const;
type Shading = 'flat' | 'gouraud' | 'phong';

function camera(position: readonly [number, number, number] = [0.6, 1.4, 6]): PerspectiveCamera {
  const c = new PerspectiveCamera(50, 1, 0.5, 40);
  c.position.set(...position);
  c.lookAt(0, 0, 0);
  c.updateMatrixWorld();
  return c;
}

/** `scene` drawn by `renderer` into a new `size` × `size` RGBA8 target (linear), rows bottom-up. */
async function draw(renderer: WebGPURenderer, scene: Scene, cam: Camera, size: number): Promise<Uint8Array> {
  const target = new RenderTarget(size, size, { depthBuffer: true });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(scene, cam);
  const pixels = await readTarget(renderer, target, size);
  renderer.setRenderTarget(null);
  target.dispose();
  return pixels;
}

/** `scene` drawn into a float target: every channel of every pixel, to find NaN and ±Infinity. */
async function drawFloat(
  renderer: WebGPURenderer,
  scene: Scene,
  cam: Camera,
  size: number,
): Promise<Float32Array> {
  const target = new RenderTarget(size, size, { depthBuffer: true, type: FloatType });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(scene, cam);
  const data = new Float32Array(
    (await renderer.readRenderTargetPixelsAsync(target, 0, 0, size, size)) as Float32Array,
  );
  renderer.setRenderTarget(null);
  target.dispose();
  return data;
}

/** The renderer's pipeline and program caches and node builds (three's internals), and renderer.info.memory. */
export interface Counts {
  memory: Record<string, number>;
  pipelines: number;
  vertexPrograms: number;
  fragmentPrograms: number;
  nodeBuilds: number;
}

function counts(r: WebGPURenderer): Counts {
  const internals = r as unknown as {
    _pipelines: {
      caches: Map<unknown, unknown>;
      programs: { vertex: Map<unknown, unknown>; fragment: Map<unknown, unknown> };
    };
    _nodes: { nodeBuilderCache: Map<unknown, unknown> };
  };
  return {
    memory: { ...(r.info.memory as unknown as Record<string, number>) },
    pipelines: internals._pipelines.caches.size,
    vertexPrograms: internals._pipelines.programs.vertex.size,
    fragmentPrograms: internals._pipelines.programs.fragment.size,
    nodeBuilds: internals._nodes.nodeBuilderCache.size,
  };
}

function maxCounts(a: Counts, b: Counts): Counts {
  const memory = { ...a.memory };
  for (const k of Object.keys(b.memory)) memory[k] = Math.max(memory[k] ?? 0, b.memory[k]);
  return {
    memory,
    pipelines: Math.max(a.pipelines, b.pipelines),
    vertexPrograms: Math.max(a.vertexPrograms, b.vertexPrograms),
    fragmentPrograms: Math.max(a.fragmentPrograms, b.fragmentPrograms),
    nodeBuilds: Math.max(a.nodeBuilds, b.nodeBuilds),
  };
}

// ---- Instance matrix extremes ------------------------------------------------------------------------------

/**
 * A box with one colour per face (r = (face + 1)/8): the oracle's face id. A triangle soup, so that flat shading
 * lights each face once at its centroid with the instance's normal (by derivatives on an indexed box).
 */
const idBox = (() => {
  const g = new BoxGeometry(1, 1, 1);
  const colors = new Float32Array(3 * 24);
  for (let v = 0; v < 24; v++) colors.set([(Math.floor(v / 4) + 1) / 8, 1, 1], 3 * v);
  g.setAttribute('color', new Float32BufferAttribute(colors, 3));
  return g.toNonIndexed();
})();
/**
 * idBox with four attributes more (unread): with the instance matrix, more vertex buffers than three binds per
 * instanced mesh, so three builds the mesh on its own (its instance matrices in a uniform array).
 */
const crowdedBox = (() => {
  const g = idBox.clone();
  for (let k = 0; k < 4; k++) {
    g.setAttribute(
      `spare${k}`,
      new Float32BufferAttribute(new Float32Array(g.getAttribute('position').count), 1),
    );
  }
  return g;
})();
/** Whether a generated shader reads instance matrices from an array indexed by the instance (WGSL or GLSL). */
const INSTANCE_ARRAY = /\[\s*(instanceIndex|uint\(\s*gl_InstanceID\s*\))\s*\]/;
/** BoxGeometry's face normals, in its vertex order (+x, −x, +y, −y, +z, −z). */
const FACE_NORMALS = [
  [1, 0, 0],
  [-1, 0, 0],
  [0, 1, 0],
  [0, -1, 0],
  [0, 0, 1],
  [0, 0, -1],
] as const;

interface ExtremeInstance {
  name: string;
  position: [number, number, number];
  rotation: [number, number, number];
  scale: [number, number, number];
  /** The uniform scale of the InstancedMesh that holds the instance. @default 1 */
  meshScale?: number;
  /**
   * The expected outward world normal of face f (object normal n): three's inverse transpose for a regular
   * matrix (float64), the plane's normal for a box flattened to a square, null where the face has no area.
   */
  normal(n: readonly number[], m: Matrix4): Vector3 | null;
}

const regular = (n: readonly number[], m: Matrix4): Vector3 =>
  new Vector3(...n).applyMatrix3(new Matrix3().getNormalMatrix(m)).normalize();

/** The extremes of the instance matrix, and a control instance. */
const EXTREME_INSTANCES: ExtremeInstance[] = [
  {
    name: 'control',
    position: [-1.6, 0.9, 0],
    rotation: [0.4, 0.6, 0],
    scale: [0.9, 0.9, 0.9],
    normal: regular,
  },
  {
    name: 'negative determinant',
    position: [1.6, 0.9, 0],
    rotation: [0.4, -0.6, 0.2],
    scale: [-0.9, 0.9, 0.9],
    normal: regular,
  },
  {
    name: 'zero scale (flattened to a square)',
    position: [0, -0.9, 0.6],
    rotation: [-0.7, 0.5, 0],
    scale: [1.2, 1.2, 0],
    normal: (n) => {
      if (n[2] === 0) return null;
      // The square's plane: the rotation of ±z.
      return new Vector3(0, 0, Math.sign(n[2])).applyQuaternion(
        new Quaternion().setFromEuler(new Euler(-0.7, 0.5, 0)),
      );
    },
  },
  { name: 'all zero', position: [0, 0.9, 1], rotation: [0, 0, 0], scale: [0, 0, 0], normal: () => null },
  // 1e20 in an InstancedMesh scaled by 1e-20 (a box of ordinary size on the screen): the instance's 3 × 3 part and
  // its determinant (1e60) overflow float32 where a normal matrix is made from them unscaled.
  {
    name: '1e20 scale',
    position: [0, 1.3e20, -3e20],
    rotation: [0.3, 0.9, 0.1],
    scale: [1.4e20, 1.4e20, 1.4e20],
    meshScale: 1e-20,
    normal: regular,
  },
];

function extremeMatrix(e: ExtremeInstance): Matrix4 {
  return new Matrix4().compose(
    new Vector3(...e.position),
    new Quaternion().setFromEuler(new Euler(...e.rotation)),
    new Vector3(...e.scale),
  );
}

/** three's lights of the extremes scenes: a directional light and an ambient light (ks = 0: colour = f(normal)). */
function directionalScene(): { lights: Light[]; shade: ShadeThreeLight[] } {
  const ambient = new AmbientLight(new Color(0.3, 0.3, 0.35), 1);
  const sun = new DirectionalLight(new Color(1, 0.9, 0.8), 2.5);
  sun.position.set(-1, 2, 1.5);
  return {
    lights: [ambient, sun],
    shade: [
      { type: 'ambient', color: [0.3, 0.3, 0.35] },
      { type: 'directional', color: [2.5, 2.25, 2], direction: sun.position.clone().normalize().toArray() },
    ],
  };
}

const KA = [0.4, 0.5, 0.6] as const;
const KD = [0.8, 0.6, 0.4] as const;

/**
 * An InstancedMesh of boxes with the extreme instance matrices, drawn by ShadingNodeMaterial (`shading`, ks = 0,
 * three's directional and ambient lights: the colour is a function of the normal only), against an id pass
 * (MeshBasicNodeMaterial, vertex colour = face, instance colour = instance) that says which face of which instance
 * each pixel shows, and shade() with that face's expected outward normal. Pixels away from the id pass's edges.
 */
async function instanceExtremes(backend: Backend, shading: Shading, crowded = false) {
  const renderer = await gpuRenderer(backend);
  const size = 128;
  const cam = camera();
  const { lights, shade: shadeLights } = directionalScene();
  const matrices = EXTREME_INSTANCES.map(extremeMatrix);
  // One InstancedMesh per mesh scale; instance k keeps its index in the id pass (instance colour (k + 1)/8).
  const build = (material: Material, ids: boolean) => {
    const scene = new Scene();
    for (const meshScale of new Set(EXTREME_INSTANCES.map((e) => e.meshScale ?? 1))) {
      const members = EXTREME_INSTANCES.flatMap((e, k) => ((e.meshScale ?? 1) === meshScale ? [k] : []));
      const mesh = new InstancedMesh(crowded ? crowdedBox : idBox, material, members.length);
      members.forEach((k, j) => {
        mesh.setMatrixAt(j, matrices[k]);
        if (ids) mesh.setColorAt(j, new Color(1, (k + 1) / 8, 1));
      });
      mesh.scale.setScalar(meshScale);
      mesh.frustumCulled = false;
      scene.add(mesh);
    }
    scene.add(...lights.map((l) => l.clone()));
    scene.updateMatrixWorld();
    return scene;
  };
  const material = new ShadingNodeMaterial({ shading, ka: [...KA], kd: [...KD], ks: 0 });
  const shadedScene = build(material, false);
  const shaded = await draw(renderer, shadedScene, cam, size);
  const first = shadedScene.children.find((o) => (o as InstancedMesh).isInstancedMesh === true);
  const { vertexShader } = await renderer.debug.getShaderAsync(shadedScene, cam, first as InstancedMesh);
  const instanceArray = INSTANCE_ARRAY.test(vertexShader ?? '');
  const idMaterial = new MeshBasicNodeMaterial({ vertexColors: true });
  const ids = await draw(renderer, build(idMaterial, true), cam, size);
  material.dispose();
  idMaterial.dispose();
  // Expected colour per (instance, face).
  const expected = new Map<string, number[] | null>();
  EXTREME_INSTANCES.forEach((e, k) => {
    FACE_NORMALS.forEach((n, f) => {
      const normal = e.normal(n, matrices[k]);
      let colour: number[] | null = null;
      if (normal !== null) {
        const c = shade(
          { position: [0, 0, 0], normal: normal.toArray(), eye: [...cam.position.toArray(), 1] },
          { ka: [...KA], kd: [...KD], ks: [0, 0, 0], shininess: 1 },
          shadeLights,
        );
        colour = c.map((x) => Math.min(Math.max(x, 0), 1) * 255);
      }
      expected.set(`${k} ${f}`, colour);
    });
  });
  const key = (i: number): string | null => {
    if (hasRgb(ids, i, CLEAR)) return null;
    const f = Math.round((ids[i] / 255) * 8) - 1;
    const k = Math.round((ids[i + 1] / 255) * 8) - 1;
    return `${k} ${f}`;
  };
  const perInstance: Record<string, { compared: number; maxError: number; drawn: number }> = {};
  for (const e of EXTREME_INSTANCES) perInstance[e.name] = { compared: 0, maxError: 0, drawn: 0 };
  let coverageMismatches = 0;
  let unexpected = 0;
  let worst: unknown = null;
  for (let y = 1; y < size - 1; y++) {
    for (let x = 1; x < size - 1; x++) {
      const i = 4 * (y * size + x);
      const id = key(i);
      if ((id === null) !== hasRgb(shaded, i, CLEAR)) coverageMismatches++;
      if (id === null) continue;
      const k = Number(id.split(' ')[0]);
      const stats = perInstance[EXTREME_INSTANCES[k]?.name ?? '?'];
      if (stats === undefined) {
        unexpected++;
        continue;
      }
      stats.drawn++;
      let interior = true;
      for (let dy = -1; interior && dy <= 1; dy++)
        for (let dx = -1; interior && dx <= 1; dx++)
          if (key(i + 4 * (dy * size + dx)) !== id) interior = false;
      if (!interior) continue;
      const want = expected.get(id);
      if (want === null || want === undefined) {
        unexpected++;
        continue;
      }
      stats.compared++;
      const error = Math.max(...want.map((w, c) => Math.abs(shaded[i + c] - w)));
      if (error > stats.maxError) {
        stats.maxError = error;
        if (error > 2) worst = { x, y, id, got: [...shaded.subarray(i, i + 3)], want };
      }
    }
  }
  return {
    backend: backendFlags(renderer),
    perInstance,
    coverageMismatches,
    unexpected,
    worst,
    instanceArray,
  };
}

// ---- Fog, opacity and alphaTest extremes ----------------------------------------------------------------------

const sphere: BufferGeometry = new IcosahedronGeometry(1, 5);
const C = [0.7, 0.45, 0.3] as const;

/** The sphere (scaled 2, 1, 2) in `fog` lit by three's lights, by ShadingNodeMaterial { ka: c, kd: c, ks: 0 } or MeshPhongNodeMaterial { color: c, specular: 0 }. */
function litScene(material: Material, fog: Scene['fog']) {
  const scene = new Scene();
  const mesh = new Mesh(sphere, material);
  mesh.scale.set(2, 1, 2);
  const ambient = new AmbientLight(0xffffff, 0.6);
  const sun = new DirectionalLight(0xffffff, 2);
  sun.position.set(-1, 2, 3);
  scene.add(mesh, ambient, sun);
  scene.fog = fog;
  scene.updateMatrixWorld();
  return { scene, mesh };
}

type FogCase = { near: number; far: number } | { density: number } | null;
const makeFog = (f: FogCase): Scene['fog'] =>
  f === null ? null : 'density' in f ? new FogExp2(0x33aa66, f.density) : new Fog(0x33aa66, f.near, f.far);

/** The same scene drawn by ShadingNodeMaterial and by MeshPhongNodeMaterial: coverage and max |Δ|. */
async function pair(backend: Backend, fog: FogCase, surface: Record<string, unknown> = {}) {
  const renderer = await gpuRenderer(backend);
  const size = 64;
  const cam = camera([0, 0.5, 6]);
  const ours = new ShadingNodeMaterial({ ka: [...C], kd: [...C], ks: 0, ...surface });
  const theirs = new MeshPhongNodeMaterial({ color: new Color(...C), specular: 0, ...surface });
  const a = await draw(renderer, litScene(ours, makeFog(fog)).scene, cam, size);
  const b = await draw(renderer, litScene(theirs, makeFog(fog)).scene, cam, size);
  ours.dispose();
  theirs.dispose();
  return { a, b, size };
}

/**
 * The fog extremes (near = far, density 0 and 1e6), opacity 0 and 1 (transparent), alphaTest 0 and 1: each
 * against MeshPhongNodeMaterial in the same scene (coverage, max |Δ|), against the unfogged picture (density 0)
 * and the fog colour (density 1e6), and in a float target (NaN, ±Infinity).
 */
async function surfaceExtremes(backend: Backend) {
  const renderer = await gpuRenderer(backend);
  const cases: Array<[string, FogCase, Record<string, unknown>]> = [
    ['no fog', null, {}],
    ['Fog near = far = 4.4', { near: 4.4, far: 4.4 }, {}],
    ['FogExp2 density 0', { density: 0 }, {}],
    ['FogExp2 density 1e6', { density: 1e6 }, {}],
    ['opacity 0, transparent', null, { opacity: 0, transparent: true }],
    ['opacity 1, transparent', null, { opacity: 1, transparent: true }],
    ['alphaTest 0', null, { alphaTest: 0 }],
    ['alphaTest 1', null, { alphaTest: 1 }],
  ];
  const rows: Record<
    string,
    {
      covered: number;
      theirsCovered: number;
      coverageMismatches: number;
      maxDelta: number;
      nonFinite: number;
    }
  > = {};
  const pictures: Record<string, Uint8Array> = {};
  for (const [name, fog, surface] of cases) {
    const { a, b, size } = await pair(backend, fog, surface);
    pictures[name] = a;
    let covered = 0;
    let theirsCovered = 0;
    let coverageMismatches = 0;
    let maxDelta = 0;
    for (let i = 0; i < 4 * size * size; i += 4) {
      const ca = !hasRgb(a, i, CLEAR);
      const cb = !hasRgb(b, i, CLEAR);
      if (ca) covered++;
      if (cb) theirsCovered++;
      if (ca !== cb) coverageMismatches++;
      else if (ca) maxDelta = Math.max(maxDelta, maxRgbDelta(a, b, i));
    }
    // Finite: the same scene in a float target.
    const material = new ShadingNodeMaterial({ ka: [...C], kd: [...C], ks: 0, ...surface });
    const data = await drawFloat(renderer, litScene(material, makeFog(fog)).scene, camera([0, 0.5, 6]), 32);
    material.dispose();
    const nonFinite = data.filter((v) => !Number.isFinite(v)).length;
    rows[name] = { covered, theirsCovered, coverageMismatches, maxDelta, nonFinite };
  }
  // Density 0 = no fog; density 1e6 = the fog colour on every covered pixel (linear 0x33aa66 in 8 bits).
  const fogColour = new Color(0x33aa66);
  const fogBytes = [fogColour.r, fogColour.g, fogColour.b].map((c) => Math.round(c * 255));
  let zeroDelta = 0;
  let fullDelta = 0;
  const none = pictures['no fog'];
  const zero = pictures['FogExp2 density 0'];
  const full = pictures['FogExp2 density 1e6'];
  const step = pictures['Fog near = far = 4.4'];
  let stepFogged = 0;
  let stepUnfogged = 0;
  let stepOther = 0;
  for (let i = 0; i < none.length; i += 4) {
    if (hasRgb(none, i, CLEAR)) continue;
    zeroDelta = Math.max(zeroDelta, maxRgbDelta(none, zero, i));
    fullDelta = Math.max(fullDelta, ...fogBytes.map((c, k) => Math.abs(full[i + k] - c)));
    if (fogBytes.every((c, k) => Math.abs(step[i + k] - c) <= 1)) stepFogged++;
    else if (maxRgbDelta(step, none, i) <= 1) stepUnfogged++;
    else stepOther++;
  }
  return {
    backend: backendFlags(renderer),
    rows,
    zeroDelta,
    fullDelta,
    step: { fogged: stepFogged, unfogged: stepUnfogged, other: stepOther },
  };
}

// ---- 0, 1 and 64 lights of each kind ----------------------------------------------------------------------

export type LightKind = 'ambient' | 'hemisphere' | 'directional' | 'point' | 'spot' | 'phong';
const LIGHT_KINDS: LightKind[] = ['ambient', 'hemisphere', 'directional', 'point', 'spot', 'phong'];

function makeLight(kind: LightKind, i: number): Object3D {
  const a = (i * 2.399) % (2 * Math.PI);
  const at = new Vector3(Math.cos(a) * 3, 2 + (i % 5) * 0.3, 3 + Math.sin(a));
  const intensity = 0.05;
  let light: Object3D;
  if (kind === 'ambient') light = new AmbientLight(0xffffff, intensity);
  else if (kind === 'hemisphere') light = new HemisphereLight(0xaaccff, 0x443322, intensity);
  else if (kind === 'directional') light = new DirectionalLight(0xffffff, intensity);
  else if (kind === 'point') light = new PointLight(0xffffff, intensity * 20, 0, 2);
  else if (kind === 'spot') light = new SpotLight(0xffffff, intensity * 20, 0, 0.6, 0.3, 2);
  else light = new PhongLight({ ambient: 0.003, diffuse: intensity, specular: intensity });
  light.position.copy(at);
  return light;
}

const materialsByShading: Record<Shading, ShadingNodeMaterial> = {
  flat: new ShadingNodeMaterial({ shading: 'flat', ks: 0.5 }),
  gouraud: new ShadingNodeMaterial({ shading: 'gouraud', ks: 0.5 }),
  phong: new ShadingNodeMaterial({ shading: 'phong', ks: 0.5 }),
};

/** The scenes of the light table, made once each (an app's scene is drawn again, not rebuilt). */
const lightScenes = new Map<string, Scene>();

/** `count` lights of each of `kinds` around the sphere, drawn by ShadingNodeMaterial in `shading`. */
function lightSceneOf(kinds: LightKind[], count: number, shading: Shading): Scene {
  const key = `${kinds.join('+')} ${count} ${shading}`;
  let scene = lightScenes.get(key);
  if (scene === undefined) {
    scene = new Scene();
    scene.add(new Mesh(sphere, materialsByShading[shading]));
    for (const kind of kinds) for (let i = 0; i < count; i++) scene.add(makeLight(kind, i));
    scene.updateMatrixWorld();
    lightScenes.set(key, scene);
  }
  return scene;
}

/** The scene drawn into a float target: whether every channel is finite and the sphere is drawn. */
async function lightScene(renderer: WebGPURenderer, kinds: LightKind[], count: number, shading: Shading) {
  const data = await drawFloat(renderer, lightSceneOf(kinds, count, shading), camera([0, 0, 4]), 24);
  let nonFinite = 0;
  for (const v of data) if (!Number.isFinite(v)) nonFinite++;
  // The centre pixel is the sphere, not the clear colour (0, 0, 1).
  const centre = 4 * (12 * 24 + 12);
  const drawn = !(data[centre] === 0 && data[centre + 1] === 0 && data[centre + 2] === 1);
  return { nonFinite, drawn };
}

/**
 * Light configurations of the table in `shadings`: for each n of `counts`, no light (n = 0), n of each kind alone
 * (`kinds` 'each' or 'both'; the kinds of `only`) and n of every kind in one scene ('together' or 'both'). Each is drawn once (compiled, finite, drawn), then `flips` random
 * configurations of them again: the renderer's counts after the sweep and at their largest during the flips (a
 * configuration drawn again compiles nothing).
 */
async function lightExtremes(
  backend: Backend,
  shadings: Shading[],
  lightCounts: number[],
  kinds: 'each' | 'together' | 'both',
  flips: number,
  only: LightKind[] = LIGHT_KINDS,
) {
  const renderer = await gpuRenderer(backend);
  const configs: Array<[LightKind[], number]> = [];
  for (const n of lightCounts) {
    if (n === 0) configs.push([[], 0]);
    else {
      if (kinds !== 'together') for (const kind of only) configs.push([[kind], n]);
      if (kinds !== 'each') configs.push([LIGHT_KINDS, n]);
    }
  }
  const before = counts(renderer);
  const results: { config: string; shading: Shading; nonFinite: number; drawn: boolean }[] = [];
  for (const [kinds, count] of configs) {
    for (const shading of shadings) {
      const r = await lightScene(renderer, kinds, count, shading);
      results.push({ config: `${count} × ${kinds.join('+') || 'none'}`, shading, ...r });
    }
  }
  const swept = counts(renderer);
  let peak = swept;
  let seed = 20261123;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  let flipProblems = 0;
  for (let i = 0; i < flips; i++) {
    const [kinds, count] = configs[Math.floor(random() * configs.length)];
    const r = await lightScene(renderer, kinds, count, shadings[Math.floor(random() * shadings.length)]);
    if (r.nonFinite > 0 || !r.drawn) flipProblems++;
    peak = maxCounts(peak, counts(renderer));
  }
  return { backend: backendFlags(renderer), results, before, swept, peak, flipProblems };
}

// ---- Device loss -------------------------------------------------------------------------------------------

/** The scene of the reliability tests: a ShadingNodeMaterial sphere with its node outline, and an impostor. */
function threeMaterialsScene() {
  const scene = new Scene();
  const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
  light.position.set(-5, 10, 20);
  const shaded = new Mesh(
    sphere,
    new ShadingNodeMaterial({ shading: 'gouraud', celBands: 4, lights: [light] }),
  );
  shaded.position.set(-1.1, 0, 0);
  const outline = createOutlineNode(shaded, { thickness: 0.08, color: [0.1, 0.05, 0] });
  const impostor = new Mesh(createImpostorQuad(), new SphereImpostorNodeMaterial({ lights: [light] }));
  impostor.position.set(1.2, 0, 0);
  impostor.scale.set(0.9, 1.2, 0.9);
  scene.add(light, shaded, impostor);
  scene.updateMatrixWorld();
  return { scene, materials: [shaded.material, outline.material, impostor.material] as Material[] };
}

export interface LossReport {
  backend: { isWebGPUBackend: boolean; isWebGLBackend: boolean };
  /** What three passed to renderer.onDeviceLost. */
  onDeviceLost: { api: string; message: string; reason: string | null }[];
  /** What the device's own `lost` promise said (WebGPU). */
  deviceLost: { reason: string; message: string } | null;
  /** How many pixels are drawn (not clear); how many of the outline's colour. */
  covered: number;
  outlinePixels: number;
  /** Whether the new renderer drew the same pixels as the first one before the loss. */
  identical: boolean;
  recovered: boolean;
}

/**
 * The three materials drawn by a WebGPURenderer, then its device lost: 'destroyed' (the app calls
 * `device.destroy()` on the renderer's own device: three ignores the reason 'destroyed', so the app watches
 * `device.lost` itself, as the playground does), 'lost' (a device lost for another reason, a GPU process crash:
 * three calls `onDeviceLost`; simulated on a device whose `lost` promise the harness resolves), or 'context'
 * (WebGL2 backend: WEBGL_lose_context; three calls `onDeviceLost`). The app's handler makes a new
 * WebGPURenderer and draws the same scene with the same materials.
 */
async function deviceLoss(trigger: 'destroyed' | 'lost' | 'context'): Promise<LossReport> {
  const size = 96;
  const cam = camera([0, 0.4, 6]);
  const { scene, materials } = threeMaterialsScene();
  const calls: LossReport['onDeviceLost'] = [];
  let deviceLost: LossReport['deviceLost'] = null;
  let resolveLost: (info: unknown) => void = () => {};
  let first: WebGPURenderer;
  if (trigger === 'lost') {
    const adapter = await navigator.gpu.requestAdapter();
    if (adapter === null) throw new Error('no WebGPU adapter');
    const device = await adapter.requestDevice();
    Object.defineProperty(device, 'lost', {
      value: new Promise((resolve) => {
        resolveLost = resolve;
      }),
    });
    first = new WebGPURenderer({ antialias: false, device } as never);
  } else first = new WebGPURenderer({ antialias: false, forceWebGL: trigger === 'context' });
  await first.init();
  // The app's recovery: on a loss, a new renderer (same options), the same scene and materials.
  let recovered: Promise<WebGPURenderer> | null = null;
  const recover = () => {
    recovered ??= (async () => {
      const next = new WebGPURenderer({ antialias: false, forceWebGL: trigger === 'context' });
      await next.init();
      return next;
    })();
  };
  const threeHandler = first.onDeviceLost.bind(first);
  first.onDeviceLost = (info) => {
    calls.push({ api: info.api, message: info.message, reason: info.reason });
    threeHandler(info);
    recover();
  };
  const gpu = (first.backend as unknown as { device?: GPUDevice }).device;
  gpu?.lost.then((info) => {
    deviceLost = { reason: info.reason, message: info.message };
    recover();
  });
  const original = console.error;
  console.error = () => {}; // three logs the loss (its default handler); the report says what happened.
  try {
    const before = await draw(first, scene, cam, size);
    if (trigger === 'context') {
      const gl = (first.backend as unknown as { gl: WebGL2RenderingContext }).gl;
      gl.getExtension('WEBGL_lose_context')?.loseContext();
    } else {
      gpu?.destroy();
      if (trigger === 'lost') resolveLost({ reason: 'unknown', message: 'simulated GPU process loss' });
    }
    // Wait for the app's handler (three's or the device's report) to have made the new renderer.
    for (let i = 0; i < 100 && recovered === null; i++) await new Promise((r) => setTimeout(r, 20));
    const next = recovered === null ? null : await (recovered as Promise<WebGPURenderer>);
    const after = next === null ? new Uint8Array(before.length) : await draw(next, scene, cam, size);
    const outlineColour = [Math.round(0.1 * 255), Math.round(0.05 * 255), 0] as const;
    let covered = 0;
    let outlinePixels = 0;
    for (let i = 0; i < before.length; i += 4) {
      if (!hasRgb(before, i, CLEAR)) covered++;
      if (hasRgb(before, i, outlineColour)) outlinePixels++;
    }
    const report: LossReport = {
      backend: backendFlags(next ?? first),
      onDeviceLost: calls,
      deviceLost,
      covered,
      outlinePixels,
      identical: next !== null && before.every((v, i) => v === after[i]),
      recovered: next !== null,
    };
    next?.dispose();
    return report;
  } finally {
    console.error = original;
    for (const m of materials) m.dispose();
  }
}

// ---- Create/dispose cycles -----------------------------------------------------------------------------------

/**
 * `n` cycles, each creating a ShadingNodeMaterial (its own shininess), an outline (createOutlineNode: a new
 * OutlineNodeMaterial) and a SphereImpostorNodeMaterial, drawing them into a target every `every`-th cycle (and
 * the first and last three), and disposing them. Pins of each kind keep the pipelines alive, as a running app
 * has them. The counts before, at their peak and after; the first and last pictures.
 */
async function cycles(backend: Backend, n: number, every: number) {
  const renderer = await gpuRenderer(backend);
  const size = 32;
  const cam = camera([0, 0.4, 6]);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const quad = createImpostorQuad();
  const make = (shininess: number) => {
    const scene = new Scene();
    const mesh = new Mesh(sphere, new ShadingNodeMaterial({ shininess, lights: [light] }));
    mesh.position.x = -1.1;
    const outline = createOutlineNode(mesh, { thickness: 0.05 });
    const impostor = new Mesh(quad, new SphereImpostorNodeMaterial({ shininess, lights: [light] }));
    impostor.position.x = 1.2;
    scene.add(light, mesh, impostor);
    scene.updateMatrixWorld();
    return { scene, materials: [mesh.material, outline.material, impostor.material] as Material[] };
  };
  const pins = make(32);
  const target = new RenderTarget(size, size, { depthBuffer: true });
  const render = async (scene: Scene, read: boolean) => {
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x0000ff, 1);
    renderer.clear();
    renderer.render(scene, cam);
    renderer.setRenderTarget(null);
    return read ? readTarget(renderer, target, size) : null;
  };
  await render(pins.scene, false);
  const before = counts(renderer);
  let peak = before;
  let frames = 0;
  const pictures: Uint8Array[] = [];
  for (let i = 0; i < n; i++) {
    const capture = i < 3 || i >= n - 3;
    // The captured cycles draw the same material as the first; the others each their own shininess.
    const made = make(capture ? 32 : 32 + (i % 7) * 1e-3);
    if (i % every === 0 || capture) {
      const picture = await render(made.scene, capture);
      if (picture) pictures.push(picture);
      frames++;
      peak = maxCounts(peak, counts(renderer));
    }
    for (const m of made.materials) m.dispose();
  }
  const after = counts(renderer);
  for (const m of pins.materials) m.dispose();
  target.dispose();
  const released = counts(renderer);
  const covered = pictures[0].filter((_, i) => i % 4 === 0 && !hasRgb(pictures[0], i, CLEAR)).length;
  return {
    backend: backendFlags(renderer),
    before,
    peak,
    after,
    released,
    frames,
    covered,
    sameAsFirst: pictures.map((p) => p.every((v, i) => v === pictures[0][i])),
  };
}

// ---- Flipping every feature ----------------------------------------------------------------------------------

const texture = (() => {
  const data = new Uint8Array(4 * 4 * 4);
  for (let i = 0; i < 16; i++)
    data.set([200 + (i % 4) * 10, 120 + (i >> 2) * 30, 90, 160 + (i % 3) * 40], 4 * i);
  const t = new DataTexture(data, 4, 4, RGBAFormat);
  t.needsUpdate = true;
  return t;
})();

/** The features flipped: each a name and its values. */
const FEATURES: Array<[string, unknown[]]> = [
  ['shading', ['flat', 'gouraud', 'phong']],
  ['lighting', ['phong', 'blinn-phong']],
  ['celBands', [0, 4]],
  ['map', [null, texture]],
  ['emissiveMap', [null, texture]],
  ['alphaMap', [null, texture]],
  ['transparent', [false, true]],
  ['alphaTest', [0, 0.4]],
  ['side', [FrontSide, DoubleSide, BackSide]],
  ['fog', [false, true]],
  ['outline fog', [false, true]],
];

/**
 * One ShadingNodeMaterial (with vertex colours on the geometry) and its node outline; `flips` times a random
 * feature is set to another of its values (from the random sequence of `seed0`) and a frame drawn. The pipelines, programs and node builds at their largest,
 * after the flips and after disposing; how many distinct states were drawn.
 */
async function flipFeatures(backend: Backend, flips: number, seed0: number) {
  const renderer = await gpuRenderer(backend);
  const size = 24;
  const cam = camera([0, 0.4, 5]);
  const geometry = sphere.clone();
  const colors = new Float32Array(3 * geometry.getAttribute('position').count).fill(0.8);
  geometry.setAttribute('color', new Float32BufferAttribute(colors, 3));
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const material = new ShadingNodeMaterial({ lights: [light], vertexColors: true, emissive: [0.1, 0, 0] });
  const mesh = new Mesh(geometry, material);
  const outline = createOutlineNode(mesh, { thickness: 0.06 });
  const scene = new Scene();
  scene.add(light, mesh);
  scene.updateMatrixWorld();
  const fog = new Fog(0x8080c0, 3, 8);
  const target = new RenderTarget(size, size, { depthBuffer: true });
  const render = () => {
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x0000ff, 1);
    renderer.clear();
    renderer.render(scene, cam);
    renderer.setRenderTarget(null);
  };
  const before = counts(renderer);
  render();
  let peak = counts(renderer);
  const state = new Map<string, unknown>(FEATURES.map(([name, values]) => [name, values[0]]));
  const states = new Set<string>();
  let seed = seed0;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  for (let i = 0; i < flips; i++) {
    // A feature set to another of its values: every flip changes the state.
    const [name, values] = FEATURES[Math.floor(random() * FEATURES.length)];
    const others = values.filter((v) => v !== state.get(name));
    const value = others[Math.floor(random() * others.length)];
    state.set(name, value);
    if (name === 'fog') scene.fog = value ? fog : null;
    else if (name === 'outline fog') outline.material.fog = value as boolean;
    else (material as unknown as Record<string, unknown>)[name] = value;
    if (name !== 'fog' && name !== 'outline fog') material.needsUpdate = true;
    render();
    states.add([...state.values()].map((v) => (v === texture ? 'tex' : String(v))).join(' '));
    peak = maxCounts(peak, counts(renderer));
  }
  const after = counts(renderer);
  const picture = await readTarget(renderer, target, size);
  material.dispose();
  outline.material.dispose();
  geometry.dispose();
  target.dispose();
  const released = counts(renderer);
  return {
    backend: backendFlags(renderer),
    before,
    peak,
    after,
    released,
    states: states.size,
    drawn: picture.filter((_, i) => i % 4 === 0 && !hasRgb(picture, i, CLEAR)).length,
  };
}

async function backendInfo(backend: Backend) {
  return backendFlags(await gpuRenderer(backend));
}

const api = {
  backendInfo,
  instanceExtremes,
  surfaceExtremes,
  lightExtremes,
  deviceLoss,
  cycles,
  flipFeatures,
};
export type WebGPUReliabilityHarness = typeof api;
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
