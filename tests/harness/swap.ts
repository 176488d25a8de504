// Harness for tests/material-swap.spec.ts (issue 22): swapMaterials on glTF models. The models are built in code,
// exported with three's GLTFExporter (binary GLB, nothing downloaded) and loaded back with GLTFLoader, as an app
// gets them: a textured mesh, a vertex-coloured mesh, a skinned mesh posed by its animation clip, instances
// (EXT_mesh_gpu_instancing), a multi-material box as glTF gives it (one mesh per primitive) and as one mesh with
// groups and a material array, two meshes sharing one material, and a mesh with a ShaderMaterial (added after
// loading: glTF cannot hold one), and two more material kinds glTF carries: an unlit mesh (KHR_materials_unlit →
// MeshBasicMaterial) and a clearcoat one (KHR_materials_clearcoat → MeshPhysicalMaterial). Each model sits in its own cell of a 5 × 2 grid, so one render gives every
// model's picture, lit by three's five light kinds as three's examples light a scene.
//
// The loaded MeshStandardMaterials are the 'standard' mode; 'lambert' and 'phong' (specular 0) re-make them as an
// app tuned for those materials has them, keeping which meshes share a material. three's own pictures are the
// oracle: coverage, the pixels of diffuse-only materials, the picture after restore().
import {
  type ShadingMaterial,
  type SwapMaterialsOptions,
  type SwappedMaterials,
  swapMaterials,
} from '@shadelab/material';
import {
  AmbientLight,
  AnimationClip,
  AnimationMixer,
  Bone,
  BoxGeometry,
  type BufferGeometry,
  Color,
  DataTexture,
  DirectionalLight,
  Euler,
  Float32BufferAttribute,
  Group,
  HemisphereLight,
  IcosahedronGeometry,
  InstancedMesh,
  type Material,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshPhongMaterial,
  MeshPhysicalMaterial,
  MeshStandardMaterial,
  type Object3D,
  PerspectiveCamera,
  PointLight,
  Quaternion,
  QuaternionKeyframeTrack,
  RGBAFormat,
  Scene,
  ShaderMaterial,
  Skeleton,
  SkinnedMesh,
  SphereGeometry,
  SpotLight,
  SRGBColorSpace,
  type Texture,
  TorusGeometry,
  TorusKnotGeometry,
  Vector3,
  WebGLRenderer,
} from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { mergeGeometries } from 'three/addons/utils/BufferGeometryUtils.js';
import { skinnedCylinder } from './lib/deform';
import { hasRgb, maxRgbDelta, readCanvas } from './lib/pixels';

declare global {
  interface Window {
    swapHarness: SwapHarness;
  }
}

/** Which materials the loaded models wear when swapped: as loaded, or re-made as an app tuned for Lambert/Phong. */
export type MaterialMode = 'standard' | 'lambert' | 'phong';

/** The models, in their cells' order (row by row, left to right). */
export const CASES = [
  'textured',
  'vertexColours',
  'skinned',
  'instanced',
  'unlit',
  'multiPrimitives',
  'multiArray',
  'shared',
  'shader',
  'physical',
] as const;
export type CaseName = (typeof CASES)[number];

/** Two pictures of one cell compared: `a` is three's (the original materials), `b` the other. */
export interface PairStats {
  /** Pixels `a` draws (not the clear colour). */
  covered: number;
  /** Pixels drawn in one picture and not in the other. */
  coverageMismatches: number;
  /** Pixels whose 3 × 3 neighbourhood both pictures draw (away from silhouettes), compared by colour. */
  compared: number;
  /** Mean over the compared pixels of max |Δ| over RGB (1/255). */
  mean: number;
  /** Largest max |Δ| over RGB of a compared pixel (1/255). */
  max: number;
  /** The compared pixel with the largest difference: position and both colours. */
  worst: string;
  /** Pixels of the whole cell that differ at all, and the largest max |Δ| over RGB among them (1/255). */
  diffPixels: number;
  maxDiff: number;
}

export interface CaseReport {
  name: CaseName;
  /** The original materials' picture against the swapped one. */
  swap: PairStats;
  /** The original materials' picture against the one after restore(). */
  restore: PairStats;
}

