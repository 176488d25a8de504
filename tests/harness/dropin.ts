// Harness for tests/material-dropin.spec.ts: the drop-in pictures. A ShadingMaterial({ ka: c, kd: c, ks: 0 })
// (ShadingNodeMaterial on WebGPURenderer) against three's MeshPhongMaterial({ color: c, specular: 0 }) and
// MeshLambertMaterial({ color: c }) (their node versions on WebGPURenderer) in the same scene: a sphere or a torus
// knot under three's lights, with or without fog, plain, textured or vertex-coloured. Each picture is what a user
// sees on the canvas (8-bit sRGB, three's output conversion): WebGLRenderer draws on its canvas, WebGPURenderer
// (either backend) into an output render target (its canvas path without presenting, which loses the device
// headless). One renderer per kind and one set of materials per page; many cases per call.
import { ShadingMaterial } from '@shadelab/material';
import { ShadingNodeMaterial, type ShadingNodeMaterialOptions } from '@shadelab/material/webgpu';
import {
  AmbientLight,
  type BufferGeometry,
  Color,
  DataTexture,
  DirectionalLight,
  Float32BufferAttribute,
  Fog,
  FogExp2,
  HemisphereLight,
  type Light,
  LinearFilter,
  type Material,
  Mesh,
  MeshLambertMaterial,
  MeshPhongMaterial,
  PerspectiveCamera,
  PointLight,
  RepeatWrapping,
  RGBAFormat,
  Scene,
  SphereGeometry,
  SpotLight,
  SRGBColorSpace,
  TorusKnotGeometry,
  WebGLRenderer,
} from 'three';
import { MeshLambertNodeMaterial, MeshPhongNodeMaterial, RenderTarget } from 'three/webgpu';
import { hasRgb, maxRgbDelta, readCanvas } from './lib/pixels';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';

/** WebGLRenderer, or WebGPURenderer on its WebGPU or its WebGL2 backend. */
export type RendererKind = 'webgl' | Backend;
/** The model: three's SphereGeometry(1, 64, 32) or TorusKnotGeometry(0.7, 0.22, 160, 24). */
export type GeometryKind = 'sphere' | 'torusKnot';
/** One of three's five light kinds alone, or all five together. */
export type LightSet = 'ambient' | 'hemisphere' | 'directional' | 'point' | 'spot' | 'all';
/** No fog, three's Fog or FogExp2. */
export type FogKind = 'none' | 'fog' | 'fogExp2';
/** The surface colour: c alone, c × an sRGB DataTexture, c × the `color` attribute, c × both. */
export type Surface = 'plain' | 'map' | 'vertexColors' | 'both';
/** ShadingMaterial's shading; three's materials are always per fragment. */
export type Shading = 'phong' | 'gouraud' | 'flat';

/** One picture of the drop-in suite. */
export interface DropinCase {
  geometry: GeometryKind;
  lights: LightSet;
  fog: FogKind;
  surface: Surface;
  shading: Shading;
}

/** ShadingMaterial's picture against one of three's (all values in 1/255 of 8-bit sRGB). */
export interface Comparison {
  /** three's material: MeshPhongMaterial({ specular: 0 }) or MeshLambertMaterial (or their node versions). */
  reference: 'phong' | 'lambert';
  /** Pixels drawn (not the clear colour) in three's picture. */
  covered: number;
  /** Pixels drawn in one picture and not in the other. */
  coverageMismatch: number;
  /** Pixels compared: those whose 3 × 3 neighbourhood is drawn in both pictures (away from silhouettes). */
  compared: number;
  /** Mean over the compared pixels of max |Δ| over R, G, B. */
  mean: number;
  /** Max over the compared pixels of max |Δ| over R, G, B. */
  max: number;
  /** Mean over the compared pixels and channels of ShadingMaterial − three's (its sign: brighter or darker). */
  signedMean: number;
  /** Where the largest difference is (x, y from the bottom left) and both pixels there. */
  worst: { x: number; y: number; ours: number[]; three: number[] } | null;
}

/** A case's result: its comparisons and what three's picture looks like (1/255 of 8-bit sRGB). */
export interface CaseResult {
  case: DropinCase;
  comparisons: Comparison[];
  /** Mean of R, G, B over the pixels three's MeshPhongMaterial drew. */
  referenceMean: number;
  /** The brightest channel three's MeshPhongMaterial drew (below 255: nothing saturates). */
  referenceMax: number;
  /**
   * Mean max|ΔRGB| between three's picture and three's picture of the same model and lights without fog, map and
   * vertex colours (over the pixels drawn in both; 0 for that case itself; null when that case was not drawn).
   */
  changeFromPlain: number | null;
  /** The surface options ShadingMaterial kept from its constructor: `map` is the texture, `vertexColors` true. */
  carried: { map: boolean; vertexColors: boolean };
}

