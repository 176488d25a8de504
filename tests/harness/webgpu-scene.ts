// Harness for tests/material-webgpu-scene.spec.ts: ShadingNodeMaterial in the scenes apps have (skinning, morph
// targets, BatchedMesh, InstancedMesh, clipping, tone mapping, output colour space) under WebGPURenderer on both
// backends, rendered offscreen and read back; compared with WebGLRenderer + ShadingMaterial (colours), three's
// MeshPhongNodeMaterial on the same renderer (coverage) and shade() (flat shading by derivatives). Also device
// loss and recovery, and create/dispose cycles.
import {
  flatShadingGeometry,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeThreeLight,
  type Shading,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  ACESFilmicToneMapping,
  AmbientLight,
  BasicShadowMap,
  BatchedMesh,
  BoxGeometry,
  type BufferGeometry,
  type Camera,
  Color,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  Euler,
  FrontSide,
  InstancedMesh,
  LinearSRGBColorSpace,
  type Material,
  Matrix3,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  NoToneMapping,
  type Object3D,
  PerspectiveCamera,
  Plane,
  PlaneGeometry,
  PointLight,
  Quaternion,
  Raycaster,
  Scene,
  SkinnedMesh,
  SphereGeometry,
  SpotLight,
  SRGBColorSpace,
  Vector2,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import {
  ClippingGroup,
  MeshBasicNodeMaterial,
  MeshPhongNodeMaterial,
  RenderTarget,
  WebGPURenderer,
} from 'three/webgpu';
import { bindTwoBones, skinnedCylinder, stretchMorph } from './lib/deform';
import { maxRgbDelta } from './lib/pixels';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';

export type { Backend };
/** The object: a sphere Mesh, a SkinnedMesh (bent cylinder), a morphed sphere, a BatchedMesh, an InstancedMesh. */
export type Kind = 'mesh' | 'skinned' | 'morphed' | 'batched' | 'instanced';
/**
 * Clipping. WebGPURenderer has no `material.clippingPlanes` nor `renderer.clippingPlanes`: its clipping is
 * `ClippingGroup`. 'local': a ClippingGroup around the object (WebGL: material.clippingPlanes); 'global': one plane
 * on an outer group and one on an inner (WebGL: renderer.clippingPlanes and material.clippingPlanes); 'intersection':
 * a group with clipIntersection and two planes (WebGL: material.clipIntersection); 'material-planes':
 * material.clippingPlanes set on the node material (which WebGPURenderer ignores).
 */
export type Clip = 'none' | 'local' | 'global' | 'intersection' | 'material-planes';
export interface SceneCase {
  kind: Kind;
  shading: Shading;
  lighting?: 'phong' | 'blinn-phong';
  celBands?: number;
  /**
   * Flat shading's geometry: indexed (flat by derivatives in both materials), a triangle soup, or a
   * flatShadingGeometry made for the renderer's provoking vertex (WebGPU's first, WebGL's last). @default 'indexed'
   */
  flatGeometry?: 'indexed' | 'soup' | 'prepared';
  clip?: Clip;
  /** Through the output conversion (WebGPU: an output render target; WebGL: the canvas). Absent: a linear target. */
  output?: 'srgb' | 'linear';
  /** renderer.toneMapping = ACESFilmicToneMapping (with `output`). */
  toneMapping?: boolean;
  /** material.toneMapped. @default true */
  toneMapped?: boolean;
  /** InstancedMesh / BatchedMesh: per-instance colours. */
  instanceColor?: boolean;
}

const SIZE = 128;
const P1 = new Plane(new Vector3(1, 0.3, 0).normalize(), 0.2);
const P2 = new Plane(new Vector3(0, -1, 0.2).normalize(), 0.35);

const sphere = (indexed: boolean) =>
  new SubdivisionSphereGeometry({ level: 2, base: 'tetrahedron', indexed });

/**
 * The geometries, one set per renderer kind: a geometry drawn by WebGPURenderer's WebGL2 backend is not drawn
 * by WebGLRenderer afterwards (GL_INVALID_OPERATION, the skin index attribute's type), and apps do not share
 * geometries between the two renderers.
 */
function geometries() {
  const cylinder = skinnedCylinder(0.6, 8, 6);
  return {
    sphereIndexed: sphere(true),
    sphereSoup: sphere(false),
    cylinderIndexed: cylinder,
    cylinderSoup: cylinder.toNonIndexed(),
    morphIndexed: stretchMorph(sphere(true)),
    morphSoup: stretchMorph(sphere(false)),
  };
}
const GEOMETRIES = { gpu: geometries(), gl: geometries() };

/** Two instances with different matrices (and colours). */
const INSTANCES = [
  {
    matrix: new Matrix4().compose(
      new Vector3(-0.75, 0.1, 0),
      new Quaternion().setFromEuler(new Euler(0.3, 0.5, 0)),
      new Vector3(0.7, 0.7, 0.7),
    ),
    color: new Color(1, 0.5, 0.25),
  },
  {
    matrix: new Matrix4().compose(
      new Vector3(0.8, -0.2, -0.3),
      new Quaternion().setFromEuler(new Euler(0, 0, 0.6)),
      new Vector3(0.55, 0.8, 0.55),
    ),
    color: new Color(0.25, 1, 0.5),
  },
];

const flatSoup = (c: SceneCase) => c.shading === 'flat' && c.flatGeometry === 'soup';

export interface Setup {
  scene: Scene;
  camera: PerspectiveCamera;
  object: Mesh;
  /** The source geometry (a BatchedMesh draws its own copy). */
  geometry: BufferGeometry;
  lights: (ShadeLight | ShadeThreeLight)[];
}

/** The scene of `c` with `material`, built for WebGPURenderer ('gpu') or WebGLRenderer ('gl'). */
/** The flatShadingGeometry of `source` for `provoking`, made once. */
const _prepared = new Map<BufferGeometry, Map<string, BufferGeometry>>();
function prepare(source: BufferGeometry, provoking: 'first' | 'last'): BufferGeometry {
  let made = _prepared.get(source);
  if (made === undefined) {
    made = new Map();
    _prepared.set(source, made);
  }
  let g = made.get(provoking);
  if (g === undefined) {
    g = flatShadingGeometry(source, { provokingVertex: provoking });
    made.set(provoking, g);
  }
  return g;
}

function build(
  material: Material,
  c: SceneCase,
  api: 'gpu' | 'gl',
  provoking: 'first' | 'last' = 'last',
): Setup {
  const soup = flatSoup(c);
  const indexed = GEOMETRIES[api];
  const { sphereSoup, cylinderSoup, morphSoup } = indexed;
  // A flatShadingGeometry stands in for the indexed geometries.
  const prepared = c.shading === 'flat' && c.flatGeometry === 'prepared';
  const maybe = (g: BufferGeometry) => (prepared ? prepare(g, provoking) : g);
  const sphereIndexed = maybe(indexed.sphereIndexed);
  const cylinderIndexed = maybe(indexed.cylinderIndexed);
  const morphIndexed = maybe(indexed.morphIndexed);
  let object: Mesh;
  let geometry: BufferGeometry;
  if (c.kind === 'skinned') {
    geometry = soup ? cylinderSoup : cylinderIndexed;
    const mesh = new SkinnedMesh(geometry, material);
    bindTwoBones(mesh, 0.7).position.x = 0.15;
    object = mesh;
  } else if (c.kind === 'morphed') {
    geometry = soup ? morphSoup : morphIndexed;
    object = new Mesh(geometry, material);
    object.morphTargetInfluences = [0.5];
    object.rotation.set(0.3, 0.5, 0);
  } else if (c.kind === 'instanced') {
    geometry = soup ? sphereSoup : sphereIndexed;
    const mesh = new InstancedMesh(geometry, material, INSTANCES.length);
    INSTANCES.forEach((instance, i) => {
      mesh.setMatrixAt(i, instance.matrix);
      if (c.instanceColor) mesh.setColorAt(i, instance.color);
    });
    object = mesh;
  } else if (c.kind === 'batched') {
    geometry = soup ? sphereSoup : sphereIndexed;
    const index = geometry.index;
    const mesh = new BatchedMesh(
      INSTANCES.length,
      geometry.getAttribute('position').count,
      index === null ? 0 : index.count,
      material,
    );
    const id = mesh.addGeometry(geometry);
    // A BatchedMesh draws its own geometry: flag it as a sphere centred at its origin, as the source is.
    mesh.geometry.userData.isSphere = true;
    INSTANCES.forEach((instance) => {
      const i = mesh.addInstance(id);
      mesh.setMatrixAt(i, instance.matrix);
      if (c.instanceColor) mesh.setColorAt(i, instance.color);
    });
    object = mesh as unknown as Mesh;
  } else {
    geometry = c.shading === 'flat' && !prepared ? sphereSoup : sphereIndexed;
    object = new Mesh(geometry, material);
    object.scale.set(1.2, 1, 1.2);
    object.rotation.set(0.3, 0.5, 0);
  }
  object.frustumCulled = false;
  const scene = new Scene();
  const clip = c.clip ?? 'none';
  if (api === 'gpu' && (clip === 'local' || clip === 'global' || clip === 'intersection')) {
    const group = new ClippingGroup();
    group.clippingPlanes = clip === 'intersection' ? [P1, P2] : [P1];
    group.clipIntersection = clip === 'intersection';
    group.add(object);
    if (clip === 'global') {
      const outer = new ClippingGroup();
      outer.clippingPlanes = [P2];
      outer.add(group);
      scene.add(outer);
    } else scene.add(group);
  } else scene.add(object);
  if (clip === 'material-planes' || (api === 'gl' && clip !== 'none')) {
    material.clippingPlanes = clip === 'intersection' ? [P1, P2] : [P1];
    material.clipIntersection = clip === 'intersection';
  }
  if (c.toneMapped === false) material.toneMapped = false;
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const sun = new DirectionalLight(new Color(1, 0.9, 0.8), 0.6);
  sun.position.set(3, 2, 4);
  scene.add(light, sun);
  const camera = new PerspectiveCamera(45, 1, 0.1, 20);
  if (c.kind === 'skinned') {
    camera.position.set(0.2, 0.3, 4.4);
    camera.lookAt(-0.45, -0.1, 0);
  } else {
    camera.position.set(0, 0, 3.8);
    camera.lookAt(0, 0, 0);
  }
  scene.updateMatrixWorld();
  camera.updateMatrixWorld();
  if (object instanceof SkinnedMesh) object.skeleton.update();
  const s = (col: Color, i: number) => [col.r * i, col.g * i, col.b * i];
  return {
    scene,
    camera,
    object,
    geometry,
    lights: [
      {
        position: light.position.toArray(),
        ambient: light.ambient.toArray(),
        diffuse: light.diffuse.toArray(),
        specular: light.specular.toArray(),
      },
      {
        type: 'directional',
        color: s(sun.color, sun.intensity),
        direction: sun.position.clone().normalize().toArray(),
      },
    ],
  };
}

const nodeMaterial = (c: SceneCase) =>
  new ShadingNodeMaterial({ shading: c.shading, lighting: c.lighting ?? 'phong', celBands: c.celBands ?? 0 });

/**
 * Draws `scene` into a new target and reads it back, rows bottom-up, RGBA8, cleared to (0, 0, 0, 0). With
 * `output`, through the renderer's output pass (tone mapping, output colour space) into the target as the output
 * render target (presenting to a WebGPU canvas headless loses the device); else linear into the target.
 */
async function drawGpu(r: WebGPURenderer, scene: Scene, camera: Camera, c: SceneCase): Promise<Uint8Array> {
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  r.setClearColor(0x000000, 0);
  if (c.output !== undefined) {
    r.toneMapping = c.toneMapping ? ACESFilmicToneMapping : NoToneMapping;
    r.outputColorSpace = c.output === 'srgb' ? SRGBColorSpace : LinearSRGBColorSpace;
    r.setOutputRenderTarget(target);
    r.setRenderTarget(null);
  } else r.setRenderTarget(target);
  try {
    r.render(scene, camera);
    return await readTarget(r, target, SIZE);
  } finally {
    r.setOutputRenderTarget(null);
    r.setRenderTarget(null);
    r.toneMapping = NoToneMapping;
    r.outputColorSpace = SRGBColorSpace;
    target.dispose();
  }
}

/** WebGPURenderer with ShadingNodeMaterial ('shading') or three's MeshPhongNodeMaterial ('phong'). */
async function renderGpu(backend: Backend, c: SceneCase, which: 'shading' | 'phong' = 'shading') {
  const r = await gpuRenderer(backend);
  const material = which === 'phong' ? new MeshPhongNodeMaterial() : nodeMaterial(c);
  const setup = build(material, c, 'gpu', backend === 'webgpu' ? 'first' : 'last');
  const pixels = await drawGpu(r, setup.scene, setup.camera, c);
  material.dispose();
  // The object is kept for the CPU reference (a disposed BatchedMesh cannot be ray cast).
  return { pixels, setup, dispose: () => (setup.object as { dispose?: () => void }).dispose?.() };
}

let gl: WebGLRenderer | null = null;
/** WebGLRenderer + ShadingMaterial: linear into a target, or with `output` on the canvas (tone mapping, colour space). */
function renderGl(c: SceneCase): Uint8Array {
  if (gl === null) {
    gl = new WebGLRenderer({ antialias: false, alpha: true, preserveDrawingBuffer: true });
    gl.setPixelRatio(1);
    gl.setSize(SIZE, SIZE, false);
  }
  const r = gl;
  const material = new ShadingMaterial({
    shading: c.shading,
    lighting: c.lighting ?? 'phong',
    celBands: c.celBands ?? 0,
  });
  const setup = build(material, c, 'gl');
  r.setClearColor(0x000000, 0);
  r.localClippingEnabled = (c.clip ?? 'none') !== 'none';
  r.clippingPlanes = c.clip === 'global' ? [P2] : [];
  const pixels = new Uint8Array(4 * SIZE * SIZE);
  if (c.output !== undefined) {
    r.toneMapping = c.toneMapping ? ACESFilmicToneMapping : NoToneMapping;
    r.outputColorSpace = c.output === 'srgb' ? SRGBColorSpace : LinearSRGBColorSpace;
    r.setRenderTarget(null);
    r.render(setup.scene, setup.camera);
    const context = r.getContext();
    context.readPixels(0, 0, SIZE, SIZE, context.RGBA, context.UNSIGNED_BYTE, pixels);
  } else {
    const target = new WebGLRenderTarget(SIZE, SIZE);
    r.setRenderTarget(target);
    r.render(setup.scene, setup.camera);
    r.readRenderTargetPixels(target, 0, 0, SIZE, SIZE, pixels);
    r.setRenderTarget(null);
    target.dispose();
  }
  r.toneMapping = NoToneMapping;
  r.outputColorSpace = SRGBColorSpace;
  r.clippingPlanes = [];
  r.localClippingEnabled = false;
  material.dispose();
  (setup.object as { dispose?: () => void }).dispose?.();
  return pixels;
}

const covered = (p: Uint8Array, i: number) => p[4 * i + 3] !== 0;
/** Whether pixel (x, y) and its 8 neighbours are all covered (true), all not (false), or mixed (null). */
function neighbourhood(p: Uint8Array, x: number, y: number): boolean | null {
  let all = true;
  let none = true;
  for (let dy = -1; dy <= 1; dy++) {
    for (let dx = -1; dx <= 1; dx++) {
      const u = Math.min(Math.max(x + dx, 0), SIZE - 1);
      const v = Math.min(Math.max(y + dy, 0), SIZE - 1);
      if (covered(p, v * SIZE + u)) none = false;
      else all = false;
    }
  }
  return all ? true : none ? false : null;
}

/** The world-space corners of every drawn triangle (three's CPU morphing and skinning, instance matrices). */
function worldTriangles(setup: Setup): Vector3[] {
  const { object, geometry } = setup;
  const index = geometry.index;
  const count = index === null ? geometry.getAttribute('position').count : index.count;
  const vertex = (k: number) => (index === null ? k : index.getX(k));
  const matrices =
    object instanceof InstancedMesh || (object as unknown as BatchedMesh).isBatchedMesh
      ? INSTANCES.map((i) => object.matrixWorld.clone().multiply(i.matrix))
      : [object.matrixWorld];
  const corners: Vector3[] = [];
  const local: Vector3[] = [];
  for (let k = 0; k < count; k++) {
    const v = new Vector3();
    if (object instanceof InstancedMesh || (object as unknown as BatchedMesh).isBatchedMesh)
      v.fromBufferAttribute(geometry.getAttribute('position'), vertex(k));
    else object.getVertexPosition(vertex(k), v);
    local.push(v);
  }
  for (const m of matrices) for (const v of local) corners.push(v.clone().applyMatrix4(m));
  return corners;
}

/** Pixels within 1.5 px of any triangle edge (where two renderers may give a pixel to different faces). */
function edgeMask(setup: Setup): Uint8Array {
  const mask = new Uint8Array(SIZE * SIZE);
  const corners = worldTriangles(setup).map((p) => {
    const s = p.clone().project(setup.camera);
    return new Vector2(((s.x + 1) / 2) * SIZE, ((s.y + 1) / 2) * SIZE);
  });
  for (let t = 0; t < corners.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = corners[t + k];
      const b = corners[t + ((k + 1) % 3)];
      const e = b.clone().sub(a);
      const l2 = Math.max(e.lengthSq(), 1e-12);
      const x0 = Math.max(0, Math.floor(Math.min(a.x, b.x) - 2));
      const x1 = Math.min(SIZE - 1, Math.ceil(Math.max(a.x, b.x) + 2));
      const y0 = Math.max(0, Math.floor(Math.min(a.y, b.y) - 2));
      const y1 = Math.min(SIZE - 1, Math.ceil(Math.max(a.y, b.y) + 2));
      for (let y = y0; y <= y1; y++) {
        for (let x = x0; x <= x1; x++) {
          const p = new Vector2(x + 0.5, y + 0.5);
          const t0 = Math.min(Math.max(p.clone().sub(a).dot(e) / l2, 0), 1);
          if (p.distanceTo(a.clone().addScaledVector(e, t0)) < 1.5) mask[y * SIZE + x] = 1;
        }
      }
    }
  }
  return mask;
}

