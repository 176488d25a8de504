// Harness for tests/material-output.spec.ts: the `output` (term views) and `normalMatrix` options of
// ShadingMaterial (WebGLRenderer) and ShadingNodeMaterial (WebGPURenderer, its WebGPU and WebGL2 backends), drawn
// offscreen into a linear render target (one renderer per kind for the whole page) and read back, against the
// CPU: shade() with the other terms zeroed, the attenuation and normal formulas, and three's MeshNormalMaterial.
import {
  type NormalMatrixMode,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeThreeLight,
  ShadingMaterial,
  type ShadingOutput,
  shade,
  threeDistanceFalloff,
} from '@shadelab/material';
import { ShadingNodeMaterial } from '@shadelab/material/webgpu';
import {
  Color,
  type Material,
  Matrix3,
  Mesh,
  MeshNormalMaterial,
  type Object3D,
  PerspectiveCamera,
  Raycaster,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { MeshNormalNodeMaterial, RenderTarget } from 'three/webgpu';
import { hasRgb } from './lib/pixels';
import { fiveThreeLights } from './lib/threeLights';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';
import { sphereGeometry } from './material-sphere';

/** WebGLRenderer + ShadingMaterial ('gl'), or WebGPURenderer + ShadingNodeMaterial on one of its backends. */
export type RendererKind = 'gl' | Backend;
type Shading = 'flat' | 'gouraud' | 'phong';
/** The lighting: Phong, Blinn-Phong or cel (Phong lighting, 4 bands). */
export type LightingCase = 'phong' | 'blinn-phong' | 'cel';
/** Two attenuated PhongLights, or three's ambient, hemisphere, directional, point and spot lights. */
export type Lights = 'phong' | 'three';
export interface Case {
  renderer: RendererKind;
  shading: Shading;
  lighting: LightingCase;
  lights: Lights;
  output: ShadingOutput;
  normalMatrix?: NormalMatrixMode;
  /** The model's scale. @default [1, 1, 1] */
  scale?: readonly [number, number, number];
}
export interface Stats {
  /** Pixels drawn (not the clear colour). */
  covered: number;
  /** Pixels compared (away from triangle edges in flat shading and from cel band edges). */
  compared: number;
  /** Largest |GPU − CPU| over R, G, B, 1/255. */
  max: number;
  /** Pixels more than 2/255 off. */
  over2: number;
  worst: { x: number; y: number; got: number[]; expected: number[] } | null;
}

const SIZE = 80;
const LEVEL = 2;
const CLEAR = [0, 0, 255] as const;
const KA: [number, number, number] = [0.5, 0.3, 0.2];
const KD: [number, number, number] = [0.6, 0.35, 0.2];
const KS: [number, number, number] = [0.5, 0.5, 0.5];
const SHININESS = 16;
const CEL_BANDS = 4;

const camera = new PerspectiveCamera(60, 1, 0.1, 10);
camera.position.set(0, 0, 3);
camera.lookAt(0, 0, 0);
camera.updateMatrixWorld();
const eye = [0, 0, 3, 1];

/** The two PhongLights: both attenuated, coloured differently, so the attenuation view is their mean. */
function phongLights(): { lights: PhongLight[]; shade: ShadeLight[] } {
  const a = new PhongLight({
    ambient: [0.2, 0.2, 0.25],
    diffuse: [1, 0.9, 0.7],
    specular: [0.6, 0.7, 0.9],
    attenuation: { a: 0.5, b: 0.2, c: 0.05 },
  });
  a.position.set(-2, 3, 4);
  const b = new PhongLight({
    ambient: [0.1, 0.15, 0.1],
    diffuse: [0.4, 0.6, 1],
    specular: [0.8, 0.8, 0.6],
    attenuation: { a: 1, b: 0, c: 0.1 },
  });
  b.position.set(3, -1, 3);
  const lights = [a, b];
  for (const light of lights) light.updateMatrixWorld();
  return {
    lights,
    shade: lights.map((light) => ({
      position: light.position.toArray(),
      ambient: light.ambient.toArray(),
      diffuse: light.diffuse.toArray(),
      specular: light.specular.toArray(),
      attenuation: light.attenuation,
    })),
  };
}

/** The model: the lecture's sphere (a triangle soup with smooth vertex normals), turned and scaled. */
function meshOf(material: Material, scale: readonly [number, number, number]): Mesh {
  const mesh = new Mesh(sphereGeometry(LEVEL, true), material);
  mesh.rotation.set(0.3, 0.5, 0);
  mesh.scale.set(...scale);
  mesh.updateMatrixWorld();
  return mesh;
}

function materialOf(c: Case): Material {
  const options = {
    shading: c.shading,
    lighting: c.lighting === 'blinn-phong' ? ('blinn-phong' as const) : ('phong' as const),
    celBands: c.lighting === 'cel' ? CEL_BANDS : 0,
    ka: KA,
    kd: KD,
    ks: KS,
    shininess: SHININESS,
    output: c.output,
    normalMatrix: c.normalMatrix ?? 'inverse-transpose',
  };
  return c.renderer === 'gl' ? new ShadingMaterial(options) : new ShadingNodeMaterial(options);
}

let gl: WebGLRenderer | null = null;

/** Draws `material` on `mesh` with `lights` into a linear target; RGBA8, rows bottom-up. */
async function draw(renderer: RendererKind, mesh: Mesh, lights: readonly Object3D[]): Promise<Uint8Array> {
  const scene = new Scene();
  scene.add(mesh, ...lights);
  if (renderer === 'gl') {
    gl ??= new WebGLRenderer({ antialias: false });
    const target = new WebGLRenderTarget(SIZE, SIZE);
    gl.setRenderTarget(target);
    gl.setClearColor(new Color(...CLEAR.map((c) => c / 255)), 1);
    gl.clear();
    gl.render(scene, camera);
    const pixels = new Uint8Array(4 * SIZE * SIZE);
    gl.readRenderTargetPixels(target, 0, 0, SIZE, SIZE, pixels);
    gl.setRenderTarget(null);
    target.dispose();
    return pixels;
  }
  const gpu = await gpuRenderer(renderer);
  const target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
  gpu.setRenderTarget(target);
  gpu.setClearColor(new Color(...CLEAR.map((c) => c / 255)), 1);
  gpu.clear();
  gpu.render(scene, camera);
  const pixels = await readTarget(gpu, target, SIZE);
  gpu.setRenderTarget(null);
  target.dispose();
  return pixels;
}

function lightsOf(kind: Lights): { lights: Object3D[]; shade: (ShadeLight | ShadeThreeLight)[] } {
  return kind === 'phong' ? phongLights() : fiveThreeLights();
}

/** The case drawn: its pixels, and the mesh and lights it was drawn with. */
async function render(c: Case) {
  const material = materialOf(c);
  const mesh = meshOf(material, c.scale ?? [1, 1, 1]);
  const setup = lightsOf(c.lights);
  const pixels = await draw(c.renderer, mesh, setup.lights);
  material.dispose();
  return { pixels, mesh, setup };
}

const smoothstep = (e0: number, e1: number, x: number): number => {
  const t = Math.min(Math.max((x - e0) / (e1 - e0), 0), 1);
  return t * t * (3 - 2 * t);
};

/** The attenuation output on the CPU: the mean of the direct lights' factors (see ShadingOutput). */
function attenuationAt(p: number[], lights: readonly (ShadeLight | ShadeThreeLight)[]): number {
  const factors: number[] = [];
  for (const light of lights) {
    if ('type' in light) {
      if (light.type === 'ambient' || light.type === 'hemisphere') continue;
      if (light.type === 'directional') {
        factors.push(1);
        continue;
      }
      const q = new Vector3().fromArray(Array.from(light.position ?? [0, 0, 0]));
      const t = q.distanceTo(new Vector3(...p));
      let f = threeDistanceFalloff(t, light.distance ?? 0, light.decay ?? 2);
      if (light.type === 'spot') {
        const l = q
          .clone()
          .sub(new Vector3(...p))
          .normalize();
        f *= smoothstep(
          light.coneCos ?? 0,
          light.penumbraCos ?? 0,
          l.dot(new Vector3().fromArray(Array.from(light.direction ?? [0, 1, 0]))),
        );
      }
      factors.push(f);
    } else {
      const t = new Vector3().fromArray(Array.from(light.position)).distanceTo(new Vector3(...p));
      const { a, b, c } = light.attenuation ?? { a: 1, b: 0, c: 0 };
      factors.push(1 / Math.max(a + b * t + c * t * t, 1e-6));
    }
  }
  return factors.length === 0 ? 0 : factors.reduce((s, f) => s + f, 0) / factors.length;
}

/** sRGB → linear, as three's `colorSpaceToWorking( …, SRGBColorSpace )` decodes. */
const srgbToLinear = (c: number): number => (c < 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);

/**
 * What `c.output` shows at a point with a (world) normal: shade() with the other terms zeroed (linear RGB), the
 * attenuation, or the packed view-space normal (the data outputs as written: see {@link stored}).
 */
function expectedAt(
  c: Case,
  lights: readonly (ShadeLight | ShadeThreeLight)[],
  p: Vector3,
  n: Vector3,
): number[] {
  const zero: [number, number, number] = [0, 0, 0];
  const m: ShadeMaterial = {
    ka: c.output === 'color' || c.output === 'ambient' ? KA : zero,
    kd: c.output === 'color' || c.output === 'diffuse' ? KD : zero,
    ks: c.output === 'color' || c.output === 'specular' ? KS : zero,
    shininess: SHININESS,
    lighting: c.lighting === 'blinn-phong' ? 'blinn-phong' : 'phong',
    celBands: c.lighting === 'cel' ? CEL_BANDS : 0,
  };
  if (c.output === 'attenuation') return Array(3).fill(Math.min(attenuationAt(p.toArray(), lights), 1));
  if (c.output === 'normal') {
    const view = n.clone().normalize().transformDirection(camera.matrixWorldInverse);
    return view.toArray().map((x) => x * 0.5 + 0.5);
  }
  return shade({ position: p.toArray(), normal: n.toArray(), eye }, m, lights);
}

/**
 * What the linear target stores of a value the fragment stage ends with: the data outputs are decoded from sRGB
 * per fragment on WebGPURenderer (after interpolation), as three's MeshNormalNodeMaterial decodes its normal.
 */
function stored(c: Case, v: number[]): number[] {
  const data = c.output === 'attenuation' || c.output === 'normal';
  return data && c.renderer !== 'gl' ? v.map(srgbToLinear) : v;
}

/** Max |a − b| over three channels. */
const delta = (a: number[], b: number[]) => Math.max(...[0, 1, 2].map((k) => Math.abs(a[k] - b[k])));

/**
 * Compares `c`'s picture with the CPU: per pixel, the ray through its centre hits the sphere's triangle; Phong
 * shading evaluates at the hit with the interpolated unit world normals (GL interpolates them per vertex),
 * Gouraud blends the three vertices' values with the hit's barycentric weights, flat evaluates at the face's
 * centroid with its face normal. The world normals are the normal matrix's (or, with `normalMatrix: 'model'`,
 * M's) × the object normals. Skipped: pixels within 1.5 px of a triangle's edge in flat shading, and points
 * where a 0.5° turn of the normal changes the value by more than 2/255 (cel band and highlight edges), and
 * silhouette pixels.
 */
async function compare(c: Case): Promise<{ stats: Stats; pixels: Uint8Array }> {
  const { pixels, mesh, setup } = await render(c);
  const lights = setup.shade;
  const g = mesh.geometry;
  const position = g.getAttribute('position');
  const normal = g.getAttribute('normal');
  const M = mesh.matrixWorld;
  const N = c.normalMatrix === 'model' ? new Matrix3().setFromMatrix4(M) : new Matrix3().getNormalMatrix(M);
  const count = position.count;
  const world = Array.from({ length: count }, (_, i) =>
    new Vector3().fromBufferAttribute(position, i).applyMatrix4(M),
  );
  const worldNormal = Array.from({ length: count }, (_, i) =>
    new Vector3().fromBufferAttribute(normal, i).applyMatrix3(N).normalize(),
  );
  const value = (p: Vector3, n: Vector3) => expectedAt(c, lights, p, n);
  // A value at a discontinuity (cel band, cel highlight edge): turning the normal a little changes it.
  const unstable = (p: Vector3, n: Vector3): boolean => {
    if (c.lighting !== 'cel') return false;
    const v0 = value(p, n);
    const u = n.clone().normalize();
    const a = new Vector3(1, 0, 0).cross(u);
    if (a.lengthSq() < 1e-6) a.set(0, 1, 0).cross(u);
    a.normalize();
    const b = u.clone().cross(a);
    for (const axis of [a, b]) {
      for (const s of [-1, 1]) {
        const turned = u.clone().addScaledVector(axis, s * 0.009);
        if (delta(value(p, turned), v0) * 255 > 2) return true;
      }
    }
    return false;
  };
  const vertexValue = world.map((p, i) => value(p, worldNormal[i]));
  const vertexUnstable = world.map((p, i) => unstable(p, worldNormal[i]));
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
  const stats: Stats = { covered: 0, compared: 0, max: 0, over2: 0, worst: null };
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const o = 4 * (y * SIZE + x);
      // A pixel the rasteriser leaves out at the silhouette (its centre just outside) is not compared.
      if (hasRgb(pixels, o, CLEAR)) continue;
      stats.covered++;
      // Nor a silhouette pixel (a neighbour left out), where a value varies fastest across the pixel.
      const inside = (i: number, j: number) =>
        i >= 0 && j >= 0 && i < SIZE && j < SIZE && !hasRgb(pixels, 4 * (j * SIZE + i), CLEAR);
      if (!(inside(x - 1, y) && inside(x + 1, y) && inside(x, y - 1) && inside(x, y + 1))) continue;
      raycaster.setFromCamera(new Vector2(((x + 0.5) / SIZE) * 2 - 1, ((y + 0.5) / SIZE) * 2 - 1), camera);
      const hit = raycaster.intersectObject(mesh)[0];
      if (hit === undefined || hit.faceIndex == null || !hit.barycoord) continue;
      const t = hit.faceIndex;
      const w = [hit.barycoord.x, hit.barycoord.y, hit.barycoord.z];
      let expected: number[];
      if (c.shading === 'flat') {
        if (edgeDistance(t, x + 0.5, y + 0.5) < 1.5) continue;
        const [a, b, d] = [0, 1, 2].map((k) => new Vector3().fromBufferAttribute(position, 3 * t + k));
        const centroid = a.clone().add(b).add(d).divideScalar(3).applyMatrix4(M);
        const n = b.clone().sub(a).cross(d.clone().sub(a)).applyMatrix3(N);
        if (unstable(centroid, n)) continue;
        expected = value(centroid, n);
      } else if (c.shading === 'gouraud') {
        if ([0, 1, 2].some((k) => vertexUnstable[3 * t + k])) continue;
        expected = [0, 1, 2].map((k) => w.reduce((s, wi, i) => s + wi * vertexValue[3 * t + i][k], 0));
      } else {
        const n = new Vector3();
        for (let i = 0; i < 3; i++) n.addScaledVector(worldNormal[3 * t + i], w[i]);
        if (unstable(hit.point, n)) continue;
        expected = value(hit.point, n);
      }
      const clamped = stored(c, expected).map((e) => Math.min(Math.max(e, 0), 1) * 255);
      const got = [pixels[o], pixels[o + 1], pixels[o + 2]];
      const error = delta(got, clamped);
      stats.compared++;
      if (error > 2) stats.over2++;
      if (error > stats.max) {
        stats.max = error;
        stats.worst = { x, y, got, expected: clamped };
      }
    }
  }
  return { stats, pixels };
}

