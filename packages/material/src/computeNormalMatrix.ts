import type { Matrix3, Matrix4 } from 'three';

/**
 * The normal matrix of `matrix` (its upper-left 3×3 A), computed robustly as sign(det A)·cof(A) and scaled
 * so that its largest entry has magnitude 1. cof(A) = det(A)·(A⁻¹)ᵀ, so for a regular A the result is a
 * positive multiple of three's `getNormalMatrix` (the inverse transpose): normals must be normalised after
 * the multiplication either way. Unlike the inverse transpose it stays finite for singular and nearly
 * singular matrices (a zero, 1e-20 or 1e20 scale): cof(A)·n is then the normal of the flattened surface,
 * or zero where there is none (the shaders and `shade` fall back to the view direction for zero normals).
 * The sign of the determinant keeps normals outward under mirroring (det < 0); det = 0 counts as positive.
 * The computation runs in float64 on A divided by its largest entry, so nothing overflows or underflows
 * before the float32 upload. A matrix with a non-finite or all-zero 3×3 part gives the zero matrix.
 *
 * @param matrix a model (world) matrix; only its upper-left 3×3 is read.
 * @param target receives the normal matrix.
 * @returns `target`.
 */
export function computeNormalMatrix(matrix: Matrix4, target: Matrix3): Matrix3 {
  const e = matrix.elements;
  const te = target.elements;
  let s = 0;
  for (const i of COLUMNS) {
    s = Math.max(s, Math.abs(e[i]), Math.abs(e[i + 1]), Math.abs(e[i + 2]));
  }
  if (!(s > 0) || !Number.isFinite(s)) {
    te.fill(0);
    return target;
  }
  const k = 1 / s;
  // Columns a0, a1, a2 of A / s.
  const x0 = e[0] * k;
  const y0 = e[1] * k;
  const z0 = e[2] * k;
  const x1 = e[4] * k;
  const y1 = e[5] * k;
  const z1 = e[6] * k;
  const x2 = e[8] * k;
  const y2 = e[9] * k;
  const z2 = e[10] * k;
  // cof(A) has the columns a1×a2, a2×a0, a0×a1.
  const c0x = y1 * z2 - z1 * y2;
  const c0y = z1 * x2 - x1 * z2;
  const c0z = x1 * y2 - y1 * x2;
  const c1x = y2 * z0 - z2 * y0;
  const c1y = z2 * x0 - x2 * z0;
  const c1z = x2 * y0 - y2 * x0;
  const c2x = y0 * z1 - z0 * y1;
  const c2y = z0 * x1 - x0 * z1;
  const c2z = x0 * y1 - y0 * x1;
  const det = x0 * c0x + y0 * c0y + z0 * c0z;
  const m = Math.max(
    Math.abs(c0x),
    Math.abs(c0y),
    Math.abs(c0z),
    Math.abs(c1x),
    Math.abs(c1y),
    Math.abs(c1z),
    Math.abs(c2x),
    Math.abs(c2y),
    Math.abs(c2z),
  );
  if (!(m > 0)) {
    te.fill(0);
    return target;
  }
  // Divide (each |c| ≤ m) rather than multiply by 1 / m, which overflows when m is subnormal.
  const f = det < 0 ? -1 : 1;
  te[0] = (c0x / m) * f;
  te[1] = (c0y / m) * f;
  te[2] = (c0z / m) * f;
  te[3] = (c1x / m) * f;
  te[4] = (c1y / m) * f;
  te[5] = (c1z / m) * f;
  te[6] = (c2x / m) * f;
  te[7] = (c2y / m) * f;
  te[8] = (c2z / m) * f;
  return target;
}

const COLUMNS = [0, 4, 8] as const;