export interface Diff {
  /** Pixels `a` covers. */
  covered: number;
  /** Pixels covered by one and not the other. */
  coverageMismatches: number;
  /** Of those, the ones whose 3 × 3 neighbourhood in `b` is uniform (not at an edge of `b`'s coverage). */
  interiorCoverageMismatches: number;
  /** Pixels compared: covered with their 3 × 3 neighbourhood in both, not masked. */
  compared: number;
  /** max |a − b| over RGB, 1/255. */
  maxDelta: number;
  /** Compared pixels differing by more than 2/255. */
  differing: number;
  worst: unknown;
}

function diff(a: Uint8Array, b: Uint8Array, mask?: Uint8Array): Diff {
  const d: Diff = {
    covered: 0,
    coverageMismatches: 0,
    interiorCoverageMismatches: 0,
    compared: 0,
    maxDelta: 0,
    differing: 0,
    worst: null,
  };
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const i = y * SIZE + x;
      const ca = covered(a, i);
      const cb = covered(b, i);
      if (ca) d.covered++;
      if (ca !== cb) {
        d.coverageMismatches++;
        if (neighbourhood(b, x, y) !== null) d.interiorCoverageMismatches++;
      }
      if (neighbourhood(a, x, y) !== true || neighbourhood(b, x, y) !== true) continue;
      if (mask !== undefined && mask[i] === 1) continue;
      d.compared++;
      const o = 4 * i;
      const delta = maxRgbDelta(a, b, o);
      if (delta > d.maxDelta) {
        d.maxDelta = delta;
        d.worst = { x, y, a: Array.from(a.subarray(o, o + 4)), b: Array.from(b.subarray(o, o + 4)) };
      }
      if (delta > 2) d.differing++;
    }
  }
  return d;
}

