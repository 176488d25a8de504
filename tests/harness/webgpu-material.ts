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
import { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  AmbientLight,
  BackSide,
  type BufferGeometry,
  Color,
  CylinderGeometry,
  DirectionalLight,
  DoubleSide,
  Fog,
  FrontSide,
  HemisphereLight,
  InstancedMesh,
  type Light,
  type Material,
  Matrix3,
  Matrix4,
  Mesh,
  Object3D,
  PerspectiveCamera,
  PointLight,
  Raycaster,
  Scene,
  type Side,
  SpotLight,
  Vector2,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { RenderTarget } from 'three/webgpu';
import { thrown } from './lib/errors';
import { hasRgb, maxRgbDelta } from './lib/pixels';
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
 * carrying the transform: flat shading by derivatives), 'fog' (the lecture's scene in three's Fog), 'prepared'
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

/** three's lights of the 'three-lights' scenario, with what shade() is given for each. */
function threeLights(): { lights: Light[]; shade: ShadeThreeLight[] } {
  const ambient = new AmbientLight(new Color(0.3, 0.25, 0.2), 0.5);
  const hemisphere = new HemisphereLight(new Color(0.2, 0.3, 0.5), new Color(0.3, 0.2, 0.1), 0.8);
  hemisphere.position.set(0.3, 1, 0.2);
  const directional = new DirectionalLight(new Color(1, 0.95, 0.9), 0.8);
  directional.position.set(-1, 2, 3);
  const point = new PointLight(new Color(0.9, 0.9, 1), 4, 0, 2);
  point.position.set(2, 1, 2);
  // Aimed at the origin (its target's default), the cone's soft edge across the sphere.
  const spot = new SpotLight(new Color(1, 0.8, 0.6), 6, 0, 0.35, 0.5, 2);
  spot.position.set(-1, -2, 2.5);
  spot.updateMatrixWorld();
  spot.target.updateMatrixWorld();
  const scaled = (c: Color, i: number) => [c.r * i, c.g * i, c.b * i];
  return {
    lights: [ambient, hemisphere, directional, point, spot],
    shade: [
      { type: 'ambient', color: scaled(ambient.color, ambient.intensity) },
      {
        type: 'hemisphere',
        color: scaled(hemisphere.color, hemisphere.intensity),
        groundColor: scaled(hemisphere.groundColor, hemisphere.intensity),
        direction: hemisphere.position.clone().normalize().toArray(),
      },
      {
        type: 'directional',
        color: scaled(directional.color, directional.intensity),
        direction: directional.position.clone().normalize().toArray(),
      },
      {
        type: 'point',
        color: scaled(point.color, point.intensity),
        position: point.position.toArray(),
        distance: 0,
        decay: 2,
      },
      {
        type: 'spot',
        color: scaled(spot.color, spot.intensity),
        position: spot.position.toArray(),
        direction: spot.position.clone().sub(spot.target.position).normalize().toArray(),
        distance: 0,
        decay: 2,
        coneCos: Math.cos(spot.angle),
        penumbraCos: Math.cos(spot.angle * (1 - spot.penumbra)),
      },
    ],
  };
}