/** What one call renders on one renderer: which backend really ran, and each case's result. */
export interface RunResult {
  renderer: RendererKind;
  /** three's flags on WebGPURenderer's backend, and whether its device is a GPUDevice (null for WebGLRenderer). */
  backend: { isWebGPUBackend: boolean; isWebGLBackend: boolean; device: boolean } | null;
  results: CaseResult[];
  /** Wall time of the call, ms (reported, never asserted). */
  ms: number;
}

const SIZE = 128;
/** The clear colour (0x0000ff) in RGB: where nothing was drawn (no case draws a pure blue). */
const CLEAR = [0, 0, 255] as const;
/** c: the diffuse colour (linear RGB), bright enough to see and dim enough that all five lights never saturate. */
const C = new Color(0.5, 0.36, 0.24);

/** A geometry with a `color` attribute (linear, 0.45 … 1, varying over the surface) for the vertex-colour cases. */
function withVertexColours(geometry: BufferGeometry): BufferGeometry {
  const position = geometry.getAttribute('position');
  const colours = new Float32Array(3 * position.count);
  for (let i = 0; i < position.count; i++) {
    const x = position.getX(i);
    const y = position.getY(i);
    const z = position.getZ(i);
    colours[3 * i] = 0.725 + 0.275 * Math.sin(3 * x + 1);
    colours[3 * i + 1] = 0.725 + 0.275 * Math.sin(2.5 * y + 2);
    colours[3 * i + 2] = 0.725 + 0.275 * Math.cos(2 * z + x);
  }
  geometry.setAttribute('color', new Float32BufferAttribute(colours, 3));
  return geometry;
}

const geometries: Record<GeometryKind, BufferGeometry> = {
  sphere: withVertexColours(new SphereGeometry(1, 64, 32)),
  torusKnot: withVertexColours(new TorusKnotGeometry(0.7, 0.22, 160, 24)),
};

/** A smooth 64 × 64 sRGB DataTexture made in code (linear filtering: no texel edges to round either way). */
function makeMap(): DataTexture {
  const n = 64;
  const data = new Uint8Array(4 * n * n);
  for (let y = 0; y < n; y++) {
    for (let x = 0; x < n; x++) {
      const u = (2 * Math.PI * x) / n;
      const v = (2 * Math.PI * y) / n;
      const o = 4 * (y * n + x);
      data[o] = Math.round(190 + 65 * Math.sin(u));
      data[o + 1] = Math.round(180 + 75 * Math.cos(2 * v + u));
      data[o + 2] = Math.round(170 + 80 * Math.sin(u + 2 * v));
      data[o + 3] = 255;
    }
  }
  const texture = new DataTexture(data, n, n, RGBAFormat);
  texture.colorSpace = SRGBColorSpace;
  texture.wrapS = RepeatWrapping;
  texture.wrapT = RepeatWrapping;
  texture.magFilter = LinearFilter;
  texture.minFilter = LinearFilter;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
}
const map = makeMap();

/**
 * three's lights, lit as three's examples light a scene (intensities in multiples of π, so that each gives c
 * times a factor below 1: three divides by π), all white-ish and coloured a little.
 */
function makeLights(): Record<Exclude<LightSet, 'all'>, Light> {
  const ambient = new AmbientLight(new Color(1, 1, 1), 0.2 * Math.PI);
  const hemisphere = new HemisphereLight(new Color(0.6, 0.75, 1), new Color(0.4, 0.3, 0.2), 0.5 * Math.PI);
  hemisphere.position.set(0.3, 1, 0.2);
  const directional = new DirectionalLight(new Color(1, 0.95, 0.85), 0.7 * Math.PI);
  directional.position.set(-1.5, 2, 3);
  const point = new PointLight(new Color(1, 0.85, 0.7), 4 * Math.PI, 0, 2);
  point.position.set(2, 1, 2.5);
  // A cone whose soft edge crosses the model, and a distance window (three's cutoff) that dims it.
  const spot = new SpotLight(new Color(0.8, 0.9, 1), 5 * Math.PI, 6, 0.32, 0.5, 2);
  spot.position.set(-1.5, -1.5, 3);
  return { ambient, hemisphere, directional, point, spot };
}
const lights = makeLights();

const camera = new PerspectiveCamera(45, 1, 0.1, 20);
camera.position.set(0, 0, 3.6);
camera.lookAt(0, 0, 0);
camera.updateMatrixWorld();

