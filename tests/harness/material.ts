// Harness for tests/material.spec.ts: renders the lecture's scene with ShadingMaterial and compares every
// pixel with shade() evaluated on the CPU for the same fragment. The CPU finds each pixel's triangle and
// barycentrics with three's Raycaster (ray through the pixel centre, nearest hit), using a screen-tile
// binning of the triangles so that each ray tests only the few triangles whose screen box covers it.
import {
  computeNormalMatrix,
  eyeOf,
  flatShadingGeometry,
  fogFactor,
  type Lighting,
  linearToSrgb8,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeThreeLight,
  type Shading,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline } from '@shadelab/material/outline';
import {
  ACESFilmicToneMapping,
  AmbientLight,
  BackSide,
  BatchedMesh,
  Bone,
  type BufferGeometry,
  type Camera,
  Color,
  DataTexture,
  DirectionalLight,
  DoubleSide,
  Euler,
  Float32BufferAttribute,
  Fog,
  FogExp2,
  HemisphereLight,
  InstancedMesh,
  type Light,
  LinearSRGBColorSpace,
  Matrix3,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshPhongMaterial,
  NoColorSpace,
  NoToneMapping,
  type Object3D,
  ObjectSpaceNormalMap,
  OrthographicCamera,
  PerspectiveCamera,
  Plane,
  PlaneGeometry,
  PointLight,
  Quaternion,
  Raycaster,
  RGBAFormat,
  Scene,
  type ShaderMaterial,
  Skeleton,
  SkinnedMesh,
  SphereGeometry,
  SpotLight,
  SRGBColorSpace,
  TangentSpaceNormalMap,
  TorusKnotGeometry,
  Vector2,
  Vector3,
  Vector4,
  WebGLRenderer,
} from 'three';
import { bindTwoBones, deformNormal, instanceSkinned, skinnedCylinder, stretchMorph } from './lib/deform';
import { hasRgb, maxRgbDelta, readCanvas } from './lib/pixels';
import { lightingDiscontinuity, pixelHits, screenEdgeDistance } from './lib/shadeOracle';
import { flatSphereGeometry, sphereGeometry } from './material-sphere';

/** What three keeps of a compiled program (`renderer.properties.get(material).currentProgram`). */
interface WebGLProgramInfo {
  cacheKey: string;
  vertexShader: WebGLShader;
  fragmentShader: WebGLShader;
}

export interface CompareConfig {
  shading: Shading;
  lighting: Lighting;
  celBands?: number;
  level?: number;
  scale?: [number, number, number];
  rotation?: [number, number, number];
  analytic?: boolean;
  orthographic?: boolean;
  shininess?: number;
  ks?: [number, number, number];
  kd?: [number, number, number];
  /** World position of the light. @default the lecture's (−5, 10, 20) */
  light?: [number, number, number];
  attenuation?: { a?: number; b?: number; c?: number };
  size?: number;
  /** Flat shading of `flatShadingGeometry(indexed sphere)` instead of the triangle soup. */
  flatCorners?: boolean;
}

export interface CompareStats {
  compared: number;
  maxError: number;
  mismatches: number;
  boundarySkipped: number;
  covered: number;
  facesChecked: number;
  facesMultiColour: number;
  darkPixels: number;
  worst: unknown;
}

const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setClearColor(0x0000ff, 1); // pure blue: a NaN pixel (black) or a hole is never mistaken for it
/** The clear colour in RGB: where nothing was drawn. */
const CLEAR = [0, 0, 255] as const;

function makeCamera(orthographic: boolean): Camera {
  const camera = orthographic
    ? new OrthographicCamera(-3, 3, 3, -3, 0.1, 10)
    : new PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

function render(config: CompareConfig): {
  pixels: Uint8Array;
  mesh: Mesh;
  material: ShadingMaterial;
  light: PhongLight;
  camera: Camera;
  size: number;
} {
  const size = config.size ?? 256;
  if (canvas.width !== size) renderer.setSize(size, size, false);
  const light = new PhongLight({ ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [0.8, 0.8, 0.8] });
  light.position.set(...(config.light ?? [-5, 10, 20]));
  if (config.attenuation) light.attenuation = config.attenuation;
  const material = new ShadingMaterial({
    shading: config.shading,
    lighting: config.lighting,
    celBands: config.celBands ?? 0,
    lights: [light],
    ...(config.shininess !== undefined ? { shininess: config.shininess } : {}),
    ...(config.ks ? { ks: config.ks } : {}),
    ...(config.kd ? { kd: config.kd } : {}),
  });
  const analytic = config.analytic ?? config.shading !== 'gouraud';
  const level = config.level ?? 6;
  const geometry = config.flatCorners ? flatSphereGeometry(level) : sphereGeometry(level, !analytic);
  const mesh = new Mesh(geometry, material);
  mesh.scale.set(...(config.scale ?? [2, 1, 2]));
  mesh.rotation.set(...(config.rotation ?? [0, 0, 0]));
  const scene = new Scene();
  scene.add(mesh, light);
  const camera = makeCamera(config.orthographic ?? false);
  renderer.render(scene, camera);
  const pixels = readCanvas(renderer, size);
  return { pixels, mesh, material, light, camera, size };
}

/** Render `config` on the GPU and compare every covered pixel away from the silhouette with shade(). */
function compare(config: CompareConfig): CompareStats {
  const { pixels, mesh, material, light, camera, size } = render(config);
  // Triangle by triangle, corners in the order drawn (a flatShadingGeometry is indexed: expand it).
  const soup = mesh.geometry.index === null ? mesh.geometry : mesh.geometry.toNonIndexed();
  const positions = soup.getAttribute('position').array as Float32Array;
  const count = positions.length / 3;
  // World positions and world normals of the vertices, as the vertex shader computes them.
  const nm = computeNormalMatrix(mesh.matrixWorld, new Matrix3());
  const world = new Float64Array(3 * count);
  const normals = new Float64Array(3 * count);
  const v = new Vector3();
  for (let i = 0; i < count; i++) {
    v.fromArray(positions, 3 * i).applyMatrix4(mesh.matrixWorld);
    world.set([v.x, v.y, v.z], 3 * i);
    v.fromArray(positions, 3 * i).applyMatrix3(nm);
    const l = v.length();
    if (l > 0) v.divideScalar(l);
    normals.set([v.x, v.y, v.z], 3 * i);
  }
  // Distance in pixels to the nearest edge of a screen triangle, for the flat shading edge margin.
  const edgeDistance = screenEdgeDistance(world, camera, size);
  const hits = pixelHits(world, camera, size, mesh.matrixWorld.determinant() < 0);
  const e = eyeOf(camera, new Vector4());
  const eye = [e.x, e.y, e.z, e.w];
  const m: ShadeMaterial = {
    ka: material.ka.toArray(),
    kd: material.kd.toArray(),
    ks: material.ks.toArray(),
    shininess: material.shininess,
    lighting: material.lighting,
    celBands: material.celBands,
  };
  const lightPosition = light.getWorldPosition(new Vector3()).toArray();
  const lights: ShadeLight[] = [
    {
      position: lightPosition,
      ambient: light.ambient.toArray(),
      diffuse: light.diffuse.toArray(),
      specular: light.specular.toArray(),
      attenuation: light.attenuation,
    },
  ];
  const atDiscontinuity = lightingDiscontinuity(m, lights, eye);
  // Per-vertex (gouraud) and per-face (flat) CPU colours, linear.
  const vertexColour = new Float64Array(3 * count);
  const faceColour = new Float64Array(count);
  const faceBoundary = new Uint8Array(count / 3);
  const vertexBoundary = new Uint8Array(count);
  if (config.shading === 'gouraud') {
    for (let i = 0; i < count; i++) {
      vertexBoundary[i] = atDiscontinuity(
        world.subarray(3 * i, 3 * i + 3),
        normals.subarray(3 * i, 3 * i + 3),
      )
        ? 1
        : 0;
      vertexColour.set(
        shade(
          { position: world.subarray(3 * i, 3 * i + 3), normal: normals.subarray(3 * i, 3 * i + 3), eye },
          m,
          lights,
        ),
        3 * i,
      );
    }
  }
  if (config.shading === 'flat') {
    const p0 = new Vector3();
    const p1 = new Vector3();
    const p2 = new Vector3();
    for (let t = 0; t < count / 3; t++) {
      p0.fromArray(positions, 9 * t);
      p1.fromArray(positions, 9 * t + 3);
      p2.fromArray(positions, 9 * t + 6);
      const centroid = p0.clone().add(p1).add(p2).divideScalar(3).applyMatrix4(mesh.matrixWorld).toArray();
      const faceNormal = p1.clone().sub(p0).cross(p2.clone().sub(p0)).applyMatrix3(nm).toArray();
      faceColour.set(shade({ position: centroid, normal: faceNormal, eye }, m, lights), 3 * t);
      faceBoundary[t] = atDiscontinuity(centroid, faceNormal) ? 1 : 0;
    }
  }
  const stats: CompareStats = {
    compared: 0,
    maxError: 0,
    mismatches: 0,
    boundarySkipped: 0,
    covered: 0,
    facesChecked: 0,
    facesMultiColour: 0,
    darkPixels: 0,
    worst: null,
  };
  const floor = linearToSrgb8([m.ka[0] * 0.2, m.ka[1] * 0.2, m.ka[2] * 0.2]);
  const faceSeen = new Map<number, number>();
  const expected = [0, 0, 0] as [number, number, number];
  const linear: [number, number, number] = [0, 0, 0];
  const normal = [0, 0, 0];
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const i = y * size + x;
      const r = pixels[4 * i];
      const g = pixels[4 * i + 1];
      const b = pixels[4 * i + 2];
      const isClear = r === 0 && g === 0 && b === 255;
      if (!isClear) {
        stats.covered++;
        // Every lit colour is ≥ ka·Ia (≈ sRGB 97, 75, 56 here): a (near-)black pixel means NaN.
        if (Math.max(r, g, b) < Math.min(32, floor[0] - 1)) stats.darkPixels++;
      }
      const t = hits.triangle[i];
      if (t < 0) continue;
      // Away from the silhouette: all 8 neighbours hit the mesh too.
      let interior = x > 0 && y > 0 && x < size - 1 && y < size - 1;
      for (let dy = -1; interior && dy <= 1; dy++)
        for (let dx = -1; interior && dx <= 1; dx++)
          if (hits.triangle[i + dy * size + dx] < 0) interior = false;
      if (!interior) continue;
      const b0 = hits.bary[3 * i];
      const b1 = hits.bary[3 * i + 1];
      const b2 = hits.bary[3 * i + 2];
      const position = hits.point.subarray(3 * i, 3 * i + 3);
      if (config.shading === 'phong') {
        for (let k = 0; k < 3; k++)
          normal[k] = b0 * normals[9 * t + k] + b1 * normals[9 * t + 3 + k] + b2 * normals[9 * t + 6 + k];
        if (atDiscontinuity(position, normal)) {
          stats.boundarySkipped++;
          continue;
        }
        shade({ position, normal, eye }, m, lights, linear);
      } else if (config.shading === 'gouraud') {
        // A vertex colour quantised on the other side of an edge changes the whole triangle.
        if (vertexBoundary[3 * t] || vertexBoundary[3 * t + 1] || vertexBoundary[3 * t + 2]) {
          stats.boundarySkipped++;
          continue;
        }
        for (let k = 0; k < 3; k++)
          linear[k] =
            b0 * vertexColour[9 * t + k] +
            b1 * vertexColour[9 * t + 3 + k] +
            b2 * vertexColour[9 * t + 6 + k];
      } else {
        // Flat: pixel centres within 0.1 px of an edge may belong to the neighbour on the GPU, whose
        // rasteriser snaps vertices to a sub-pixel grid.
        if (edgeDistance(t, x + 0.5, y + 0.5) < 0.1 || faceBoundary[t]) {
          stats.boundarySkipped++;
          continue;
        }
        linear[0] = faceColour[3 * t];
        linear[1] = faceColour[3 * t + 1];
        linear[2] = faceColour[3 * t + 2];
        const packed = (r << 16) | (g << 8) | b;
        const seen = faceSeen.get(t);
        if (seen === undefined) faceSeen.set(t, packed);
        else if (seen !== packed && seen !== -1) {
          stats.facesMultiColour++;
          faceSeen.set(t, -1);
        }
      }
      linearToSrgb8(linear, expected);
      const err = Math.max(Math.abs(expected[0] - r), Math.abs(expected[1] - g), Math.abs(expected[2] - b));
      stats.compared++;
      if (err > stats.maxError) {
        stats.maxError = err;
        stats.worst = { x, y, gpu: [r, g, b], cpu: [...expected], triangle: t, bary: [b0, b1, b2] };
      }
      if (err > 2) stats.mismatches++;
    }
  }
  stats.facesChecked = faceSeen.size;
  material.dispose();
  return stats;
}

