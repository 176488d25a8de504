// Harness for tests/material.spec.ts: renders the lecture's scene with ShadingMaterial and compares every
// pixel with shade() evaluated on the CPU for the same fragment. The CPU finds each pixel's triangle and
// barycentrics with three's Raycaster (ray through the pixel centre, nearest hit), using a screen-tile
// binning of the triangles so that each ray tests only the few triangles whose screen box covers it.
import {
  computeNormalMatrix,
  eyeOf,
  type Lighting,
  linearToSrgb8,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  type Shading,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline } from '@shadelab/material/outline';
import {
  type Camera,
  Matrix3,
  Mesh,
  type Object3D,
  OrthographicCamera,
  PerspectiveCamera,
  Raycaster,
  Scene,
  type ShaderMaterial,
  Triangle,
  Vector2,
  Vector3,
  Vector4,
  WebGLRenderer,
} from 'three';
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

function makeCamera(orthographic: boolean): Camera {
  const camera = orthographic
    ? new OrthographicCamera(-3, 3, 3, -3, 0.1, 10)
    : new PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

interface Hits {
  triangle: Int32Array; // per pixel, −1 = miss
  bary: Float32Array; // 3 per pixel
  point: Float64Array; // 3 per pixel, world
}

/** Per-pixel nearest triangle and barycentrics with three's Raycaster; candidates from screen tiles. */
function raycastPixels(world: Float64Array, camera: Camera, size: number, mirrored: boolean): Hits {
  const triangles = world.length / 9;
  const tile = 8;
  const tiles = Math.ceil(size / tile);
  const bins: number[][] = Array.from({ length: tiles * tiles }, () => []);
  const v = new Vector3();
  const px = new Float64Array(6);
  for (let t = 0; t < triangles; t++) {
    let minX = Number.POSITIVE_INFINITY;
    let minY = Number.POSITIVE_INFINITY;
    let maxX = Number.NEGATIVE_INFINITY;
    let maxY = Number.NEGATIVE_INFINITY;
    for (let k = 0; k < 3; k++) {
      v.set(world[9 * t + 3 * k], world[9 * t + 3 * k + 1], world[9 * t + 3 * k + 2]).project(camera);
      px[2 * k] = ((v.x + 1) / 2) * size;
      px[2 * k + 1] = ((v.y + 1) / 2) * size;
      minX = Math.min(minX, px[2 * k]);
      maxX = Math.max(maxX, px[2 * k]);
      minY = Math.min(minY, px[2 * k + 1]);
      maxY = Math.max(maxY, px[2 * k + 1]);
    }
    if (!Number.isFinite(minX + maxX + minY + maxY)) continue;
    const x0 = Math.max(0, Math.floor((minX - 1) / tile));
    const x1 = Math.min(tiles - 1, Math.floor((maxX + 1) / tile));
    const y0 = Math.max(0, Math.floor((minY - 1) / tile));
    const y1 = Math.min(tiles - 1, Math.floor((maxY + 1) / tile));
    for (let ty = y0; ty <= y1; ty++) for (let tx = x0; tx <= x1; tx++) bins[ty * tiles + tx].push(t);
  }
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  const a = new Vector3();
  const b = new Vector3();
  const c = new Vector3();
  const hit = new Vector3();
  const best = new Vector3();
  const bc = new Vector3();
  const triangle = new Int32Array(size * size).fill(-1);
  const bary = new Float32Array(3 * size * size);
  const point = new Float64Array(3 * size * size);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const bin = bins[Math.floor(y / tile) * tiles + Math.floor(x / tile)];
      if (bin.length === 0) continue;
      ndc.set(((x + 0.5) / size) * 2 - 1, ((y + 0.5) / size) * 2 - 1);
      raycaster.setFromCamera(ndc, camera);
      let bestT = -1;
      let bestD = Number.POSITIVE_INFINITY;
      for (const t of bin) {
        a.fromArray(world, 9 * t);
        b.fromArray(world, 9 * t + 3);
        c.fromArray(world, 9 * t + 6);
        // Cull back faces as three does (its front face flips when the determinant is negative).
        const hitTriangle = mirrored
          ? raycaster.ray.intersectTriangle(a, c, b, true, hit)
          : raycaster.ray.intersectTriangle(a, b, c, true, hit);
        if (hitTriangle === null) continue;
        const dist = hit.distanceTo(raycaster.ray.origin);
        if (dist < bestD) {
          bestD = dist;
          bestT = t;
          best.copy(hit);
        }
      }
      if (bestT < 0) continue;
      const i = y * size + x;
      triangle[i] = bestT;
      a.fromArray(world, 9 * bestT);
      b.fromArray(world, 9 * bestT + 3);
      c.fromArray(world, 9 * bestT + 6);
      Triangle.getBarycoord(best, a, b, c, bc);
      bary[3 * i] = bc.x;
      bary[3 * i + 1] = bc.y;
      bary[3 * i + 2] = bc.z;
      point[3 * i] = best.x;
      point[3 * i + 1] = best.y;
      point[3 * i + 2] = best.z;
    }
  }
  return { triangle, bary, point };
}