function scene(
  material: Material,
  scenario: Scenario = 'lecture',
  backend: Backend | 'webgl' = 'webgl',
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
  if (scenario === 'instanced') {
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
    const three = threeLights();
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

/** Rows bottom-up, RGBA8, linear (a render target has no output colour space conversion). */
async function renderGpu(backend: Backend, v: Variant, scenario: Scenario = 'lecture') {
  const renderer = await gpuRenderer(backend);
  const material = new ShadingNodeMaterial({ ...v, shininess: shininessOf(scenario), lights: [] });
  material.side = sideOf(scenario);
  const setup = scene(material, scenario, backend);
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(setup.scene, setup.camera);
  const pixels = await readTarget(renderer, target, SIZE);
  renderer.setRenderTarget(null);
  target.dispose();
  material.dispose();
  return { pixels, setup, material, backend: renderer.backend };
}

let gl: WebGLRenderer | null = null;
function renderGl(v: Variant, scenario: Scenario = 'lecture'): Uint8Array {
  gl ??= new WebGLRenderer({ antialias: false });
  const material = new ShadingMaterial(v);
  material.side = sideOf(scenario);
  const setup = scene(material, scenario);
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
async function compare(backend: Backend, v: Variant, scenario: Scenario = 'lecture'): Promise<Stats> {
  const { pixels, setup } = await renderGpu(backend, v, scenario);
  const { mesh, camera, lights } = setup;
  // Triangle k of the indexed sphere is triangle k of its soup (and of its flatShadingGeometry, corners rotated).
  const fromIndexed = scenario === 'indexed' || scenario === 'prepared' || scenario === 'prepared-other';
  const soup = fromIndexed ? indexedGeometry.toNonIndexed() : scenario === 'doubleside' ? cylinder : geometry;
  const positions = soup.getAttribute('position');
  // Flat shading by derivatives: per fragment, the face normal at the fragment's position.
  const perFragmentFlat = scenario === 'indexed' || scenario === 'instanced' || scenario === 'prepared-other';
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
  // Near a cel band edge, the cel highlight edge or the terminator (where the specular jumps: cel, or 0⁰ = 1),
  // float32 and float64 may round either way: for each light (a directional one as a far point light).
  const toLight = (light: ShadeLight | ShadeThreeLight, p: Vector3): Vector3 | null => {
    if ('type' in light) {
      if (light.type === 'directional') return new Vector3().fromArray(light.direction ?? [0, 1, 0]);
      if (light.type === 'point' || light.type === 'spot')
        return new Vector3()
          .fromArray(light.position ?? [0, 0, 0])
          .sub(p)
          .normalize();
      return null;
    }
    return new Vector3().fromArray(light.position).sub(p).normalize();
  };
  const atDiscontinuity = (p: Vector3, n: Vector3): boolean => {
    if (v.celBands === 0 && m.shininess !== 0) return false;
    for (const light of lights) {
      const l = toLight(light, p);
      if (l === null) continue;
      const ndl = n.clone().normalize().dot(l);
      if (Math.abs(ndl) < 0.01) return true;
      if (v.celBands === 0) continue;
      const scaled = Math.max(ndl, 0) * v.celBands;
      const edge = Math.round(scaled);
      if (Math.abs(scaled - edge) < 0.02 && edge > 0 && edge < v.celBands) return true;
      const far = p.clone().addScaledVector(l, 1e6).toArray();
      const raw = shade(
        { position: p.toArray(), normal: n.toArray(), eye },
        { ...m, celBands: 0, ka: [0, 0, 0], kd: [0, 0, 0], ks: [1, 1, 1] },
        [{ position: far, ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [1, 1, 1] }],
      );
      if (Math.abs(raw[0] - 0.5) < 0.02) return true;
    }
    return false;
  };
  const vertexColour = world.map((p, i) =>
    shade({ position: p.toArray(), normal: worldNormal[i].toArray(), eye }, m, lights),
  );
  const vertexEdge = world.map((p, i) => atDiscontinuity(p, worldNormal[i]));
  const faces = count / 3;
  const faceColour: number[][] = [];
  const faceEdge: boolean[] = [];
  for (let t = 0; t < faces; t++) {
    const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
    const centroid = a.clone().add(b).add(c).divideScalar(3);
    const normal = b.clone().sub(a).cross(c.clone().sub(a));
    faceColour.push(shade({ position: centroid.toArray(), normal: normal.toArray(), eye }, m, lights));
    faceEdge.push(atDiscontinuity(centroid, normal));
  }
  const screen = world.map((p) => {
    const s = p.clone().project(camera);
    return new Vector2(((s.x + 1) / 2) * SIZE, ((s.y + 1) / 2) * SIZE);
  });
  const edgeDistance = (t: number, x: number, y: number): number => {
    let d = Number.POSITIVE_INFINITY;
    for (let k = 0; k < 3; k++) {
      const p = screen[3 * t + k];
      const q = screen[3 * t + ((k + 1) % 3)];
      const e = q.clone().sub(p);
      d = Math.min(d, Math.abs((x - p.x) * e.y - (y - p.y) * e.x) / e.length());
    }
    return d;
  };
  const raycaster = new Raycaster();
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
      raycaster.setFromCamera(new Vector2(((x + 0.5) / SIZE) * 2 - 1, ((y + 0.5) / SIZE) * 2 - 1), camera);
      const hit = raycaster.intersectObject(mesh)[0];
      if (covered) stats.covered++;
      if (hit === undefined || hit.faceIndex === undefined || hit.faceIndex === null || !hit.barycoord)
        continue;
      const t = hit.faceIndex;
      if (edgeDistance(t, x + 0.5, y + 0.5) < 1.5) continue;
      let expected: number[];
      const bc = hit.barycoord;
      const w = [bc.x, bc.y, bc.z];
      if (v.shading === 'flat' && perFragmentFlat) {
        const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
        const normal = b.clone().sub(a).cross(c.clone().sub(a));
        if (atDiscontinuity(hit.point, normal)) continue;
        expected = shade({ position: hit.point.toArray(), normal: normal.toArray(), eye }, m, lights);
      } else if (v.shading === 'flat') {
        if (faceEdge[t]) continue;
        expected = faceColour[t];
        // A back face (seen from behind its winding) is lit with the face normal turned round.
        const [a, b, c] = [world[3 * t], world[3 * t + 1], world[3 * t + 2]];
        const normal = b.clone().sub(a).cross(c.clone().sub(a));
        if (normal.dot(hit.point.clone().sub(camera.position)) > 0) {
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
        if (atDiscontinuity(hit.point, n)) continue;
        expected = shade({ position: hit.point.toArray(), normal: n.toArray(), eye }, m, lights);
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
async function crossRenderer(backend: Backend, v: Variant, scenario: Scenario = 'lecture') {
  const a = renderGl(v, scenario);
  const { pixels: b } = await renderGpu(backend, v, scenario);
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
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x0000ff, 1);
    renderer.clear();
    renderer.render(s, camera);
    const pixels = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, SIZE, SIZE)) as Uint8Array;
    renderer.setRenderTarget(null);
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
  const frame = async () => {
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x0000ff, 1);
    renderer.clear();
    renderer.render(s, camera);
    const pixels = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, SIZE, SIZE)) as Uint8Array;
    renderer.setRenderTarget(null);
    return Array.from(pixels);
  };
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

const api = { backendInfo, compare, crossRenderer, errors, fogEffect, inPlaceEdits, sceneLights };
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