/** Flip options `flips` times, rendering after each flip; report the live program count. */
function flipPrograms(flips: number): { before: number; after: number; max: number; variants: number } {
  const size = 64;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const material = new ShadingMaterial({ lights: [light] });
  const mesh = new Mesh(sphereGeometry(3, false), material);
  mesh.scale.set(2, 1, 2);
  const scene = new Scene();
  scene.add(mesh, light);
  const camera = makeCamera(false);
  renderer.render(scene, camera);
  const before = renderer.info.programs?.length ?? 0;
  let max = before;
  const shadings: Shading[] = ['flat', 'gouraud', 'phong'];
  const lightings: Lighting[] = ['phong', 'blinn-phong'];
  const variants = new Set<string>();
  let seed = 12345;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  for (let i = 0; i < flips; i++) {
    material.shading = shadings[Math.floor(random() * 3)];
    material.lighting = lightings[Math.floor(random() * 2)];
    material.celBands = random() < 0.5 ? 0 : 4;
    material.shininess = random() * 100;
    renderer.render(scene, camera);
    variants.add(JSON.stringify(material.defines));
    max = Math.max(max, renderer.info.programs?.length ?? 0);
  }
  const after = renderer.info.programs?.length ?? 0;
  material.dispose();
  return { before, after, max, variants: variants.size };
}

/**
 * Two differently transformed spheres drawn with one shared material, then each with its own: the images
 * must be identical (per-object uniforms are re-uploaded between draws of the same material).
 */
function sharedMaterial(): { identical: boolean; differing: number; covered: number } {
  const size = 128;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const camera = makeCamera(false);
  const draw = (shared: boolean): Uint8Array => {
    const a = new ShadingMaterial({ shading: 'phong', lighting: 'blinn-phong', lights: [light] });
    const b = shared
      ? a
      : new ShadingMaterial({ shading: 'phong', lighting: 'blinn-phong', lights: [light] });
    const left = new Mesh(sphereGeometry(4, false), a);
    left.position.set(-1.4, 0, 0);
    left.scale.set(1, 1.5, 1);
    const right = new Mesh(sphereGeometry(4, false), b);
    right.position.set(1.4, 0, 0);
    right.scale.set(-1, 0.5, 1);
    right.rotation.set(0.5, 1, 0);
    const scene = new Scene();
    scene.add(left, right, light);
    renderer.render(scene, camera);
    const pixels = readCanvas(renderer, size);
    a.dispose();
    b.dispose();
    return pixels;
  };
  const one = draw(true);
  const two = draw(false);
  let differing = 0;
  let covered = 0;
  for (let i = 0; i < one.length; i += 4) {
    if (!(one[i] === 0 && one[i + 2] === 255)) covered++;
    if (one[i] !== two[i] || one[i + 1] !== two[i + 1] || one[i + 2] !== two[i + 2]) differing++;
  }
  return { identical: differing === 0, differing, covered };
}

/** A cel-shaded sphere without, then with, a black inverted-hull outline. */
function outline(thickness: number): {
  ring: number;
  ringBlack: number;
  insideChanged: number;
  covered: number;
} {
  const size = 128;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const camera = makeCamera(false);
  const material = new ShadingMaterial({ shading: 'phong', celBands: 3, lights: [light] });
  const mesh = new Mesh(sphereGeometry(5, false), material);
  mesh.scale.set(2, 1, 2);
  const scene = new Scene();
  scene.add(mesh, light);
  const read = (): Uint8Array => {
    renderer.render(scene, camera);
    return readCanvas(renderer, size);
  };
  const before = read();
  const hull = createOutline(mesh, { thickness, color: '#000000' });
  const after = read();
  hull.material.dispose();
  material.dispose();
  let ring = 0;
  let ringBlack = 0;
  let insideChanged = 0;
  let covered = 0;
  for (let i = 0; i < before.length; i += 4) {
    const wasClear = hasRgb(before, i, CLEAR);
    const isClear = hasRgb(after, i, CLEAR);
    if (!wasClear) {
      covered++;
      if (before[i] !== after[i] || before[i + 1] !== after[i + 1] || before[i + 2] !== after[i + 2])
        insideChanged++;
    } else if (!isClear) {
      ring++;
      if (after[i] === 0 && after[i + 1] === 0 && after[i + 2] === 0) ringBlack++;
    }
  }
  return { ring, ringBlack, insideChanged, covered };
}

/** A program as the GPU got it: three's cache key and the final GLSL of both stages. */
export interface ProgramSource {
  /** Which scene of {@link programSources} drew it. */
  name: string;
  /** three's program cache key without its last part, the material's `customProgramCacheKey()`. */
  cacheKey: string;
  vertex: string;
  fragment: string;
}

/**
 * The programs of the lecture's scenes without any of three's scene features (no instancing, skinning, morph
 * targets, fog, clipping or tone mapping): every shading × lighting × cel variant on each geometry path, light
 * counts 0 … 2 and attenuation, the outline and the impostor, with a standard and a logarithmic depth buffer.
 * Each entry is the program the material used for that scene, with the GLSL three handed to WebGL.
 */
