import type { Camera, Vector4 } from 'three';

/**
 * The eye of `camera` in world space as a homogeneous point: the centre of projection of its projection
 * matrix P (the null vector of P's x, y and w rows), (position, 1) for a perspective camera, (direction
 * towards the viewer, 0) for an orthographic one, mapped to world space by `camera.matrixWorld`.
 * @param target receives the eye.
 * @returns `target`.
 */
export function eyeOf(camera: Camera, target: Vector4): Vector4 {
  const p = camera.projectionMatrix.elements;
  // Rows 0, 1, 3 of P (column-major storage).
  const r0x = p[0],
    r0y = p[4],
    r0z = p[8],
    r0w = p[12];
  const r1x = p[1],
    r1y = p[5],
    r1z = p[9],
    r1w = p[13];
  const r3x = p[3],
    r3y = p[7],
    r3z = p[11],
    r3w = p[15];
  // Generalised cross product of the three rows: E ⟂ r0, r1, r3.
  let ex = r0y * (r1z * r3w - r1w * r3z) - r0z * (r1y * r3w - r1w * r3y) + r0w * (r1y * r3z - r1z * r3y);
  let ey = -(r0x * (r1z * r3w - r1w * r3z) - r0z * (r1x * r3w - r1w * r3x) + r0w * (r1x * r3z - r1z * r3x));
  let ez = r0x * (r1y * r3w - r1w * r3y) - r0y * (r1x * r3w - r1w * r3x) + r0w * (r1x * r3y - r1y * r3x);
  let ew = -(r0x * (r1y * r3z - r1z * r3y) - r0y * (r1x * r3z - r1z * r3x) + r0z * (r1x * r3y - r1y * r3x));
  const size = Math.hypot(ex, ey, ez, ew);
  if (!(size > 0) || !Number.isFinite(size)) {
    // Degenerate projection: fall back to the camera's position.
    return target.set(
      camera.matrixWorld.elements[12],
      camera.matrixWorld.elements[13],
      camera.matrixWorld.elements[14],
      1,
    );
  }
  if (Math.abs(ew) > 1e-12 * size) {
    ex /= ew;
    ey /= ew;
    ez /= ew;
    ew = 1;
  } else {
    // A direction: orient it towards the viewer, where NDC depth decreases (row 2 of P · d < 0).
    const depth = p[2] * ex + p[6] * ey + p[10] * ez;
    const s = (depth > 0 ? -1 : 1) / Math.hypot(ex, ey, ez);
    ex *= s;
    ey *= s;
    ez *= s;
    ew = 0;
  }
  const m = camera.matrixWorld.elements;
  const x = m[0] * ex + m[4] * ey + m[8] * ez + m[12] * ew;
  const y = m[1] * ex + m[5] * ey + m[9] * ez + m[13] * ew;
  const z = m[2] * ex + m[6] * ey + m[10] * ez + m[14] * ew;
  if (ew === 0) {
    const len = Math.hypot(x, y, z);
    return len > 0 ? target.set(x / len, y / len, z / len, 0) : target.set(0, 0, 1, 0);
  }
  return target.set(x, y, z, 1);
}
