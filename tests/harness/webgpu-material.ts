// Harness for tests/material-webgpu.spec.ts: ShadingNodeMaterial under WebGPURenderer (its WebGPU backend and,
// with forceWebGL, its WebGL2 backend), rendered offscreen into a RenderTarget (presenting to a WebGPU canvas
// headless loses the device) and read back; compared with shade() per pixel and with ShadingMaterial under
// WebGLRenderer.
import {
  flatShadingGeometry,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeThreeLight,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { createImpostorQuad } from '@shadelab/material/impostor';
import { ShadingNodeMaterial, SphereImpostorNodeMaterial } from '@shadelab/material/webgpu';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  AmbientLight,
  BackSide,
  BufferAttribute,
  type BufferGeometry,
  Color,
  CylinderGeometry,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  Fog,
  FogExp2,
  FrontSide,
  InstancedMesh,
  LinearFilter,
  type Material,
  Matrix3,
  Matrix4,
  Mesh,
  MeshPhongMaterial,
  Object3D,
  ObjectSpaceNormalMap,
  PerspectiveCamera,
  RGBAFormat,
  Scene,
  type Side,
  SRGBColorSpace,
  Vector2,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import {
  MeshLambertNodeMaterial,
  MeshPhongNodeMaterial,
  RenderTarget,
  type WebGPURenderer,
} from 'three/webgpu';
import { thrown } from './lib/errors';
import { hasRgb, maxRgbDelta } from './lib/pixels';
import { lightingDiscontinuity, pixelHits, screenEdgeDistance } from './lib/shadeOracle';
import { fiveThreeLights } from './lib/threeLights';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';

type Shading = 'flat' | 'gouraud' | 'phong';
type Lighting = 'phong' | 'blinn-phong';
export interface Variant {
  shading: Shading;
  lighting: Lighting;
  celBands: number;
}
export type { Backend };
/**
 * The lights and the geometry: 'lecture' (one PhongLight, the lecture's), 'attenuated' (a near coloured
 * PhongLight with a + b·t + c·t², shininess 0: the 0⁰ = 1 rule), 'three-lights' (three's ambient, hemisphere,
 * directional, point and spot lights, no PhongLight), 'analytic' (the lecture's light, a sphere without normals),
 * 'indexed' (an indexed sphere: flat shading by derivatives) and 'instanced' (one instance of an InstancedMesh
 * carrying the transform: exact flat shading, the instance's face at its centroid), 'fog' (the lecture's scene in three's Fog), 'prepared'
 * (the indexed sphere through flatShadingGeometry for the backend's provoking vertex: one colour per face),
 * 'prepared-other' (made for the other backend's: by derivatives, with a warning), 'flattened' (the lecture's
 * scene with the sphere's y scale 0: a disc, whose normal only the robust normal matrix gives), 'backside' (the
 * sphere drawn BackSide: its far inner half), 'doubleside' (an open cylinder, non-indexed, drawn DoubleSide: its
 * outside and, through the open end, its inside).
 */
export type Scenario =
  | 'lecture'
  | 'attenuated'
  | 'three-lights'
  | 'analytic'
  | 'indexed'
  | 'instanced'
  | 'fog'
  | 'prepared'
  | 'prepared-other'
  | 'flattened'
  | 'backside'
  | 'doubleside';

/**
 * three's surface properties set on both materials (the lecture's scene with a non-indexed sphere that has `uv`
 * and an RGBA `color` attribute, smooth functions of the position): `map` (a 4 × 4 RGBA texture, bilinear),
 * `vertexColors` (RGB, or RGBA: the alpha too), `instanceColor` (an InstancedMesh of one instance with a colour),
 * `emissive`, `emissiveMap` (the map's texture), `opacity`, `transparent`, `alphaTest`, `alphaMap` (a texture
 * whose green differs from its red: three reads green), `side`.
 */
export interface SurfaceCase {
  map?: boolean;
  vertexColors?: 'rgb' | 'rgba';
  instanceColor?: boolean;
  emissive?: boolean;
  emissiveMap?: boolean;
  opacity?: number;
  transparent?: boolean;
  alphaTest?: number;
  alphaMap?: boolean;
  side?: 'front' | 'back' | 'double';
  /** A 4 × 4 normal map (bilinear): tangent space (through the derivative tangent frame) or object space. */
  normalMap?: 'tangent' | 'object';
}

const SIZE = 128;
/** The clear colour (0x0000ff) in RGB: where nothing was drawn. */
const CLEAR = [0, 0, 255] as const;
const geometry: BufferGeometry = new SubdivisionSphereGeometry({
  level: 3,
  base: 'tetrahedron',
  indexed: false,
});
const indexedGeometry: BufferGeometry = new SubdivisionSphereGeometry({
  level: 3,
  base: 'tetrahedron',
  indexed: true,
});
const bareGeometry: BufferGeometry = new SubdivisionSphereGeometry({
  level: 3,
  base: 'tetrahedron',
  indexed: false,
  normals: 'none',
});

/** The provoking vertex of flat varyings: the first on WebGPU, the last on WebGL2. */
const provoking = (backend: Backend | 'webgl'): 'first' | 'last' => (backend === 'webgpu' ? 'first' : 'last');
const prepared = {
  first: flatShadingGeometry(indexedGeometry, { provokingVertex: 'first' }),
  last: flatShadingGeometry(indexedGeometry, { provokingVertex: 'last' }),
};

const cylinder = new CylinderGeometry(0.8, 0.8, 1.6, 12, 1, true).toNonIndexed();

const surfaceSide = (surface: SurfaceCase): Side =>
  surface.side === 'double' ? DoubleSide : surface.side === 'back' ? BackSide : FrontSide;

/** Adds `uv` and an RGBA `color` attribute, smooth functions of the position, to a copy of `source`. */
function withSurface(source: BufferGeometry): BufferGeometry {
  const g = source.clone();
  const position = g.getAttribute('position');
  const color = new Float32Array(4 * position.count);
  const uv = new Float32Array(2 * position.count);
  for (let i = 0; i < position.count; i++) {
    const [x, y, z] = [position.getX(i), position.getY(i), position.getZ(i)];
    color.set([0.55 + 0.4 * x, 0.55 + 0.4 * y, 0.55 + 0.4 * z, 0.65 + 0.3 * z], 4 * i);
    uv.set([0.5 + 0.45 * x, 0.5 + 0.45 * (y + z) * 0.7], 2 * i);
  }
  g.setAttribute('color', new BufferAttribute(color, 4));
  if (!g.hasAttribute('uv')) g.setAttribute('uv', new BufferAttribute(uv, 2));
  return g;
}
const surfaceSphere = withSurface(geometry);
const surfaceCylinder = withSurface(cylinder);
/** The RGB-only vertex colours of the same geometries. */
function rgbColours(source: BufferGeometry): BufferGeometry {
  const g = source.clone();
  const c = g.getAttribute('color');
  const rgb = new Float32Array(3 * c.count);
  for (let i = 0; i < c.count; i++) rgb.set([c.getX(i), c.getY(i), c.getZ(i)], 3 * i);
  g.setAttribute('color', new BufferAttribute(rgb, 3));
  return g;
}
const surfaceGeometries = {
  rgba: { sphere: surfaceSphere, cylinder: surfaceCylinder },
  rgb: { sphere: rgbColours(surfaceSphere), cylinder: rgbColours(surfaceCylinder) },
};
const surfaceGeometryOf = (surface: SurfaceCase): BufferGeometry =>
  surfaceGeometries[surface.vertexColors === 'rgb' ? 'rgb' : 'rgba'][
    surface.side === 'double' ? 'cylinder' : 'sphere'
  ];

/** 4 × 4 RGBA8 texels (rows from v = 0): the map's, and the alpha map's (green ≠ red: three reads green). */
const MAP_TEXELS = texels((x, y) => [
  120 + 30 * x + 10 * y,
  200 - 25 * y,
  90 + 20 * x + 15 * y,
  150 + 25 * x,
]);
const ALPHA_TEXELS = texels((x, y) => [60 + 30 * y, 255 - 40 * x, 0, 255]);
/** A tangent-space normal map: x and y in −0.45 … 0.45, z up (8-bit, 0 … 255 ↦ −1 … 1). */
const NORMAL_TEXELS = texels((x, y) => [128 + 38 * (x - 1.5), 128 - 30 * (y - 1.5), 210, 255]);
/** An object-space normal map: the sphere's outward directions, bent. */
const OBJECT_NORMAL_TEXELS = texels((x, y) => [
  128 + 40 * (x - 1.5),
  128 + 40 * (y - 1.5),
  200 - 20 * x,
  255,
]);
function texels(f: (x: number, y: number) => number[]): Uint8Array {
  const data = new Uint8Array(64);
  for (let y = 0; y < 4; y++) for (let x = 0; x < 4; x++) data.set(f(x, y), 4 * (4 * y + x));
  return data;
}
/** The texture of `data`: linear (no colour space), bilinear, no mipmaps, clamped. One per renderer. */
const _textures = new Map<string, DataTexture>();
function textureOf(data: Uint8Array, api: 'gpu' | 'gl'): DataTexture {
  const name =
    data === MAP_TEXELS
      ? 'map'
      : data === NORMAL_TEXELS
        ? 'normal'
        : data === OBJECT_NORMAL_TEXELS
          ? 'object'
          : 'alpha';
  const key = `${name} ${api}`;
  let t = _textures.get(key);
  if (t === undefined) {
    t = new DataTexture(data, 4, 4, RGBAFormat);
    t.magFilter = LinearFilter;
    t.minFilter = LinearFilter;
    t.generateMipmaps = false;
    t.needsUpdate = true;
    _textures.set(key, t);
  }
  return t;
}
/** Bilinear sample of `data` at (u, v), clamped to the edge, as the GPU filters it: RGBA in 0 … 1. */
function sample(data: Uint8Array, u: number, v: number): number[] {
  const x = u * 4 - 0.5;
  const y = v * 4 - 0.5;
  const x0 = Math.floor(x);
  const y0 = Math.floor(y);
  const fx = x - x0;
  const fy = y - y0;
  const c = (i: number) => Math.min(Math.max(i, 0), 3);
  const at = (i: number, j: number, k: number) => data[4 * (4 * c(j) + c(i)) + k] / 255;
  return [0, 1, 2, 3].map(
    (k) =>
      (at(x0, y0, k) * (1 - fx) + at(x0 + 1, y0, k) * fx) * (1 - fy) +
      (at(x0, y0 + 1, k) * (1 - fx) + at(x0 + 1, y0 + 1, k) * fx) * fy,
  );
}
const EMISSIVE = [0.12, 0.05, 0.2];
const INSTANCE_COLOUR = [0.9, 0.6, 0.45];

/** The options of `surface` for either material. */
function surfaceOptions(surface: SurfaceCase | undefined, api: 'gpu' | 'gl') {
  if (surface === undefined) return {};
  return {
    map: surface.map ? textureOf(MAP_TEXELS, api) : null,
    vertexColors: surface.vertexColors !== undefined,
    emissive: surface.emissive || surface.emissiveMap ? (EMISSIVE as [number, number, number]) : 0,
    emissiveMap: surface.emissiveMap ? textureOf(MAP_TEXELS, api) : null,
    opacity: surface.opacity ?? 1,
    transparent: surface.transparent === true,
    alphaTest: surface.alphaTest ?? 0,
    alphaMap: surface.alphaMap ? textureOf(ALPHA_TEXELS, api) : null,
    normalMap:
      surface.normalMap === undefined
        ? null
        : textureOf(surface.normalMap === 'object' ? OBJECT_NORMAL_TEXELS : NORMAL_TEXELS, api),
  };
}

/** The side a scenario's material draws. */
const sideOf = (scenario: Scenario): Side =>
  scenario === 'backside' ? BackSide : scenario === 'doubleside' ? DoubleSide : FrontSide;

function geometryOf(scenario: Scenario, backend: Backend | 'webgl'): BufferGeometry {
  if (scenario === 'doubleside') return cylinder;
  if (scenario === 'analytic') return bareGeometry;
  if (scenario === 'indexed') return indexedGeometry;
  if (scenario === 'prepared') return prepared[provoking(backend)];
  if (scenario === 'prepared-other') return prepared[provoking(backend) === 'first' ? 'last' : 'first'];
  return geometry;
}

function scene(
  material: Material,
  scenario: Scenario = 'lecture',
  backend: Backend | 'webgl' = 'webgl',
  surface?: SurfaceCase,
): {
  scene: Scene;
  camera: PerspectiveCamera;
  mesh: Mesh;
  lights: (ShadeLight | ShadeThreeLight)[];
} {
  const transform = new Object3D();
  transform.scale.set(1.2, scenario === 'flattened' ? 0 : 1, 1.2);
  transform.rotation.set(0.3, 0.5, 0);
  transform.updateMatrix();
  let mesh: Mesh;
  if (surface !== undefined) {
    const g = surfaceGeometryOf(surface);
    if (surface.instanceColor) {
      const instanced = new InstancedMesh(g, material, 1);
      instanced.setMatrixAt(0, transform.matrix);
      instanced.setColorAt(0, new Color(...(INSTANCE_COLOUR as [number, number, number])));
      mesh = instanced;
    } else {
      mesh = new Mesh(g, material);
      mesh.applyMatrix4(transform.matrix);
    }
  } else if (scenario === 'instanced') {
    const instanced = new InstancedMesh(geometry, material, 1);
    instanced.setMatrixAt(0, transform.matrix);
    mesh = instanced;
  } else {
    mesh = new Mesh(geometryOf(scenario, backend), material);
    mesh.applyMatrix4(transform.matrix);
  }
  const s = new Scene();
  s.add(mesh);
  if (scenario === 'fog') s.fog = new Fog(new Color(0.2, 0.4, 0.6), 1.9, 3.2);
  let lights: (ShadeLight | ShadeThreeLight)[];
  if (scenario === 'three-lights') {
    const three = fiveThreeLights();
    s.add(...three.lights);
    lights = three.shade;
  } else {
    const light = new PhongLight();
    light.position.set(-5, 10, 20);
    if (scenario === 'attenuated') {
      light.position.set(-2, 3, 4);
      light.diffuse = [1, 0.9, 0.7];
      light.specular = [0.6, 0.7, 0.9];
      light.attenuation = { a: 0.5, b: 0.2, c: 0.05 };
    }
    s.add(light);
    lights = [
      {
        position: light.position.toArray(),
        ambient: light.ambient.toArray(),
        diffuse: light.diffuse.toArray(),
        specular: light.specular.toArray(),
        attenuation: light.attenuation,
      },
    ];
  }
  const camera = new PerspectiveCamera(60, 1, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  s.updateMatrixWorld();
  camera.updateMatrixWorld();
  return { scene: s, camera, mesh, lights };
}

const shininessOf = (scenario: Scenario): number => (scenario === 'attenuated' ? 0 : 32);

/** `s` drawn into `target` over the blue clear colour and read back: rows bottom-up, RGBA8, linear. */
async function drawInto(
  renderer: WebGPURenderer,
  target: RenderTarget,
  s: Scene,
  camera: PerspectiveCamera,
): Promise<Uint8Array> {
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(s, camera);
  const pixels = await readTarget(renderer, target, SIZE);
  renderer.setRenderTarget(null);
  return pixels;
}

/** Rows bottom-up, RGBA8, linear (a render target has no output colour space conversion). */
async function renderGpu(
  backend: Backend,
  v: Variant,
  scenario: Scenario = 'lecture',
  surface?: SurfaceCase,
) {
  const renderer = await gpuRenderer(backend);
  const material = new ShadingNodeMaterial({
    ...v,
    shininess: shininessOf(scenario),
    lights: [],
    ...surfaceOptions(surface, 'gpu'),
  });
  material.side = surface !== undefined ? surfaceSide(surface) : sideOf(scenario);
  if (surface?.normalMap === 'object') material.normalMapType = ObjectSpaceNormalMap;
  const setup = scene(material, scenario, backend, surface);
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  const pixels = await drawInto(renderer, target, setup.scene, setup.camera);
  target.dispose();
  material.dispose();
  return { pixels, setup, material, backend: renderer.backend };
}

let gl: WebGLRenderer | null = null;
function renderGl(v: Variant, scenario: Scenario = 'lecture', surface?: SurfaceCase): Uint8Array {
  gl ??= new WebGLRenderer({ antialias: false });
  const material = new ShadingMaterial({ ...v, ...surfaceOptions(surface, 'gl') });
  material.side = surface !== undefined ? surfaceSide(surface) : sideOf(scenario);
  if (surface?.normalMap === 'object') material.normalMapType = ObjectSpaceNormalMap;
  const setup = scene(material, scenario, 'webgl', surface);
  const target = new WebGLRenderTarget(SIZE, SIZE);
  gl.setRenderTarget(target);
  gl.setClearColor(0x0000ff, 1);
  gl.clear();
  gl.render(setup.scene, setup.camera);
  const pixels = new Uint8Array(4 * SIZE * SIZE);
  gl.readRenderTargetPixels(target, 0, 0, SIZE, SIZE, pixels);
  gl.setRenderTarget(null);
  target.dispose();
  material.dispose();
  return pixels;
}

/** Which backend runs and what the adapter is: proof that WebGPU is not a silent fallback to WebGL2. */
async function backendInfo(backend: Backend) {
  const renderer = await gpuRenderer(backend);
  const { device } = renderer.backend as unknown as { device?: unknown };
  const adapter =
    'gpu' in navigator
      ? await (navigator as unknown as { gpu: { requestAdapter(): Promise<unknown> } }).gpu.requestAdapter()
      : null;
  return {
    ...backendFlags(renderer),
    device: typeof GPUDevice !== 'undefined' && device instanceof GPUDevice,
    adapter: adapter !== null,
  };
}

interface Stats {
  covered: number;
  compared: number;
  maxError: number;
  mismatches: number;
  facesChecked: number;
  facesMultiColour: number;
  worst: unknown;
}

/** Per pixel away from triangle edges and lighting discontinuities: |GPU − shade()| in 1/255 (linear). */
async function compare(
  backend: Backend,
  v: Variant,
  scenario: Scenario = 'lecture',
  surface?: SurfaceCase,
): Promise<Stats> {
  const { pixels, setup } = await renderGpu(backend, v, scenario, surface);
  const { mesh, camera, lights } = setup;
  // Triangle k of the indexed sphere is triangle k of its soup (and of its flatShadingGeometry, corners rotated).
  const fromIndexed = scenario === 'indexed' || scenario === 'prepared' || scenario === 'prepared-other';
  const soup =
    surface !== undefined
      ? surfaceGeometryOf(surface)
      : fromIndexed
        ? indexedGeometry.toNonIndexed()
        : scenario === 'doubleside'
          ? cylinder
          : geometry;
  const positions = soup.getAttribute('position');
  // Flat shading by derivatives: per fragment, the face normal at the fragment's position.
  // (An InstancedMesh's soup is exact flat shading, as ShadingMaterial's: each face at its centroid.)
  const perFragmentFlat = scenario === 'indexed' || scenario === 'prepared-other';
  const matrix = mesh.matrixWorld.clone();
  if (mesh instanceof InstancedMesh) {
    const instance = new Matrix4();
    mesh.getMatrixAt(0, instance);
    matrix.multiply(instance);
  }
  // The analytic sphere's normal is its position.
  const normals = scenario === 'analytic' ? positions : soup.getAttribute('normal');
  const count = positions.count;
  const world: Vector3[] = [];
  const worldNormal: Vector3[] = [];
  const nm = new Matrix3().getNormalMatrix(matrix);
  for (let i = 0; i < count; i++) {
    world.push(new Vector3().fromBufferAttribute(positions, i).applyMatrix4(matrix));
    worldNormal.push(new Vector3().fromBufferAttribute(normals, i).applyMatrix3(nm).normalize());
  }
  const eye = [camera.position.x, camera.position.y, camera.position.z, 1];
  const m: ShadeMaterial = {
    ka: [0.6, 0.35, 0.2],
    kd: [0.6, 0.35, 0.2],
    ks: [0.5, 0.5, 0.5],
    shininess: shininessOf(scenario),
    ...v,
  };
  const discontinuity = lightingDiscontinuity(m, lights, eye);
  const atDiscontinuity = (p: Vector3, n: Vector3): boolean => discontinuity(p.toArray(), n.toArray());
  // The surface: per vertex, uv and colour; the tint of the vertex stage (instance × vertex colour); the ka/kd
  // part and the ks part of a vertex or face colour apart (the texel multiplies the first per fragment).
  const sf: SurfaceCase = surface ?? {};
  const uvs = soup.getAttribute('uv');
  const colours = soup.getAttribute('color');
  const instanceTint = sf.instanceColor ? INSTANCE_COLOUR : [1, 1, 1];
  const vertexTint = (i: number): number[] =>
    sf.vertexColors !== undefined
      ? [colours.getX(i), colours.getY(i), colours.getZ(i)].map((c, k) => c * instanceTint[k])
      : instanceTint;
  // The normal map (phong shading): the interpolated unit normal n of triangle t perturbed at (u, v), three's
  // getTangentFrame on the triangle's own edges (the derivatives' frame: its formula is bilinear and
  // antisymmetric in the two difference vectors, so any two of the plane's give it), or the object-space texel
  // through the normal matrix.
  const mapNormal = (n: Vector3, t: number, u: number, vv: number): Vector3 => {
    if (sf.normalMap === 'object') {
      const texel = sample(OBJECT_NORMAL_TEXELS, u, vv);
      return new Vector3(texel[0] * 2 - 1, texel[1] * 2 - 1, texel[2] * 2 - 1).applyMatrix3(nm).normalize();
    }
    const texel = sample(NORMAL_TEXELS, u, vv).map((c) => c * 2 - 1);
    const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
    const q0 = b.clone().sub(a);
    const q1 = c.clone().sub(a);
    const uv = (i: number) => new Vector2(uvs.getX(3 * t + i), uvs.getY(3 * t + i));
    const st0 = uv(1).sub(uv(0));
    const st1 = uv(2).sub(uv(0));
    const q1perp = q1.clone().cross(n);
    const q0perp = n.clone().cross(q0);
    const T = q1perp.clone().multiplyScalar(st0.x).addScaledVector(q0perp, st1.x);
    const B = q1perp.clone().multiplyScalar(st0.y).addScaledVector(q0perp, st1.y);
    const det = Math.max(T.dot(T), B.dot(B));
    const scale = det === 0 ? 0 : 1 / Math.sqrt(det);
    return T.multiplyScalar(scale * texel[0])
      .addScaledVector(B, scale * texel[1])
      .addScaledVector(n, texel[2])
      .normalize();
  };
  const kadOnly: ShadeMaterial = { ...m, ks: [0, 0, 0] };
  const ksOnly: ShadeMaterial = { ...m, ka: [0, 0, 0], kd: [0, 0, 0] };
  const split = (position: number[], normal: number[], tint: number[]) => ({
    kad: shade({ position, normal, eye, tint }, kadOnly, lights),
    ks: shade({ position, normal, eye }, ksOnly, lights),
  });
  const vertexSplit = world.map((p, i) => split(p.toArray(), worldNormal[i].toArray(), vertexTint(i)));
  const vertexColour = world.map((p, i) =>
    shade({ position: p.toArray(), normal: worldNormal[i].toArray(), eye }, m, lights),
  );
  const vertexEdge = world.map((p, i) => atDiscontinuity(p, worldNormal[i]));
  const faces = count / 3;
  const faceColour: number[][] = [];
  const faceEdge: boolean[] = [];
  const faceSplit: { kad: number[]; ks: number[] }[] = [];
  for (let t = 0; t < faces; t++) {
    const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
    const centroid = a.clone().add(b).add(c).divideScalar(3);
    const normal = b.clone().sub(a).cross(c.clone().sub(a));
    faceColour.push(shade({ position: centroid.toArray(), normal: normal.toArray(), eye }, m, lights));
    faceEdge.push(atDiscontinuity(centroid, normal));
    // ShadingMaterial's flat tint: the last vertex's (WebGL's provoking vertex), on every backend.
    faceSplit.push(split(centroid.toArray(), normal.toArray(), vertexTint(3 * t + 2)));
  }
  const soupWorld = new Float64Array(world.flatMap((p) => p.toArray()));
  const edgeDistance = screenEdgeDistance(soupWorld, camera, SIZE);
  const side = (mesh.material as Material).side;
  const hits = pixelHits(
    soupWorld,
    camera,
    SIZE,
    matrix.determinant() < 0,
    side === DoubleSide ? 'double' : side === BackSide ? 'back' : 'front',
  );
  const stats: Stats = {
    covered: 0,
    compared: 0,
    maxError: 0,
    mismatches: 0,
    facesChecked: 0,
    facesMultiColour: 0,
    worst: null,
  };
  const faceSeen = new Map<number, string>();
  const faceMulti = new Set<number>();
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const o = 4 * (y * SIZE + x);
      const covered = !hasRgb(pixels, o, CLEAR);
      if (covered) stats.covered++;
      const pixel = y * SIZE + x;
      const t = hits.triangle[pixel];
      if (t < 0) continue;
      if (edgeDistance(t, x + 0.5, y + 0.5) < 1.5) continue;
      let expected: number[];
      const w = Array.from(hits.bary.subarray(3 * pixel, 3 * pixel + 3));
      const point = new Vector3().fromArray(hits.point, 3 * pixel);
      if (v.shading === 'flat' && perFragmentFlat) {
        const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
        const normal = b.clone().sub(a).cross(c.clone().sub(a));
        if (atDiscontinuity(point, normal)) continue;
        expected = shade({ position: point.toArray(), normal: normal.toArray(), eye }, m, lights);
      } else if (v.shading === 'flat') {
        if (faceEdge[t]) continue;
        expected = faceColour[t];
        // A back face (seen from behind its winding) is lit with the face normal turned round.
        const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
        const normal = b.clone().sub(a).cross(c.clone().sub(a));
        if (normal.dot(point.clone().sub(camera.position)) > 0) {
          const centroid = a.clone().add(b).add(c).divideScalar(3);
          if (atDiscontinuity(centroid, normal)) continue;
          expected = shade(
            { position: centroid.toArray(), normal: normal.negate().toArray(), eye },
            m,
            lights,
          );
        }
        const key = `${pixels[o]},${pixels[o + 1]},${pixels[o + 2]}`;
        const seen = faceSeen.get(t);
        if (seen === undefined) faceSeen.set(t, key);
        else if (seen !== key) faceMulti.add(t);
      } else if (v.shading === 'gouraud') {
        if (vertexEdge[3 * t] || vertexEdge[3 * t + 1] || vertexEdge[3 * t + 2]) continue;
        expected = [0, 1, 2].map((k) => w.reduce((s, wi, i) => s + wi * vertexColour[3 * t + i][k], 0));
      } else {
        const n = new Vector3();
        for (let i = 0; i < 3; i++) n.addScaledVector(worldNormal[3 * t + i], w[i]);
        if (atDiscontinuity(point, n)) continue;
        expected = shade({ position: point.toArray(), normal: n.toArray(), eye }, m, lights);
      }
      if (surface !== undefined) {
        const at = (attribute: typeof uvs, k: number) =>
          w.reduce((sum, wi, i) => sum + wi * attribute.getComponent(3 * t + i, k), 0);
        const [u, vv] = [at(uvs, 0), at(uvs, 1)];
        const texel = sf.map ? sample(MAP_TEXELS, u, vv) : [1, 1, 1, 1];
        const colour = [0, 1, 2, 3].map((k) => at(colours, k));
        const position = point.toArray();
        if (v.shading === 'phong' || (v.shading === 'flat' && perFragmentFlat)) {
          const normal = new Vector3();
          if (v.shading === 'phong') {
            for (let i = 0; i < 3; i++) normal.addScaledVector(worldNormal[3 * t + i], w[i]);
            if (sf.normalMap !== undefined) normal.copy(mapNormal(normal.normalize(), t, u, vv));
          } else {
            // Flat shading by derivatives (an InstancedMesh): per fragment, the face normal.
            const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
            normal.copy(b.clone().sub(a).cross(c.clone().sub(a)));
          }
          const tint = instanceTint.map(
            (c, k) => c * texel[k] * (sf.vertexColors !== undefined ? colour[k] : 1),
          );
          expected = shade({ position, normal: normal.toArray(), eye, tint }, m, lights);
        } else {
          const part =
            v.shading === 'flat'
              ? faceSplit[t]
              : {
                  kad: [0, 1, 2].map((k) =>
                    w.reduce((sum, wi, i) => sum + wi * vertexSplit[3 * t + i].kad[k], 0),
                  ),
                  ks: [0, 1, 2].map((k) =>
                    w.reduce((sum, wi, i) => sum + wi * vertexSplit[3 * t + i].ks[k], 0),
                  ),
                };
          expected = [0, 1, 2].map((k) => part.kad[k] * texel[k] + part.ks[k]);
        }
        if (sf.emissive || sf.emissiveMap) {
          const e = sf.emissiveMap ? sample(MAP_TEXELS, u, vv) : [1, 1, 1];
          expected = expected.map((c, k) => c + EMISSIVE[k] * e[k]);
        }
        const alpha =
          (sf.opacity ?? 1) *
          texel[3] *
          (sf.vertexColors === 'rgba' ? colour[3] : 1) *
          (sf.alphaMap ? sample(ALPHA_TEXELS, u, vv)[1] : 1);
        if (sf.alphaTest !== undefined && sf.alphaTest > 0) {
          // Near the threshold float rounding may go either way.
          if (Math.abs(alpha - sf.alphaTest) < 0.02) continue;
          if (alpha < sf.alphaTest) expected = CLEAR.map((c) => c / 255);
        }
        if (sf.transparent && !(sf.alphaTest !== undefined && alpha < sf.alphaTest)) {
          expected = expected.map(
            (c, k) => Math.min(Math.max(c, 0), 1) * alpha + (CLEAR[k] / 255) * (1 - alpha),
          );
        }
        if (sf.map || sf.emissiveMap || sf.transparent || sf.alphaTest) faceMulti.delete(t);
      }
      stats.compared++;
      let error = 0;
      for (let k = 0; k < 3; k++)
        error = Math.max(error, Math.abs(pixels[o + k] - Math.min(Math.max(expected[k], 0), 1) * 255));
      if (error > stats.maxError) {
        stats.maxError = error;
        stats.worst = {
          x,
          y,
          t,
          got: Array.from(pixels.subarray(o, o + 3)),
          expected: expected.map((e) => e * 255),
        };
      }
      if (error > 2) stats.mismatches++;
    }
  }
  stats.facesChecked = faceSeen.size;
  stats.facesMultiColour = faceMulti.size;
  return stats;
}

