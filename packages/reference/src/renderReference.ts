import { linearToSrgb8Channel, type ShadeLight, type ShadeMaterial, shade } from '@shadelab/material';
import { invert, type Mat4Like, multiply, normalMatrix, transform4 } from './mat4.js';

/** Options of {@link renderReference}. Matrices are 16 numbers, column-major (three's `Matrix4.elements`). */
export interface RenderReferenceOptions {
  /** Image width in pixels, an integer in 1 … 16384. */
  width: number;
  /** Image height in pixels, an integer in 1 … 16384. */
  height: number;
  /** The camera's projection matrix (`camera.projectionMatrix.elements`): perspective or orthographic. */
  projectionMatrix: Mat4Like;
  /** World → camera (`camera.matrixWorldInverse.elements`). */
  viewMatrix: Mat4Like;
  /** Model → world of the sphere (`mesh.matrixWorld.elements`); a scale makes it an ellipsoid. @default identity */
  modelMatrix?: Mat4Like;
  /** Radius of the sphere in model space, finite and > 0. @default 1 */
  radius?: number;
  /** The material, as `shade` takes it. */
  material: ShadeMaterial;
  /** The lights, as `shade` takes them (world positions). */
  lights: readonly ShadeLight[];
  /** Background colour, linear RGB. @default [0, 0, 0] */
  background?: ArrayLike<number>;
  /**
   * Silhouette supersampling: pixels within 1 px of the exact silhouette are covered by samples × samples
   * rays on a regular grid; an integer in 1 … 16. @default 4
   */
  samples?: number;
}

/** The exact image of a lit sphere (ellipsoid), as {@link renderReference} computes it. */
export interface ReferenceImage {
  /** Width in pixels. */
  readonly width: number;
  /** Height in pixels. */
  readonly height: number;
  /**
   * 8-bit sRGB RGBA, rows bottom-up (row 0 is the bottom row, like `gl.readPixels`), alpha 255. Interior
   * pixels are the colour at the pixel centre; silhouette pixels the supersampled blend with the background.
   */
  readonly rgba: Uint8ClampedArray;
  /** Linear RGB at the pixel centre (3 per pixel); the background where the centre ray misses. */
  readonly linear: Float32Array;
  /** Whether the ray through the pixel centre hits the visible (front) surface: 1 or 0. */
  readonly hit: Uint8Array;
  /** Fraction of the pixel covered by the sphere, from the silhouette supersampling (0 … 1). */
  readonly coverage: Float32Array;
  /**
   * Signed distance from the pixel centre to the exact silhouette, in pixels (negative inside), to first
   * order: g/|∇g| with g the distance in model space from the sphere's centre to the pixel's ray, minus the
   * radius, and ∇g by central differences over the pixel grid. Accurate near the silhouette (where it is
   * used); it assumes the sphere lies between the near and far planes.
   */
  readonly edgeDistance: Float32Array;
  /** Window depth (0 … 1, three's default depth range) of the centre hit; NaN where the centre misses. */
  readonly depth: Float32Array;
}

const MAX_SIZE = 16384;

function checkInteger(name: string, value: unknown, min: number, max: number): number {
  if (typeof value !== 'number')
    throw new TypeError(`renderReference: ${name} must be a number, got ${String(value)}`);
  if (!Number.isInteger(value) || value < min || value > max) {
    throw new RangeError(`renderReference: ${name} must be an integer in ${min} … ${max}, got ${value}`);
  }
  return value;
}

function checkMatrix(name: string, m: unknown): Mat4Like {
  const a = m as Mat4Like;
  if (a === null || typeof a !== 'object' || typeof a.length !== 'number' || a.length < 16) {
    throw new TypeError(`renderReference: ${name} must be 16 numbers (column-major), got ${String(m)}`);
  }
  for (let i = 0; i < 16; i++) {
    if (!Number.isFinite(a[i])) {
      throw new RangeError(`renderReference: ${name}[${i}] must be finite, got ${a[i]}`);
    }
  }
  return a;
}