function programSources(): ProgramSource[] {
  const out: ProgramSource[] = [];
  const logCanvas = document.createElement('canvas');
  const renderers: Array<[string, WebGLRenderer]> = [
    ['standard', renderer],
    ['logarithmic', new WebGLRenderer({ canvas: logCanvas, antialias: false, logarithmicDepthBuffer: true })],
  ];
  for (const [depth, r] of renderers) {
    r.setSize(16, 16, false);
    const gl = r.getContext();
    const camera = makeCamera(false);
    const lights = [0, 1, 2].map((i) => {
      const light = new PhongLight();
      light.position.set(-5 + 3 * i, 10, 20);
      return light;
    });
    const attenuated = new PhongLight({ attenuation: { a: 1, b: 0.2, c: 0.05 } });
    attenuated.position.set(1, 2, 4);
    const draw = (
      name: string,
      mesh: Mesh,
      material: ShaderMaterial,
      extra: Object3D[] = [],
      withLights = true,
    ): void => {
      const scene = new Scene();
      scene.add(mesh, ...extra);
      // A material with no PhongLight listed is lit by the scene's: its 0-light program is that of a scene without.
      if (withLights) scene.add(...lights, attenuated);
      r.render(scene, camera);
      const program = (r.properties.get(material) as { currentProgram?: WebGLProgramInfo }).currentProgram;
      if (program === undefined) throw new Error(`no program for ${name}`);
      // The key ends with material.customProgramCacheKey() (onBeforeCompile's source text): left out.
      const custom = `,${material.customProgramCacheKey()}`;
      if (!program.cacheKey.endsWith(custom)) throw new Error(`unexpected cache key for ${name}`);
      out.push({
        name: `${depth} ${name}`,
        cacheKey: program.cacheKey.slice(0, -custom.length),
        vertex: gl.getShaderSource(program.vertexShader) ?? '',
        fragment: gl.getShaderSource(program.fragmentShader) ?? '',
      });
    };
    const geometries = {
      soup: sphereGeometry(2, false),
      corners: flatSphereGeometry(2),
      analytic: sphereGeometry(2, false),
      normals: sphereGeometry(2, true),
    };
    for (const shading of ['flat', 'gouraud', 'phong'] as const) {
      for (const lighting of ['phong', 'blinn-phong'] as const) {
        for (const celBands of [0, 3]) {
          const paths =
            shading === 'flat' ? (['soup', 'corners'] as const) : (['analytic', 'normals'] as const);
          for (const path of paths) {
            const material = new ShadingMaterial({ shading, lighting, celBands, lights: [lights[0]] });
            draw(
              `${shading} ${lighting} cel ${celBands} ${path}`,
              new Mesh(geometries[path], material),
              material,
            );
          }
        }
      }
      for (const [count, list] of [
        [0, []],
        [2, lights.slice(0, 2)],
        ['attenuated', [lights[0], attenuated]],
      ] as const) {
        const material = new ShadingMaterial({ shading, lights: [...list] });
        const geometry = shading === 'flat' ? geometries.corners : geometries.analytic;
        draw(`${shading} lights ${count}`, new Mesh(geometry, material), material, [], count !== 0);
      }
    }
    for (const path of ['analytic', 'normals'] as const) {
      const material = new ShadingMaterial({ celBands: 3, lights: [lights[0]] });
      const mesh = new Mesh(geometries[path], material);
      const hull = createOutline(mesh, { thickness: 0.05 });
      draw(`outline ${path}`, mesh, hull.material);
    }
    for (const [name, options] of [
      ['impostor', { lights: [lights[0]] }],
      [
        'impostor blinn-phong cel 3 lights 2',
        { lighting: 'blinn-phong', celBands: 3, lights: lights.slice(0, 2) },
      ],
    ] as const) {
      const material = new SphereImpostorMaterial({ ...options, lights: [...options.lights] });
      draw(name, new SphereImpostor(material), material);
    }
  }
  return out;
}

// ---- ShadingMaterial in any three.js scene (tests/material-scene.spec.ts) ----------------------------------

/** One instance of an InstancedMesh or BatchedMesh (or the hybrid instanced SkinnedMesh). */
export interface SceneInstance {
  position: readonly [number, number, number];
  scale?: readonly [number, number, number];
  rotation?: readonly [number, number, number];
  /** Shear of the instance matrix: x += shear · y. @default 0 */
  shear?: number;
  /** instanceColor (linear). */
  color?: readonly [number, number, number];
}

export interface SceneConfig {
  shading: Shading;
  lighting?: Lighting;
  /** What draws. @default 'mesh' */
  object?:
    | 'mesh'
    | 'instanced'
    | 'batched'
    | 'skinned'
    | 'morphed'
    | 'instanced-skinned'
    | 'instanced-morphed'
    | 'impostor'
    | 'torus-knot'
    | 'uv-sphere'
    | 'plane';
  /** Flat shading of flatShadingGeometry(geometry) instead of the triangle soup. */
  flatCorners?: boolean;
  /**
   * Flat shading of the plain indexed geometry (no preparation): the derivative face normal per fragment. The
   * torus knot is always indexed.
   */
  indexedFlat?: boolean;
  /** Sphere without a normal attribute (analytic normals; spheres only). @default false */
  analytic?: boolean;
  /** Sphere level. @default 5 */
  level?: number;
  instances?: readonly SceneInstance[];
  /** Object scale. @default [1, 1, 1] */
  scale?: readonly [number, number, number];
  /** Rotation of the skinned mesh's second bone about z, radians. @default 0.7 */
  bone?: number;
  fog?: { near: number; far: number } | { density: number };
  /** Planes (normal x, y, z, constant) kept where normal·p + constant ≥ 0. */
  clip?: {
    planes: ReadonlyArray<readonly [number, number, number, number]>;
    global?: boolean;
    intersection?: boolean;
  };
  /** Inverted-hull outline of this thickness (createOutline). */
  outline?: number;
  logarithmic?: boolean;
  /** ACES filmic tone mapping with this exposure. */
  toneMapping?: number;
  /** The materials' toneMapped (ShadingMaterial's and the oracle's). @default true */
  toneMapped?: boolean;
  /** renderer.outputColorSpace = LinearSRGBColorSpace. */
  linearOutput?: boolean;
  /** ka·Ia only (kd = ks = 0, Ia = 1): colours compared exactly with MeshPhongMaterial's emissive. */
  constant?: boolean;
  ka?: readonly [number, number, number];
  size?: number;
  /** three's lights in the scene (besides the PhongLight). */
  threeLights?: readonly SceneThreeLight[];
  /** The PhongLight at (−5, 10, 20) in the scene and the material's list. @default true */
  phongLight?: boolean;
  /** The PhongLight in the material's list (else found in the scene). @default true */
  listed?: boolean;
  /** Textures, vertex colours, emissive and alpha (the torus knot has uvs). */
  surface?: SceneSurface;
}

/** The surface of a ShadingMaterial (and of its MeshPhongMaterial oracle). */
export interface SceneSurface {
  /** A 4 × 4 sRGB colour texture (nearest); `'alpha'`: its alpha varies too. */
  map?: boolean | 'alpha';
  /** Vertex colours: RGB, or RGBA with a varying alpha. */
  vertexColors?: 'rgb' | 'rgba';
  emissive?: readonly [number, number, number];
  /** A 4 × 4 sRGB texture multiplying emissive. */
  emissiveMap?: boolean;
  opacity?: number;
  transparent?: boolean;
  alphaTest?: number;
  /** A 4 × 4 alpha map (green 0 … 1). */
  alphaMap?: boolean;
  /** A 4 × 4 normal map (tilted normals), tangent space or object space. */
  normalMap?: 'tangent' | 'object';
  normalScale?: readonly [number, number];
  /** The CPU leaves the normal map out (to show that it changes the picture). */
  unperturbed?: boolean;
  /** `material.side` DoubleSide or BackSide (phong shading only in the comparison). */
  side?: 'double' | 'back';
}