/** WebGLRenderer + ShadingMaterial against WebGPURenderer + ShadingNodeMaterial, same scene: max |Δ| in 1/255. */
async function crossRenderer(
  backend: Backend,
  v: Variant,
  scenario: Scenario = 'lecture',
  surface?: SurfaceCase,
) {
  const a = renderGl(v, scenario, surface);
  const { pixels: b } = await renderGpu(backend, v, scenario, surface);
  let maxDelta = 0;
  let differing = 0;
  let covered = 0;
  let coverageMismatch = 0;
  let worst: unknown = null;
  for (let i = 0; i < a.length; i += 4) {
    const ca = !hasRgb(a, i, CLEAR);
    const cb = !hasRgb(b, i, CLEAR);
    if (ca !== cb) coverageMismatch++;
    if (!ca || !cb) continue;
    covered++;
    const d = maxRgbDelta(a, b, i);
    if (d > maxDelta) {
      maxDelta = d;
      const p = i / 4;
      worst = {
        x: p % SIZE,
        y: Math.floor(p / SIZE),
        webgl: [a[i], a[i + 1], a[i + 2]],
        gpu: [b[i], b[i + 1], b[i + 2]],
      };
    }
    if (d > 2) differing++;
  }
  return { covered, maxDelta, differing, coverageMismatch, worst };
}