/** Flat shading by derivatives against shade(): each fragment lit at its point with its deformed face's normal. */
function shadeFlat(setup: Setup, pixels: Uint8Array, c: SceneCase, mask: Uint8Array) {
  const { object, camera, lights } = setup;
  const eye = [camera.position.x, camera.position.y, camera.position.z, 1];
  const m: ShadeMaterial = {
    ka: [0.6, 0.35, 0.2],
    kd: [0.6, 0.35, 0.2],
    ks: [0.5, 0.5, 0.5],
    shininess: 32,
    lighting: c.lighting ?? 'phong',
    celBands: 0,
  };
  const raycaster = new Raycaster();
  const stats = { compared: 0, maxError: 0, mismatches: 0, worst: null as unknown };
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const i = y * SIZE + x;
      if (mask[i] === 1 || neighbourhood(pixels, x, y) !== true) continue;
      raycaster.setFromCamera(new Vector2(((x + 0.5) / SIZE) * 2 - 1, ((y + 0.5) / SIZE) * 2 - 1), camera);
      const hit = raycaster.intersectObject(object as Object3D, false)[0];
      if (hit?.face == null) continue;
      // face.normal is the deformed triangle's, in the object's (instance's) space.
      let world = object.matrixWorld;
      const instance = hit.instanceId ?? (hit as { batchId?: number }).batchId;
      if (instance !== undefined) world = object.matrixWorld.clone().multiply(INSTANCES[instance].matrix);
      const normal = hit.face.normal.clone().applyMatrix3(new Matrix3().getNormalMatrix(world));
      const expected = shade({ position: hit.point.toArray(), normal: normal.toArray(), eye }, m, lights);
      stats.compared++;
      const o = 4 * i;
      let error = 0;
      for (let k = 0; k < 3; k++)
        error = Math.max(error, Math.abs(pixels[o + k] - Math.min(Math.max(expected[k], 0), 1) * 255));
      if (error > stats.maxError) {
        stats.maxError = error;
        stats.worst = {
          x,
          y,
          got: Array.from(pixels.subarray(o, o + 3)),
          expected: expected.map((e) => e * 255),
        };
      }
      if (error > 2) stats.mismatches++;
    }
  }
  return stats;
}