const IDENTITY: readonly number[] = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

/**
 * The exact answer: ray-cast the analytic sphere of `radius` (an ellipsoid under the model matrix's scale)
 * through every pixel and light it with `shade()` at the exact hit point and normal.
 *
 * Each pixel's ray is the line through its centre between the near and far planes, mapped to model space by
 * (P·V·M)⁻¹ (so perspective and orthographic cameras alike, and near/far clipping, are exact). It meets the
 * sphere by the numerically stable intersection of Ray Tracing Gems ch. 7 (see `intersectSphere`); only the
 * front surface counts (the entry point between the planes, like a mesh drawn with three's `FrontSide`). The
 * world position is M·p and the world normal sign(det)·cof(M)·p (the exact normal, also for mirrored M and
 * for scales from 1e-20 to 1e20). A zero scale (singular M of rank 2) gives the flattened ellipsoid, an elliptic
 * disc: the ray meets its plane, and of the two sheets (p and its mirror through the kernel of M) the one facing
 * the viewer is drawn, its normal cof(M)·p = ±(the plane's normal) towards the eye, as the camera-facing
 * triangles of a flattened mesh are; rank ≤ 1 has no area and draws nothing. The eye is the camera's centre of projection (a point, or a direction for orthographic).
 *
 * Pixels are sampled at their centres, like the GPU rasteriser; the silhouette pixels are supersampled
 * (`samples`²) for the blended `rgba` and `coverage`. Cost: about one `shade` per pixel, plus samples² per
 * silhouette pixel (1280×720: about 0.4–0.7 s in Node or Chromium).
 *
 * @throws TypeError / RangeError naming the option for a bad size, sample count, radius or matrix, and a
 * RangeError when P·V is singular.
 */
