// Harness for tests/material-outline-impostor.spec.ts: the outline of deformed and instanced meshes, and the
// instanced ray-cast impostor, in headless Chromium. Each picture is judged against an independent oracle
// drawn by three's own materials: for the outline, the hull built on the CPU from three's own deformation
// (Mesh.getVertexPosition with morph targets and bones, the instance matrices) drawn with MeshBasicMaterial;
// for the impostor, fine sphere meshes with MeshPhongMaterial at the same matrices (where it draws) and
// shade() at the exact ray hit (what colour).
import { eyeOf, linearToSrgb8, PhongLight, type ShadeLight, shade } from '@shadelab/material';
import { createImpostorQuad, SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline } from '@shadelab/material/outline';
import {
  type BufferGeometry,
  type Camera,
  Color,
  Fog,
  InstancedMesh,
  Matrix3,
  Matrix4,
  MeshBasicMaterial,
  MeshPhongMaterial,
  PerspectiveCamera,
  Plane,
  Raycaster,
  Scene,
  Vector2,
  Vector3,
  Vector4,
  WebGLRenderer,
} from 'three';
import {
  CLEAR,
  classify,
  compareClasses,
  cpuHull,
  type Instance,
  instanceMatrix,
  type OutlineConfig,
  type OutlineGeometries,
  outlinedObject,
  outlineGeometries,
} from './lib/outlineOracle';
import { hasRgb, readCanvas } from './lib/pixels';
import { sphereGeometry } from './material-sphere';

const canvas = document.querySelector<HTMLCanvasElement>('#viewport');
if (canvas === null) throw new Error('no #viewport canvas');
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setClearColor(0x0000ff, 1);

let logRenderer: WebGLRenderer | null = null;

/** A renderer with a logarithmic depth buffer (made once). */
function logarithmicRenderer(): WebGLRenderer {
  logRenderer ??= new WebGLRenderer({
    canvas: document.createElement('canvas'),
    antialias: false,
    preserveDrawingBuffer: true,
    logarithmicDepthBuffer: true,
  });
  logRenderer.setPixelRatio(1);
  logRenderer.setClearColor(0x0000ff, 1);
  return logRenderer;
}

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

function readPixels(scene: Scene, camera: Camera, size: number, r = renderer): Uint8Array {
  r.setSize(size, size, false);
  r.render(scene, camera);
  return readCanvas(r, size);
}

// ---- The outline of deformed and instanced meshes ------------------------------------------------------

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

export type { Instance, OutlineConfig };

let geometries: OutlineGeometries | undefined;

/**
 * A red MeshBasicMaterial object with `createOutline`'s black hull, against the same object with the CPU hull
 * (the oracle) and with the hull of the raw geometry (the outline before it followed deformation and instances).
 */