/**
 * One case on one backend: ShadingNodeMaterial against three's MeshPhongNodeMaterial on the same renderer
 * (coverage), against WebGLRenderer + ShadingMaterial (colours away from triangle edges, coverage), and for flat
 * shading against shade() per fragment with the deformed face normal.
 */
async function sceneCompare(backend: Backend, c: SceneCase) {
  const { pixels, setup, dispose } = await renderGpu(backend, c);
  const { pixels: phong } = await renderGpu(backend, c, 'phong');
  const webgl = renderGl(c);
  const mask = c.shading === 'flat' ? edgeMask(setup) : undefined;
  const result = {
    phongNode: diff(pixels, phong),
    webgl: diff(pixels, webgl, mask),
    shade: c.shading === 'flat' && mask !== undefined ? shadeFlat(setup, pixels, c, mask) : null,
  };
  dispose();
  return result;
}

/**
 * Exact flat shading (a triangle soup or a flatShadingGeometry) against shade(): each face (of each instance) one
 * colour, = shade() at the deformed, placed face's centroid with its face normal (away from triangle edges).
 */
function shadeExactFlat(setup: Setup, pixels: Uint8Array, c: SceneCase, mask: Uint8Array) {
  const { object, camera, lights, geometry } = setup;
  const eye = [camera.position.x, camera.position.y, camera.position.z, 1];
  const m: ShadeMaterial = {
    ka: [0.6, 0.35, 0.2],
    kd: [0.6, 0.35, 0.2],
    ks: [0.5, 0.5, 0.5],
    shininess: 32,
    lighting: c.lighting ?? 'phong',
    celBands: c.celBands ?? 0,
  };
  const raycaster = new Raycaster();
  const stats = { compared: 0, maxError: 0, mismatches: 0, faces: 0, multiColour: 0, worst: null as unknown };
  const colours = new Map<string, string>();
  const multi = new Set<string>();
  const position = geometry.getAttribute('position');
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const i = y * SIZE + x;
      if (mask[i] === 1 || neighbourhood(pixels, x, y) !== true) continue;
      raycaster.setFromCamera(new Vector2(((x + 0.5) / SIZE) * 2 - 1, ((y + 0.5) / SIZE) * 2 - 1), camera);
      const hit = raycaster.intersectObject(object as Object3D, false)[0];
      if (hit?.face == null || hit.faceIndex == null) continue;
      const instance = hit.instanceId;
      const world =
        instance !== undefined
          ? object.matrixWorld.clone().multiply(INSTANCES[instance].matrix)
          : object.matrixWorld;
      const corner = (k: number) =>
        (instance !== undefined
          ? new Vector3().fromBufferAttribute(position, k)
          : object.getVertexPosition(k, new Vector3())
        ).applyMatrix4(world);
      const [a, b, cc] = [hit.face.a, hit.face.b, hit.face.c].map(corner);
      const centroid = a.clone().add(b).add(cc).divideScalar(3);
      const normal = b.clone().sub(a).cross(cc.clone().sub(a));
      const expected = shade({ position: centroid.toArray(), normal: normal.toArray(), eye }, m, lights);
      const o = 4 * i;
      const key = `${instance ?? 0}:${hit.faceIndex}`;
      const colour = `${pixels[o]},${pixels[o + 1]},${pixels[o + 2]}`;
      const seen = colours.get(key);
      if (seen === undefined) colours.set(key, colour);
      else if (seen !== colour) multi.add(key);
      stats.compared++;
      let error = 0;
      for (let k = 0; k < 3; k++)
        error = Math.max(error, Math.abs(pixels[o + k] - Math.min(Math.max(expected[k], 0), 1) * 255));
      if (error > stats.maxError) {
        stats.maxError = error;
        stats.worst = {
          x,
          y,
          key,
          got: Array.from(pixels.subarray(o, o + 3)),
          expected: expected.map((e) => e * 255),
        };
      }
      if (error > 2) stats.mismatches++;
    }
  }
  stats.faces = colours.size;
  stats.multiColour = multi.size;
  return stats;
}

/**
 * Exact flat shading of a soup or a flatShadingGeometry (made for the backend's provoking vertex) of a mesh,
 * SkinnedMesh, morphed mesh or InstancedMesh: coverage as MeshPhongNodeMaterial's, colours as WebGLRenderer +
 * ShadingMaterial's (away from triangle edges), one colour per face = shade() at the centroid.
 */
async function flatExactCompare(backend: Backend, c: SceneCase) {
  const { pixels, setup, dispose } = await renderGpu(backend, c);
  const { pixels: phong } = await renderGpu(backend, c, 'phong');
  const webgl = renderGl(c);
  const mask = edgeMask(setup);
  const result = {
    backend: backendFlags(await gpuRenderer(backend)),
    phongNode: diff(pixels, phong),
    webgl: diff(pixels, webgl, mask),
    exact: shadeExactFlat(setup, pixels, c, mask),
  };
  dispose();
  return result;
}

/** Clipping: coverage as MeshPhongNodeMaterial's, the clipped pixels exactly background, the rest unchanged. */
async function clipCompare(backend: Backend, c: SceneCase) {
  const clipped = await renderGpu(backend, c);
  const whole = await renderGpu(backend, { ...c, clip: 'none' });
  const { pixels: phong } = await renderGpu(backend, c, 'phong');
  let removed = 0;
  let removedNotBackground = 0;
  let kept = 0;
  let keptChanged = 0;
  let added = 0;
  for (let i = 0; i < SIZE * SIZE; i++) {
    const o = 4 * i;
    const a = clipped.pixels;
    const w = whole.pixels;
    if (covered(w, i) && !covered(a, i)) {
      removed++;
      if (a[o] !== 0 || a[o + 1] !== 0 || a[o + 2] !== 0 || a[o + 3] !== 0) removedNotBackground++;
    } else if (covered(a, i) && covered(w, i)) {
      kept++;
      if ([0, 1, 2, 3].some((k) => a[o + k] !== w[o + k])) keptChanged++;
    } else if (covered(a, i)) added++;
  }
  const mask = c.shading === 'flat' ? edgeMask(clipped.setup) : undefined;
  return {
    removed,
    removedNotBackground,
    kept,
    keptChanged,
    added,
    phongNode: diff(clipped.pixels, phong),
    webgl: c.clip === 'material-planes' ? null : diff(clipped.pixels, renderGl(c), mask),
  };
}

/** Two pictures of the same case on WebGPURenderer (e.g. toneMapped true and false): how many pixels differ. */
async function pairDiff(backend: Backend, a: SceneCase, b: SceneCase) {
  const { pixels: pa } = await renderGpu(backend, a);
  const { pixels: pb } = await renderGpu(backend, b);
  return diff(pa, pb);
}

/** Same as pairDiff, for three's MeshPhongNodeMaterial (what three does with the same settings). */
async function phongPairDiff(backend: Backend, a: SceneCase, b: SceneCase) {
  const { pixels: pa } = await renderGpu(backend, a, 'phong');
  const { pixels: pb } = await renderGpu(backend, b, 'phong');
  return diff(pa, pb);
}