/** A deterministic 4 × 4 normal map (linear): unit normals tilted up to ~40° from +z. */
function normalTexture(): DataTexture {
  const data = new Uint8Array(4 * TEXELS * TEXELS);
  for (let i = 0; i < TEXELS * TEXELS; i++) {
    const x = 0.45 * Math.sin(1.7 * i + 0.3);
    const y = 0.45 * Math.cos(2.3 * i + 1.1);
    const z = Math.sqrt(1 - x * x - y * y);
    data.set([x, y, z].map((c) => Math.round(((c + 1) / 2) * 255)).concat(255), 4 * i);
  }
  const texture = new DataTexture(data, TEXELS, TEXELS, RGBAFormat);
  texture.colorSpace = NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

/** The side of the harness's textures, in texels. */
const TEXELS = 4;

/** A deterministic 4 × 4 RGBA8 texture: `seed` picks the pattern; `alpha` gives the texels alpha 0.25 … 1. */
function surfaceTexture(seed: number, alpha: boolean, srgbSpace: boolean): DataTexture {
  const data = new Uint8Array(4 * TEXELS * TEXELS);
  for (let i = 0; i < TEXELS * TEXELS; i++) {
    const k = (i * 7 + seed * 5) % 16;
    data.set(
      [
        96 + ((k * 37) % 160),
        96 + ((k * 71 + 40) % 160),
        96 + ((k * 113 + 80) % 160),
        alpha ? 64 + 12 * k : 255,
      ],
      4 * i,
    );
  }
  const texture = new DataTexture(data, TEXELS, TEXELS, RGBAFormat);
  texture.colorSpace = srgbSpace ? SRGBColorSpace : NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

/** The linear RGBA of the nearest texel at `uv` as the GPU samples it (sRGB decoded), or null near a texel edge. */
function texelAt(texture: DataTexture, u: number, v: number): number[] | null {
  const x = u * TEXELS;
  const y = v * TEXELS;
  const fx = x - Math.floor(x);
  const fy = y - Math.floor(y);
  if (Math.min(fx, 1 - fx, fy, 1 - fy) < 0.08) return null;
  const i = Math.min(Math.max(Math.floor(x), 0), TEXELS - 1);
  const j = Math.min(Math.max(Math.floor(y), 0), TEXELS - 1);
  const data = texture.image.data as Uint8Array;
  const t = Array.from(data.subarray(4 * (j * TEXELS + i), 4 * (j * TEXELS + i) + 4), (c) => c / 255);
  if (texture.colorSpace === SRGBColorSpace)
    for (let k = 0; k < 3; k++) t[k] = t[k] < 0.04045 ? t[k] / 12.92 : ((t[k] + 0.055) / 1.055) ** 2.4;
  return t;
}

/** Deterministic vertex colours (linear, 0.35 … 1; alpha 0.3 … 1 for RGBA) from the positions. */
function setVertexColors(geometry: BufferGeometry, rgba: boolean): void {
  const position = geometry.getAttribute('position');
  const size = rgba ? 4 : 3;
  const colors = new Float32Array(size * position.count);
  for (let i = 0; i < position.count; i++) {
    const x = position.getX(i);
    const y = position.getY(i);
    const z = position.getZ(i);
    colors[size * i] = 0.675 + 0.325 * Math.sin(3 * x + 1);
    colors[size * i + 1] = 0.675 + 0.325 * Math.sin(2 * y + 3 * z);
    colors[size * i + 2] = 0.675 + 0.325 * Math.cos(4 * z - x);
    if (rgba) colors[size * i + 3] = 0.65 + 0.35 * Math.sin(5 * x + 2 * y);
  }
  geometry.setAttribute('color', new Float32BufferAttribute(colors, size));
}

/** The surface options on `material` (a ShadingMaterial or its MeshPhongMaterial oracle). */
function applySurface(material: ShadingMaterial | MeshPhongMaterial, surface: SceneSurface): void {
  if (surface.map) material.map = surfaceTexture(1, surface.map === 'alpha', true);
  if (surface.vertexColors) material.vertexColors = true;
  if (surface.emissive) material.emissive = new Color(...surface.emissive);
  if (surface.emissiveMap) material.emissiveMap = surfaceTexture(2, false, true);
  if (surface.opacity !== undefined) material.opacity = surface.opacity;
  if (surface.transparent) material.transparent = true;
  if (surface.alphaTest !== undefined) material.alphaTest = surface.alphaTest;
  if (surface.alphaMap) material.alphaMap = surfaceTexture(3, false, false);
  if (surface.normalMap) {
    material.normalMap = normalTexture();
    material.normalMapType = surface.normalMap === 'object' ? ObjectSpaceNormalMap : TangentSpaceNormalMap;
  }
  if (surface.normalScale) material.normalScale.set(...surface.normalScale);
  if (surface.side) material.side = surface.side === 'double' ? DoubleSide : BackSide;
}

/** One of three's lights (colours linear). */
export interface SceneThreeLight {
  type: 'ambient' | 'hemisphere' | 'directional' | 'point' | 'spot';
  color: readonly [number, number, number];
  intensity?: number;
  position?: readonly [number, number, number];
  target?: readonly [number, number, number];
  distance?: number;
  decay?: number;
  angle?: number;
  penumbra?: number;
  groundColor?: readonly [number, number, number];
}

/** three's light for a SceneThreeLight, added to `scene` (with its target). */
function threeLight(spec: SceneThreeLight, scene: Scene): Light {
  const color = new Color(...spec.color);
  const intensity = spec.intensity ?? 1;
  let light: Light;
  if (spec.type === 'ambient') light = new AmbientLight(color, intensity);
  else if (spec.type === 'hemisphere')
    light = new HemisphereLight(color, new Color(...(spec.groundColor ?? [0, 0, 0])), intensity);
  else if (spec.type === 'directional') light = new DirectionalLight(color, intensity);
  else if (spec.type === 'point')
    light = new PointLight(color, intensity, spec.distance ?? 0, spec.decay ?? 2);
  else
    light = new SpotLight(
      color,
      intensity,
      spec.distance ?? 0,
      spec.angle ?? Math.PI / 3,
      spec.penumbra ?? 0,
      spec.decay ?? 2,
    );
  if (spec.position) light.position.set(...spec.position);
  const target = (light as DirectionalLight).target;
  if (target) {
    target.position.set(...(spec.target ?? [0, 0, 0]));
    scene.add(target);
  }
  scene.add(light);
  return light;
}

/** What shade() takes for one of three's lights, in world space. */
function shadeThreeLight(light: Light): ShadeThreeLight {
  const world = light.getWorldPosition(new Vector3());
  const color = light.color.clone().multiplyScalar(light.intensity).toArray();
  if ((light as AmbientLight).isAmbientLight) return { type: 'ambient', color };
  if ((light as HemisphereLight).isHemisphereLight) {
    const ground = (light as HemisphereLight).groundColor.clone().multiplyScalar(light.intensity).toArray();
    return { type: 'hemisphere', color, groundColor: ground, direction: world.clone().normalize().toArray() };
  }
  const target = (light as DirectionalLight).target;
  const direction = target
    ? world.clone().sub(target.getWorldPosition(new Vector3())).normalize().toArray()
    : undefined;
  if ((light as DirectionalLight).isDirectionalLight) return { type: 'directional', color, direction };
  const point = light as PointLight;
  const base = { color, position: world.toArray(), distance: point.distance, decay: point.decay };
  if ((light as SpotLight).isSpotLight) {
    const spot = light as SpotLight;
    return {
      type: 'spot',
      ...base,
      direction,
      coneCos: Math.cos(spot.angle),
      penumbraCos: Math.cos(spot.angle * (1 - spot.penumbra)),
    };
  }
  return { type: 'point', ...base };
}

export interface SceneStats {
  /** Pixels drawn by ShadingMaterial / by the oracle (MeshPhongMaterial). */
  covered: number;
  oracleCovered: number;
  /** Pixels whose 3 × 3 neighbourhood is all drawn or all clear in the oracle, and how many differ. */
  coverageCompared: number;
  coverageMismatches: number;
  /** Constant mode: covered pixels compared with the oracle's colour, and the largest difference. */
  oracleCompared: number;
  oracleMaxError: number;
  /** Pixels compared with shade() (away from silhouettes, clipped surfaces and flat faces' edges). */
  compared: number;
  maxError: number;
  mismatches: number;
  /** Covered pixels darker than any lit colour: NaN. */
  darkPixels: number;
  /**
   * Pixels drawn by both whose 3 × 3 neighbourhood is all lit or all black in the oracle, and how many differ
   * (black here where the oracle is lit, or above 3/255 where it is black).
   */
  litCompared: number;
  litMismatches: number;
  /** Outline (pure black) pixels, and those where the planes clip. */
  black: number;
  clippedBlack: number;
  worst: unknown;
  /** The defines ShadingMaterial compiled for the draw (its variant). */
  defines: Record<string, unknown>;
}

const WHITE_LIGHT: [number, number, number] = [1, 1, 1];
let logRenderer: WebGLRenderer | null = null;

/** The sphere with one morph target at full influence: stretched to (1.6, 0.8, 1.2), normals to match. */
const morphedSphere = (level: number, indexed = false): BufferGeometry =>
  stretchMorph(sphereGeometry(level, true, indexed));

function instanceMatrix(instance: SceneInstance): Matrix4 {
  const m = new Matrix4().compose(
    new Vector3(...instance.position),
    new Quaternion().setFromEuler(new Euler(...(instance.rotation ?? [0, 0, 0]))),
    new Vector3(...(instance.scale ?? [1, 1, 1])),
  );
  if (instance.shear) m.multiply(new Matrix4().makeShear(0, 0, instance.shear, 0, 0, 0));
  return m;
}

interface SceneSetup {
  scene: Scene;
  object: Mesh;
  geometry: BufferGeometry;
  material: ShadingMaterial;
  light: PhongLight;
  threeLights: Light[];
  instances: Matrix4[];
  tints: Array<readonly [number, number, number]>;
  hull: Mesh | null;
  dispose: () => void;
}

function buildScene(config: SceneConfig): SceneSetup {
  const kind = config.object ?? 'mesh';
  const level = config.level ?? 5;
  const light = new PhongLight(
    config.constant
      ? { ambient: 1, diffuse: 0, specular: 0 }
      : { ambient: [0.2, 0.2, 0.2], diffuse: WHITE_LIGHT, specular: [0.8, 0.8, 0.8] },
  );
  light.position.set(-5, 10, 20);
  const material = new (kind === 'impostor' ? SphereImpostorMaterial : ShadingMaterial)({
    ...(kind === 'impostor' ? {} : { shading: config.shading }),
    lighting: config.lighting ?? 'phong',
    lights: config.phongLight === false || config.listed === false ? [] : [light],
    ...(config.ka ? { ka: config.ka } : {}),
    ...(config.constant ? { kd: 0, ks: 0 } : {}),
  });
  if (config.toneMapped === false) material.toneMapped = false;
  if (config.surface) applySurface(material as ShadingMaterial, config.surface);
  const flat = config.shading === 'flat';
  let geometry: BufferGeometry;
  const skinned = kind === 'skinned' || kind === 'instanced-skinned';
  if (skinned) {
    const cylinder = skinnedCylinder(0.5, 16, 12);
    geometry = flat
      ? config.flatCorners
        ? flatShadingGeometry(cylinder)
        : config.indexedFlat
          ? cylinder
          : cylinder.toNonIndexed()
      : cylinder;
  } else if (kind === 'torus-knot' || kind === 'uv-sphere' || kind === 'plane') {
    // The knot hides parts of itself; three's UV sphere (uvs, normals, indexed) is convex: nothing shows
    // through its alpha-tested holes or behind its blended pixels but the clear colour. The plane's normal is
    // its face normal (a normal map's tangent frame is then exactly the uv gradients).
    geometry =
      kind === 'torus-knot'
        ? new TorusKnotGeometry(0.8, 0.28, 96, 12)
        : kind === 'plane'
          ? new PlaneGeometry(3, 3, 4, 4)
          : new SphereGeometry(1.2, 48, 24);
    if (config.surface?.vertexColors) setVertexColors(geometry, config.surface.vertexColors === 'rgba');
    // Flat shading: the triangle soup (exact, one colour per face) unless the plain indexed one is asked for.
    if (flat && !config.indexedFlat) geometry = geometry.toNonIndexed();
  } else if (kind === 'morphed' || kind === 'instanced-morphed') {
    const sphere = morphedSphere(level, config.indexedFlat ?? false);
    geometry = flat ? (config.flatCorners ? flatShadingGeometry(sphere) : sphere) : sphere;
  } else if (flat) {
    geometry = config.flatCorners
      ? flatSphereGeometry(level)
      : sphereGeometry(level, false, config.indexedFlat ?? false);
  } else {
    geometry = sphereGeometry(level, !(config.analytic ?? false));
  }
  const specs = config.instances ?? [{ position: [0, 0, 0] }];
  const instances = specs.map(instanceMatrix);
  const tints = specs.map((s) => s.color ?? WHITE_LIGHT);
  const colored = specs.some((s) => s.color !== undefined);
  let object: Mesh;
  if (kind === 'instanced' || kind === 'instanced-morphed') {
    const mesh = new InstancedMesh(geometry, material, instances.length);
    instances.forEach((m, i) => {
      mesh.setMatrixAt(i, m);
      if (colored) mesh.setColorAt(i, new Color(...tints[i]));
    });
    if (kind === 'instanced-morphed') {
      // Per-instance morph weights (InstancedMesh.setMorphAt), all at full influence.
      mesh.morphTargetInfluences = [1];
      for (let i = 0; i < instances.length; i++) mesh.setMorphAt(i, mesh);
      if (mesh.morphTexture) mesh.morphTexture.needsUpdate = true;
    }
    object = mesh;
  } else if (kind === 'impostor') {
    object = new SphereImpostor(material as SphereImpostorMaterial);
  } else if (kind === 'batched') {
    const index = geometry.index;
    const mesh = new BatchedMesh(
      instances.length,
      geometry.getAttribute('position').count,
      index === null ? 0 : index.count,
      material,
    );
    const id = mesh.addGeometry(geometry);
    // A BatchedMesh draws its own geometry: flag it as spheres (centred at their origins) like any geometry.
    if (geometry.userData.isSphere === true || geometry.type === 'SubdivisionSphereGeometry')
      mesh.geometry.userData.isSphere = true;
    instances.forEach((m, i) => {
      const instance = mesh.addInstance(id);
      mesh.setMatrixAt(instance, m);
      if (colored) mesh.setColorAt(instance, new Color(...tints[i]));
    });
    object = mesh as unknown as Mesh;
  } else if (skinned) {
    const mesh = new SkinnedMesh(geometry, material);
    bindTwoBones(mesh, config.bone ?? 0.7);
    if (kind === 'instanced-skinned') {
      instanceSkinned(mesh, instances);
    }
    object = mesh;
  } else {
    object = new Mesh(geometry, material);
    if (kind === 'morphed') object.morphTargetInfluences = [1];
  }
  object.frustumCulled = false;
  object.scale.set(...(config.scale ?? [1, 1, 1]));
  if (
    kind === 'mesh' ||
    kind === 'morphed' ||
    kind === 'skinned' ||
    kind === 'impostor' ||
    kind === 'torus-knot' ||
    kind === 'uv-sphere' ||
    kind === 'plane'
  ) {
    // A single object stands where instance 0 would.
    object.applyMatrix4(instances[0]);
    instances[0] = new Matrix4();
  }
  const scene = new Scene();
  scene.add(object);
  if (config.phongLight !== false) scene.add(light);
  const threeLights = (config.threeLights ?? []).map((spec) => threeLight(spec, scene));
  if (config.fog) {
    scene.fog =
      'density' in config.fog
        ? new FogExp2(0x8080c0, config.fog.density)
        : new Fog(0x8080c0, config.fog.near, config.fog.far);
  }
  let hull: Mesh | null = null;
  if (config.clip && !config.clip.global) {
    material.clippingPlanes = config.clip.planes.map(([x, y, z, c]) => new Plane(new Vector3(x, y, z), c));
    material.clipIntersection = config.clip.intersection ?? false;
  }
  if (config.outline !== undefined) hull = createOutline(object, { thickness: config.outline, color: 0 });
  scene.updateMatrixWorld();
  return {
    scene,
    object,
    geometry,
    material,
    light,
    threeLights,
    instances,
    tints,
    hull,
    dispose: () => {
      material.dispose();
      (hull?.material as ShaderMaterial | undefined)?.dispose();
    },
  };
}

/** The renderer for `config`, set up as it asks (restored by the returned function). */
function sceneRenderer(config: SceneConfig, size: number): [WebGLRenderer, () => void] {
  let r = renderer;
  if (config.logarithmic) {
    logRenderer ??= new WebGLRenderer({
      canvas: document.createElement('canvas'),
      antialias: false,
      preserveDrawingBuffer: true,
      logarithmicDepthBuffer: true,
    });
    logRenderer.setPixelRatio(1);
    logRenderer.setClearColor(0x0000ff, 1);
    r = logRenderer;
  }
  r.setSize(size, size, false);
  if (config.toneMapping !== undefined) {
    r.toneMapping = ACESFilmicToneMapping;
    r.toneMappingExposure = config.toneMapping;
  }
  if (config.linearOutput) r.outputColorSpace = LinearSRGBColorSpace;
  r.localClippingEnabled = config.clip !== undefined && !config.clip.global;
  if (config.clip?.global)
    r.clippingPlanes = config.clip.planes.map(([x, y, z, c]) => new Plane(new Vector3(x, y, z), c));
  return [
    r,
    () => {
      r.toneMapping = NoToneMapping;
      r.toneMappingExposure = 1;
      r.outputColorSpace = SRGBColorSpace;
      r.localClippingEnabled = false;
      r.clippingPlanes = [];
    },
  ];
}

function readPixels(r: WebGLRenderer, scene: Scene, camera: Camera, size: number): Uint8Array {
  r.render(scene, camera);
  return readCanvas(r, size);
}

/** three's sRGB transfer (linearToOutputTexel), not clamped above (three's fog mixes before the write clamps). */
const srgb = (x: number) => (x <= 0.0031308 ? Math.max(x, 0) * 12.92 : 1.055 * x ** (1 / 2.4) - 0.055);

/** The deformed object-space position of `vertex` as three's CPU helpers compute it (morph targets, bones). */
function objectPosition(object: Mesh, geometry: BufferGeometry, vertex: number, target: Vector3): Vector3 {
  if ((object as SkinnedMesh).isSkinnedMesh || geometry.morphAttributes.position !== undefined)
    return object.getVertexPosition(vertex, target);
  return target.fromBufferAttribute(geometry.getAttribute('position'), vertex);
}

/** The object-space normal of `vertex` as the vertex stage computes it (attribute or position, morphs, skin). */
function objectNormal(
  object: Mesh,
  geometry: BufferGeometry,
  analytic: boolean,
  vertex: number,
  target: Vector3,
): Vector3 {
  if (analytic) target.fromBufferAttribute(geometry.getAttribute('position'), vertex);
  else target.fromBufferAttribute(geometry.getAttribute('normal'), vertex);
  // A direction (w = 0), normalised by shade().
  return deformNormal(object, geometry, vertex, target, !analytic);
}

/**
 * Render `config` with ShadingMaterial and with three's MeshPhongMaterial (the oracle of where and whether
 * something is drawn: same objects, instances, bones, morphs, fog, clipping, depth buffer), compare the
 * coverage away from the oracle's edges, and compare every interior pixel with shade() on the CPU (three's
 * CPU deformation: Mesh.getVertexPosition with morph targets and bones; instance matrices; fog in the output
 * colour space) or, for `constant`, with the oracle's colour (its emissive is ka·Ia).
 */
function sceneCompare(config: SceneConfig): SceneStats {
  const size = config.size ?? 192;
  const setup = buildScene(config);
  const { scene, object, geometry, material, light, threeLights, instances, tints, hull } = setup;
  const camera = makeCamera(false);
  const [r, restore] = sceneRenderer(config, size);
  const ours = readPixels(r, scene, camera, size);
  const defines = { ...material.defines };
  // The oracle: three's own material on the same objects.
  const oracle = new MeshPhongMaterial(
    config.constant
      ? { color: 0x000000, specular: 0x000000, emissive: new Color().copy(material.ka), shininess: 0 }
      : { color: new Color().copy(material.kd) },
  );
  oracle.clippingPlanes = material.clippingPlanes;
  oracle.clipIntersection = material.clipIntersection;
  oracle.toneMapped = material.toneMapped;
  oracle.flatShading = config.shading === 'flat';
  if (config.surface) {
    applySurface(oracle, config.surface);
    // The same textures (the oracle's only decide where and how opaque it draws).
    const ours = material as ShadingMaterial;
    oracle.map = ours.map;
    oracle.alphaMap = ours.alphaMap;
    oracle.emissiveMap = ours.emissiveMap;
    oracle.normalMap = ours.normalMap;
  }
  object.material = oracle;
  // The impostor's oracle is a fine sphere mesh (level 7) with the same transform.
  if (config.object === 'impostor') object.geometry = sphereGeometry(7, true);
  let oracleHull: MeshBasicMaterial | null = null;
  if (hull !== null) {
    // The hull of a unit sphere with normals = positions is the sphere scaled by 1 + thickness.
    oracleHull = new MeshBasicMaterial({ color: 0x000000, side: BackSide });
    oracleHull.clippingPlanes = material.clippingPlanes;
    oracleHull.clipIntersection = material.clipIntersection;
    hull.material = oracleHull;
    hull.scale.setScalar(1 + (config.outline ?? 0));
    hull.updateMatrixWorld();
  }
  const theirs = readPixels(r, scene, camera, size);
  restore();
  oracle.dispose();
  oracleHull?.dispose();
  const isClear = (p: Uint8Array, i: number) => hasRgb(p, 4 * i, CLEAR);
  const stats: SceneStats = {
    covered: 0,
    oracleCovered: 0,
    coverageCompared: 0,
    coverageMismatches: 0,
    oracleCompared: 0,
    oracleMaxError: 0,
    compared: 0,
    maxError: 0,
    mismatches: 0,
    darkPixels: 0,
    litCompared: 0,
    litMismatches: 0,
    black: 0,
    clippedBlack: 0,
    worst: null,
    defines,
  };
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const i = y * size + x;
      const a = !isClear(ours, i);
      const b = !isClear(theirs, i);
      if (a) stats.covered++;
      if (b) stats.oracleCovered++;
      if (a && Math.max(ours[4 * i], ours[4 * i + 1], ours[4 * i + 2]) < 24) {
        if (hull === null) stats.darkPixels++;
      }
      let uniform = x > 0 && y > 0 && x < size - 1 && y < size - 1;
      for (let dy = -1; uniform && dy <= 1; dy++)
        for (let dx = -1; uniform && dx <= 1; dx++)
          if (!isClear(theirs, i + dy * size + dx) !== b) uniform = false;
      if (!uniform) continue;
      if (a && b) {
        const lit = (p: Uint8Array, j: number) => p[4 * j] + p[4 * j + 1] + p[4 * j + 2] > 0;
        let same = true;
        for (let dy = -1; same && dy <= 1; dy++)
          for (let dx = -1; same && dx <= 1; dx++)
            if (isClear(theirs, i + dy * size + dx) || lit(theirs, i + dy * size + dx) !== lit(theirs, i))
              same = false;
        if (same) {
          stats.litCompared++;
          // Lit where the oracle is lit; black where it is black, up to 3/255 (three's Phong divides the diffuse
          // term by π, so the last faint pixels of a penumbra or terminator round to 0 there first).
          const bright = Math.max(ours[4 * i], ours[4 * i + 1], ours[4 * i + 2]) > 3;
          if (lit(theirs, i) ? !lit(ours, i) : bright) stats.litMismatches++;
        }
      }
      stats.coverageCompared++;
      if (a !== b) stats.coverageMismatches++;
      if (config.constant && a && b) {
        stats.oracleCompared++;
        const err = maxRgbDelta(ours, theirs, 4 * i);
        stats.oracleMaxError = Math.max(stats.oracleMaxError, err);
      }
    }
  }
  // Outline pixels on the clipped side (where every plane, or with clipIntersection some plane, clips).
  const planes = (config.clip?.planes ?? []).map(([px, py, pz, c]) => new Plane(new Vector3(px, py, pz), c));
  const clipped = (p: Vector3): boolean => {
    if (planes.length === 0) return false;
    const out = planes.map((plane) => plane.distanceToPoint(p) < 0);
    return config.clip?.intersection ? out.every(Boolean) : out.some(Boolean);
  };
  if (config.constant) {
    setup.dispose();
    return stats;
  }
  // The world-space soup of every instance: corners, their normals, each face's centroid, normal and tint.
  const index = geometry.index;
  const corners = index === null ? geometry.getAttribute('position').count : index.count;
  const triangles = (corners / 3) * instances.length;
  const world = new Float64Array(9 * triangles);
  const normals = new Float64Array(9 * triangles);
  const centroids = new Float64Array(3 * triangles);
  const faceNormals = new Float64Array(3 * triangles);
  const faceTint = new Float64Array(3 * triangles);
  // Per corner: uv and vertex colour (RGBA, alpha 1 for RGB), for the surface.
  const cornerUv = new Float64Array(6 * triangles);
  const cornerColor = new Float64Array(12 * triangles).fill(1);
  const uvAttribute = geometry.getAttribute('uv');
  const colorAttribute = config.surface?.vertexColors ? geometry.getAttribute('color') : undefined;
  const analytic = geometry.getAttribute('normal') === undefined;
  const p = [new Vector3(), new Vector3(), new Vector3()];
  const n = new Vector3();
  const e1 = new Vector3();
  const e2 = new Vector3();
  const nm = new Matrix3();
  const model = new Matrix4();
  let t = 0;
  for (let k = 0; k < instances.length; k++) {
    model.multiplyMatrices(object.matrixWorld, instances[k]);
    computeNormalMatrix(model, nm);
    for (let c = 0; c < corners; c += 3, t++) {
      for (let j = 0; j < 3; j++) {
        const vertex = index === null ? c + j : index.getX(c + j);
        objectPosition(object, geometry, vertex, p[j]);
        const w = p[j].clone().applyMatrix4(model);
        world.set([w.x, w.y, w.z], 9 * t + 3 * j);
        if (uvAttribute !== undefined)
          cornerUv.set([uvAttribute.getX(vertex), uvAttribute.getY(vertex)], 6 * t + 2 * j);
        if (colorAttribute !== undefined)
          for (let k = 0; k < colorAttribute.itemSize; k++)
            cornerColor[12 * t + 4 * j + k] = colorAttribute.getComponent(vertex, k);
        if (config.shading !== 'flat') {
          objectNormal(object, geometry, analytic, vertex, n).applyMatrix3(nm);
          const l = n.length();
          if (l > 0) n.divideScalar(l);
          normals.set([n.x, n.y, n.z], 9 * t + 3 * j);
        }
      }
      const centroid = p[0].clone().add(p[1]).add(p[2]).divideScalar(3).applyMatrix4(model);
      centroids.set([centroid.x, centroid.y, centroid.z], 3 * t);
      e1.subVectors(p[1], p[0]);
      e2.subVectors(p[2], p[0]);
      const face = e1.cross(e2).applyMatrix3(nm);
      faceNormals.set([face.x, face.y, face.z], 3 * t);
      faceTint.set(tints[k], 3 * t);
    }
  }
  // Flat shading of a plain indexed geometry: lit per fragment with the face normal (screen-space derivatives).
  const derivatives = config.shading === 'flat' && index !== null && !config.flatCorners;
  const hits = pixelHits(
    world,
    camera,
    size,
    object.matrixWorld.determinant() < 0,
    config.surface?.side ?? 'front',
  );
  const edgeDistance = screenEdgeDistance(world, camera, size);
  const e = eyeOf(camera, new Vector4());
  const eye = [e.x, e.y, e.z, e.w];
  const base: ShadeMaterial = {
    ka: material.ka.toArray(),
    kd: material.kd.toArray(),
    ks: material.ks.toArray(),
    shininess: material.shininess,
    lighting: material.lighting,
  };
  let m = base;
  const surface = config.surface;
  const surfaceMaterial = material as ShadingMaterial;
  const emissive = surface?.emissive ?? [0, 0, 0];
  const pixelTint = [1, 1, 1];
  // A normal map, as three's normal_fragment_maps: tangent space through getTangentFrame, which on a planar
  // triangle whose normal is its face normal is exactly (∇u, ∇v) / max(|∇u|, |∇v|) (the uv gradients in the
  // triangle's plane); object space through the normal matrix.
  const objectNormalMatrix = computeNormalMatrix(object.matrixWorld, new Matrix3());
  const perturb = (n: number[], tri: number, texel: number[], s: SceneSurface): void => {
    const map = [texel[0] * 2 - 1, texel[1] * 2 - 1, texel[2] * 2 - 1];
    if (s.normalMap === 'object') {
      const w = new Vector3(...map).applyMatrix3(objectNormalMatrix);
      n.splice(0, 3, w.x, w.y, w.z);
      return;
    }
    const [sx, sy] = s.normalScale ?? [1, 1];
    const p0 = new Vector3().fromArray(world, 9 * tri);
    const e1 = new Vector3().fromArray(world, 9 * tri + 3).sub(p0);
    const e2 = new Vector3().fromArray(world, 9 * tri + 6).sub(p0);
    const f = new Vector3().crossVectors(e1, e2);
    const gradient = (c: number) => {
      const d1 = cornerUv[6 * tri + 2 + c] - cornerUv[6 * tri + c];
      const d2 = cornerUv[6 * tri + 4 + c] - cornerUv[6 * tri + c];
      return new Vector3()
        .crossVectors(e2, f)
        .multiplyScalar(d1)
        .add(new Vector3().crossVectors(f, e1).multiplyScalar(d2))
        .divideScalar(f.lengthSq());
    };
    const gu = gradient(0);
    const gv = gradient(1);
    const scale = 1 / Math.max(gu.length(), gv.length());
    const nn = new Vector3(n[0], n[1], n[2]).normalize();
    const out = gu
      .multiplyScalar(scale * sx * map[0])
      .add(gv.multiplyScalar(scale * sy * map[1]))
      .add(nn.multiplyScalar(map[2]));
    n.splice(0, 3, out.x, out.y, out.z);
  };
  const lights: Array<ShadeLight | ShadeThreeLight> = threeLights.map(shadeThreeLight);
  if (config.phongLight !== false)
    lights.push({
      position: light.getWorldPosition(new Vector3()).toArray(),
      ambient: light.ambient.toArray(),
      diffuse: light.diffuse.toArray(),
      specular: light.specular.toArray(),
    });
  const fogColor = new Color(0x8080c0);
  const fogOut = config.linearOutput ? fogColor.toArray() : fogColor.toArray().map(srgb);
  const view = camera.matrixWorldInverse;
  const linear: [number, number, number] = [0, 0, 0];
  const corner: [number, number, number] = [0, 0, 0];
  const normal = [0, 0, 0];
  const hit = new Vector3();
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const i = y * size + x;
      const tri = hits.triangle[i];
      if (tri < 0) continue;
      // Away from silhouettes and clipped surfaces: all 8 neighbours hit an unclipped surface too.
      let interior = x > 0 && y > 0 && x < size - 1 && y < size - 1;
      for (let dy = -1; interior && dy <= 1; dy++)
        for (let dx = -1; interior && dx <= 1; dx++) {
          const j = i + dy * size + dx;
          if (hits.triangle[j] < 0 || clipped(hit.fromArray(hits.point, 3 * j))) interior = false;
        }
      if (!interior) continue;
      const [b0, b1, b2] = hits.bary.subarray(3 * i, 3 * i + 3);
      const position = hits.point.subarray(3 * i, 3 * i + 3);
      let tint: ArrayLike<number> = faceTint.subarray(3 * tri, 3 * tri + 3);
      // The surface: texel × vertex colour multiplies ka and kd (the vertex's own colour with vertex lighting),
      // emissive × its texel is added, alpha = opacity × texel alpha × vertex alpha × alphaMap.g.
      let alpha = 1;
      let normalTexel: number[] | null = null;
      let vertexTint: (j: number) => ArrayLike<number> = () => tint;
      if (surface !== undefined) {
        const u = b0 * cornerUv[6 * tri] + b1 * cornerUv[6 * tri + 2] + b2 * cornerUv[6 * tri + 4];
        const v = b0 * cornerUv[6 * tri + 1] + b1 * cornerUv[6 * tri + 3] + b2 * cornerUv[6 * tri + 5];
        const texel = surfaceMaterial.map ? texelAt(surfaceMaterial.map as DataTexture, u, v) : [1, 1, 1, 1];
        const glow = surfaceMaterial.emissiveMap
          ? texelAt(surfaceMaterial.emissiveMap as DataTexture, u, v)
          : [1, 1, 1, 1];
        const mask = surfaceMaterial.alphaMap
          ? texelAt(surfaceMaterial.alphaMap as DataTexture, u, v)
          : [1, 1, 1, 1];
        const bump = surfaceMaterial.normalMap
          ? texelAt(surfaceMaterial.normalMap as DataTexture, u, v)
          : [0.5, 0.5, 1, 1];
        if (texel === null || glow === null || mask === null || bump === null) continue; // a texel edge
        normalTexel = bump;
        const c = (j: number, k: number) => cornerColor[12 * tri + 4 * j + k];
        const interpolated = [0, 1, 2, 3].map((k) => b0 * c(0, k) + b1 * c(1, k) + b2 * c(2, k));
        alpha = (surface.opacity ?? 1) * texel[3] * interpolated[3] * mask[1];
        if (surface.alphaTest !== undefined && Math.abs(alpha - surface.alphaTest) < 0.02) continue;
        const faceTintRgb = Array.from(tint);
        vertexTint = (j) => [0, 1, 2].map((k) => faceTintRgb[k] * c(j, k) * texel[k]);
        for (let k = 0; k < 3; k++) pixelTint[k] = faceTintRgb[k] * interpolated[k] * texel[k];
        tint = config.shading === 'flat' && !derivatives ? vertexTint(2) : pixelTint;
        m = { ...base, emissive: emissive.map((e, k) => e * glow[k]) };
        if (surface.alphaTest !== undefined && alpha < surface.alphaTest) {
          // Discarded: the clear colour, as the oracle's hole.
          stats.compared++;
          const err = Math.max(ours[4 * i], ours[4 * i + 1], Math.abs(ours[4 * i + 2] - 255));
          stats.maxError = Math.max(stats.maxError, err);
          if (err > 2) stats.mismatches++;
          continue;
        }
      }
      // A back face (its outward face normal turned away from the eye; drawn with `surface.side`) is lit with
      // the flipped normal, in every shading.
      const outward = faceNormals.subarray(3 * tri, 3 * tri + 3);
      let facing = 0;
      for (let k = 0; k < 3; k++) facing += outward[k] * (eye[k] - position[k] * eye[3]);
      const flip = surface?.side !== undefined && facing < 0 ? -1 : 1;
      const faceNormal = Array.from(outward, (c) => flip * c);
      if (config.shading === 'phong') {
        for (let k = 0; k < 3; k++)
          normal[k] =
            b0 * normals[9 * tri + k] + b1 * normals[9 * tri + 3 + k] + b2 * normals[9 * tri + 6 + k];
        if (normalTexel !== null && surface?.normalMap && !surface.unperturbed)
          perturb(normal, tri, normalTexel, surface);
        for (let k = 0; k < 3; k++) normal[k] *= flip;
        shade({ position, normal, eye, tint }, m, lights, linear);
      } else if (config.shading === 'gouraud') {
        linear.fill(0);
        for (let j = 0; j < 3; j++) {
          shade(
            {
              position: world.subarray(9 * tri + 3 * j, 9 * tri + 3 * j + 3),
              normal: Array.from(normals.subarray(9 * tri + 3 * j, 9 * tri + 3 * j + 3), (c) => flip * c),
              eye,
              tint: vertexTint(j),
            },
            m,
            lights,
            corner,
          );
          const bj = j === 0 ? b0 : j === 1 ? b1 : b2;
          for (let k = 0; k < 3; k++) linear[k] += bj * corner[k];
        }
      } else if (derivatives) {
        if (edgeDistance(tri, x + 0.5, y + 0.5) < 0.5) continue;
        shade({ position, normal: faceNormal, eye, tint }, m, lights, linear);
      } else {
        if (edgeDistance(tri, x + 0.5, y + 0.5) < 0.1) continue;
        shade(
          {
            position: centroids.subarray(3 * tri, 3 * tri + 3),
            normal: faceNormal,
            eye,
            tint,
          },
          m,
          lights,
          linear,
        );
      }
      // Output: the colour space's transfer, then three's fog blend (in the output space), then the 8-bit write.
      const depth = -hit.fromArray(position).applyMatrix4(view).z;
      const f = config.fog ? fogFactor(config.fog, depth) : 0;
      if (
        config.fog &&
        'near' in config.fog &&
        Math.abs(depth - config.fog.near) < 0.02 &&
        !(config.fog.far > config.fog.near)
      )
        continue; // a step fog: either side at its depth
      let err = 0;
      const expected = [0, 0, 0];
      const blend = surface?.transparent ? alpha : 1;
      for (let k = 0; k < 3; k++) {
        const out = config.linearOutput ? Math.max(linear[k], 0) : srgb(linear[k]);
        // Transparent: three's normal blending over the clear colour (0, 0, 1), in the output space.
        const source = Math.min(Math.max(out + (fogOut[k] - out) * f, 0), 1);
        const mixed = source * blend + (k === 2 ? 1 - blend : 0);
        expected[k] = Math.round(Math.min(Math.max(mixed, 0), 1) * 255);
        err = Math.max(err, Math.abs(expected[k] - ours[4 * i + k]));
      }
      stats.compared++;
      if (err > stats.maxError) {
        stats.maxError = err;
        stats.worst = {
          x,
          y,
          gpu: [ours[4 * i], ours[4 * i + 1], ours[4 * i + 2]],
          cpu: expected,
          triangle: tri,
        };
      }
      if (err > 2) stats.mismatches++;
    }
  }
  if (hull !== null) {
    // Pure black (the outline's colour) where the planes clip the world point under the pixel's ray at the
    // sphere's depth plane z = 0 … the ring lies at |p| ≈ 1 + thickness: test the ray's point nearest the origin.
    const ray = new Raycaster();
    const ndc = new Vector2();
    for (let y = 0; y < size; y++) {
      for (let x = 0; x < size; x++) {
        const i = y * size + x;
        if (!(ours[4 * i] === 0 && ours[4 * i + 1] === 0 && ours[4 * i + 2] === 0)) continue;
        stats.black++;
        ndc.set(((x + 0.5) / size) * 2 - 1, ((y + 0.5) / size) * 2 - 1);
        ray.setFromCamera(ndc, camera);
        ray.ray.closestPointToPoint(new Vector3(), hit);
        if (clipped(hit)) stats.clippedBlack++;
      }
    }
  }
  setup.dispose();
  return stats;
}