export interface SwapRun {
  mode: MaterialMode;
  /** The options the swap was given. */
  options: SwapMaterialsOptions;
  cases: CaseReport[];
  /** The whole canvas after restore() against before the swap. */
  restoreDiffPixels: number;
  restoreMaxDiff: number;
  /** Drawn pixels within 2 px of a cell's border in any picture (the cells must not touch). */
  borderCovered: number;
  /** `skipped` as the swap returned it: the object's name, the material's type, the reason. */
  skipped: { object: string; material: string; reason: string }[];
  /** What console.warn printed during the swap, and during restore(). */
  swapWarnings: string[];
  restoreWarnings: string[];
  /** ShadingMaterials the swap returned, and the distinct original materials it should have converted. */
  made: number;
  distinctOriginals: number;
  /** Every broken expectation about the objects (references, sharing, order, disposal), one sentence each. */
  failures: string[];
}

/** What must come back to its baseline after the swap/restore cycles. */
export interface InfoCounts {
  programs: number;
  geometries: number;
  textures: number;
}

export interface CycleRun {
  cycles: number;
  /** A render every `every` cycles (swapped, then restored). */
  every: number;
  frames: number;
  before: InfoCounts;
  /** The largest counts seen while swapped (the cycles did hold something). */
  peak: InfoCounts;
  after: InfoCounts;
  /** Distinct original materials a swap converts. */
  distinctOriginals: number;
  /** Made materials in all, and how many were disposed exactly once by their restore(). */
  made: number;
  disposedOnce: number;
  /** Dispose events on anything the user owns (original materials, their textures, the geometries). */
  userDisposals: number;
  /** console.warn calls during the cycles (one per swap: the ShaderMaterial mesh). */
  warnings: number;
  failures: string[];
  /** Time of the loop's JavaScript, ms (reported, not asserted; the GPU work finishes at the read-back after it). */
  ms: number;
}

export interface SwapHarness {
  cases: readonly CaseName[];
  /** Loading facts checked once: what GLTFLoader gave back. */
  loaded: {
    instanced: boolean;
    instanceColors: boolean;
    skinned: boolean;
    animations: number;
    multiPrimitivesChildren: number;
    sharedLoadedShared: boolean;
    /** The material types GLTFLoader made for the unlit and the clearcoat model. */
    unlitType: string;
    physicalType: string;
    extensionsUsed: string[];
  };
  run(mode: MaterialMode, options?: SwapMaterialsOptions): SwapRun;
  /** The original and the swapped picture of `mode` as PNG data URLs (to look at; restores after). */
  pictures(mode: MaterialMode): { original: string; swapped: string };
  cycles(cycles: number, every: number, options?: SwapMaterialsOptions): CycleRun;
}

// ---------------------------------------------------------------------------------------------------------------
// The renderer, the camera (the z = 0 plane from x −10 … 10, y −4 … 4 fills the canvas: 40 px a unit, 160 px a
// cell) and the lights, as three's examples use them.

const COLUMNS = 5;
const WIDTH = 800;
const HEIGHT = 320;
const CELL = 160;
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(WIDTH, HEIGHT, false);
renderer.setClearColor(0x0000ff, 1); // pure blue: never a lit colour here
const CLEAR = [0, 0, 255] as const;

const camera = new PerspectiveCamera((2 * Math.atan(4 / 20) * 180) / Math.PI, WIDTH / HEIGHT, 1, 100);
camera.position.set(0, 0, 20);
camera.lookAt(0, 0, 0);

const scene = new Scene();
scene.add(new HemisphereLight(0xffffff, 0x8d8d8d, 0.8));
scene.add(new AmbientLight(0x404040, 1));
const sun = new DirectionalLight(0xffffff, 1.5);
sun.position.set(5, 10, 7.5);
scene.add(sun);
const point = new PointLight(0xffaa88, 40, 0, 2);
point.position.set(-4, 3, 6);
scene.add(point);
// Its cone's edge crosses the multi-material boxes and the shared-material meshes.
const spot = new SpotLight(0x88aaff, 80, 0, Math.PI / 7, 0.3, 2);
spot.position.set(-2, -6, 10);
spot.target.position.set(-1, -2, 0);
scene.add(spot, spot.target);