/** How many pixels three's Fog changes by more than 2/255 on WebGPURenderer (the fog is really applied). */
async function fogEffect(backend: Backend, v: Variant): Promise<number> {
  const { pixels: clear } = await renderGpu(backend, v, 'lecture');
  const { pixels: fogged } = await renderGpu(backend, v, 'fog');
  let changed = 0;
  for (let i = 0; i < clear.length; i += 4) {
    const d = maxRgbDelta(clear, fogged, i);
    if (d > 2) changed++;
  }
  return changed;
}

/** The fog of {@link fogParity}: half-way (fog factor 0.5) at the front of the sphere, view depth 2. */
export type FogKind = 'none' | 'range' | 'exp2';
const FOG_COLOUR = new Color(0.2, 0.4, 0.6);
function fogOf(kind: FogKind): Fog | FogExp2 | null {
  if (kind === 'range') return new Fog(FOG_COLOUR, 1.2, 2.8);
  if (kind === 'exp2') return new FogExp2(FOG_COLOUR, Math.sqrt(Math.LN2) / 2);
  return null;
}
let glCanvas: WebGLRenderer | null = null;

/**
 * A sphere under three's ambient and directional lights in `fog`, drawn through the output colour space (sRGB),
 * rows bottom-up: `which` is ShadingNodeMaterial({ ka: c, kd: c, ks: 0 }) or three's MeshPhongNodeMaterial /
 * MeshLambertNodeMaterial on WebGPURenderer, or ShadingMaterial / MeshPhongMaterial on WebGLRenderer.
 */