export function renderReference(options: RenderReferenceOptions): ReferenceImage {
  const {
    width,
    height,
    projectionMatrix,
    viewMatrix,
    modelMatrix = IDENTITY,
    radius = 1,
    material,
    lights,
    background = [0, 0, 0],
    samples = 4,
  } = options;
  checkInteger('width', width, 1, MAX_SIZE);
  checkInteger('height', height, 1, MAX_SIZE);
  checkInteger('samples', samples, 1, 16);
  if (typeof radius !== 'number' || !(radius > 0) || !Number.isFinite(radius)) {
    throw new RangeError(`renderReference: radius must be a finite number > 0, got ${String(radius)}`);
  }
  const P = checkMatrix('projectionMatrix', projectionMatrix);
  const V = checkMatrix('viewMatrix', viewMatrix);
  const M = checkMatrix('modelMatrix', modelMatrix);
  const nm = normalMatrix(M);
  // det A = a0·(a1 × a2): the first column of M against the first column of its cofactor matrix.
  const det3 = M[0] * nm[0] + M[1] * nm[1] + M[2] * nm[2];
  const pv = multiply(P, V);
  const mvp = multiply(pv, M);
  // The ray is built in world space by (P·V)⁻¹ and taken to model space by M⁻¹ on its own, not by (P·V·M)⁻¹:
  // an anisotropic scale (1e20 along one axis, 1e-20 along another) keeps the tiny components of the model-
  // space direction exact instead of burying them in the rounding of the far − near difference.
  const invPV = invert(pv);
  if (invPV === null) {
    throw new RangeError(
      'renderReference: projectionMatrix · viewMatrix must be invertible, got a singular matrix',
    );
  }
  // A zero scale (singular M) flattens the sphere into an elliptic disc (rank 2; nothing for rank ≤ 1).
  const invM = det3 === 0 ? null : invert(M);
  const disc = invM === null ? flatEllipsoid(M, nm) : null;
  const eye = eyeOfCamera(P, V);

  const n = width * height;
  const rgba = new Uint8ClampedArray(4 * n);
  const linear = new Float32Array(3 * n);
  const hit = new Uint8Array(n);
  const coverage = new Float32Array(n);
  const edgeDistance = new Float32Array(n);
  const depth = new Float32Array(n).fill(Number.NaN);
  const g = new Float64Array(n);

  const near = new Float64Array(4);
  const far = new Float64Array(4);
  const clip = new Float64Array(4);
  const origin = new Float64Array(4);
  const direction = new Float64Array(4);
  const position: [number, number, number] = [0, 0, 0];
  const normal: [number, number, number] = [0, 0, 0];
  const color: [number, number, number] = [0, 0, 0];
  const sample = { position, normal, eye };
  let px = 0;
  let py = 0;
  let pz = 0;

  // Cast the ray through window point (x, y) (pixels, origin bottom-left). Returns whether it hits the
  // front surface between the planes; leaves the model-space hit in px, py, pz and returns m − r in `miss`.
  let miss = 0;
  const cast = (x: number, y: number): boolean => {
    const nx = (2 * x) / width - 1;
    const ny = (2 * y) / height - 1;
    transform4(invPV, nx, ny, -1, 1, near);
    transform4(invPV, nx, ny, 1, 1, far);
    const wx = near[0] / near[3];
    const wy = near[1] / near[3];
    const wz = near[2] / near[3];
    if (invM === null) {
      // The flattened ellipsoid: meet its plane, take the hit's preimage p0 ⊥ kernel, then the sheet facing the
      // viewer, p = p0 ± √(r² − |p0|²)·k̂, whose normal cof(M)·p = (k·p)·m points towards the eye (the triangles
      // of a flattened mesh that face the camera are exactly those).
      miss = Number.POSITIVE_INFINITY;
      if (disc === null) return false; // rank ≤ 1: no area
      const { m, k, inv } = disc;
      const ex = far[0] / far[3] - wx;
      const ey = far[1] / far[3] - wy;
      const ez = far[2] / far[3] - wz;
      const denom = m[0] * ex + m[1] * ey + m[2] * ez;
      if (denom === 0 || !Number.isFinite(denom)) return false; // edge-on
      const tau = (m[0] * (M[12] - wx) + m[1] * (M[13] - wy) + m[2] * (M[14] - wz)) / denom;
      const hx = wx + tau * ex - M[12];
      const hy = wy + tau * ey - M[13];
      const hz = wz + tau * ez - M[14];
      let qx = inv[0] * hx + inv[3] * hy + inv[6] * hz;
      let qy = inv[1] * hx + inv[4] * hy + inv[7] * hz;
      let qz = inv[2] * hx + inv[5] * hy + inv[8] * hz;
      const along = qx * k[0] + qy * k[1] + qz * k[2];
      qx -= along * k[0];
      qy -= along * k[1];
      qz -= along * k[2];
      const q = Math.hypot(qx, qy, qz);
      miss = q - radius;
      if (!(tau >= 0 && tau <= 1) || !(q <= radius)) return false;
      const s = (denom > 0 ? -1 : 1) * Math.sqrt(radius * radius - q * q);
      px = qx + s * k[0];
      py = qy + s * k[1];
      pz = qz + s * k[2];
      return true;
    }
    transform4(invM, wx, wy, wz, 1, origin);
    transform4(invM, far[0] / far[3] - wx, far[1] / far[3] - wy, far[2] / far[3] - wz, 0, direction);
    const ox = origin[0];
    const oy = origin[1];
    const oz = origin[2];
    let dx = direction[0];
    let dy = direction[1];
    let dz = direction[2];
    const len = Math.hypot(dx, dy, dz);
    dx /= len;
    dy /= len;
    dz /= len;
    // Ray Tracing Gems ch. 7 (centre at the origin).
    const b = ox * dx + oy * dy + oz * dz;
    const qx = ox - b * dx;
    const qy = oy - b * dy;
    const qz = oz - b * dz;
    const m = Math.hypot(qx, qy, qz);
    miss = m - radius;
    const delta = radius * radius - m * m;
    if (!(delta >= 0)) return false;
    const c = ox * ox + oy * oy + oz * oz - radius * radius;
    const q = -b - (b >= 0 ? 1 : -1) * Math.sqrt(delta);
    const t0 = q === 0 ? 0 : Math.min(c / q, q);
    if (!(t0 >= 0 && t0 <= len)) return false;
    // The entry point from the ray's closest point to the centre, q − √Δ·d̂, not o + t0·d̂: with the origin far
    // from a small sphere (the eye 1e20 model units away under a 1e-20 scale), o + t0·d̂ cancels to the
    // rounding of |o| and can land behind the surface.
    const s = Math.sqrt(delta);
    px = qx - s * dx;
    py = qy - s * dy;
    pz = qz - s * dz;
    return true;
  };
  // Shade the last hit into `color` (linear).
  const shadeHit = (): void => {
    position[0] = M[0] * px + M[4] * py + M[8] * pz + M[12];
    position[1] = M[1] * px + M[5] * py + M[9] * pz + M[13];
    position[2] = M[2] * px + M[6] * py + M[10] * pz + M[14];
    normal[0] = nm[0] * px + nm[3] * py + nm[6] * pz;
    normal[1] = nm[1] * px + nm[4] * py + nm[7] * pz;
    normal[2] = nm[2] * px + nm[5] * py + nm[8] * pz;
    shade(sample, material, lights, color);
  };

  // 1. Centre rays.
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const k = j * width + i;
      const h = cast(i + 0.5, j + 0.5);
      g[k] = miss;
      if (h) {
        hit[k] = 1;
        coverage[k] = 1;
        shadeHit();
        linear[3 * k] = color[0];
        linear[3 * k + 1] = color[1];
        linear[3 * k + 2] = color[2];
        transform4(mvp, px, py, pz, 1, clip);
        depth[k] = (clip[2] / clip[3]) * 0.5 + 0.5;
      } else {
        linear[3 * k] = background[0];
        linear[3 * k + 1] = background[1];
        linear[3 * k + 2] = background[2];
      }
    }
  }
  // 2. Signed distance to the silhouette, and supersampling where it is within 1 px.
  const at = (i: number, j: number): number =>
    g[Math.min(Math.max(j, 0), height - 1) * width + Math.min(Math.max(i, 0), width - 1)];
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const k = j * width + i;
      const gx = (at(i + 1, j) - at(i - 1, j)) / (i === 0 || i === width - 1 ? 1 : 2);
      const gy = (at(i, j + 1) - at(i, j - 1)) / (j === 0 || j === height - 1 ? 1 : 2);
      const grad = Math.hypot(gx, gy);
      const d = grad > 0 ? g[k] / grad : g[k] > 0 ? Number.POSITIVE_INFINITY : Number.NEGATIVE_INFINITY;
      edgeDistance[k] = d;
      let r = linear[3 * k];
      let gg = linear[3 * k + 1];
      let b = linear[3 * k + 2];
      if (Math.abs(d) < 1 && samples > 1) {
        let hits = 0;
        r = 0;
        gg = 0;
        b = 0;
        for (let sy = 0; sy < samples; sy++) {
          for (let sx = 0; sx < samples; sx++) {
            if (cast(i + (sx + 0.5) / samples, j + (sy + 0.5) / samples)) {
              hits++;
              shadeHit();
              r += color[0];
              gg += color[1];
              b += color[2];
            } else {
              r += background[0];
              gg += background[1];
              b += background[2];
            }
          }
        }
        const s2 = samples * samples;
        coverage[k] = hits / s2;
        r /= s2;
        gg /= s2;
        b /= s2;
      }
      rgba[4 * k] = linearToSrgb8Channel(r);
      rgba[4 * k + 1] = linearToSrgb8Channel(gg);
      rgba[4 * k + 2] = linearToSrgb8Channel(b);
      rgba[4 * k + 3] = 255;
    }
  }
  return { width, height, rgba, linear, hit, coverage, edgeDistance, depth };
}