/** The centre of a case's cell on the z = 0 plane. */
function cellCentre(name: CaseName): Vector3 {
  const i = CASES.indexOf(name);
  return new Vector3(-8 + 4 * (i % COLUMNS), 2 - 4 * Math.floor(i / COLUMNS), 0);
}

// ---------------------------------------------------------------------------------------------------------------
// The models, built in code.

function checkerTexture(n = 16): DataTexture {
  const step = Math.floor(200 / n);
  const data = new Uint8Array(4 * n * n);
  for (let y = 0; y < n; y++)
    for (let x = 0; x < n; x++)
      data.set([40 + step * x, 40 + step * y, (x + y) % 2 ? 210 : 70, 255], 4 * (y * n + x));
  const texture = new DataTexture(data, n, n, RGBAFormat);
  texture.colorSpace = SRGBColorSpace;
  texture.needsUpdate = true;
  return texture;
}

function standard(color: number, extra: ConstructorParameters<typeof MeshStandardMaterial>[0] = {}) {
  const name = `#${color.toString(16).padStart(6, '0')}`;
  return new MeshStandardMaterial({ name, color, roughness: 0.5, metalness: 0, ...extra });
}

function place(object: Object3D, name: CaseName): Object3D {
  object.name = name;
  object.position.copy(cellCentre(name));
  return object;
}