async function drawFogged(
  api: Backend | 'webgl',
  which: 'shading' | 'phong' | 'lambert',
  fog: FogKind,
  shading: Shading = 'phong',
): Promise<Uint8Array> {
  const c: [number, number, number] = [0.6, 0.35, 0.2];
  const material =
    api === 'webgl'
      ? which === 'shading'
        ? new ShadingMaterial({ shading, ka: c, kd: c, ks: 0 })
        : new MeshPhongMaterial({ color: new Color(...c), specular: 0 })
      : which === 'shading'
        ? new ShadingNodeMaterial({ shading, ka: c, kd: c, ks: 0 })
        : which === 'lambert'
          ? new MeshLambertNodeMaterial({ color: new Color(...c) })
          : new MeshPhongNodeMaterial({ color: new Color(...c), specular: 0 });
  const s = new Scene();
  const mesh = new Mesh(geometry, material);
  mesh.scale.set(1.2, 1, 1.2);
  mesh.rotation.set(0.3, 0.5, 0);
  const sun = new DirectionalLight(new Color(1, 0.95, 0.9), 2.5);
  sun.position.set(-1, 2, 3);
  s.add(mesh, sun, new AmbientLight(new Color(0.3, 0.3, 0.35), 1.5));
  s.fog = fogOf(fog);
  const camera = new PerspectiveCamera(60, 1, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  s.updateMatrixWorld();
  camera.updateMatrixWorld();
  try {
    if (api === 'webgl') {
      // The canvas: three's output conversion in the shader, then fog_fragment in that space (an sRGB render
      // target would be encoded by the hardware after the shader instead).
      if (glCanvas === null) {
        glCanvas = new WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
        glCanvas.setPixelRatio(1);
        glCanvas.setSize(SIZE, SIZE, false);
      }
      glCanvas.setClearColor(0x0000ff, 1);
      glCanvas.render(s, camera);
      const context = glCanvas.getContext();
      const pixels = new Uint8Array(4 * SIZE * SIZE);
      context.readPixels(0, 0, SIZE, SIZE, context.RGBA, context.UNSIGNED_BYTE, pixels);
      return pixels;
    }
    const renderer = await gpuRenderer(api);
    const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
    // The output render target: WebGPURenderer's output pass (colour space) runs as it does for the canvas.
    renderer.outputColorSpace = SRGBColorSpace;
    renderer.setOutputRenderTarget(target);
    renderer.setRenderTarget(null);
    renderer.setClearColor(0x0000ff, 1);
    renderer.render(s, camera);
    const pixels = await readTarget(renderer, target, SIZE);
    renderer.setOutputRenderTarget(null);
    target.dispose();
    return pixels;
  } finally {
    material.dispose();
  }
}

/** Max |Δ| (1/255) and mean over pixels both pictures cover, away from the silhouette (3 × 3 covered in both). */
function pictureDelta(a: Uint8Array, b: Uint8Array) {
  const inside = (p: Uint8Array, x: number, y: number) => {
    for (let dy = -1; dy <= 1; dy++)
      for (let dx = -1; dx <= 1; dx++) {
        const i = 4 * ((y + dy) * SIZE + x + dx);
        if (hasRgb(p, i, CLEAR)) return false;
      }
    return true;
  };
  let max = 0;
  let sum = 0;
  let n = 0;
  for (let y = 1; y < SIZE - 1; y++)
    for (let x = 1; x < SIZE - 1; x++) {
      if (!inside(a, x, y) || !inside(b, x, y)) continue;
      const d = maxRgbDelta(a, b, 4 * (y * SIZE + x));
      max = Math.max(max, d);
      sum += d;
      n++;
    }
  return { compared: n, max, mean: n > 0 ? sum / n : 0 };
}

/**
 * How far the fog moves each covered pixel at the sphere's centre (the 16 × 16 pixels around the middle, where
 * the fog factor is ≈ 0.5) towards the fog colour, in the 8-bit sRGB output: (fogged − clear) / (fog − clear),
 * channel-wise (channels where the two differ by ≥ 40/255), averaged.
 */
function fogFraction(clear: Uint8Array, fogged: Uint8Array): number {
  const f = FOG_COLOUR.clone().convertLinearToSRGB();
  const fog = [f.r, f.g, f.b].map((c) => c * 255);
  let sum = 0;
  let n = 0;
  for (let y = SIZE / 2 - 8; y < SIZE / 2 + 8; y++)
    for (let x = SIZE / 2 - 8; x < SIZE / 2 + 8; x++) {
      const i = 4 * (y * SIZE + x);
      for (let k = 0; k < 3; k++) {
        if (Math.abs(fog[k] - clear[i + k]) < 40) continue;
        sum += (fogged[i + k] - clear[i + k]) / (fog[k] - clear[i + k]);
        n++;
      }
    }
  return n > 0 ? sum / n : Number.NaN;
}

/**
 * ShadingNodeMaterial({ ka: c, kd: c, ks: 0 }) against three's MeshPhongNodeMaterial and MeshLambertNodeMaterial on
 * WebGPURenderer, without and in fog (sRGB output); and how far half-way fog moves a pixel there and on
 * WebGLRenderer (ShadingMaterial and MeshPhongMaterial blend the fog in the output colour space, three's node
 * materials in linear before the output conversion).
 */
async function fogParity(backend: Backend, fog: FogKind, shading: Shading = 'phong') {
  const node = await drawFogged(backend, 'shading', fog, shading);
  const phong = await drawFogged(backend, 'phong', fog);
  const lambert = await drawFogged(backend, 'lambert', fog);
  const nodeClear = await drawFogged(backend, 'shading', 'none', shading);
  const phongClear = await drawFogged(backend, 'phong', 'none');
  const webgl = await drawFogged('webgl', 'shading', fog, shading);
  const webglClear = await drawFogged('webgl', 'shading', 'none', shading);
  const webglPhong = await drawFogged('webgl', 'phong', fog);
  const webglPhongClear = await drawFogged('webgl', 'phong', 'none');
  return {
    againstPhong: pictureDelta(node, phong),
    againstLambert: pictureDelta(node, lambert),
    againstWebGL: pictureDelta(node, webgl),
    fraction: {
      node: fogFraction(nodeClear, node),
      phongNode: fogFraction(phongClear, phong),
      webgl: fogFraction(webglClear, webgl),
      webglPhong: fogFraction(webglPhongClear, webglPhong),
    },
  };
}

/** The message each material throws for the same bad input (ShadingMaterial's, ShadingNodeMaterial's). */
function errors() {
  const cases: Record<string, unknown>[] = [
    { shading: 'smooth' },
    { lighting: 'toon' },
    { celBands: 1 },
    { celBands: 2.5 },
    { celBands: 256 },
    { celBands: '4' },
    { ka: -1 },
    { ks: 'not a colour' },
    { shininess: Number.NaN },
    { shininess: -1 },
    { lights: [{}] },
    { lights: 'none' },
    { map: 'texture.png' },
    { emissiveMap: {} },
    { alphaMap: 1 },
    { normalMap: [0, 0, 1] },
    { normalScale: [1, 1] },
    { emissive: -1 },
    { emissive: 'not a colour' },
    { opacity: 1.5 },
    { opacity: '1' },
    { alphaTest: -0.1 },
    { alphaTest: Number.NaN },
  ];
  return cases.map((options) => ({
    options: JSON.stringify(options),
    webgl: thrown(() => new ShadingMaterial(options as never)),
    node: thrown(() => new ShadingNodeMaterial(options as never)),
  }));
}

/**
 * Values edited in place (bypassing the setters) to NaN or a negative channel: material.ka, then a PhongLight's
 * diffuse. Each frame's pixels (rows as read) and the console errors logged while it was drawn.
 */
async function inPlaceEdits(backend: Backend) {
  const renderer = await gpuRenderer(backend);
  const material = new ShadingNodeMaterial({ lights: [] });
  const { scene: s, camera } = scene(material);
  const light = s.children.find((c) => c instanceof PhongLight) as PhongLight;
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  const logged: string[] = [];
  const original = console.error;
  console.error = (...args: unknown[]) => {
    logged.push(args.map(String).join(' '));
  };
  const frame = async () => {
    const pixels = await drawInto(renderer, target, s, camera);
    const errors = logged.splice(0);
    return { pixels: Array.from(pixels), errors };
  };
  try {
    const frames: { pixels: number[]; errors: string[] }[] = [];
    frames.push(await frame()); // 0: valid
    material.ka.r = Number.NaN;
    frames.push(await frame()); // 1: ka NaN → reported, drawn as frame 0
    frames.push(await frame()); // 2: still NaN → not reported again
    material.ka.r = 0.6;
    light.diffuse.g = -1;
    frames.push(await frame()); // 3: the light's diffuse negative → reported, drawn as frame 0
    light.diffuse.g = 1;
    material.kd.setRGB(0.2, 0.5, 0.8);
    frames.push(await frame()); // 4: valid again, kd edited in place to a valid value → drawn with it
    return frames.map((f, i) => ({
      errors: f.errors,
      sameAsFirst: f.pixels.every((v, k) => v === frames[0].pixels[k]),
      index: i,
    }));
  } finally {
    console.error = original;
    target.dispose();
    material.dispose();
  }
}

/**
 * The emissive is built in only while it is not black (as ShadingMaterial's SHADING_EMISSIVE): frames of one
 * material whose emissive is set through the setter (black → red → black), then edited in place (black → red →
 * black), each frame's pixels against the same scene drawn by a new material made black or red; and
 * `material.version` over steady frames (a rebuild raises it), for it and for an emissive impostor (whose
 * lighting adds no emissive).
 */
async function emissiveEdits(backend: Backend) {
  const renderer = await gpuRenderer(backend);
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  const draw = async (material: ShadingNodeMaterial) => {
    const { scene: s, camera } = scene(material);
    return Array.from(await drawInto(renderer, target, s, camera));
  };
  const RED = [0.2, 0, 0] as const;
  const fresh = async (emissive: readonly number[]) => {
    const m = new ShadingNodeMaterial({ lights: [], emissive: [...emissive] as [number, number, number] });
    const pixels = await draw(m);
    m.dispose();
    return pixels;
  };
  const black = await fresh([0, 0, 0]);
  const red = await fresh(RED);
  const material = new ShadingNodeMaterial({ lights: [] });
  const frames: { step: string; is: 'black' | 'red' | 'other'; version: number }[] = [];
  const frame = async (step: string) => {
    const pixels = await draw(material);
    const same = (p: number[]) => p.every((v, k) => v === pixels[k]);
    frames.push({ step, is: same(black) ? 'black' : same(red) ? 'red' : 'other', version: material.version });
  };
  try {
    await frame('black');
    await frame('black, steady');
    material.emissive = [...RED] as [number, number, number];
    await frame('set red');
    await frame('red, steady');
    await frame('red, steady');
    material.emissive = 0;
    await frame('set black');
    material.emissive.setRGB(...RED);
    await frame('red in place');
    await frame('red in place, next frame');
    await frame('red in place, steady');
    material.emissive.setRGB(0, 0, 0);
    await frame('black in place');
    await frame('black in place, next frame');
    await frame('black in place, steady');
    const impostor = new SphereImpostorNodeMaterial({
      lights: [],
      emissive: [...RED] as [number, number, number],
    });
    const versions: number[] = [];
    const { scene: s, camera, mesh } = scene(impostor);
    mesh.geometry = createImpostorQuad();
    for (let i = 0; i < 3; i++) {
      renderer.setRenderTarget(target);
      renderer.render(s, camera);
      renderer.setRenderTarget(null);
      versions.push(impostor.version);
    }
    mesh.geometry.dispose();
    impostor.dispose();
    return { frames, impostorVersions: versions };
  } finally {
    target.dispose();
    material.dispose();
  }
}

/**
 * The scene's PhongLights followed frame by frame, and a material's `lights` list: pixels of (0) the lecture's
 * scene, (1) after adding a second PhongLight, (2) a new material in that two-light scene, (3) after removing
 * it again, (4) the two-light scene drawn by a material listing only the first light.
 */
async function sceneLights(backend: Backend) {
  const renderer = await gpuRenderer(backend);
  const material = new ShadingNodeMaterial({ lights: [] });
  const { scene: s, camera, mesh } = scene(material);
  const first = s.children.find((c) => c instanceof PhongLight) as PhongLight;
  const second = new PhongLight({ ambient: 0, diffuse: [0.2, 0.6, 1], specular: 0.3 });
  second.position.set(4, -2, 3);
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  const frame = async () => Array.from(await drawInto(renderer, target, s, camera));
  const frames: number[][] = [];
  frames.push(await frame());
  s.add(second);
  s.updateMatrixWorld();
  frames.push(await frame());
  const fresh = new ShadingNodeMaterial({ lights: [] });
  mesh.material = fresh;
  frames.push(await frame());
  mesh.material = material;
  s.remove(second);
  frames.push(await frame());
  s.add(second);
  const listed = new ShadingNodeMaterial({ lights: [first] });
  mesh.material = listed;
  frames.push(await frame());
  target.dispose();
  for (const m of [material, fresh, listed]) m.dispose();
  const same = (a: number[], b: number[]) => a.every((v, i) => v === b[i]);
  return {
    addedChanges: !same(frames[0], frames[1]),
    addedAsFresh: same(frames[1], frames[2]),
    removedAsFirst: same(frames[3], frames[0]),
    listedAsFirst: same(frames[4], frames[0]),
  };
}

const api = {
  backendInfo,
  compare,
  crossRenderer,
  emissiveEdits,
  errors,
  fogEffect,
  fogParity,
  inPlaceEdits,
  sceneLights,
};
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
