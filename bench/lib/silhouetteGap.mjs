// The true silhouette error of a sphere mesh in the image, measured the auditor's way: project the mesh's
// vertices, take the convex hull of their images (the outline of a convex mesh), and compare it with the exact
// outline of the ellipsoid found by ray casting (three's Raycaster and Ray.intersectsSphere, a bisection per
// direction): the largest distance on screen between the two outlines, either way, counting only what is on
// screen. Independent of the bound it checks (no contour formula, no projection algebra of ours). Shared by
// bench/autodetail.bench.mjs and the sphere tests (packages/sphere/src/silhouetteGap.test-util.ts).
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Matrix4, Ray, Raycaster, Sphere, Vector2, Vector3 } from 'three';

/** @type {Map<string, SubdivisionSphereGeometry>} */
const spheres = new Map();
/**
 * The unit subdivision sphere of a base and level (default options), built once and kept: the meshes the gap
 * is measured on.
 * @param {import('@shadelab/sphere').SphereBase} base @param {number} level
 */
export function sphereMesh(base, level) {
  const key = `${base}/${level}`;
  let g = spheres.get(key);
  if (!g) {
    g = new SubdivisionSphereGeometry({ base, level });
    spheres.set(key, g);
  }
  return g;
}

/**
 * @typedef {object} GapScene
 * @property {import('three').Camera} camera
 * @property {import('three').Matrix4} matrixWorld the mesh's world matrix (model scale and position)
 * @property {number} widthPx
 * @property {number} heightPx
 * @property {number} [radius] model-space radius of the exact sphere (default 1)
 */
/** @typedef {[number, number]} P */

/**
 * Pixel coordinates (x right, y down) of the world point `p`, or null when at or behind the eye.
 * @param {Vector3} p @param {import('three').Camera} camera @param {number} w @param {number} h
 * @returns {P | null}
 */
function toPixel(p, camera, w, h) {
  const view = p.clone().applyMatrix4(camera.matrixWorldInverse);
  if (/** @type {{ isPerspectiveCamera?: boolean }} */ (camera).isPerspectiveCamera && view.z >= 0)
    return null;
  const ndc = p.clone().project(camera);
  return [((ndc.x + 1) / 2) * w, ((1 - ndc.y) / 2) * h];
}

/** Convex hull (Andrew's monotone chain). @param {P[]} points @returns {P[]} */
function hull(points) {
  const pts = [...points].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  /** @param {P} o @param {P} a @param {P} b */
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  /** @type {P[]} */
  const lower = [];
  for (const p of pts) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], p) <= 0) lower.pop();
    lower.push(p);
  }
  /** @type {P[]} */
  const upper = [];
  for (let i = pts.length - 1; i >= 0; i--) {
    const p = pts[i];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], p) <= 0) upper.pop();
    upper.push(p);
  }
  return lower.slice(0, -1).concat(upper.slice(0, -1));
}

/** @param {P} p @param {P} a @param {P} b */
function segmentDistance(p, a, b) {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const len2 = dx * dx + dy * dy;
  const t = len2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2)) : 0;
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/** Distance from `p` to the closed polyline `loop`. @param {P} p @param {P[]} loop */
function loopDistance(p, loop) {
  let best = Number.POSITIVE_INFINITY;
  for (let i = 0; i < loop.length; i++)
    best = Math.min(best, segmentDistance(p, loop[i], loop[(i + 1) % loop.length]));
  return best;
}

/**
 * The exact outline of the ellipsoid (the sphere of `radius` under `matrixWorld`) in pixels: `samples` points,
 * each the boundary, found by bisection, between pixels whose ray hits the ellipsoid and pixels whose ray
 * misses it, along a ray in the image from the image of the centre.
 * @param {GapScene} scene @param {number} [samples] @returns {P[]}
 */
export function exactOutline(scene, samples = 2048) {
  const { camera, matrixWorld, widthPx: w, heightPx: h, radius = 1 } = scene;
  const toModel = new Matrix4().copy(matrixWorld).invert();
  const sphere = new Sphere(new Vector3(), radius);
  const caster = new Raycaster();
  const ray = new Ray();
  const ndc = new Vector2();
  /** @param {number} x @param {number} y */
  const hits = (x, y) => {
    ndc.set((x / w) * 2 - 1, 1 - (y / h) * 2);
    caster.setFromCamera(ndc, camera);
    return ray.copy(caster.ray).applyMatrix4(toModel).intersectsSphere(sphere);
  };
  const centre = toPixel(new Vector3().setFromMatrixPosition(matrixWorld), camera, w, h);
  if (centre === null || !hits(centre[0], centre[1])) throw new Error('exactOutline: the centre is not seen');
  /** @type {P[]} */
  const out = [];
  for (let i = 0; i < samples; i++) {
    const a = (2 * Math.PI * i) / samples;
    const dx = Math.cos(a);
    const dy = Math.sin(a);
    let lo = 0;
    let hi = 1;
    while (hits(centre[0] + hi * dx, centre[1] + hi * dy)) {
      lo = hi;
      hi *= 2;
      if (hi > 1e7) throw new Error('exactOutline: the outline is unbounded');
    }
    for (let k = 0; k < 60 && hi - lo > 1e-7; k++) {
      const mid = (lo + hi) / 2;
      if (hits(centre[0] + mid * dx, centre[1] + mid * dy)) lo = mid;
      else hi = mid;
    }
    out.push([centre[0] + lo * dx, centre[1] + lo * dy]);
  }
  return out;
}

/**
 * The largest distance on screen, in pixels, between the outline of the mesh `geometry` (its vertices under
 * `matrixWorld`, projected; their convex hull) and the exact outline of the ellipsoid, either way: every point
 * of either outline that is on screen, to the other outline.
 * @param {import('three').BufferGeometry} geometry @param {GapScene} scene @param {number} [samples]
 * @returns {number}
 */
export function silhouetteGapPx(geometry, scene, samples = 2048) {
  const { camera, matrixWorld, widthPx: w, heightPx: h } = scene;
  camera.updateMatrixWorld();
  const position = geometry.getAttribute('position');
  const v = new Vector3();
  /** @type {P[]} */
  const projected = [];
  for (let i = 0; i < position.count; i++) {
    v.fromBufferAttribute(position, i).applyMatrix4(matrixWorld);
    const p = toPixel(v, camera, w, h);
    if (p === null) throw new Error('silhouetteGapPx: a vertex is at or behind the eye');
    projected.push(p);
  }
  const mesh = hull(projected);
  const exact = exactOutline(scene, samples);
  /** @param {P} p */
  const onScreen = (p) => p[0] >= 0 && p[0] <= w && p[1] >= 0 && p[1] <= h;
  let gap = 0;
  for (const p of exact) if (onScreen(p)) gap = Math.max(gap, loopDistance(p, mesh));
  for (let i = 0; i < mesh.length; i++) {
    const a = mesh[i];
    const b = mesh[(i + 1) % mesh.length];
    // Distance to a convex outline is concave along a chord inside it: check the ends and a few points between.
    for (const t of [0, 0.25, 0.5, 0.75]) {
      /** @type {P} */
      const p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
      if (onScreen(p)) gap = Math.max(gap, loopDistance(p, exact));
    }
  }
  return gap;
}