const fogs = {
  none: null,
  fog: new Fog(new Color(0.2, 0.3, 0.55), 2, 4.8),
  fogExp2: new FogExp2(new Color(0.2, 0.3, 0.55), 0.25),
};

const mesh = new Mesh(geometries.sphere);
mesh.rotation.set(0.4, 0.6, 0.1);
const scene = new Scene();
scene.add(mesh);

/** Puts the case's model, lights and fog into the scene. */
function setScene(c: DropinCase): void {
  mesh.geometry = geometries[c.geometry];
  for (const light of Object.values(lights)) scene.remove(light);
  for (const [kind, light] of Object.entries(lights)) {
    if (c.lights === 'all' || c.lights === kind) {
      scene.add(light);
      if (light instanceof DirectionalLight || light instanceof SpotLight) scene.add(light.target);
    }
  }
  scene.fog = fogs[c.fog];
  scene.updateMatrixWorld();
}

type Kind = 'ours' | 'phong' | 'lambert';
const materials = new Map<string, Material>();

/** The page's material of `kind` for the case's surface and shading (made once; three compiles per scene). */
function materialOf(renderer: RendererKind, kind: Kind, c: DropinCase): Material {
  const node = renderer !== 'webgl';
  const key = `${node} ${kind} ${c.surface} ${kind === 'ours' ? c.shading : ''}`;
  let m = materials.get(key);
  if (m !== undefined) return m;
  const surface = {
    map: c.surface === 'map' || c.surface === 'both' ? map : null,
    vertexColors: c.surface === 'vertexColors' || c.surface === 'both',
  };
  if (kind === 'ours') {
    const options = { ka: C, kd: C, ks: 0, shading: c.shading, ...surface };
    // The node material's options are ShadingMaterial's; map and vertexColors are passed as a user passes them.
    m = node ? new ShadingNodeMaterial(options as ShadingNodeMaterialOptions) : new ShadingMaterial(options);
  } else if (kind === 'phong') {
    m = node
      ? new MeshPhongNodeMaterial({ color: C, specular: 0, ...surface })
      : new MeshPhongMaterial({ color: C, specular: 0, ...surface });
  } else {
    m = node
      ? new MeshLambertNodeMaterial({ color: C, ...surface })
      : new MeshLambertMaterial({ color: C, ...surface });
  }
  materials.set(key, m);
  return m;
}

let gl: WebGLRenderer | null = null;

/** The picture of the scene with `material` on the model: SIZE × SIZE, RGBA8 sRGB, rows bottom-up. */
async function draw(renderer: RendererKind, material: Material): Promise<Uint8Array> {
  mesh.material = material;
  if (renderer === 'webgl') {
    if (gl === null) {
      gl = new WebGLRenderer({ antialias: false });
      gl.setPixelRatio(1);
      gl.setSize(SIZE, SIZE, false);
      gl.setClearColor(0x0000ff, 1);
    }
    gl.render(scene, camera);
    return readCanvas(gl, SIZE);
  }
  const gpu = await gpuRenderer(renderer);
  const target = outputTarget(gpu);
  // The canvas path: drawn into three's frame-buffer target, then its output pass (sRGB) into the output target.
  gpu.setOutputRenderTarget(target);
  gpu.setRenderTarget(null);
  gpu.render(scene, camera);
  const pixels = await readTarget(gpu, target, SIZE);
  gpu.setOutputRenderTarget(null);
  return pixels;
}

const outputTargets = new WeakMap<object, RenderTarget>();
function outputTarget(gpu: Awaited<ReturnType<typeof gpuRenderer>>): RenderTarget {
  let target = outputTargets.get(gpu);
  if (target === undefined) {
    // The frame-buffer target has the canvas's size.
    gpu.setPixelRatio(1);
    gpu.setSize(SIZE, SIZE, false);
    gpu.setClearColor(0x0000ff, 1);
    target = new RenderTarget(SIZE, SIZE, { depthBuffer: true });
    outputTargets.set(gpu, target);
  }
  return target;
}

const covered = (p: Uint8Array, i: number): boolean => !hasRgb(p, i, CLEAR);