function buildSource(): { source: Scene; clip: AnimationClip } {
  const source = new Scene();

  const textured = new Mesh(new SphereGeometry(1.3, 48, 24), standard(0xffffff, { map: checkerTexture() }));
  textured.rotation.set(0.3, -0.6, 0);
  source.add(place(textured, 'textured'));

  const knot = new TorusKnotGeometry(0.8, 0.28, 128, 16);
  const p = knot.getAttribute('position');
  const colours = new Float32Array(3 * p.count);
  for (let i = 0; i < p.count; i++) {
    colours.set(
      [0.5 + 0.45 * (p.getX(i) / 1.2), 0.5 + 0.45 * (p.getY(i) / 1.2), 0.5 + 0.45 * (p.getZ(i) / 0.5)].map(
        (c) => Math.min(Math.max(c, 0.05), 0.95),
      ),
      3 * i,
    );
  }
  knot.setAttribute('color', new Float32BufferAttribute(colours, 3));
  const vertexColoured = new Mesh(knot, standard(0xffffff, { vertexColors: true }));
  source.add(place(vertexColoured, 'vertexColours'));

  // The skinned cylinder (bones at y = −1.5 and 0), bent by its clip.
  const skinnedGroup = new Group();
  place(skinnedGroup, 'skinned');
  skinnedGroup.scale.setScalar(0.75);
  const skinned = new SkinnedMesh(skinnedCylinder(0.45, 24, 16), standard(0xd08050));
  skinned.name = 'skinnedMesh';
  const rootBone = new Bone();
  rootBone.name = 'skinRoot';
  rootBone.position.y = -1.5;
  const bendBone = new Bone();
  bendBone.name = 'skinBend';
  bendBone.position.y = 1.5;
  rootBone.add(bendBone);
  skinned.add(rootBone);
  skinnedGroup.add(skinned);
  source.add(skinnedGroup);
  source.updateMatrixWorld(true);
  skinned.bind(new Skeleton([rootBone, bendBone]));
  const q0 = new Quaternion();
  const q1 = new Quaternion().setFromEuler(new Euler(0.4, 0, 1.2));
  const clip = new AnimationClip('bend', 1, [
    new QuaternionKeyframeTrack('skinBend.quaternion', [0, 1], [...q0.toArray(), ...q1.toArray()]),
  ]);

  const instanced = new InstancedMesh(new IcosahedronGeometry(0.55, 2), standard(0xffffff), 4);
  const m = new Matrix4();
  const offsets = [
    [-0.8, 0.8, 0],
    [0.8, 0.8, 0.3],
    [-0.8, -0.8, -0.3],
    [0.8, -0.8, 0],
  ];
  const tints = [0xe07050, 0x60c070, 0x7080e0, 0xd0c060];
  offsets.forEach((o, i) => {
    m.compose(
      new Vector3(...(o as [number, number, number])),
      new Quaternion().setFromEuler(new Euler(i * 0.5, i * 0.3, 0)),
      new Vector3(1, 0.8 + 0.1 * i, 1),
    );
    instanced.setMatrixAt(i, m);
    instanced.setColorAt(i, new Color(tints[i]));
  });
  source.add(place(instanced, 'instanced'));

  // Unlit: glTF's KHR_materials_unlit, which GLTFLoader gives as a MeshBasicMaterial (colour × map).
  const unlit = new Mesh(
    new TorusGeometry(0.9, 0.4, 24, 64),
    new MeshBasicMaterial({ name: 'unlit', color: 0xffd0a0, map: checkerTexture(8) }),
  );
  unlit.rotation.set(0.9, 0.2, 0);
  source.add(place(unlit, 'unlit'));

  // Clearcoat: KHR_materials_clearcoat, which GLTFLoader gives as a MeshPhysicalMaterial.
  const physical = new Mesh(
    new SphereGeometry(1.2, 48, 24),
    new MeshPhysicalMaterial({
      name: 'clearcoat',
      color: 0xc05090,
      roughness: 0.45,
      metalness: 0,
      clearcoat: 0.7,
      clearcoatRoughness: 0.15,
    }),
  );
  source.add(place(physical, 'physical'));

  // A box whose six faces (groups) wear three materials, each twice; the faces in view (+x, +y, +z) wear all three.
  for (const name of ['multiPrimitives', 'multiArray'] as const) {
    const faces = [standard(0xe06040), standard(0x50b060), standard(0x6070d0)];
    const box = new Mesh(new BoxGeometry(1.7, 1.7, 1.7), [...faces, ...faces]);
    box.rotation.set(0.6, -0.7, 0);
    source.add(place(box, name));
  }

  const sharedGroup = new Group();
  place(sharedGroup, 'shared');
  const one = standard(0x88cc44);
  const sharedA = new Mesh(new SphereGeometry(0.8, 32, 16), one);
  sharedA.name = 'sharedA';
  sharedA.position.set(-0.8, 0.7, 0);
  const sharedB = new Mesh(new TorusGeometry(0.6, 0.25, 16, 48), one);
  sharedB.name = 'sharedB';
  sharedB.position.set(0.8, -0.7, 0);
  sharedB.rotation.x = 0.8;
  sharedGroup.add(sharedA, sharedB);
  source.add(sharedGroup);

  return { source, clip };
}

// ---------------------------------------------------------------------------------------------------------------
// Export, load, and what an app adds after loading.

const { source, clip } = buildSource();
const glb = (await new GLTFExporter().parseAsync(source, {
  binary: true,
  animations: [clip],
})) as ArrayBuffer;
const jsonLength = new DataView(glb).getUint32(12, true);
const json = JSON.parse(new TextDecoder().decode(new Uint8Array(glb, 20, jsonLength))) as {
  extensionsUsed?: string[];
};
const gltf = await new GLTFLoader().parseAsync(glb, '');
const root = gltf.scene;
scene.add(root);

const mixer = new AnimationMixer(root);
for (const a of gltf.animations) mixer.clipAction(a).play();
mixer.setTime(0.6);

const byName = (name: string): Object3D => {
  const found = root.getObjectByName(name);
  if (!found) throw new Error(`the loaded scene has no object named ${name}`);
  return found;
};

// glTF gives a multi-material mesh as a Group with one Mesh per primitive; an app may merge them back into one
// mesh with groups and a material array (the materials repeat: each is on two faces).
const multiArrayGroup = byName('multiArray') as Group;
const parts = multiArrayGroup.children.filter((c): c is Mesh => (c as Mesh).isMesh === true);
const merged = new Mesh(
  mergeGeometries(
    parts.map((c) => c.geometry),
    true,
  ),
  parts.map((c) => c.material as Material),
);
merged.name = 'multiArrayMesh';
for (const c of parts) multiArrayGroup.remove(c);
multiArrayGroup.add(merged);

