import { createOutline } from '@shadelab/material/outline';
import {
  BackSide,
  Bone,
  BufferAttribute,
  BufferGeometry,
  type Camera,
  CylinderGeometry,
  Euler,
  Float32BufferAttribute,
  InstancedMesh,
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
  Uint16BufferAttribute,
  Vector3,
  WebGLRenderer,
} from 'three';

const canvas = document.querySelector<HTMLCanvasElement>('#viewport');
if (canvas === null) throw new Error('no #viewport canvas');
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setClearColor(0x0000ff, 1);

function makeCamera(size: number): PerspectiveCamera {
  const camera = new PerspectiveCamera(60, 1, 0.1, 20);
  camera.position.set(0, 0.3, 6);
  camera.lookAt(0, 0, 0);
  camera.aspect = 1;
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
  renderer.setSize(size, size, false);
  return camera;
}

function readPixels(scene: Scene, camera: Camera, size: number): Uint8Array {
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const pixels = new Uint8Array(4 * size * size);
  gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

/** One instance: position, Euler rotation, scale. */
export interface Instance {
  position: readonly [number, number, number];
  rotation?: readonly [number, number, number];
  scale?: readonly [number, number, number];
  /** instanceColor (linear). */
  color?: readonly [number, number, number];
}

function instanceMatrix(instance: Instance): Matrix4 {
  return new Matrix4().compose(
    new Vector3(...instance.position),
    new Quaternion().setFromEuler(new Euler(...(instance.rotation ?? [0, 0, 0]))),
    new Vector3(...(instance.scale ?? [1, 1, 1])),
  );
}

// ---- The outline of deformed and instanced meshes ------------------------------------------------------

export interface OutlineConfig {
  /** What is outlined. */
  object: 'mesh' | 'skinned' | 'morphed' | 'instanced' | 'instanced-morphed';
  /** Outline width, world units. */
  thickness: number;
  /** The skinned cylinder's second bone about z, radians. @default 0.9 */
  bone?: number;
  instances?: readonly Instance[];
  size?: number;
}

export interface OutlineStats {
  /** Pixels of the outline's colour (pure black) in our picture and in the oracle's. */
  ring: number;
  oracleRing: number;
  /** Pixels of the mesh (red) in both. */
  body: number;
  /** Pixels whose 3 × 3 neighbourhood is one class (clear, outline, mesh) in the oracle; how many differ. */
  compared: number;
  mismatches: number;
  /** The same comparison against the hull of the undeformed, uninstanced geometry (the old outline). */
  staleMismatches: number;
}

/** The bone-weighted cylinder: 3 high, radius 0.5, bones at y = −1.5 (root) and y = 0, blended over |y| < 0.5. */
function skinnedCylinder(): BufferGeometry {
  const g = new CylinderGeometry(0.5, 0.5, 3, 24, 12);
  const position = g.getAttribute('position');
  const index = new Uint16Array(4 * position.count);
  const weight = new Float32Array(4 * position.count);
  for (let i = 0; i < position.count; i++) {
    const t = Math.min(Math.max(position.getY(i) + 0.5, 0), 1);
    const w = t * t * (3 - 2 * t);
    index.set([0, 1, 0, 0], 4 * i);
    weight.set([1 - w, w, 0, 0], 4 * i);
  }
  g.setAttribute('skinIndex', new Uint16BufferAttribute(index, 4));
  g.setAttribute('skinWeight', new Float32BufferAttribute(weight, 4));
  return g;
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

/** The object-space normal of `vertex` as three's vertex chunks move it (morph normals, then the skin matrix). */
function deformedNormal(object: Mesh, vertex: number, deformed: boolean, target: Vector3): Vector3 {
  const geometry = object.geometry;
  target.fromBufferAttribute(geometry.getAttribute('normal'), vertex);
  if (!deformed) return target;
  const morphs = geometry.morphAttributes.normal;
  const influences = object.morphTargetInfluences;
  if (morphs !== undefined && influences !== undefined) {
    const sum = influences.reduce((a, b) => a + b, 0);
    target.multiplyScalar(geometry.morphTargetsRelative ? 1 : 1 - sum);
    const m = new Vector3();
    morphs.forEach((attribute, i) => {
      if (influences[i] !== 0)
        target.addScaledVector(m.fromBufferAttribute(attribute, vertex), influences[i]);
    });
  }
  const skinned = object as SkinnedMesh;
  if (skinned.isSkinnedMesh) {
    const index = geometry.getAttribute('skinIndex');
    const weight = geometry.getAttribute('skinWeight');
    const sum = new Matrix4().set(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    const bone = new Matrix4();
    for (let j = 0; j < 4; j++) {
      const w = weight.getComponent(vertex, j);
      if (w === 0) continue;
      const b = index.getComponent(vertex, j);
      bone.multiplyMatrices(skinned.skeleton.bones[b].matrixWorld, skinned.skeleton.boneInverses[b]);
      for (let e = 0; e < 16; e++) sum.elements[e] += w * bone.elements[e];
    }
    const skin = new Matrix4().multiplyMatrices(skinned.bindMatrixInverse, sum).multiply(skinned.bindMatrix);
    target.transformDirection(skin);
  }
  return target;
}

/**
 * The inverted hull on the CPU, in world space: each vertex of each instance, deformed as three deforms it
 * (`getVertexPosition`: morph targets, then bones), through the instance and object matrices, pushed out by
 * `thickness` along its unit world normal (the inverse transpose of each matrix). `deformed: false` builds the
 * hull of the raw geometry at the object's origin (what the outline drew before it followed the mesh).
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
  const mesh = new Mesh(hull, new MeshBasicMaterial({ color: 0x000000, side: BackSide }));
  mesh.frustumCulled = false;
  return mesh;
}

/** 0 clear (the blue background), 1 the outline (black), 2 the mesh. */
function classify(p: Uint8Array, i: number): number {
  if (p[4 * i] === 0 && p[4 * i + 1] === 0 && p[4 * i + 2] === 255) return 0;
  if (p[4 * i] === 0 && p[4 * i + 1] === 0 && p[4 * i + 2] === 0) return 1;
  return 2;
}

/** Our picture against the oracle's: pixels away from the oracle's class edges, and how many differ. */
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

/**
 * A red MeshBasicMaterial object with `createOutline`'s black hull, against the same object with the CPU hull
 * (the oracle) and with the hull of the raw geometry (the outline before it followed deformation and instances).
 */
function outlineCompare(config: OutlineConfig): OutlineStats {
  const size = config.size ?? 192;
  const camera = makeCamera(size);
  const body = new MeshBasicMaterial({ color: 0xff0000 });
  const specs = config.instances ?? [{ position: [0, 0, 0] }];
  let object: Mesh;
  let matrices = [new Matrix4()];
  if (config.object === 'skinned') {
    const mesh = new SkinnedMesh(skinnedCylinder(), body);
    const root = new Bone();
    root.position.set(0, -1.5, 0);
    const joint = new Bone();
    joint.position.set(0, 1.5, 0);
    root.add(joint);
    mesh.add(root);
    mesh.bind(new Skeleton([root, joint]));
    joint.rotation.z = config.bone ?? 0.9;
    mesh.rotation.y = 0.3;
    object = mesh;
  } else if (config.object === 'morphed') {
    object = new Mesh(morphedSphere(), body);
    object.morphTargetInfluences = [1];
    object.rotation.set(0.2, 0.4, 0);
  } else if (config.object === 'instanced' || config.object === 'instanced-morphed') {
    const geometry = config.object === 'instanced' ? new SphereGeometry(1, 48, 24) : morphedSphere();
    const mesh = new InstancedMesh(geometry, body, specs.length);
    matrices = specs.map(instanceMatrix);
    matrices.forEach((m, i) => {
      mesh.setMatrixAt(i, m);
    });
    if (config.object === 'instanced-morphed') {
      mesh.morphTargetInfluences = [1];
      for (let i = 0; i < specs.length; i++) mesh.setMorphAt(i, mesh);
      if (mesh.morphTexture) mesh.morphTexture.needsUpdate = true;
    }
    mesh.scale.set(1.1, 1, 1);
    object = mesh;
  } else {
    object = new Mesh(new SphereGeometry(1, 48, 24), body);
    object.scale.set(1.5, 1, 1.5);
  }
  const scene = new Scene();
  scene.add(object);
  const outline = createOutline(object, { thickness: config.thickness, color: 0 });
  scene.updateMatrixWorld();
  const ours = readPixels(scene, camera, size);
  outline.visible = false;
  const oracleHull = cpuHull(object, matrices, config.thickness, true);
  scene.add(oracleHull);
  const theirs = readPixels(scene, camera, size);
  scene.remove(oracleHull);
  const staleHull = cpuHull(object, [new Matrix4()], config.thickness, false);
  scene.add(staleHull);
  const stale = readPixels(scene, camera, size);
  const stats: OutlineStats = {
    ring: 0,
    oracleRing: 0,
    body: 0,
    compared: 0,
    mismatches: 0,
    staleMismatches: 0,
  };
  for (let i = 0; i < size * size; i++) {
    if (classify(ours, i) === 1) stats.ring++;
    if (classify(theirs, i) === 1) stats.oracleRing++;
    if (classify(ours, i) === 2 && classify(theirs, i) === 2) stats.body++;
  }
  [stats.compared, stats.mismatches] = compareClasses(ours, theirs, size);
  stats.staleMismatches = compareClasses(stale, theirs, size)[1];
  for (const mesh of [oracleHull, staleHull]) {
    mesh.geometry.dispose();
    (mesh.material as MeshBasicMaterial).dispose();
  }
  outline.material.dispose();
  body.dispose();
  return stats;
}

const api = { outlineCompare };
declare global {
  interface Window {
    outlineImpostorHarness: typeof api;
  }
}
window.outlineImpostorHarness = api;
document.body.dataset.ready = '1';