/**
 * Turn three's scene features on and off `flips` times at random (fixed seed), rendering after each flip, with
 * one ShadingMaterial: the object (a Mesh, InstancedMesh, BatchedMesh, SkinnedMesh or morphed Mesh), fog,
 * clipping and tone mapping; report the live program count.
 */
function flipFeatures(flips: number): { before: number; after: number; max: number; variants: number } {
  const size = 32;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const material = new ShadingMaterial({ lights: [light] });
  const geometry = sphereGeometry(2, true);
  const mesh = new Mesh(geometry, material);
  const instanced = new InstancedMesh(geometry, material, 2);
  instanced.setMatrixAt(1, new Matrix4().makeTranslation(1, 0, 0));
  const batched = new BatchedMesh(1, geometry.getAttribute('position').count, 0, material);
  batched.addInstance(batched.addGeometry(geometry));
  const skinned = new SkinnedMesh(skinnedCylinder(0.5, 16, 12), material);
  const bone = new Bone();
  skinned.add(bone);
  skinned.bind(new Skeleton([bone, new Bone()]));
  const morphed = new Mesh(morphedSphere(2), material);
  morphed.morphTargetInfluences = [0.5];
  const objects = [mesh, instanced, batched, skinned, morphed];
  const scene = new Scene();
  scene.add(light, ...objects);
  const fog = new Fog(0x8080c0, 1, 5);
  const plane = [new Plane(new Vector3(1, 0, 0), 0)];
  renderer.localClippingEnabled = true;
  const camera = makeCamera(false);
  const show = (k: number) =>
    objects.forEach((o, i) => {
      o.visible = i === k;
    });
  show(0);
  renderer.render(scene, camera);
  const before = renderer.info.programs?.length ?? 0;
  let max = before;
  const variants = new Set<string>();
  let seed = 20261123;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  for (let i = 0; i < flips; i++) {
    const k = Math.floor(random() * objects.length);
    show(k);
    scene.fog = random() < 0.5 ? fog : null;
    material.clippingPlanes = random() < 0.5 ? plane : [];
    renderer.toneMapping = random() < 0.5 ? ACESFilmicToneMapping : NoToneMapping;
    renderer.render(scene, camera);
    variants.add(`${k} ${scene.fog !== null} ${material.clippingPlanes.length} ${renderer.toneMapping}`);
    max = Math.max(max, renderer.info.programs?.length ?? 0);
  }
  const after = renderer.info.programs?.length ?? 0;
  renderer.toneMapping = NoToneMapping;
  renderer.localClippingEnabled = false;
  material.dispose();
  return { before, after, max, variants: variants.size };
}