/** Materials of different variants drawn in one scene (one renderer, live together) against WebGL's. */
async function mixedVariants(backend: Backend) {
  const variants: SceneCase[] = [
    { kind: 'mesh', shading: 'phong' },
    { kind: 'mesh', shading: 'gouraud', lighting: 'blinn-phong' },
    { kind: 'mesh', shading: 'phong', celBands: 4 },
  ];
  const place = (setup: Setup, k: number) => {
    setup.object.position.set(-1.1 + 1.1 * k, 0, 0);
    setup.object.scale.setScalar(0.5);
    setup.scene.updateMatrixWorld();
  };
  const r = await gpuRenderer(backend);
  const materials = variants.map(nodeMaterial);
  const setups = variants.map((v, k) => build(materials[k], v, 'gpu'));
  setups.forEach(place);
  const scene = setups[0].scene;
  for (const s of setups.slice(1)) scene.add(s.object);
  const together = await drawGpu(r, scene, setups[0].camera, variants[0]);
  // Each one alone with a fresh material.
  const alone: Uint8Array[] = [];
  for (let k = 0; k < variants.length; k++) {
    const m = nodeMaterial(variants[k]);
    const s = build(m, variants[k], 'gpu');
    place(s, k);
    alone.push(await drawGpu(r, s.scene, s.camera, variants[k]));
    m.dispose();
  }
  for (const m of materials) m.dispose();
  // Each alone covers its own third of the picture: combine them.
  const combined = new Uint8Array(together.length);
  for (let i = 0; i < SIZE * SIZE; i++)
    for (const a of alone) if (covered(a, i)) combined.set(a.subarray(4 * i, 4 * i + 4), 4 * i);
  return diff(together, combined);
}

/** A material's variant changed through its setters after it was drawn: the picture of a fresh material of it. */
async function variantSwitch(backend: Backend, from: SceneCase, to: Partial<SceneCase>) {
  const r = await gpuRenderer(backend);
  const material = nodeMaterial(from);
  const setup = build(material, from, 'gpu');
  const before = await drawGpu(r, setup.scene, setup.camera, from);
  if (to.shading !== undefined) material.shading = to.shading;
  if (to.lighting !== undefined) material.lighting = to.lighting;
  if (to.celBands !== undefined) material.celBands = to.celBands;
  const after = await drawGpu(r, setup.scene, setup.camera, from);
  material.dispose();
  const { pixels: fresh } = await renderGpu(backend, { ...from, ...to });
  return { changed: diff(after, before).differing, againstFresh: diff(after, fresh) };
}

interface LossReport {
  before: number[];
  afterRecovery: number[];
  messages: string[];
  deviceLostCalls: { api: string; message: string; reason: string | null }[];
  isDeviceLost: boolean;
  renderAfterLoss: string;
  readAfterLoss: string;
  identical: boolean;
  covered: number;
}

/**
 * Device loss. 'lost' (WebGPU): what a GPU process crash or driver reset gives, the device lost with a reason
 * other than 'destroyed' (simulated: the app's device, whose `lost` promise the harness resolves with reason
 * 'unknown', then really destroyed); 'destroyed' (WebGPU): `device.destroy()` alone; 'context' (WebGL2 backend):
 * WEBGL_lose_context. Then what three reports and does, and a new WebGPURenderer drawing the same scene with
 * the same material.
 */
async function deviceLoss(trigger: 'lost' | 'destroyed' | 'context'): Promise<LossReport> {
  const messages: string[] = [];
  const original = console.error;
  console.error = (...args: unknown[]) => {
    messages.push(args.map(String).join(' '));
    original.apply(console, args as never);
  };
  let resolveLost: (info: unknown) => void = () => {};
  let device: GPUDevice | null = null;
  let first: WebGPURenderer;
  if (trigger === 'context') first = new WebGPURenderer({ antialias: false, forceWebGL: true });
  else {
    const adapter = await navigator.gpu.requestAdapter();
    if (adapter === null) throw new Error('no WebGPU adapter');
    device = await adapter.requestDevice();
    if (trigger === 'lost') {
      const lost = new Promise((resolve) => {
        resolveLost = resolve;
      });
      Object.defineProperty(device, 'lost', { value: lost });
    }
    first = new WebGPURenderer({ antialias: false, device } as never);
  }
  const calls: LossReport['deviceLostCalls'] = [];
  const threeHandler = first.onDeviceLost.bind(first);
  first.onDeviceLost = (info) => {
    calls.push({ api: info.api, message: info.message, reason: info.reason });
    threeHandler(info);
  };
  await first.init();
  const c: SceneCase = { kind: 'skinned', shading: 'gouraud' };
  const material = nodeMaterial(c);
  const setup = build(material, c, 'gpu');
  const report: Partial<LossReport> = { messages, deviceLostCalls: calls };
  try {
    const before = await drawGpu(first, setup.scene, setup.camera, c);
    if (trigger === 'context') {
      const context = (first.backend as unknown as { gl: WebGL2RenderingContext }).gl;
      const lostEvent = new Promise((resolve) =>
        context.canvas.addEventListener('webglcontextlost', resolve),
      );
      context.getExtension('WEBGL_lose_context')?.loseContext();
      await lostEvent;
    } else {
      device?.destroy();
      resolveLost({ reason: 'unknown', message: 'simulated GPU process loss' });
    }
    await new Promise((resolve) => setTimeout(resolve, 50));
    report.isDeviceLost = (first as unknown as { _isDeviceLost: boolean })._isDeviceLost;
    const attempt = async (f: () => unknown) => {
      try {
        const value = await f();
        return value === undefined ? 'returned' : `returned ${Object.prototype.toString.call(value)}`;
      } catch (e) {
        return `${(e as Error).name}: ${(e as Error).message}`;
      }
    };
    report.renderAfterLoss = await attempt(() => first.render(setup.scene, setup.camera));
    const target = new RenderTarget(SIZE, SIZE);
    report.readAfterLoss = await attempt(async () => {
      first.setRenderTarget(target);
      first.render(setup.scene, setup.camera);
      first.setRenderTarget(null);
      // A lost device never answers a readback: give up after a while rather than hang the test.
      return Promise.race([
        first.readRenderTargetPixelsAsync(target, 0, 0, SIZE, SIZE),
        new Promise((_, reject) => setTimeout(() => reject(new Error('no answer within 2 s')), 2000)),
      ]);
    });
    // What the app does on loss: a new renderer (a new device or context), the same scene and material.
    const second = new WebGPURenderer({ antialias: false, forceWebGL: trigger === 'context' });
    await second.init();
    const after = await drawGpu(second, setup.scene, setup.camera, c);
    second.dispose();
    report.before = Array.from(before);
    report.afterRecovery = Array.from(after);
    report.identical = before.every((v, i) => v === after[i]);
    report.covered = before.filter((_, i) => i % 4 === 3 && before[i] !== 0).length;
  } finally {
    console.error = original;
    material.dispose();
  }
  return report as LossReport;
}

interface Counts {
  memory: Record<string, number>;
  pipelines: number;
  vertexPrograms: number;
  fragmentPrograms: number;
  nodeBuilds: number;
}

function counts(r: WebGPURenderer): Counts {
  const memory = { ...(r.info.memory as unknown as Record<string, number>) };
  const internals = r as unknown as {
    _pipelines: {
      caches: Map<unknown, unknown>;
      programs: { vertex: Map<unknown, unknown>; fragment: Map<unknown, unknown> };
    };
    _nodes: { nodeBuilderCache: Map<unknown, unknown> };
  };
  return {
    memory,
    pipelines: internals._pipelines.caches.size,
    vertexPrograms: internals._pipelines.programs.vertex.size,
    fragmentPrograms: internals._pipelines.programs.fragment.size,
    nodeBuilds: internals._nodes.nodeBuilderCache.size,
  };
}

/**
 * `cycles` create → render one frame → dispose cycles of a ShadingNodeMaterial (shading i mod 3, its own
 * shininess), rendering every `every`-th; the renderer's counts before, at their peak and after, how many times
 * the material's lighting was built (TSL), and the picture of the first and the last cycle of each shading.
 */