/**
 * The plane of a sphere flattened by a singular model matrix of rank 2: the world unit normal m of the image
 * plane, the unit kernel k of M's 3×3 part A (cof(A) = m·kᵀ up to scale: every column of it is a multiple of
 * m) and the inverse of A + σ·m·kᵀ (σ = |A|), which maps a point of the plane (relative to M's translation) to
 * its preimage perpendicular to k. `null` for rank ≤ 1 (cof(A) = 0: a segment or a point, no area).
 */
function flatEllipsoid(
  M: Mat4Like,
  nm: Float64Array,
): { m: [number, number, number]; k: [number, number, number]; inv: Float64Array } | null {
  let best = -1;
  let size = 0;
  for (let j = 0; j < 3; j++) {
    const len = Math.hypot(nm[3 * j], nm[3 * j + 1], nm[3 * j + 2]);
    if (len > size) {
      size = len;
      best = j;
    }
  }
  if (!(size > 0) || !Number.isFinite(size)) return null;
  const m: [number, number, number] = [nm[3 * best] / size, nm[3 * best + 1] / size, nm[3 * best + 2] / size];
  const k: [number, number, number] = [0, 0, 0];
  for (let j = 0; j < 3; j++) k[j] = nm[3 * j] * m[0] + nm[3 * j + 1] * m[1] + nm[3 * j + 2] * m[2];
  const kl = Math.hypot(k[0], k[1], k[2]);
  for (let j = 0; j < 3; j++) k[j] /= kl;
  const sigma = Math.hypot(M[0], M[1], M[2], M[4], M[5], M[6], M[8], M[9], M[10]);
  // B = A + σ·m·kᵀ as a 4×4 (column-major) with a unit w, inverted; its 3×3 part is B⁻¹.
  const B = new Float64Array(16);
  for (let c = 0; c < 3; c++) for (let r = 0; r < 3; r++) B[4 * c + r] = M[4 * c + r] + sigma * m[r] * k[c];
  B[15] = 1;
  const inv4 = invert(B);
  if (inv4 === null) return null;
  const inv = new Float64Array(9);
  for (let c = 0; c < 3; c++) for (let r = 0; r < 3; r++) inv[3 * c + r] = inv4[4 * c + r];
  return { m, k, inv };
}