/**
 * A colour edited in place (as React Three Fiber writes `kd={[NaN, -1, 0]}` into the Color): `frames` frames
 * good, `frames` with a bad kd, `frames` fixed, `frames` with a bad PhongLight colour, `frames` fixed again.
 * Returns the centre pixel after each phase (the console errors are counted by the test).
 */
function inPlaceEdits(frames: number): number[][] {
  const size = 32;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const material = new ShadingMaterial({ lights: [light] });
  const scene = new Scene();
  scene.add(light, new Mesh(sphereGeometry(2, true), material));
  const camera = makeCamera(false);
  const centre: number[][] = [];
  const run = (edit: () => void) => {
    edit();
    let pixels: Uint8Array = new Uint8Array(0);
    for (let i = 0; i < frames; i++) pixels = readPixels(renderer, scene, camera, size);
    const j = 4 * ((size / 2) * size + size / 2);
    centre.push(Array.from(pixels.slice(j, j + 3)));
  };
  run(() => {});
  run(() => material.kd.setRGB(Number.NaN, -1, 0));
  run(() => material.kd.setRGB(0.6, 0.35, 0.2));
  run(() => {
    light.specular.b = Number.POSITIVE_INFINITY;
  });
  run(() => {
    light.specular.b = 0.8;
  });
  material.dispose();
  return centre;
}