async function cycles(backend: Backend, n: number, every: number) {
  const r = await gpuRenderer(backend);
  const shadings: Shading[] = ['flat', 'gouraud', 'phong'];
  const c = (i: number): SceneCase => ({ kind: 'mesh', shading: shadings[i % 3] });
  // Materials that keep each variant's pipeline alive, as leaks.ts pins ShadingMaterial's programs.
  const pins = shadings.map((shading) => nodeMaterial({ kind: 'mesh', shading }));
  for (let k = 0; k < 3; k++) {
    const s = build(pins[k], c(k), 'gpu');
    await drawGpu(r, s.scene, s.camera, c(k));
  }
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  // The target's textures exist from its first use on: before the baseline.
  r.setRenderTarget(target);
  r.clear();
  r.setRenderTarget(null);
  const builds = { count: 0 };
  const proto = ShadingNodeMaterial.prototype as unknown as { setupLighting: (b: unknown) => unknown };
  const setupLighting = proto.setupLighting;
  proto.setupLighting = function (this: unknown, b: unknown) {
    builds.count++;
    return setupLighting.call(this, b);
  };
  const first: Uint8Array[] = [];
  const last: Uint8Array[] = [];
  const before = counts(r);
  const peak = counts(r);
  let frames = 0;
  try {
    for (let i = 0; i < n; i++) {
      const material = nodeMaterial(c(i));
      const capture = i < 3 || i >= n - 3;
      // Each its own shininess, but the pictures compared.
      if (!capture) material.shininess = 32 + (i % 7) * 1e-3;
      const s = build(material, c(i), 'gpu');
      if (i % every === 0 || capture) {
        r.setClearColor(0x000000, 0);
        r.setRenderTarget(target);
        r.render(s.scene, s.camera);
        r.setRenderTarget(null);
        frames++;
        if (capture) {
          const data = new Uint8Array(
            (await r.readRenderTargetPixelsAsync(target, 0, 0, SIZE, SIZE)) as Uint8Array,
          );
          (i < 3 ? first : last).push(data);
        }
        const now = counts(r);
        peak.pipelines = Math.max(peak.pipelines, now.pipelines);
        peak.vertexPrograms = Math.max(peak.vertexPrograms, now.vertexPrograms);
        peak.fragmentPrograms = Math.max(peak.fragmentPrograms, now.fragmentPrograms);
        peak.nodeBuilds = Math.max(peak.nodeBuilds, now.nodeBuilds);
        for (const k of Object.keys(now.memory)) peak.memory[k] = Math.max(peak.memory[k], now.memory[k]);
      }
      material.dispose();
    }
  } finally {
    proto.setupLighting = setupLighting;
  }
  const after = counts(r);
  target.dispose();
  for (const p of pins) p.dispose();
  const released = counts(r);
  // Cycles n−3 … n−1 have shadings (n−3) mod 3 …: line them up with the first three.
  const sameAsFirst = last.map((p, k) => {
    const j = (n - 3 + k) % 3;
    return p.every((v, i) => v === first[j][i]);
  });
  return {
    before,
    peak,
    after,
    released,
    builds: builds.count,
    frames,
    sameAsFirst,
    covered: first.map((p) => p.filter((_, i) => i % 4 === 3 && p[i] !== 0).length),
  };
}

// ---------------------------------------------------------------------------------------------------------------
// Shadows: a ground plane that receives an occluder's shadow (the occluder outside the view) from one of three's
// shadow-casting lights, as tests/harness/material-shadow.ts on WebGLRenderer. Where the shadow falls: three's
// MeshPhongNodeMaterial on the same renderer (the pixels its shadow darkens); colours: shade() with the light's
// colour × three's shadow factor; and WebGLRenderer + ShadingMaterial in the same scene.

export interface ShadowCase {
  shading: Shading;
  light: 'directional' | 'spot' | 'point';
  /** The ground's receiveShadow. @default true */
  receive?: boolean;
  /** The light's shadow.intensity. @default 1 */
  intensity?: number;
  /** ks of the ground. @default 0 */
  ks?: number;
  /** A uniform texture (TEXEL, linear) as the ground's map. @default false */
  map?: boolean;
  /** DoubleSide on the ground. @default false */
  doubleSide?: boolean;
  /** A PhongLight with castShadow = true in the scene too (it lights the ground, casts nothing). @default false */
  phongCaster?: boolean;
}

export interface ShadowStats {
  /** Pixels the shadow darkens (by more than 2/255 on some channel): three's material, this material. */
  oracleShadowed: number;
  shadowed: number;
  /** Pixels whose 3 × 3 neighbourhood is all shadowed or all lit for three's material, and how many differ. */
  maskCompared: number;
  maskMismatches: number;
  /** Pixels compared with shade(), in full shadow among them, the largest difference (1/255), how many > 2. */
  compared: number;
  shadowCompared: number;
  maxError: number;
  mismatches: number;
  worst: unknown;
  /** Against WebGLRenderer + ShadingMaterial: pixels uniform (3 × 3, shadow and light) in both pictures. */
  webgl: { compared: number; maxDelta: number; differing: number; maskMismatches: number; worst: unknown };
  /** console.warn calls while WebGLRenderer drew (three warns of a shadow-casting light without a shadow). */
  webglWarnings: string[];
  /** Which backend drew (three's flags on the renderer). */
  backend: ReturnType<typeof backendFlags>;
}

const SHADOW_SIZE = 128;
const SHADOW_KD: [number, number, number] = [0.6, 0.35, 0.2];
const SHADOW_TEXEL = [200, 220, 255] as const;
const SHADOW_AMBIENT = 0.2;

function shadowLight(kind: ShadowCase['light']): DirectionalLight | SpotLight | PointLight {
  const color = new Color(1, 0.95, 0.9);
  let light: DirectionalLight | SpotLight | PointLight;
  if (kind === 'directional') {
    light = new DirectionalLight(color, 1.5);
    Object.assign(light.shadow.camera, { left: -4, right: 4, top: 4, bottom: -4 });
  } else if (kind === 'spot') light = new SpotLight(color, 30, 0, Math.PI / 4, 0, 2);
  else light = new PointLight(color, 30, 0, 2);
  light.position.set(-3, 4, 0);
  light.castShadow = true;
  light.shadow.mapSize.set(512, 512);
  light.shadow.camera.near = 0.5;
  light.shadow.camera.far = 20;
  return light;
}

/** What shade() takes for `light`, its colour × `visibility` (three's shadow factor). */
function shadeThreeLight(
  light: DirectionalLight | SpotLight | PointLight,
  visibility: number,
): ShadeThreeLight {
  const color = light.color
    .clone()
    .multiplyScalar(light.intensity * visibility)
    .toArray();
  const position = light.position.clone();
  if (light instanceof DirectionalLight) {
    return { type: 'directional', color, direction: position.clone().normalize().toArray() };
  }
  const base = { color, position: position.toArray(), distance: 0, decay: 2 };
  if (light instanceof SpotLight) {
    return {
      type: 'spot',
      ...base,
      direction: position.clone().normalize().toArray(),
      coneCos: Math.cos(light.angle),
      penumbraCos: Math.cos(light.angle * (1 - light.penumbra)),
    };
  }
  return { type: 'point', ...base };
}

