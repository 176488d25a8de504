import { type Camera, Matrix4 } from 'three';
import { fail } from './validate.js';

/** Options of {@link projectedRadiusPx} and {@link silhouetteErrorScalePx}. */
export interface ProjectedRadiusOptions {
  /** The camera (its `projectionMatrix` and `matrixWorld` are read; keep them current). */
  camera: Camera;
  /**
   * The sphere's world matrix (`object.matrixWorld`): `projectedRadiusPx` scales the radius by its largest scale
   * axis; `silhouetteErrorScalePx` uses all of it (the ellipsoid, turned and placed).
   */
  matrixWorld: Matrix4;
  /** Height of the viewport in pixels (physical pixels: `renderer.getCurrentViewport(v).w`). Finite, > 0. */
  viewportHeightPx: number;
  /** Radius in model space (the geometry's radius). Finite, > 0. @default 1 */
  radius?: number;
}

/** Both functions' size options: finite numbers > 0, or a RangeError naming the function and the option. */
function checkSizes(fn: string, viewportHeightPx: unknown, radius: unknown): void {
  for (const [name, value] of [
    ['viewportHeightPx', viewportHeightPx],
    ['radius', radius],
  ] as const) {
    if (typeof value !== 'number' || !(value > 0) || !Number.isFinite(value)) {
      fail(fn, name, 'a finite number > 0', value);
    }
  }
}

/**
 * The radius of a sphere on screen, in pixels, from any three.js camera's projection matrix (so also
 * shadelab's `Camera`, which has no `fov`):
 *
 * - perspective (P₃₃ = 0): R·(H/2)·P₁₁ / √(d² − R²), with P₁₁ = 1/tan(fovy/2) (zoom included), d the distance
 *   from the eye to the sphere's centre and R = radius · the largest scale axis of `matrixWorld`. This is the
 *   exact radius of a sphere centred on the view axis (the tangent cone's half-angle is asin(R/d)), slightly
 *   more than the lecture-note approximation R·(H/2)/(d·tan(fovy/2)); off axis perspective stretches the
 *   image further (by up to 1/cos² of the angle off axis), which this does not include.
 * - orthographic: R·(H/2)·P₁₁ = R·H·zoom/(top − bottom), exact.
 *
 * This is the size of the sphere, not the size of its error on screen: the error of a subdivision sphere
 * changes faster than the radius near the camera (the radius grows like 1/√(d² − R²), its error like
 * d²/(d² − R²)^{3/2}). Choose detail with {@link silhouetteErrorScalePx}, which bounds the error.
 *
 * @param options - The camera, the sphere's world matrix, the viewport height (pixels) and the radius.
 * @returns pixels ≥ 0; `Infinity` when the eye is inside or on the sphere (d ≤ R).
 * @throws RangeError naming the option for a non-positive or non-finite `viewportHeightPx` or `radius`.
 */
export function projectedRadiusPx({
  camera,
  matrixWorld,
  viewportHeightPx,
  radius = 1,
}: ProjectedRadiusOptions): number {
  checkSizes('projectedRadiusPx', viewportHeightPx, radius);
  const m = matrixWorld.elements;
  const scale = Math.sqrt(
    Math.max(
      m[0] * m[0] + m[1] * m[1] + m[2] * m[2],
      m[4] * m[4] + m[5] * m[5] + m[6] * m[6],
      m[8] * m[8] + m[9] * m[9] + m[10] * m[10],
    ),
  );
  const R = radius * scale;
  const p = camera.projectionMatrix.elements;
  const halfH = viewportHeightPx / 2;
  const focal = Math.abs(p[5]);
  if (p[15] !== 0 || p[11] === 0) return R * halfH * focal; // orthographic
  const c = camera.matrixWorld.elements;
  const d = Math.hypot(m[12] - c[12], m[13] - c[13], m[14] - c[14]);
  if (!(d > R)) return Number.POSITIVE_INFINITY;
  return (R * halfH * focal) / Math.sqrt((d - R) * (d + R));
}

const _view = /* @__PURE__ */ new Matrix4();