// A ShaderMaterial mesh, as an app adds its own effect: glTF cannot hold one.
const shaderMesh = new Mesh(
  new TorusKnotGeometry(0.9, 0.3, 96, 12),
  new ShaderMaterial({
    vertexShader: /* glsl */ `
      varying vec3 vNormal;
      void main() {
        vNormal = normalize(normalMatrix * normal);
        gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
      }`,
    fragmentShader: /* glsl */ `
      varying vec3 vNormal;
      void main() { gl_FragColor = vec4(0.5 * normalize(vNormal) + 0.5, 1.0); }`,
  }),
);
shaderMesh.name = 'shaderMesh';
const shaderGroup = new Group();
place(shaderGroup, 'shader');
shaderGroup.add(shaderMesh);
root.add(shaderGroup);
root.updateMatrixWorld(true);

const meshes: Mesh[] = [];
root.traverse((o) => {
  if ((o as Mesh).isMesh) meshes.push(o as Mesh);
});
/** Which case an object belongs to (its ancestor named after a case). */
function caseOf(object: Object3D): string {
  for (let o: Object3D | null = object; o; o = o.parent)
    if ((CASES as readonly string[]).includes(o.name)) return o.name;
  return `(no case: ${object.name})`;
}

type Slot = Material | Material[];
const loadedMaterials = new Map<Mesh, Slot>(meshes.map((mesh) => [mesh, mesh.material as Slot]));

function remake(mode: 'lambert' | 'phong', cache: Map<Material, Material>, m: Material): Material {
  if (!(m instanceof MeshStandardMaterial)) return m;
  let made = cache.get(m);
  if (!made) {
    const common = {
      name: m.name,
      color: m.color,
      map: m.map,
      vertexColors: m.vertexColors,
      side: m.side,
      transparent: m.transparent,
      opacity: m.opacity,
      alphaTest: m.alphaTest,
    };
    made =
      mode === 'lambert'
        ? new MeshLambertMaterial(common)
        : new MeshPhongMaterial({ ...common, specular: 0x000000, shininess: 30 });
    cache.set(m, made);
  }
  return made;
}

const modeMaterials = new Map<MaterialMode, Map<Mesh, Slot>>([['standard', loadedMaterials]]);
for (const mode of ['lambert', 'phong'] as const) {
  const cache = new Map<Material, Material>();
  modeMaterials.set(
    mode,
    new Map(
      meshes.map((mesh) => {
        const slot = loadedMaterials.get(mesh)!;
        return [
          mesh,
          Array.isArray(slot) ? slot.map((x) => remake(mode, cache, x)) : remake(mode, cache, slot),
        ];
      }),
    ),
  );
}

function setMode(mode: MaterialMode): Map<Mesh, Slot> {
  const slots = modeMaterials.get(mode)!;
  for (const [mesh, slot] of slots) mesh.material = slot;
  return slots;
}

// ---------------------------------------------------------------------------------------------------------------
// Watching: console.warn, dispose events on what the user owns.

const realWarn = console.warn.bind(console);
let warnings: string[] | null = null;
let forward = true;
console.warn = (...args: unknown[]) => {
  warnings?.push(args.map(String).join(' '));
  if (forward) realWarn(...args);
};
/**
 * Runs `run`, returning what console.warn printed meanwhile. The cycles keep the warnings in the page
 * (`quiet`): a thousand forwarded messages cost the test runner far more than the cycles themselves.
 */
function capture<T>(run: () => T, quiet = false): [T, string[]] {
  warnings = [];
  forward = !quiet;
  try {
    return [run(), warnings];
  } finally {
    warnings = null;
    forward = true;
  }
}

const texturesOf = (m: Material): Texture[] =>
  Object.values(m).filter((v): v is Texture => (v as Texture | null)?.isTexture === true);