/** The shadow scene: the ground (exact flat shading: a triangle soup), an occluder, the light, an ambient light. */
function shadowScene(c: ShadowCase, groundMaterial: Material, occluderMaterial: Material) {
  const scene = new Scene();
  const camera = new PerspectiveCamera(40, 1, 0.5, 20);
  camera.position.set(0, 5, 0);
  camera.up.set(0, 0, -1);
  camera.lookAt(0, 0, 0);
  const light = shadowLight(c.light);
  light.shadow.intensity = c.intensity ?? 1;
  scene.add(light, new AmbientLight(0xffffff, SHADOW_AMBIENT));
  const phong = new PhongLight({ ambient: 0.05, diffuse: [0.3, 0.5, 0.4], specular: 0.6 });
  phong.position.set(1, 1.5, -0.5);
  phong.attenuation = { a: 1, b: 0.1, c: 0.05 };
  if (c.phongCaster) {
    (phong as unknown as { castShadow: boolean }).castShadow = true;
    scene.add(phong);
  }
  const occluder = new Mesh(new BoxGeometry(0.6, 0.1, 1.6), occluderMaterial);
  occluder.position.set(-1.9, 1.6, 0);
  occluder.castShadow = true;
  scene.add(occluder);
  const plane = new PlaneGeometry(4, 4, 8, 8).rotateX(-Math.PI / 2);
  const ground = new Mesh(c.shading === 'flat' ? plane.toNonIndexed() : plane, groundMaterial);
  ground.receiveShadow = c.receive ?? true;
  scene.add(ground);
  scene.updateMatrixWorld();
  camera.updateMatrixWorld();
  return { scene, camera, light, phong, ground };
}

function shadowOptions(c: ShadowCase) {
  const texture = c.map ? new DataTexture(new Uint8Array([...SHADOW_TEXEL, 255]), 1, 1) : null;
  if (texture !== null) texture.needsUpdate = true;
  return {
    shading: c.shading,
    ka: SHADOW_KD,
    kd: SHADOW_KD,
    ks: c.ks ?? 0,
    shininess: 16,
    map: texture,
    side: c.doubleSide ? DoubleSide : FrontSide,
  } as const;
}

/** Whether pixel i of `shadowed` is darker than of `lit` by more than 2/255 on some channel. */
const darker = (shadowed: Uint8Array, lit: Uint8Array, i: number) =>
  lit[4 * i] - shadowed[4 * i] > 2 ||
  lit[4 * i + 1] - shadowed[4 * i + 1] > 2 ||
  lit[4 * i + 2] - shadowed[4 * i + 2] > 2;

/** Whether the 3 × 3 neighbourhood of pixel (x, y) is all darker or all not (true), or mixed (false). */
function uniformShadow(shadowed: Uint8Array, lit: Uint8Array, x: number, y: number): boolean {
  const b = darker(shadowed, lit, y * SHADOW_SIZE + x);
  for (let dy = -1; dy <= 1; dy++)
    for (let dx = -1; dx <= 1; dx++)
      if (darker(shadowed, lit, (y + dy) * SHADOW_SIZE + x + dx) !== b) return false;
  return true;
}

/** Whether the 8 neighbours of pixel (x, y) have its RGB. */
function sameNeighbours(p: Uint8Array, x: number, y: number): boolean {
  const o = 4 * (y * SHADOW_SIZE + x);
  for (let dy = -1; dy <= 1; dy++)
    for (let dx = -1; dx <= 1; dx++)
      if (maxRgbDelta(p, p, o, 4 * ((y + dy) * SHADOW_SIZE + x + dx)) !== 0) return false;
  return true;
}

let shadowGl: WebGLRenderer | null = null;

/** The shadow scene with ShadingMaterial on WebGLRenderer, linear into a target: receiving, and not. */
function shadowGlPictures(c: ShadowCase): { ours: Uint8Array; lit: Uint8Array; warnings: string[] } {
  if (shadowGl === null) {
    shadowGl = new WebGLRenderer({ antialias: false, alpha: true, preserveDrawingBuffer: true });
    shadowGl.setPixelRatio(1);
    shadowGl.setSize(SHADOW_SIZE, SHADOW_SIZE, false);
    shadowGl.shadowMap.enabled = true;
    shadowGl.shadowMap.type = BasicShadowMap;
  }
  const r = shadowGl;
  const { side, ...options } = shadowOptions(c);
  const material = new ShadingMaterial(options);
  material.side = side;
  const setup = shadowScene(c, material, new MeshBasicMaterial());
  const target = new WebGLRenderTarget(SHADOW_SIZE, SHADOW_SIZE);
  const warnings: string[] = [];
  const warn = console.warn;
  console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
  const draw = (receive: boolean) => {
    setup.ground.receiveShadow = receive;
    r.setRenderTarget(target);
    r.setClearColor(0x000000, 0);
    r.render(setup.scene, setup.camera);
    const pixels = new Uint8Array(4 * SHADOW_SIZE * SHADOW_SIZE);
    r.readRenderTargetPixels(target, 0, 0, SHADOW_SIZE, SHADOW_SIZE, pixels);
    r.setRenderTarget(null);
    return pixels;
  };
  try {
    const ours = draw(c.receive ?? true);
    const lit = draw(false);
    return { ours, lit, warnings };
  } finally {
    console.warn = warn;
    target.dispose();
    material.map?.dispose();
    material.dispose();
  }
}

/**
 * One shadow case on one backend: ShadingNodeMaterial's ground against MeshPhongNodeMaterial's (where the shadow
 * falls), shade() (colours: the light × three's factor; flat shading at the face's centroid), and WebGLRenderer +
 * ShadingMaterial (colours, away from both pictures' shadow edges).
 */
