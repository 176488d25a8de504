import type { Camera, Matrix4 } from 'three';
import { fail } from './validate.js';

/** Options of {@link projectedRadiusPx}. */
export interface ProjectedRadiusOptions {
  /** The camera (its `projectionMatrix` and `matrixWorld` are read; keep them current). */
  camera: Camera;
  /** The sphere's world matrix (`object.matrixWorld`); its largest scale axis scales the radius. */
  matrixWorld: Matrix4;
  /** Height of the viewport in pixels (physical pixels: `renderer.getCurrentViewport(v).w`). Finite, > 0. */
  viewportHeightPx: number;
  /** Radius in model space (the geometry's radius). Finite, > 0. @default 1 */
  radius?: number;
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
 * @returns pixels ≥ 0; `Infinity` when the eye is inside or on the sphere (d ≤ R).
 * @throws RangeError naming the option for a non-positive or non-finite `viewportHeightPx` or `radius`.
 */
export function projectedRadiusPx({
  camera,
  matrixWorld,
  viewportHeightPx,
  radius = 1,
}: ProjectedRadiusOptions): number {
  if (typeof viewportHeightPx !== 'number' || !(viewportHeightPx > 0) || !Number.isFinite(viewportHeightPx)) {
    fail('projectedRadiusPx', 'viewportHeightPx', 'a finite number > 0', viewportHeightPx);
  }
  if (typeof radius !== 'number' || !(radius > 0) || !Number.isFinite(radius)) {
    fail('projectedRadiusPx', 'radius', 'a finite number > 0', radius);
  }
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