/**
 * The eye of the camera as a homogeneous world point: the centre of projection P⁻¹·(0, 0, 1, 0) in camera space
 * (the origin, w ≠ 0, for perspective; a direction, w = 0, for orthographic, oriented towards the viewer as
 * `eyeOf` in @shadelab/material gives it), then mapped to world space by V⁻¹. Deciding point or direction on
 * P alone keeps a perspective eye a point at any distance (on P·V, an eye 1e20 from the origin has
 * |w| < 1e-12·|xyz| and passed for a direction).
 */
function eyeOfCamera(P: Mat4Like, V: Mat4Like): [number, number, number, number] {
  const invP = invert(P);
  const invV = invert(V);
  if (invP === null || invV === null) return [0, 0, 0, 1];
  const e = transform4(invP, 0, 0, 1, 0);
  const size = Math.hypot(e[0], e[1], e[2], e[3]);
  if (Math.abs(e[3]) > 1e-12 * size) {
    const w = transform4(invV, e[0] / e[3], e[1] / e[3], e[2] / e[3], 1);
    return [w[0] / w[3], w[1] / w[3], w[2] / w[3], 1];
  }
  // A direction: P⁻¹(0, 0, 1, 0) points away from the viewer (clip z grows with distance).
  const d = transform4(invV, -e[0], -e[1], -e[2], 0);
  const len = Math.hypot(d[0], d[1], d[2]);
  return [d[0] / len, d[1] / len, d[2] / len, 0];
}