/** {@link compare}'s numbers. */
async function check(c: Case): Promise<Stats> {
  return (await compare(c)).stats;
}

/**
 * The term views against the colour, per covered pixel where no value is clamped (every channel of the colour
 * below 255): |ambient + diffuse + specular − colour| over R, G, B, in linear 1/255 (the target is linear), and
 * each term against the CPU (see {@link check}).
 */
async function terms(
  renderer: RendererKind,
  shading: Shading,
  lighting: LightingCase,
  lights: Lights,
): Promise<{ sum: { compared: number; max: number }; checks: Record<string, Stats> }> {
  const outputs: ShadingOutput[] = ['color', 'ambient', 'diffuse', 'specular', 'attenuation'];
  const pictures: Record<string, Uint8Array> = {};
  const checks: Record<string, Stats> = {};
  for (const output of outputs) {
    const c: Case = { renderer, shading, lighting, lights, output };
    const { stats, pixels } = await compare(c);
    checks[output] = stats;
    pictures[output] = pixels;
  }
  let compared = 0;
  let max = 0;
  const colour = pictures.color;
  for (let o = 0; o < colour.length; o += 4) {
    if (hasRgb(colour, o, CLEAR)) continue;
    if ([0, 1, 2].some((k) => colour[o + k] === 255)) continue;
    compared++;
    for (let k = 0; k < 3; k++) {
      const sum = pictures.ambient[o + k] + pictures.diffuse[o + k] + pictures.specular[o + k];
      max = Math.max(max, Math.abs(sum - colour[o + k]));
    }
  }
  return { sum: { compared, max }, checks };
}

