// Harness for tests/material-webgpu-outline.spec.ts: OutlineNodeMaterial (createOutlineNode) under WebGPURenderer,
// on its WebGPU backend and (forceWebGL) its WebGL2 backend, rendered offscreen into a RenderTarget and read back,
// against two references in the same scene: OutlineMaterial (createOutline) under WebGLRenderer, and the hull built
// on the CPU from three's own deformation (Mesh.getVertexPosition: morph targets and bones; the instance and object
// matrices; as tests/harness/outline-impostor.ts builds it for the WebGL outline) drawn by three's own
// MeshBasicNodeMaterial on the same WebGPURenderer.
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import { createOutlineNode, OutlineNodeMaterial } from '@shadelab/material/webgpu';
import {
  BackSide,
  Bone,
  BufferAttribute,
  BufferGeometry,
  type Camera,
  Euler,
  Float32BufferAttribute,
  InstancedMesh,
  type Material,
  Matrix3,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  PerspectiveCamera,
  Quaternion,
  Scene,
  Skeleton,
  SkinnedMesh,
  SphereGeometry,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { MeshBasicNodeMaterial, RenderTarget } from 'three/webgpu';
import { deformNormal, instanceSkinned, skinnedCylinder } from './lib/deform';
import { thrown } from './lib/errors';
import { hasRgb } from './lib/pixels';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';

export type { Backend };

/** The clear colour in RGB: where nothing was drawn. */
const CLEAR = [0, 0, 255] as const;

/** One instance: position, Euler rotation, scale. */
export interface Instance {
  position: readonly [number, number, number];
  rotation?: readonly [number, number, number];
  scale?: readonly [number, number, number];
}

/** What is outlined. 'sphere' is a sphere without normals flagged `userData.isSphere` (normal = position). */
export type OutlineObject = 'mesh' | 'sphere' | 'skinned' | 'morphed' | 'instanced' | 'instanced-skinned';

export interface OutlineConfig {
  object: OutlineObject;
  /** Outline width, world units. */
  thickness: number;
  instances?: readonly Instance[];
  size?: number;
}

export interface OutlineStats {
  backend: { isWebGPUBackend: boolean; isWebGLBackend: boolean };
  /** Pixels of the outline's colour (pure black) in the node outline's picture, the CPU hull's and the GLSL one's. */
  ring: number;
  oracleRing: number;
  glRing: number;
  /** Pixels of the mesh (red) in the node outline's picture and the CPU hull's; in the GLSL one's. */
  body: number;
  glBody: number;
  /** Pixels whose 3 × 3 neighbourhood is one class (clear, outline, mesh) in the CPU hull's picture; how many differ. */
  compared: number;
  mismatches: number;
  /** The same against WebGLRenderer + OutlineMaterial's picture (its classes, its edges). */
  glCompared: number;
  glMismatches: number;
  /** The same comparison against the hull of the undeformed, uninstanced geometry (not vacuous). */
  staleMismatches: number;
  /** Pixels of a colour that is none of the three classes' (a NaN vertex, a stray triangle). */
  stray: number;
}

function instanceMatrix(instance: Instance): Matrix4 {
  return new Matrix4().compose(
    new Vector3(...instance.position),
    new Quaternion().setFromEuler(new Euler(...(instance.rotation ?? [0, 0, 0]))),
    new Vector3(...(instance.scale ?? [1, 1, 1])),
  );
}

/** A smooth sphere with one morph target: stretched to (1.6, 0.8, 1.2), normals to match. */
function morphedSphere(): BufferGeometry {
  const g = new SphereGeometry(1, 48, 24);
  const position = g.getAttribute('position');
  const k = [1.6, 0.8, 1.2];
  const p = new Float32Array(3 * position.count);
  const n = new Float32Array(3 * position.count);
  for (let i = 0; i < position.count; i++) {
    const [x, y, z] = [position.getX(i), position.getY(i), position.getZ(i)];
    p.set([x * k[0], y * k[1], z * k[2]], 3 * i);
    const l = Math.hypot(x / k[0], y / k[1], z / k[2]);
    n.set([x / k[0] / l, y / k[1] / l, z / k[2] / l], 3 * i);
  }
  g.morphAttributes.position = [new Float32BufferAttribute(p, 3)];
  g.morphAttributes.normal = [new Float32BufferAttribute(n, 3)];
  return g;
}

/** The geometries (made once per renderer: the pictures compare the same vertices; a skinned geometry drawn by
 * WebGPURenderer is not drawn by WebGLRenderer afterwards). */
function makeGeometries() {
  const analytic = new SphereGeometry(1, 48, 24);
  analytic.deleteAttribute('normal');
  analytic.userData.isSphere = true;
  return {
    sphere: new SphereGeometry(1, 48, 24),
    analytic,
    morphed: morphedSphere(),
    cylinder: skinnedCylinder(0.5, 24, 12),
  };
}
const geometrySets = { gpu: makeGeometries(), gl: makeGeometries() };

/** The outlined object (its body drawn with `body`) and its instance matrices (one identity when not instanced). */
function makeObject(
  config: OutlineConfig,
  body: Material,
  api: 'gpu' | 'gl',
): { object: Mesh; matrices: Matrix4[] } {
  const geometries = geometrySets[api];
  const specs = config.instances ?? [{ position: [0, 0, 0] }];
  let matrices = [new Matrix4()];
  if (config.object === 'skinned' || config.object === 'instanced-skinned') {
    const mesh = new SkinnedMesh(geometries.cylinder, body);
    const root = new Bone();
    root.position.set(0, -1.5, 0);
    const joint = new Bone();
    joint.position.set(0, 1.5, 0);
    root.add(joint);
    mesh.add(root);
    mesh.bind(new Skeleton([root, joint]));
    joint.rotation.z = 0.9;
    mesh.rotation.y = 0.3;
    if (config.object === 'instanced-skinned') {
      matrices = specs.map(instanceMatrix);
      instanceSkinned(mesh, matrices);
      mesh.frustumCulled = false;
    }
    return { object: mesh, matrices };
  }
  if (config.object === 'morphed') {
    const mesh = new Mesh(geometries.morphed, body);
    mesh.morphTargetInfluences = [1];
    mesh.rotation.set(0.2, 0.4, 0);
    return { object: mesh, matrices };
  }
  if (config.object === 'instanced') {
    const mesh = new InstancedMesh(geometries.sphere, body, specs.length);
    matrices = specs.map(instanceMatrix);
    matrices.forEach((m, i) => {
      mesh.setMatrixAt(i, m);
    });
    mesh.scale.set(1.1, 1, 1);
    mesh.frustumCulled = false;
    return { object: mesh, matrices };
  }
  const mesh = new Mesh(config.object === 'sphere' ? geometries.analytic : geometries.sphere, body);
  mesh.scale.set(1.5, 1, 1.5);
  return { object: mesh, matrices };
}

/** The object-space normal of `vertex` as three moves it (morph normals, then the skin matrix). */
function deformedNormal(object: Mesh, vertex: number, deformed: boolean, target: Vector3): Vector3 {
  const geometry = object.geometry;
  const normal = geometry.getAttribute('normal');
  // A flagged sphere without normals: normal = position.
  target.fromBufferAttribute(normal ?? geometry.getAttribute('position'), vertex);
  if (!deformed) return target;
  return deformNormal(object, geometry, vertex, target);
}

/**
 * The inverted hull on the CPU, in world space: each vertex of each instance, deformed as three deforms it
 * (`getVertexPosition`: morph targets, then bones), through the instance and object matrices, pushed out by
 * `thickness` along its unit world normal (the inverse transpose of each matrix). `deformed: false` builds the
 * hull of the raw geometry at the object's origin. Drawn black, back faces, by MeshBasicNodeMaterial.
 */
function cpuHull(object: Mesh, matrices: Matrix4[], thickness: number, deformed: boolean): Mesh {
  const geometry = object.geometry;
  const count = geometry.getAttribute('position').count;
  const out = new Float32Array(3 * count * matrices.length);
  const p = new Vector3();
  const n = new Vector3();
  const objectNormal = new Matrix3().getNormalMatrix(object.matrixWorld);
  const index: number[] = [];
  const source = geometry.index;
  matrices.forEach((instance, k) => {
    const instanceNormal = new Matrix3().getNormalMatrix(instance);
    for (let i = 0; i < count; i++) {
      if (deformed) object.getVertexPosition(i, p);
      else p.fromBufferAttribute(geometry.getAttribute('position'), i);
      deformedNormal(object, i, deformed, n);
      p.applyMatrix4(instance).applyMatrix4(object.matrixWorld);
      n.applyMatrix3(instanceNormal).applyMatrix3(objectNormal).normalize();
      p.addScaledVector(n, thickness);
      p.toArray(out, 3 * (k * count + i));
    }
    if (source !== null) for (let j = 0; j < source.count; j++) index.push(k * count + source.getX(j));
  });
  const hull = new BufferGeometry();
  hull.setAttribute('position', new BufferAttribute(out, 3));
  if (source !== null) hull.setIndex(index);
  const mesh = new Mesh(hull, new MeshBasicNodeMaterial({ color: 0x000000, side: BackSide }));
  mesh.frustumCulled = false;
  return mesh;
}

function makeCamera(): PerspectiveCamera {
  const camera = new PerspectiveCamera(60, 1, 0.1, 20);
  camera.position.set(0, 0.3, 6);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

/** 0 clear (the blue background), 1 the outline (black), 2 the mesh (red), 3 anything else. */
function classify(p: Uint8Array, i: number): number {
  if (hasRgb(p, 4 * i, CLEAR)) return 0;
  if (hasRgb(p, 4 * i, [0, 0, 0])) return 1;
  if (hasRgb(p, 4 * i, [255, 0, 0])) return 2;
  return 3;
}

/** Our picture against a reference: pixels away from the reference's class edges, and how many differ. */
function compareClasses(ours: Uint8Array, theirs: Uint8Array, size: number): [number, number] {
  let compared = 0;
  let mismatches = 0;
  for (let y = 1; y < size - 1; y++) {
    for (let x = 1; x < size - 1; x++) {
      const i = y * size + x;
      const c = classify(theirs, i);
      let uniform = true;
      for (let dy = -1; uniform && dy <= 1; dy++)
        for (let dx = -1; uniform && dx <= 1; dx++)
          if (classify(theirs, i + dy * size + dx) !== c) uniform = false;
      if (!uniform) continue;
      compared++;
      if (classify(ours, i) !== c) mismatches++;
    }
  }
  return [compared, mismatches];
}

async function drawGpu(backend: Backend, scene: Scene, camera: Camera, size: number): Promise<Uint8Array> {
  const renderer = await gpuRenderer(backend);
  const target = new RenderTarget(size, size, { depthBuffer: true });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(scene, camera);
  const pixels = await readTarget(renderer, target, size);
  renderer.setRenderTarget(null);
  target.dispose();
  return pixels;
}

let gl: WebGLRenderer | null = null;
function drawGl(scene: Scene, camera: Camera, size: number): Uint8Array {
  gl ??= new WebGLRenderer({ antialias: false });
  const target = new WebGLRenderTarget(size, size);
  gl.setRenderTarget(target);
  gl.setClearColor(0x0000ff, 1);
  gl.clear();
  gl.render(scene, camera);
  const pixels = new Uint8Array(4 * size * size);
  gl.readRenderTargetPixels(target, 0, 0, size, size, pixels);
  gl.setRenderTarget(null);
  target.dispose();
  return pixels;
}

/**
 * A red object with `createOutlineNode`'s black hull on `backend`, against the same object with the CPU hull on
 * the same renderer (the oracle), with the hull of the raw geometry, and against WebGLRenderer drawing the object
 * with `createOutline`'s OutlineMaterial.
 */
async function outlineCompare(backend: Backend, config: OutlineConfig): Promise<OutlineStats> {
  const size = config.size ?? 192;
  const camera = makeCamera();
  const renderer = await gpuRenderer(backend);
  // WebGPURenderer: the node outline, then (hidden) the CPU hulls.
  const body = new MeshBasicNodeMaterial({ color: 0xff0000 });
  const { object, matrices } = makeObject(config, body, 'gpu');
  const scene = new Scene();
  scene.add(object);
  const outline = createOutlineNode(object, { thickness: config.thickness, color: 0 });
  scene.updateMatrixWorld();
  const ours = await drawGpu(backend, scene, camera, size);
  outline.visible = false;
  const oracleHull = cpuHull(object, matrices, config.thickness, true);
  scene.add(oracleHull);
  const theirs = await drawGpu(backend, scene, camera, size);
  scene.remove(oracleHull);
  const staleHull = cpuHull(object, [new Matrix4()], config.thickness, false);
  scene.add(staleHull);
  const stale = await drawGpu(backend, scene, camera, size);
  // WebGLRenderer: the same object with the GLSL outline.
  const glBody = new MeshBasicMaterial({ color: 0xff0000 });
  const glMade = makeObject(config, glBody, 'gl');
  const glScene = new Scene();
  glScene.add(glMade.object);
  const glOutline = createOutline(glMade.object, { thickness: config.thickness, color: 0 });
  glScene.updateMatrixWorld();
  const glPixels = drawGl(glScene, camera, size);
  const stats: OutlineStats = {
    backend: backendFlags(renderer),
    ring: 0,
    oracleRing: 0,
    glRing: 0,
    body: 0,
    glBody: 0,
    compared: 0,
    mismatches: 0,
    glCompared: 0,
    glMismatches: 0,
    staleMismatches: 0,
    stray: 0,
  };
  for (let i = 0; i < size * size; i++) {
    if (classify(ours, i) === 1) stats.ring++;
    if (classify(theirs, i) === 1) stats.oracleRing++;
    if (classify(glPixels, i) === 1) stats.glRing++;
    if (classify(ours, i) === 2 && classify(theirs, i) === 2) stats.body++;
    if (classify(glPixels, i) === 2) stats.glBody++;
    if (classify(ours, i) === 3) stats.stray++;
  }
  [stats.compared, stats.mismatches] = compareClasses(ours, theirs, size);
  [stats.glCompared, stats.glMismatches] = compareClasses(ours, glPixels, size);
  stats.staleMismatches = compareClasses(stale, theirs, size)[1];
  for (const mesh of [oracleHull, staleHull]) {
    mesh.geometry.dispose();
    (mesh.material as Material).dispose();
  }
  outline.material.dispose();
  glOutline.material.dispose();
  body.dispose();
  glBody.dispose();
  return stats;
}

/** `OutlineNodeMaterial`'s errors for bad options against `OutlineMaterial`'s, and its defaults against its. */
function errors(): { rows: { options: string; webgl: string; node: string }[]; defaults: string[] } {
  const bad: unknown[] = [
    { thickness: -1 },
    { thickness: Number.NaN },
    { thickness: Number.POSITIVE_INFINITY },
    { thickness: '0.1' },
    { thickness: 1e19 },
    { color: 0xff8000 },
    { color: 2 },
    { color: [Number.NaN, 0, 0] },
    { color: [1, 0] },
    { color: 'not a colour' },
    { color: {} },
  ];
  const rows = bad.map((options) => ({
    options: JSON.stringify(options, (_, v) =>
      typeof v === 'number' && !Number.isFinite(v) ? String(v) : v,
    ),
    webgl: thrown(() => new OutlineMaterial(options as never)),
    node: thrown(() => new OutlineNodeMaterial(options as never)),
  }));
  const a = new OutlineMaterial();
  const b = new OutlineNodeMaterial();
  const setter = thrown(() => {
    b.thickness = -2;
  });
  return {
    rows,
    defaults: [
      `${a.thickness} ${a.color.toArray()} ${a.side} ${a.fog}`,
      `${b.thickness} ${b.color.toArray()} ${b.side} ${b.fog}`,
      setter,
      `${b.clone().thickness} ${new OutlineNodeMaterial({ thickness: 0.2, color: '#ff0000' }).clone().color.getHexString()}`,
    ],
  };
}

async function backendInfo(backend: Backend) {
  return backendFlags(await gpuRenderer(backend));
}

const api = { backendInfo, outlineCompare, errors };
export type WebGPUOutlineHarness = typeof api;
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