let userDisposals = 0;
const userDisposed: string[] = [];
const watched = new Set<object>();
function watch(target: Material | Texture | BufferGeometry, label: string): void {
  if (watched.has(target)) return;
  watched.add(target);
  target.addEventListener('dispose', () => {
    userDisposals++;
    userDisposed.push(label);
  });
}
for (const slots of modeMaterials.values()) {
  for (const [mesh, slot] of slots) {
    watch(mesh.geometry, `${mesh.name}'s geometry`);
    for (const m of Array.isArray(slot) ? slot : [slot]) {
      watch(m, `${mesh.name}'s ${m.type}`);
      for (const t of texturesOf(m)) watch(t, `${mesh.name}'s texture`);
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Pictures.

function picture(): Uint8Array {
  renderer.render(scene, camera);
  return readCanvas(renderer, WIDTH, HEIGHT);
}

/** The pixel rectangle of a case's cell (GL rows, bottom-up). */
function cellRect(name: CaseName): { x0: number; y0: number } {
  const i = CASES.indexOf(name);
  return { x0: CELL * (i % COLUMNS), y0: CELL * (1 - Math.floor(i / COLUMNS)) };
}

const drawn = (p: Uint8Array, x: number, y: number): boolean => !hasRgb(p, 4 * (y * WIDTH + x), CLEAR);

function compareCell(a: Uint8Array, b: Uint8Array, name: CaseName): PairStats {
  const { x0, y0 } = cellRect(name);
  const s: PairStats = {
    covered: 0,
    coverageMismatches: 0,
    compared: 0,
    mean: 0,
    max: 0,
    worst: '',
    diffPixels: 0,
    maxDiff: 0,
  };
  let sum = 0;
  for (let y = y0; y < y0 + CELL; y++) {
    for (let x = x0; x < x0 + CELL; x++) {
      const i = 4 * (y * WIDTH + x);
      const inA = drawn(a, x, y);
      if (inA) s.covered++;
      if (inA !== drawn(b, x, y)) s.coverageMismatches++;
      const d = maxRgbDelta(a, b, i);
      if (d > 0) s.diffPixels++;
      s.maxDiff = Math.max(s.maxDiff, d);
      let interior = x > x0 && y > y0 && x < x0 + CELL - 1 && y < y0 + CELL - 1;
      for (let dy = -1; interior && dy <= 1; dy++)
        for (let dx = -1; interior && dx <= 1; dx++)
          interior = drawn(a, x + dx, y + dy) && drawn(b, x + dx, y + dy);
      if (!interior) continue;
      s.compared++;
      sum += d;
      if (d > s.max) {
        s.max = d;
        s.worst = `(${x - x0}, ${y - y0}) of the cell: three ${a.slice(i, i + 3).join(',')}, other ${b.slice(i, i + 3).join(',')}`;
      }
    }
  }
  s.mean = s.compared ? sum / s.compared : 0;
  return s;
}

function borderCovered(p: Uint8Array): number {
  let n = 0;
  for (let y = 0; y < HEIGHT; y++)
    for (let x = 0; x < WIDTH; x++) {
      const cx = x % CELL;
      const cy = y % CELL;
      if ((cx < 2 || cx >= CELL - 2 || cy < 2 || cy >= CELL - 2) && drawn(p, x, y)) n++;
    }
  return n;
}

// ---------------------------------------------------------------------------------------------------------------
// The checks of one swap and its restore().

const isShading = (m: unknown): m is ShadingMaterial =>
  (m as ShadingMaterial | null)?.isShadingMaterial === true;

/** The materials of `slots` in traversal order, each once, without the ShaderMaterial (which is skipped). */
function distinctInOrder(slots: Map<Mesh, Slot>): Material[] {
  const seen = new Set<Material>();
  for (const mesh of meshes)
    for (const m of [slots.get(mesh)!].flat())
      if (!(m as ShaderMaterial).isShaderMaterial && !seen.has(m)) seen.add(m);
  return [...seen];
}

/** Checks the swapped scene against the originals; returns the failures and the made materials' dispose counts. */
function checkSwapped(
  slots: Map<Mesh, Slot>,
  swap: SwappedMaterials,
  failures: string[],
): Map<Material, number> {
  const madeFor = new Map<Material, Material>();
  for (const mesh of meshes) {
    const was = slots.get(mesh)!;
    const now = mesh.material as Slot;
    const where = `${caseOf(mesh)} (${mesh.name || mesh.type})`;
    if (Array.isArray(was) !== Array.isArray(now)) {
      failures.push(`${where}: material array ${Array.isArray(was)} became ${Array.isArray(now)}`);
      continue;
    }
    const pairs: [Material, Material][] = Array.isArray(was)
      ? was.map((m, k) => [m, (now as Material[])[k]])
      : [[was, now as Material]];
    if (Array.isArray(now) && now.length !== (was as Material[]).length)
      failures.push(`${where}: array of ${(was as Material[]).length} became ${now.length}`);
    for (const [w, n] of pairs) {
      if ((w as ShaderMaterial).isShaderMaterial) {
        if (n !== w) failures.push(`${where}: its ShaderMaterial was replaced`);
        continue;
      }
      if (!isShading(n)) {
        failures.push(`${where}: ${w.type} became ${n?.type}, not a ShadingMaterial`);
        continue;
      }
      const before = madeFor.get(w);
      if (before && before !== n) failures.push(`${where}: one ${w.type} became two ShadingMaterials`);
      madeFor.set(w, n);
    }
  }
  const made = [...madeFor.values()];
  if (new Set(made).size !== made.length)
    failures.push('two different original materials became one ShadingMaterial');
  const order = distinctInOrder(slots).map((m) => madeFor.get(m));
  const listed = swap.materials;
  if (listed.length !== order.length || listed.some((m, k) => m !== order[k]))
    failures.push(
      `swap.materials: ${listed.length} materials, expected the ${order.length} made, in traversal order of their originals`,
    );
  const disposals = new Map<Material, number>();
  for (const m of new Set([...made, ...listed])) {
    disposals.set(m, 0);
    m.addEventListener('dispose', () => disposals.set(m, (disposals.get(m) ?? 0) + 1));
  }
  return disposals;
}

function checkRestored(slots: Map<Mesh, Slot>, failures: string[], when: string): void {
  for (const mesh of meshes) {
    const was = slots.get(mesh)!;
    const now = mesh.material as Slot;
    const where = `${caseOf(mesh)} (${mesh.name || mesh.type})`;
    if (now !== was)
      failures.push(
        `${when}: ${where} does not have its original material${Array.isArray(was) ? ' array' : ''} back`,
      );
    if (Array.isArray(was) && was.some((m, k) => (now as Material[])[k] !== m))
      failures.push(`${when}: ${where}'s material array does not hold its original materials`);
  }
}

function disposalFailures(disposals: Map<Material, number>, failures: string[], when: string): void {
  const wrong = [...disposals.values()].filter((n) => n !== 1).length;
  if (wrong) failures.push(`${when}: ${wrong} of ${disposals.size} made materials not disposed exactly once`);
}

function run(mode: MaterialMode, options: SwapMaterialsOptions = {}): SwapRun {
  const slots = setMode(mode);
  const failures: string[] = [];
  const disposalsBefore = userDisposals;
  const original = picture();
  const [swap, swapWarnings] = capture(() => swapMaterials(root, options));
  const disposals = checkSwapped(slots, swap, failures);
  const swapped = picture();
  for (const m of swap.materials)
    if ((renderer.properties.get(m) as { currentProgram?: unknown }).currentProgram === undefined)
      failures.push(`the made material for ${m.name || m.uuid} was not drawn`);
  const [, restoreWarnings] = capture(() => swap.restore());
  checkRestored(slots, failures, 'after restore()');
  disposalFailures(disposals, failures, 'after restore()');
  const restored = picture();
  swap.restore(); // idempotent: nothing changes, nothing disposed twice
  checkRestored(slots, failures, 'after a second restore()');
  disposalFailures(disposals, failures, 'after a second restore()');
  if (userDisposals !== disposalsBefore)
    failures.push(`disposed what the user owns: ${userDisposed.slice(-5).join(', ')}`);
  let restoreDiffPixels = 0;
  let restoreMaxDiff = 0;
  for (let i = 0; i < original.length; i += 4) {
    const d = maxRgbDelta(original, restored, i);
    if (d) restoreDiffPixels++;
    restoreMaxDiff = Math.max(restoreMaxDiff, d);
  }
  return {
    mode,
    options,
    cases: CASES.map((name) => ({
      name,
      swap: compareCell(original, swapped, name),
      restore: compareCell(original, restored, name),
    })),
    restoreDiffPixels,
    restoreMaxDiff,
    borderCovered: Math.max(borderCovered(original), borderCovered(swapped)),
    skipped: swap.skipped.map((s) => ({
      object: s.object.name,
      material: s.material?.type ?? 'null',
      reason: s.reason,
    })),
    swapWarnings,
    restoreWarnings,
    made: swap.materials.length,
    distinctOriginals: distinctInOrder(slots).length,
    failures,
  };
}

function pictures(mode: MaterialMode): { original: string; swapped: string } {
  setMode(mode);
  renderer.render(scene, camera);
  const original = canvas.toDataURL('image/png');
  const [swap] = capture(() => swapMaterials(root), true);
  renderer.render(scene, camera);
  const swapped = canvas.toDataURL('image/png');
  swap.restore();
  return { original, swapped };
}

function counts(): InfoCounts {
  return {
    programs: renderer.info.programs?.length ?? 0,
    geometries: renderer.info.memory.geometries,
    textures: renderer.info.memory.textures,
  };
}

function cycles(n: number, every: number, options: SwapMaterialsOptions = {}): CycleRun {
  const slots = setMode('standard');
  const failures: string[] = [];
  picture();
  const before = counts();
  const peak = { ...before };
  const disposalsBefore = userDisposals;
  let frames = 0;
  let made = 0;
  let disposedOnce = 0;
  let warned = 0;
  const start = performance.now();
  for (let i = 0; i < n; i++) {
    const draw = i % every === 0;
    const [swap, w] = capture(() => swapMaterials(root, options), true);
    warned += w.length;
    const disposals = new Map<Material, number>();
    for (const m of swap.materials) {
      disposals.set(m, 0);
      m.addEventListener('dispose', () => disposals.set(m, (disposals.get(m) ?? 0) + 1));
    }
    made += disposals.size;
    if (draw) {
      renderer.render(scene, camera);
      frames++;
      const now = counts();
      for (const k of Object.keys(peak) as (keyof InfoCounts)[]) peak[k] = Math.max(peak[k], now[k]);
    }
    const [, rw] = capture(() => swap.restore(), true);
    warned += rw.length;
    disposedOnce += [...disposals.values()].filter((c) => c === 1).length;
    if (draw) {
      renderer.render(scene, camera);
      frames++;
    }
  }
  const ms = performance.now() - start;
  checkRestored(slots, failures, `after ${n} cycles`);
  picture();
  frames++;
  return {
    cycles: n,
    every,
    frames,
    before,
    peak,
    after: counts(),
    distinctOriginals: distinctInOrder(slots).length,
    made,
    disposedOnce,
    userDisposals: userDisposals - disposalsBefore,
    warnings: warned,
    failures,
    ms,
  };
}

const multiPrimitives = byName('multiPrimitives');
window.swapHarness = {
  cases: CASES,
  loaded: {
    instanced: (byName('instanced') as InstancedMesh).isInstancedMesh === true,
    instanceColors: (byName('instanced') as InstancedMesh).instanceColor !== null,
    skinned: meshes.some((m) => (m as SkinnedMesh).isSkinnedMesh),
    animations: gltf.animations.length,
    multiPrimitivesChildren: multiPrimitives.children.filter((c) => (c as Mesh).isMesh).length,
    sharedLoadedShared: (byName('sharedA') as Mesh).material === (byName('sharedB') as Mesh).material,
    unlitType: ((byName('unlit') as Mesh).material as Material).type,
    physicalType: ((byName('physical') as Mesh).material as Material).type,
    extensionsUsed: json.extensionsUsed ?? [],
  },
  run,
  pictures,
  cycles,
};
document.body.dataset.ready = '1';