/**
 * The normal view against three's own: MeshNormalMaterial (WebGLRenderer) or MeshNormalNodeMaterial
 * (WebGPURenderer), `flatShading` for flat shading, on the same mesh; max |Δ| over the pixels both draw.
 */
async function normalOracle(
  renderer: RendererKind,
  shading: Shading,
  scale: readonly [number, number, number],
) {
  const ours = await render({
    renderer,
    shading,
    lighting: 'phong',
    lights: 'phong',
    output: 'normal',
    scale,
  });
  const three =
    renderer === 'gl'
      ? new MeshNormalMaterial({ flatShading: shading === 'flat' })
      : new MeshNormalNodeMaterial({ flatShading: shading === 'flat' });
  const theirs = await draw(renderer, meshOf(three, scale), []);
  three.dispose();
  let compared = 0;
  let max = 0;
  let coverageDiffers = 0;
  for (let o = 0; o < theirs.length; o += 4) {
    const a = hasRgb(ours.pixels, o, CLEAR);
    const b = hasRgb(theirs, o, CLEAR);
    if (a !== b) coverageDiffers++;
    if (a || b) continue;
    compared++;
    max = Math.max(max, ...[0, 1, 2].map((k) => Math.abs(ours.pixels[o + k] - theirs[o + k])));
  }
  return { compared, max, coverageDiffers };
}