/** ShadingMaterial's picture `ours` against three's `three`, away from silhouettes. */
function compare(reference: 'phong' | 'lambert', ours: Uint8Array, three: Uint8Array): Comparison {
  const out: Comparison = {
    reference,
    covered: 0,
    coverageMismatch: 0,
    compared: 0,
    mean: 0,
    max: 0,
    signedMean: 0,
    worst: null,
  };
  let sum = 0;
  let signed = 0;
  for (let y = 0; y < SIZE; y++) {
    for (let x = 0; x < SIZE; x++) {
      const i = 4 * (y * SIZE + x);
      const a = covered(ours, i);
      const b = covered(three, i);
      if (b) out.covered++;
      if (a !== b) out.coverageMismatch++;
      if (x === 0 || y === 0 || x === SIZE - 1 || y === SIZE - 1) continue;
      let inside = true;
      for (let dy = -1; dy <= 1 && inside; dy++) {
        for (let dx = -1; dx <= 1; dx++) {
          const j = 4 * ((y + dy) * SIZE + x + dx);
          if (!covered(ours, j) || !covered(three, j)) {
            inside = false;
            break;
          }
        }
      }
      if (!inside) continue;
      out.compared++;
      const d = maxRgbDelta(ours, three, i);
      sum += d;
      signed += ours[i] - three[i] + ours[i + 1] - three[i + 1] + ours[i + 2] - three[i + 2];
      if (d > out.max || out.worst === null) {
        out.max = Math.max(out.max, d);
        out.worst = {
          x,
          y,
          ours: Array.from(ours.subarray(i, i + 3)),
          three: Array.from(three.subarray(i, i + 3)),
        };
      }
    }
  }
  out.mean = out.compared > 0 ? sum / out.compared : 0;
  out.signedMean = out.compared > 0 ? signed / (3 * out.compared) : 0;
  return out;
}

/** Mean of R, G, B and the brightest channel over the drawn pixels of `p`. */
function brightness(p: Uint8Array): { mean: number; max: number } {
  let sum = 0;
  let n = 0;
  let max = 0;
  for (let i = 0; i < p.length; i += 4) {
    if (!covered(p, i)) continue;
    n++;
    sum += p[i] + p[i + 1] + p[i + 2];
    max = Math.max(max, p[i], p[i + 1], p[i + 2]);
  }
  return { mean: n > 0 ? sum / (3 * n) : 0, max };
}

/** Mean max|ΔRGB| over the pixels drawn in both `a` and `b`. */
function meanChange(a: Uint8Array, b: Uint8Array): number {
  let sum = 0;
  let n = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (!covered(a, i) || !covered(b, i)) continue;
    n++;
    sum += maxRgbDelta(a, b, i);
  }
  return n > 0 ? sum / n : 0;
}

/** three's pictures by renderer, material and scene: they do not depend on ShadingMaterial's shading. */
const threePictures = new Map<string, Uint8Array>();

async function threePicture(renderer: RendererKind, kind: 'phong' | 'lambert', c: DropinCase) {
  const key = `${renderer} ${kind} ${c.geometry} ${c.lights} ${c.fog} ${c.surface}`;
  let p = threePictures.get(key);
  if (p === undefined) {
    p = await draw(renderer, materialOf(renderer, kind, c));
    threePictures.set(key, p);
  }
  return p;
}

/**
 * Every case drawn with ShadingMaterial (ShadingNodeMaterial) and compared with MeshPhongMaterial and
 * MeshLambertMaterial (their node versions) on `renderer`; three's pictures are drawn once per scene.
 */
async function run(renderer: RendererKind, cases: DropinCase[]): Promise<RunResult> {
  const start = performance.now();
  const results: CaseResult[] = [];
  for (const c of cases) {
    setScene(c);
    const ours = materialOf(renderer, 'ours', c);
    const oursPixels = await draw(renderer, ours);
    const phong = await threePicture(renderer, 'phong', c);
    const lambert = await threePicture(renderer, 'lambert', c);
    const { mean, max } = brightness(phong);
    const plain = threePictures.get(`${renderer} phong ${c.geometry} ${c.lights} none plain`);
    const kept = ours as Material & { map?: unknown; vertexColors?: unknown };
    results.push({
      case: c,
      comparisons: [compare('phong', oursPixels, phong), compare('lambert', oursPixels, lambert)],
      referenceMean: mean,
      referenceMax: max,
      changeFromPlain: plain === undefined ? null : meanChange(plain, phong),
      carried: { map: kept.map === map, vertexColors: kept.vertexColors === true },
    });
  }
  let backend: RunResult['backend'] = null;
  if (renderer !== 'webgl') {
    const gpu = await gpuRenderer(renderer);
    const { device } = gpu.backend as unknown as { device?: unknown };
    backend = {
      ...backendFlags(gpu),
      device: typeof GPUDevice !== 'undefined' && device instanceof GPUDevice,
    };
  }
  return { renderer, backend, results, ms: performance.now() - start };
}

const api = { run };
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