const SHADING_LIST = ['flat', 'gouraud', 'phong'] as const;

/**
 * 0, 1 and 64 of each of three's light kinds (intensity 1/count, around the sphere) lighting a ShadingMaterial in
 * each shading, then the same flipped at random 200 times: the live program count and every render's centre pixel.
 */
function threeLightExtremes(): { swept: number; programs: number; variants: number; centres: number[][] } {
  const size = 16;
  renderer.setSize(size, size, false);
  const kinds = ['ambient', 'hemisphere', 'directional', 'point', 'spot'] as const;
  const camera = makeCamera(false);
  const centres: number[][] = [];
  const variants = new Set<string>();
  const j = 4 * ((size / 2) * size + size / 2);
  const materials = SHADING_LIST.map((shading) => new ShadingMaterial({ shading }));
  const geometries = { flat: sphereGeometry(2, false), smooth: sphereGeometry(2, true) };
  const render = (kind: (typeof kinds)[number], count: number, shading: number) => {
    const scene = new Scene();
    const material = materials[shading];
    scene.add(new Mesh(SHADING_LIST[shading] === 'flat' ? geometries.flat : geometries.smooth, material));
    for (let i = 0; i < count; i++) {
      const a = (2 * Math.PI * i) / count;
      threeLight(
        {
          type: kind,
          color: [1, 0.8, 0.6],
          intensity: 1 / count,
          position: [3 * Math.cos(a), 2, 3 + Math.sin(a)],
          angle: 0.6,
          penumbra: 0.5,
          distance: 20,
        },
        scene,
      );
    }
    scene.updateMatrixWorld();
    const pixels = readPixels(renderer, scene, camera, size);
    centres.push(Array.from(pixels.slice(j, j + 3)));
    variants.add(`${kind} ${count} ${shading}`);
  };
  for (const kind of kinds)
    for (const count of [0, 1, 64]) for (let k = 0; k < 3; k++) render(kind, count, k);
  const swept = renderer.info.programs?.length ?? 0;
  let seed = 14;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  for (let i = 0; i < 200; i++)
    render(kinds[Math.floor(random() * 5)], [0, 1, 64][Math.floor(random() * 3)], Math.floor(random() * 3));
  const programs = renderer.info.programs?.length ?? 0;
  for (const m of materials) m.dispose();
  return { swept, programs, variants: variants.size, centres };
}