/** 'model' against 'inverse-transpose', same output and scale: pixels that differ by more than 2/255, max |Δ|. */
async function modelAgainstInverse(
  renderer: RendererKind,
  shading: Shading,
  output: ShadingOutput,
  scale: readonly [number, number, number],
) {
  const base: Case = { renderer, shading, lighting: 'phong', lights: 'phong', output, scale };
  const model = (await render({ ...base, normalMatrix: 'model' })).pixels;
  const inverse = (await render(base)).pixels;
  let compared = 0;
  let differing = 0;
  let max = 0;
  for (let o = 0; o < model.length; o += 4) {
    if (hasRgb(model, o, CLEAR) && hasRgb(inverse, o, CLEAR)) continue;
    compared++;
    const d = Math.max(...[0, 1, 2].map((k) => Math.abs(model[o + k] - inverse[o + k])));
    if (d > 2) differing++;
    max = Math.max(max, d);
  }
  return { compared, differing, max };
}

/** Which backend each WebGPURenderer runs (proof against a silent fallback to WebGL2). */
async function backendInfo(backend: Backend) {
  return backendFlags(await gpuRenderer(backend));
}

const harness = { backendInfo, check, terms, normalOracle, modelAgainstInverse };
(window as unknown as { harness: typeof harness }).harness = harness;
document.body.dataset.ready = '1';