function outlineCompare(config: OutlineConfig): OutlineStats {
  const size = config.size ?? 192;
  const camera = makeCamera(size);
  geometries ??= outlineGeometries();
  const body = new MeshBasicMaterial({ color: 0xff0000 });
  const { object, matrices } = outlinedObject(config, body, geometries);
  const scene = new Scene();
  scene.add(object);
  const outline = createOutline(object, { thickness: config.thickness, color: 0 });
  scene.updateMatrixWorld();
  const ours = readPixels(scene, camera, size);
  outline.visible = false;
  const oracleHull = cpuHull(object, matrices, config.thickness, true, new MeshBasicMaterial({ color: 0 }));
  scene.add(oracleHull);
  const theirs = readPixels(scene, camera, size);
  scene.remove(oracleHull);
  const staleHull = cpuHull(
    object,
    [new Matrix4()],
    config.thickness,
    false,
    new MeshBasicMaterial({ color: 0 }),
  );
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

// ---- The instanced impostor --------------------------------------------------------------------------

export interface ImpostorConfig {
  instances: readonly Instance[];
  size?: number;
  /** The InstancedMesh's own scale. @default [1, 1, 1] */
  scale?: readonly [number, number, number];
  /** scene.fog = Fog(near, far): only the pictures are compared (not shade()). */
  fog?: { near: number; far: number };
  /** One clipping plane (normal x, y, z, constant) on the materials: only the pictures are compared. */
  clip?: readonly [number, number, number, number];
  /** A renderer with a logarithmic depth buffer. */
  logarithmic?: boolean;
}

export interface ImpostorStats {
  /** Pixels drawn by the impostors / by the oracle (MeshPhongMaterial on level-7 sphere meshes). */
  covered: number;
  oracleCovered: number;
  /**
   * The same spheres drawn as one SphereImpostor each (model matrix M·I): pixels drawn, and pixels where the
   * two pictures differ in coverage or by more than 1/255.
   */
  objectsCovered: number;
  objectsMismatches: number;
  /** Pixels whose centre's ray hits a sphere (the CPU ray cast), and how many of those and ours differ. */
  rayCovered: number;
  rayMismatches: number;
  /** Pixels whose 3 × 3 neighbourhood is all drawn or all clear in the oracle, and how many differ. */
  coverageCompared: number;
  coverageMismatches: number;
  /** Pixels whose 3 × 3 neighbourhood is on one instance (CPU ray cast), compared with shade() there. */
  compared: number;
  maxError: number;
  mismatches: number;
  /** Covered pixels darker than any lit colour (NaN). */
  darkPixels: number;
  /** Per instance: pixels compared on it. */
  perInstance: number[];
  worst: unknown;
}

/**
 * An InstancedMesh of the impostor's quad with SphereImpostorMaterial against (1) the same instances of a
 * level-7 sphere mesh with three's MeshPhongMaterial (where something is drawn) and (2) shade() at the exact
 * hit of each pixel's ray with the nearest instance's sphere (the unit sphere under M·I: an ellipsoid under a
 * non-uniform instance scale), with the instance colour as the tint.
 */
function impostorCompare(config: ImpostorConfig): ImpostorStats {
  const size = config.size ?? 192;
  const camera = makeCamera(size);
  const light = new PhongLight({ ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [0.8, 0.8, 0.8] });
  light.position.set(-5, 10, 20);
  const material = new SphereImpostorMaterial({ lights: [light], ka: [0.9, 0.8, 0.7], shininess: 20 });
  const r = config.logarithmic ? logarithmicRenderer() : renderer;
  const planes = config.clip ? [new Plane(new Vector3(...config.clip.slice(0, 3)), config.clip[3])] : null;
  renderer.localClippingEnabled = planes !== null;
  r.localClippingEnabled = planes !== null;
  const clipped = (m: SphereImpostorMaterial | MeshPhongMaterial) => {
    m.clippingPlanes = planes;
    return m;
  };
  clipped(material);
  const specs = config.instances;
  const matrices = specs.map(instanceMatrix);
  const colored = specs.some((s) => s.color !== undefined);
  const tints = specs.map((s) => new Color(...(s.color ?? [1, 1, 1])));
  const build = (geometry: BufferGeometry, m: SphereImpostorMaterial | MeshPhongMaterial) => {
    const mesh = new InstancedMesh(geometry, m, specs.length);
    matrices.forEach((matrix, i) => {
      // A singular instance: the impostor draws nothing (documented), a mesh the flattened shape.
      const singular = m instanceof MeshPhongMaterial && matrix.determinant() === 0;
      mesh.setMatrixAt(i, singular ? new Matrix4().makeScale(0, 0, 0) : matrix);
      if (colored) mesh.setColorAt(i, tints[i]);
    });
    mesh.scale.set(...(config.scale ?? [1, 1, 1]));
    mesh.frustumCulled = false;
    return mesh;
  };
  const quad = createImpostorQuad();
  const impostors = build(quad, material);
  const scene = new Scene();
  scene.add(impostors, light);
  if (config.fog) scene.fog = new Fog(0x8080c0, config.fog.near, config.fog.far);
  scene.updateMatrixWorld();
  const ours = readPixels(scene, camera, size, r);
  scene.remove(impostors);
  const oracleMaterial = clipped(new MeshPhongMaterial({ color: 0xffffff }));
  const oracle = build(sphereGeometry(7, true), oracleMaterial);
  scene.add(oracle);
  scene.updateMatrixWorld();
  const theirs = readPixels(scene, camera, size, r);
  scene.remove(oracle);
  // One SphereImpostor per instance, at M·I, each with the instance colour folded into ka and kd.
  const objectMaterials: SphereImpostorMaterial[] = [];
  matrices.forEach((matrix, i) => {
    const tinted = new SphereImpostorMaterial({
      lights: [light],
      ka: material.ka.clone().multiply(tints[i]),
      kd: material.kd.clone().multiply(tints[i]),
      shininess: material.shininess,
    });
    clipped(tinted);
    objectMaterials.push(tinted);
    const object = new SphereImpostor(tinted);
    object.matrixAutoUpdate = false;
    object.matrix.multiplyMatrices(impostors.matrixWorld, matrix);
    scene.add(object);
  });
  scene.updateMatrixWorld();
  const objects = readPixels(scene, camera, size, r);
  renderer.localClippingEnabled = false;
  r.localClippingEnabled = false;
  const pictureOnly = config.fog !== undefined || planes !== null;
  // The CPU ray cast: the nearest hit of each pixel's ray with the instances' spheres.
  const models = matrices.map((m) => new Matrix4().multiplyMatrices(impostors.matrixWorld, m));
  const inverses = models.map((m) => m.clone().invert());
  const normals = models.map((m) => new Matrix3().getNormalMatrix(m));
  const raycaster = new Raycaster();
  const hitInstance = new Int32Array(size * size).fill(-1);
  const hitPoint = new Float64Array(3 * size * size);
  const hitNormal = new Float64Array(3 * size * size);
  const o = new Vector3();
  const d = new Vector3();
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      raycaster.setFromCamera(new Vector2(((x + 0.5) / size) * 2 - 1, ((y + 0.5) / size) * 2 - 1), camera);
      const ray = raycaster.ray;
      let best = Number.POSITIVE_INFINITY;
      for (let k = 0; k < models.length; k++) {
        const det = models[k].determinant();
        if (!(det !== 0 && Number.isFinite(det))) continue;
        o.copy(ray.origin).applyMatrix4(inverses[k]);
        d.copy(ray.direction).transformDirection(inverses[k]).multiplyScalar(1); // direction, unit
        // transformDirection normalises: the parameter along d is not the world one, but the nearest hit is
        // found by the world distance below.
        const b = o.dot(d);
        const c = o.lengthSq() - 1;
        const disc = b * b - c;
        if (disc < 0) continue;
        const t = -b - Math.sqrt(disc);
        if (t < 0) continue;
        const local = o.clone().addScaledVector(d, t);
        const world = local.clone().applyMatrix4(models[k]);
        const distance = world.distanceTo(ray.origin);
        if (distance >= best || distance > camera.far) continue;
        best = distance;
        const i = y * size + x;
        hitInstance[i] = k;
        world.toArray(hitPoint, 3 * i);
        local.applyMatrix3(normals[k]).toArray(hitNormal, 3 * i);
      }
    }
  }
  const e = eyeOf(camera, new Vector4());
  const eye = [e.x, e.y, e.z, e.w];
  const m = {
    ka: material.ka.toArray(),
    kd: material.kd.toArray(),
    ks: material.ks.toArray(),
    shininess: material.shininess,
    lighting: material.lighting,
  };
  const lights: ShadeLight[] = [
    {
      position: light.getWorldPosition(new Vector3()).toArray(),
      ambient: light.ambient.toArray(),
      diffuse: light.diffuse.toArray(),
      specular: light.specular.toArray(),
    },
  ];
  const floor = linearToSrgb8(
    m.ka.map((k: number, c: number) => k * 0.2 * Math.min(...tints.map((t) => t.toArray()[c]))),
  );
  const isClear = (p: Uint8Array, i: number) => hasRgb(p, 4 * i, CLEAR);
  const stats: ImpostorStats = {
    covered: 0,
    oracleCovered: 0,
    objectsCovered: 0,
    objectsMismatches: 0,
    rayCovered: 0,
    rayMismatches: 0,
    coverageCompared: 0,
    coverageMismatches: 0,
    compared: 0,
    maxError: 0,
    mismatches: 0,
    darkPixels: 0,
    perInstance: specs.map(() => 0),
    worst: null,
  };
  const expected: [number, number, number] = [0, 0, 0];
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const i = y * size + x;
      const a = !isClear(ours, i);
      const b = !isClear(theirs, i);
      if (a) stats.covered++;
      if (b) stats.oracleCovered++;
      if (!isClear(objects, i)) stats.objectsCovered++;
      const differ = [0, 1, 2].some((c) => Math.abs(objects[4 * i + c] - ours[4 * i + c]) > 1);
      if (differ || isClear(objects, i) !== !a) stats.objectsMismatches++;
      if (hitInstance[i] >= 0) stats.rayCovered++;
      if (hitInstance[i] >= 0 !== a) stats.rayMismatches++;
      if (a && ours[4 * i] < floor[0] - 2 && ours[4 * i + 1] < floor[1] - 2 && ours[4 * i + 2] < floor[2] - 2)
        stats.darkPixels++;
      if (x === 0 || y === 0 || x === size - 1 || y === size - 1) continue;
      let uniform = true;
      let sameInstance = hitInstance[i] >= 0;
      for (let dy = -1; dy <= 1; dy++)
        for (let dx = -1; dx <= 1; dx++) {
          const j = i + dy * size + dx;
          if (!isClear(theirs, j) !== b) uniform = false;
          if (hitInstance[j] !== hitInstance[i]) sameInstance = false;
        }
      if (uniform) {
        stats.coverageCompared++;
        if (a !== b) stats.coverageMismatches++;
      }
      if (!sameInstance || pictureOnly) continue;
      const k = hitInstance[i];
      shade(
        {
          position: Array.from(hitPoint.subarray(3 * i, 3 * i + 3)),
          normal: Array.from(hitNormal.subarray(3 * i, 3 * i + 3)),
          eye,
          tint: tints[k].toArray(),
        },
        m,
        lights,
        expected,
      );
      const want = linearToSrgb8(expected);
      const err = Math.max(
        Math.abs(ours[4 * i] - want[0]),
        Math.abs(ours[4 * i + 1] - want[1]),
        Math.abs(ours[4 * i + 2] - want[2]),
      );
      stats.compared++;
      stats.perInstance[k]++;
      if (err > stats.maxError) {
        stats.maxError = err;
        stats.worst = { x, y, k, ours: Array.from(ours.slice(4 * i, 4 * i + 3)), want };
      }
      if (err > 2) stats.mismatches++;
    }
  }
  material.dispose();
  for (const m of objectMaterials) m.dispose();
  oracleMaterial.dispose();
  quad.dispose();
  return stats;
}

const api = { outlineCompare, impostorCompare };
declare global {
  interface Window {
    outlineImpostorHarness: typeof api;
  }
}
window.outlineImpostorHarness = api;
document.body.dataset.ready = '1';