/**
 * How many pixels of silhouette error on screen a unit of relative radial error costs: a mesh inscribed in the
 * sphere (every point of its surface between radius·(1 − e) and radius from the centre, e.g.
 * e = `sphereError(base, level)`), drawn with `matrixWorld` (any scale, non-uniform too) and `camera`, has its
 * outline on screen within e · `silhouetteErrorScalePx(…)` pixels of the exact outline of the ellipsoid
 * (the largest distance, either way, between the two outlines; any camera, anywhere on or off screen). It is
 * an upper bound, tight on the view axis, and costs a few dozen multiplications: compute it once per frame,
 * then test any number of levels.
 *
 * Why. The mesh lies between the ellipsoid E and E′, E shrunk by (1 − e) about its centre c, so its outline
 * lies between theirs, at most the largest distance from a point of E's outline to E′'s outline. Shrinking about
 * c moves a point x of depth w towards c's image, by e·|s − s_c|·c_w/w′ in image units (s = x/w the image point,
 * s_c and c_w those of c, w′ the depth of the moved point): exact for perspective. Over E's contour (the ring of
 * tangent points, a plane ellipse found in closed form) that is at most e·N/(w_min·min(w_min, c_w)), N the
 * largest c_w·x − w·c over the ring, w_min its least depth; times the focal length in pixels (H/2)·P₁₁
 * (square pixels assumed). On the view axis this is (H/2)·P₁₁·R·d²/(d² − R²)^{3/2}, the derivative of the
 * on-screen radius with respect to R: 1/cos² of the tangent cone's half-angle larger than the radius. For an
 * orthographic camera it is (H/2)·P₁₁ times the ellipsoid's largest radius across the view (exact).
 *
 * @param options - The camera, the sphere's world matrix, the viewport height (pixels) and the radius.
 * @returns pixels ≥ 0; `Infinity` when the eye is inside or on the ellipsoid, or when part of the ellipsoid's
 * outline is at or behind the eye plane (its image is unbounded); 0 when all of it is behind the eye.
 * @throws RangeError naming the option for a non-positive or non-finite `viewportHeightPx` or `radius`.
 */
export function silhouetteErrorScalePx({
  camera,
  matrixWorld,
  viewportHeightPx,
  radius = 1,
}: ProjectedRadiusOptions): number {
  checkSizes('silhouetteErrorScalePx', viewportHeightPx, radius);
  const p = camera.projectionMatrix.elements;
  const f = (viewportHeightPx / 2) * Math.abs(p[5]);
  // Model → view; the ellipsoid is c + A·u, |u| ≤ 1 (columns of A: the scaled axes in view space).
  const m = _view.copy(camera.matrixWorld).invert().multiply(matrixWorld).elements;
  const ax = [m[0] * radius, m[4] * radius, m[8] * radius];
  const ay = [m[1] * radius, m[5] * radius, m[9] * radius];
  const az = [m[2] * radius, m[6] * radius, m[10] * radius]; // rows of A; depth w = −z
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  /** Largest singular value of the 2×3 matrix [a; b] with the component along unit `e` removed (if any). */
  const norm2 = (a: number[], b: number[], e?: number[]) => {
    const ae = e ? dot(a, e) : 0;
    const be = e ? dot(b, e) : 0;
    const g11 = dot(a, a) - ae * ae;
    const g22 = dot(b, b) - be * be;
    const g12 = dot(a, b) - ae * be;
    const h = (g11 - g22) / 2;
    return Math.sqrt(Math.max(0, (g11 + g22) / 2 + Math.sqrt(h * h + g12 * g12)));
  };
  if (p[15] !== 0 || p[11] === 0) return f * norm2(ax, ay); // orthographic
  const cx = m[12];
  const cy = m[13];
  const cw = -m[14];
  // L(x) = c_w·(x, y) − w·(c_x, c_y) is linear and zero at c: its rows on A.
  const g1 = [0, 1, 2].map((j) => cw * ax[j] + cx * az[j]);
  const g2 = [0, 1, 2].map((j) => cw * ay[j] + cy * az[j]);
  const bound = (n: number, wMin: number) =>
    wMin > 0 ? (f * n) / (wMin * Math.min(wMin, cw)) : cw + Math.hypot(...az) <= 0 ? 0 : Infinity;
  // The eye in the unit sphere's coordinates: e = A⁻¹(−c) (rows of A⁻¹ = cofactors / det).
  const r0 = [ay[1] * az[2] - ay[2] * az[1], az[1] * ax[2] - az[2] * ax[1], ax[1] * ay[2] - ax[2] * ay[1]];
  const r1 = [ay[2] * az[0] - ay[0] * az[2], az[2] * ax[0] - az[0] * ax[2], ax[2] * ay[0] - ax[0] * ay[2]];
  const r2 = [ay[0] * az[1] - ay[1] * az[0], az[0] * ax[1] - az[1] * ax[0], ax[0] * ay[1] - ax[1] * ay[0]];
  const det = ax[0] * r0[0] + ax[1] * r1[0] + ax[2] * r2[0];
  const c = [-cx, -cy, cw];
  const e = [dot(r0, c) / det, dot(r1, c) / det, dot(r2, c) / det];
  const d2 = dot(e, e);
  // A flat (singular) ellipsoid: the same bound over all of it instead of its contour.
  if (!Number.isFinite(d2)) return bound(norm2(g1, g2), cw - Math.hypot(...az));
  if (!(d2 > 1)) return Infinity;
  // The contour: the circle u = e/d² + ρ·(unit ⊥ e), ρ = √(1 − 1/d²), mapped by A.
  const d = Math.sqrt(d2);
  const unit = e.map((v) => v / d);
  const rho = Math.sqrt(1 - 1 / d2);
  return bound(rho * norm2(g1, g2, unit), cw - dot(az, e) / d2 - rho * norm2(az, [0, 0, 0], unit));
}