async function shadowCompare(backend: Backend, c: ShadowCase): Promise<ShadowStats> {
  const r = await gpuRenderer(backend);
  const { side, ...options } = shadowOptions(c);
  const material = new ShadingNodeMaterial(options);
  material.side = side;
  const occluder = new MeshBasicNodeMaterial();
  const setup = shadowScene(c, material, occluder);
  const target = new RenderTarget(SHADOW_SIZE, SHADOW_SIZE, { depthBuffer: true });
  const oracle = new MeshPhongNodeMaterial({
    color: new Color(...SHADOW_KD),
    specular: 0x000000,
    shininess: 16,
  });
  r.shadowMap.enabled = true;
  r.shadowMap.type = BasicShadowMap;
  const draw = async (m: Material, receive: boolean) => {
    setup.ground.material = m;
    setup.ground.receiveShadow = receive;
    r.setRenderTarget(target);
    r.setClearColor(0x000000, 0);
    r.render(setup.scene, setup.camera);
    r.setRenderTarget(null);
    return readTarget(r, target, SHADOW_SIZE);
  };
  const receive = c.receive ?? true;
  let ours: Uint8Array;
  let oursLit: Uint8Array;
  let theirs: Uint8Array;
  let theirsLit: Uint8Array;
  try {
    ours = await draw(material, receive);
    oursLit = await draw(material, false);
    theirs = await draw(oracle, true);
    theirsLit = await draw(oracle, false);
  } finally {
    r.shadowMap.enabled = false;
    target.dispose();
    oracle.dispose();
    occluder.dispose();
    material.map?.dispose();
    material.dispose();
  }
  const gl = shadowGlPictures(c);
  const stats: ShadowStats = {
    oracleShadowed: 0,
    shadowed: 0,
    maskCompared: 0,
    maskMismatches: 0,
    compared: 0,
    shadowCompared: 0,
    maxError: 0,
    mismatches: 0,
    worst: null,
    webgl: { compared: 0, maxDelta: 0, differing: 0, maskMismatches: 0, worst: null },
    webglWarnings: gl.warnings,
    backend: backendFlags(r),
  };
  const { camera, light, phong, ground } = setup;
  const eye = camera.position.toArray();
  const others: (ShadeLight | ShadeThreeLight)[] = [
    { type: 'ambient', color: [SHADOW_AMBIENT, SHADOW_AMBIENT, SHADOW_AMBIENT] },
  ];
  if (c.phongCaster) {
    others.push({
      position: phong.position.toArray(),
      ambient: phong.ambient.toArray(),
      diffuse: phong.diffuse.toArray(),
      specular: phong.specular.toArray(),
      attenuation: phong.attenuation,
    });
  }
  const litLights = [...others, shadeThreeLight(light, 1)];
  const shadowLights = [...others, shadeThreeLight(light, 1 - light.shadow.intensity)];
  const m: ShadeMaterial = {
    ka: SHADOW_KD,
    kd: SHADOW_KD,
    ks: [c.ks ?? 0, c.ks ?? 0, c.ks ?? 0],
    shininess: 16,
    lighting: 'phong',
    celBands: 0,
  };
  const tint = c.map ? SHADOW_TEXEL.map((t) => t / 255) : [1, 1, 1];
  // Gouraud shading interpolates the vertices' colours: shade() per pixel only where they are constant.
  const shadeable = c.shading !== 'gouraud' || (c.light === 'directional' && (c.ks ?? 0) === 0);
  const raycaster = new Raycaster();
  const position = ground.geometry.getAttribute('position');
  for (let y = 1; y < SHADOW_SIZE - 1; y++) {
    for (let x = 1; x < SHADOW_SIZE - 1; x++) {
      const i = y * SHADOW_SIZE + x;
      const a = darker(ours, oursLit, i);
      const b = darker(theirs, theirsLit, i);
      if (a) stats.shadowed++;
      if (b) stats.oracleShadowed++;
      if (!uniformShadow(theirs, theirsLit, x, y)) continue;
      stats.maskCompared++;
      if (a !== b) stats.maskMismatches++;
      const o = 4 * i;
      // Against WebGLRenderer + ShadingMaterial, away from the edges of both renderers' shadows.
      if (uniformShadow(gl.ours, gl.lit, x, y)) {
        const g = darker(gl.ours, gl.lit, i);
        if (g !== b) stats.webgl.maskMismatches++;
        else {
          stats.webgl.compared++;
          const delta = maxRgbDelta(ours, gl.ours, o);
          if (delta > 2) stats.webgl.differing++;
          if (delta > stats.webgl.maxDelta) {
            stats.webgl.maxDelta = delta;
            stats.webgl.worst = {
              x,
              y,
              ours: Array.from(ours.subarray(o, o + 3)),
              gl: Array.from(gl.ours.subarray(o, o + 3)),
            };
          }
        }
      }
      if (!shadeable) continue;
      // Flat shading: one colour per face; a pixel whose neighbours are not all its colour is at a face's edge,
      // where the rasteriser and the ray may take different faces.
      if (c.shading === 'flat' && !sameNeighbours(ours, x, y)) continue;
      raycaster.setFromCamera(
        new Vector2(((x + 0.5) / SHADOW_SIZE) * 2 - 1, ((y + 0.5) / SHADOW_SIZE) * 2 - 1),
        camera,
      );
      const hit = raycaster.intersectObject(ground, false)[0];
      if (hit?.face == null) continue;
      let point = hit.point;
      if (c.shading === 'flat') {
        // Lit once per face, at its centroid.
        const { a: fa, b: fb, c: fc } = hit.face;
        point = new Vector3()
          .fromBufferAttribute(position, fa)
          .add(new Vector3().fromBufferAttribute(position, fb))
          .add(new Vector3().fromBufferAttribute(position, fc))
          .divideScalar(3)
          .applyMatrix4(ground.matrixWorld);
      }
      const expected = shade(
        { position: point.toArray(), normal: [0, 1, 0], eye, tint },
        m,
        b && receive ? shadowLights : litLights,
      );
      let error = 0;
      for (let k = 0; k < 3; k++)
        error = Math.max(error, Math.abs(ours[o + k] - Math.min(Math.max(expected[k], 0), 1) * 255));
      stats.compared++;
      if (b) stats.shadowCompared++;
      if (error > 2) stats.mismatches++;
      if (error > stats.maxError) {
        stats.maxError = error;
        stats.worst = {
          x,
          y,
          ours: Array.from(ours.subarray(o, o + 3)),
          expected: expected.map((e) => e * 255),
        };
      }
    }
  }
  return stats;
}

/**
 * A PhongLight with castShadow = true beside three's MeshPhongNodeMaterial and ShadingNodeMaterial, both receiving
 * shadows, with a shadow-casting DirectionalLight and the renderer's shadow map on: the picture of the same scene
 * with the PhongLight's castShadow false (pixels differing), and the pixels drawn.
 */
async function phongCaster(backend: Backend) {
  const r = await gpuRenderer(backend);
  const scene = new Scene();
  const camera = new PerspectiveCamera(45, 1, 0.1, 20);
  camera.position.set(0, 1.5, 4);
  camera.lookAt(0, 0, 0);
  const phong = new PhongLight();
  phong.position.set(-2, 3, 3);
  const sun = shadowLight('directional');
  scene.add(phong, sun, new AmbientLight(0xffffff, SHADOW_AMBIENT));
  const ours = new ShadingNodeMaterial({ shading: 'gouraud' });
  const three = new MeshPhongNodeMaterial({ color: 0x8080ff });
  const left = new Mesh(new SphereGeometry(0.6, 24, 12), ours);
  left.position.set(-0.7, 0.2, 0);
  const right = new Mesh(new SphereGeometry(0.6, 24, 12), three);
  right.position.set(0.7, 0.2, 0);
  const floor = new Mesh(new PlaneGeometry(4, 4).rotateX(-Math.PI / 2), new ShadingNodeMaterial());
  floor.position.y = -0.5;
  for (const o of [left, right, floor]) {
    o.castShadow = true;
    o.receiveShadow = true;
  }
  scene.add(left, right, floor);
  scene.updateMatrixWorld();
  camera.updateMatrixWorld();
  r.shadowMap.enabled = true;
  r.shadowMap.type = BasicShadowMap;
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  const draw = async (cast: boolean) => {
    (phong as unknown as { castShadow: boolean }).castShadow = cast;
    r.setRenderTarget(target);
    r.setClearColor(0x000000, 0);
    r.render(scene, camera);
    r.setRenderTarget(null);
    return readTarget(r, target, SIZE);
  };
  try {
    const casting = await draw(true);
    const plain = await draw(false);
    const again = await draw(true);
    let differing = 0;
    let drawn = 0;
    let black = 0;
    for (let i = 0; i < SIZE * SIZE; i++) {
      const o = 4 * i;
      if (maxRgbDelta(casting, plain, o) > 0 || maxRgbDelta(again, plain, o) > 0) differing++;
      if (covered(casting, i)) {
        drawn++;
        if (casting[o] + casting[o + 1] + casting[o + 2] === 0) black++;
      }
    }
    return { differing, drawn, black, backend: backendFlags(r) };
  } finally {
    r.shadowMap.enabled = false;
    target.dispose();
    for (const m of [ours, three, floor.material]) m.dispose();
  }
}

const api = {
  flatExactCompare,
  shadowCompare,
  phongCaster,
  sceneCompare,
  clipCompare,
  pairDiff,
  phongPairDiff,
  mixedVariants,
  variantSwitch,
  deviceLoss,
  cycles,
};
export type WebGPUSceneHarness = typeof api;
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