/**
 * A 4 × 4 plane turned away from the camera (its back face visible), optionally mirrored (scale.x = −1), with
 * `side` DoubleSide or BackSide, lit by a far PhongLight on the camera's side: every pixel against shade() with
 * the normal the lecture's rule gives (the world normal flipped towards the viewer).
 */
function sideCompare(config: {
  side: 'double' | 'back';
  mirrored: boolean;
  shading: Shading;
  /** Flat shading of the indexed plane (derivative normals) instead of its soup. */
  indexed?: boolean;
}): {
  compared: number;
  maxError: number;
  centre: number[];
  expected: number[];
} {
  const size = 64;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(3000, 4000, 10000);
  const material = new ShadingMaterial({ shading: config.shading, ka: 0.2, ks: 0, lights: [light] });
  material.side = config.side === 'double' ? DoubleSide : BackSide;
  const plane = new PlaneGeometry(4, 4, 8, 8);
  const mesh = new Mesh(
    config.shading === 'flat' && !config.indexed ? plane.toNonIndexed() : plane,
    material,
  );
  mesh.rotation.y = Math.PI; // its front face looks down −z, away from the camera
  if (config.mirrored) mesh.scale.x = -1;
  const scene = new Scene();
  scene.add(mesh, light);
  scene.updateMatrixWorld();
  const camera = makeCamera(false);
  const pixels = readPixels(renderer, scene, camera, size);
  const nm = computeNormalMatrix(mesh.matrixWorld, new Matrix3());
  const e = eyeOf(camera, new Vector4());
  const ray = new Raycaster();
  const hit = new Vector3();
  const m: ShadeMaterial = {
    ka: material.ka.toArray(),
    kd: material.kd.toArray(),
    ks: [0, 0, 0],
    shininess: 32,
  };
  const lights: ShadeLight[] = [
    {
      position: light.position.toArray(),
      ambient: light.ambient.toArray(),
      diffuse: light.diffuse.toArray(),
      specular: light.specular.toArray(),
    },
  ];
  let compared = 0;
  let maxError = 0;
  let centre: number[] = [];
  let expectedCentre: number[] = [];
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      ray.setFromCamera(new Vector2(((x + 0.5) / size) * 2 - 1, ((y + 0.5) / size) * 2 - 1), camera);
      ray.ray.intersectPlane(new Plane(new Vector3(0, 0, 1), 0), hit);
      if (Math.abs(hit.x) > 1.9 || Math.abs(hit.y) > 1.9) continue;
      const n = new Vector3(0, 0, 1).applyMatrix3(nm).normalize();
      if (n.dot(new Vector3(e.x, e.y, e.z).sub(hit)) < 0) n.negate(); // the visible side's normal
      const linear = shade(
        { position: hit.toArray(), normal: n.toArray(), eye: [e.x, e.y, e.z, e.w] },
        m,
        lights,
      );
      const i = 4 * (y * size + x);
      const expected = linear.map((c) => Math.round(Math.min(srgb(c), 1) * 255));
      const err = Math.max(...expected.map((c, k) => Math.abs(c - pixels[i + k])));
      compared++;
      maxError = Math.max(maxError, err);
      if (x === size / 2 && y === size / 2) {
        centre = Array.from(pixels.slice(i, i + 3));
        expectedCentre = expected;
      }
    }
  }
  material.dispose();
  return { compared, maxError, centre, expected: expectedCentre };
}

/**
 * Each surface feature (normalMap, map, vertexColors, emissive, emissiveMap, transparent, alphaTest, alphaMap, and flat
 * shading of a plain indexed geometry) flipped on and off `flips` times at random (fixed seed), the others off,
 * rendering after each flip, with one ShadingMaterial: the live program count.
 */
function flipSurface(flips: number): { before: number; after: number; max: number; variants: number } {
  const size = 16;
  renderer.setSize(size, size, false);
  const light = new PhongLight();
  light.position.set(-5, 10, 20);
  const material = new ShadingMaterial({ lights: [light] });
  const indexed: BufferGeometry = new SphereGeometry(1, 12, 8);
  setVertexColors(indexed, false);
  const soup = indexed.toNonIndexed();
  const mesh = new Mesh(indexed, material);
  const scene = new Scene();
  scene.add(light, mesh);
  const camera = makeCamera(false);
  const map = surfaceTexture(1, false, true);
  const glow = surfaceTexture(2, false, true);
  const mask = surfaceTexture(3, false, false);
  const bumps = normalTexture();
  const features: Array<(on: boolean) => void> = [
    (on) => {
      material.normalMap = on ? bumps : null;
    },
    (on) => {
      material.map = on ? map : null;
    },
    (on) => {
      material.vertexColors = on;
    },
    (on) => {
      material.emissive = on ? [0.1, 0, 0] : 0;
    },
    (on) => {
      material.emissiveMap = on ? glow : null;
    },
    (on) => {
      material.transparent = on;
    },
    (on) => {
      material.alphaTest = on ? 0.5 : 0;
    },
    (on) => {
      material.alphaMap = on ? mask : null;
    },
    (on) => {
      material.shading = 'flat';
      mesh.geometry = on ? indexed : soup;
    },
  ];
  const reset = () => {
    for (const f of features) f(false);
    material.shading = 'phong';
    mesh.geometry = indexed;
  };
  reset();
  renderer.render(scene, camera);
  const before = renderer.info.programs?.length ?? 0;
  let max = before;
  const variants = new Set<string>(['none']);
  let seed = 1414;
  const random = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  features.forEach((flip, k) => {
    for (let i = 0; i < flips; i++) {
      reset();
      const on = random() < 0.5;
      flip(on);
      renderer.render(scene, camera);
      variants.add(on ? `${k}` : k === features.length - 1 ? 'flat soup' : 'none');
      max = Math.max(max, renderer.info.programs?.length ?? 0);
    }
  });
  reset();
  const after = renderer.info.programs?.length ?? 0;
  material.dispose();
  return { before, after, max, variants: variants.size };
}

const api = {
  flipSurface,
  sideCompare,
  threeLightExtremes,
  inPlaceEdits,
  compare,
  flipPrograms,
  sharedMaterial,
  outline,
  programSources,
  sceneCompare,
  flipFeatures,
};
declare global {
  interface Window {
    materialHarness: typeof api;
  }
}
window.materialHarness = api;
document.body.dataset.ready = '1';