const hitCache = new Map<string, Hits>();

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
  const gl = renderer.getContext();
  const pixels = new Uint8Array(4 * size * size);
  gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
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
  // Screen positions (pixels) of the vertices, for the flat shading edge margin.
  const screen = new Float64Array(2 * count);
  for (let i = 0; i < count; i++) {
    v.fromArray(world, 3 * i).project(camera);
    screen[2 * i] = ((v.x + 1) / 2) * size;
    screen[2 * i + 1] = ((v.y + 1) / 2) * size;
  }
  /** Distance in pixels from (x, y) to the nearest edge line of screen triangle t. */
  const edgeDistance = (t: number, x: number, y: number): number => {
    let d = Number.POSITIVE_INFINITY;
    for (let k = 0; k < 3; k++) {
      const i = 3 * t + k;
      const j = 3 * t + ((k + 1) % 3);
      const ex = screen[2 * j] - screen[2 * i];
      const ey = screen[2 * j + 1] - screen[2 * i + 1];
      const len = Math.hypot(ex, ey);
      if (!(len > 0)) return 0;
      d = Math.min(d, Math.abs((x - screen[2 * i]) * ey - (y - screen[2 * i + 1]) * ex) / len);
    }
    return d;
  };
  const key = `${config.level ?? 6}/${config.flatCorners ?? false}/${mesh.matrixWorld.elements.join(',')}/${config.orthographic ?? false}/${size}`;
  let hits = hitCache.get(key);
  if (hits === undefined) {
    hits = raycastPixels(world, camera, size, mesh.matrixWorld.determinant() < 0);
    hitCache.set(key, hits);
  }
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
  const bands = material.celBands;
  /**
   * Near a discontinuity of the lighting, where GPU (float32) and CPU (float64) may round to either side:
   * a cel band edge, the cel highlight edge, or the terminator (l·n = 0) when the specular jumps there
   * (shininess 0 or cel).
   */
  const atDiscontinuity = (position: ArrayLike<number>, normal: ArrayLike<number>): boolean => {
    if (bands === 0 && m.shininess !== 0) return false;
    const n = new Vector3().fromArray(normal).normalize();
    const l = new Vector3().fromArray(lightPosition).sub(new Vector3().fromArray(position)).normalize();
    const ndl = n.dot(l);
    if (Math.abs(ndl) < 0.01) return true;
    if (bands === 0) return false;
    const scaled = Math.max(ndl, 0) * bands;
    const edge = Math.round(scaled);
    if (Math.abs(scaled - edge) < 0.02 && edge > 0 && edge < bands) return true;
    const raw = shade(
      { position, normal, eye },
      { ...m, celBands: 0, ka: [0, 0, 0], kd: [0, 0, 0], ks: [1, 1, 1] },
      [{ ...lights[0], ambient: [0, 0, 0], specular: [1, 1, 1], attenuation: { a: 1, b: 0, c: 0 } }],
    );
    return Math.abs(raw[0] - 0.5) < 0.02;
  };
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
    const gl = renderer.getContext();
    const pixels = new Uint8Array(4 * size * size);
    gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
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
  const gl = renderer.getContext();
  const read = (): Uint8Array => {
    renderer.render(scene, camera);
    const pixels = new Uint8Array(4 * size * size);
    gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return pixels;
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
    const wasClear = before[i] === 0 && before[i + 1] === 0 && before[i + 2] === 255;
    const isClear = after[i] === 0 && after[i + 1] === 0 && after[i + 2] === 255;
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
    const draw = (name: string, mesh: Mesh, material: ShaderMaterial, extra: Object3D[] = []): void => {
      const scene = new Scene();
      scene.add(mesh, ...lights, attenuated, ...extra);
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
        draw(`${shading} lights ${count}`, new Mesh(geometry, material), material);
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

const api = { compare, flipPrograms, sharedMaterial, outline, programSources };
declare global {
  interface Window {
    materialHarness: typeof api;
  }
}
window.materialHarness = api;
document.body.dataset.ready = '1';
