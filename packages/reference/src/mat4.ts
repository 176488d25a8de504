// Internal float64 4×4 helpers (column-major, like three's Matrix4.elements). Three-free.

/** A 4×4 matrix as 16 numbers in column-major order (three's `Matrix4.elements`). */
export type Mat4Like = ArrayLike<number>;

/** out = a · b */
export function multiply(a: Mat4Like, b: Mat4Like, out: Float64Array = new Float64Array(16)): Float64Array {
  for (let c = 0; c < 4; c++) {
    for (let r = 0; r < 4; r++) {
      out[4 * c + r] =
        a[r] * b[4 * c] + a[4 + r] * b[4 * c + 1] + a[8 + r] * b[4 * c + 2] + a[12 + r] * b[4 * c + 3];
    }
  }
  return out;
}

/** out = m⁻¹ (cofactor expansion); `null` when m is singular or not finite. */
export function invert(m: Mat4Like, out: Float64Array = new Float64Array(16)): Float64Array | null {
  const [a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33] = Array.from(
    { length: 16 },
    (_, i) => m[i],
  );
  const b00 = a00 * a11 - a01 * a10;
  const b01 = a00 * a12 - a02 * a10;
  const b02 = a00 * a13 - a03 * a10;
  const b03 = a01 * a12 - a02 * a11;
  const b04 = a01 * a13 - a03 * a11;
  const b05 = a02 * a13 - a03 * a12;
  const b06 = a20 * a31 - a21 * a30;
  const b07 = a20 * a32 - a22 * a30;
  const b08 = a20 * a33 - a23 * a30;
  const b09 = a21 * a32 - a22 * a31;
  const b10 = a21 * a33 - a23 * a31;
  const b11 = a22 * a33 - a23 * a32;
  const det = b00 * b11 - b01 * b10 + b02 * b09 + b03 * b08 - b04 * b07 + b05 * b06;
  if (det === 0 || !Number.isFinite(det)) return null;
  const k = 1 / det;
  out[0] = (a11 * b11 - a12 * b10 + a13 * b09) * k;
  out[1] = (a02 * b10 - a01 * b11 - a03 * b09) * k;
  out[2] = (a31 * b05 - a32 * b04 + a33 * b03) * k;
  out[3] = (a22 * b04 - a21 * b05 - a23 * b03) * k;
  out[4] = (a12 * b08 - a10 * b11 - a13 * b07) * k;
  out[5] = (a00 * b11 - a02 * b08 + a03 * b07) * k;
  out[6] = (a32 * b02 - a30 * b05 - a33 * b01) * k;
  out[7] = (a20 * b05 - a22 * b02 + a23 * b01) * k;
  out[8] = (a10 * b10 - a11 * b08 + a13 * b06) * k;
  out[9] = (a01 * b08 - a00 * b10 - a03 * b06) * k;
  out[10] = (a30 * b04 - a31 * b02 + a33 * b00) * k;
  out[11] = (a21 * b02 - a20 * b04 - a23 * b00) * k;
  out[12] = (a11 * b07 - a10 * b09 - a12 * b06) * k;
  out[13] = (a00 * b09 - a01 * b07 + a02 * b06) * k;
  out[14] = (a31 * b01 - a30 * b03 - a32 * b00) * k;
  out[15] = (a20 * b03 - a21 * b01 + a22 * b00) * k;
  return out;
}

/** out = m · (x, y, z, w) */
export function transform4(
  m: Mat4Like,
  x: number,
  y: number,
  z: number,
  w: number,
  out: Float64Array = new Float64Array(4),
): Float64Array {
  out[0] = m[0] * x + m[4] * y + m[8] * z + m[12] * w;
  out[1] = m[1] * x + m[5] * y + m[9] * z + m[13] * w;
  out[2] = m[2] * x + m[6] * y + m[10] * z + m[14] * w;
  out[3] = m[3] * x + m[7] * y + m[11] * z + m[15] * w;
  return out;
}

/**
 * The normal matrix sign(det A)·cof(A) of m's upper-left 3×3 A (proportional to (A⁻¹)ᵀ, finite for
 * singular A, outward under mirroring), column-major 3×3. Normals must be normalised after it.
 */
export function normalMatrix(m: Mat4Like, out: Float64Array = new Float64Array(9)): Float64Array {
  const x0 = m[0];
  const y0 = m[1];
  const z0 = m[2];
  const x1 = m[4];
  const y1 = m[5];
  const z1 = m[6];
  const x2 = m[8];
  const y2 = m[9];
  const z2 = m[10];
  // Columns a1×a2, a2×a0, a0×a1.
  out[0] = y1 * z2 - z1 * y2;
  out[1] = z1 * x2 - x1 * z2;
  out[2] = x1 * y2 - y1 * x2;
  out[3] = y2 * z0 - z2 * y0;
  out[4] = z2 * x0 - x2 * z0;
  out[5] = x2 * y0 - y2 * x0;
  out[6] = y0 * z1 - z0 * y1;
  out[7] = z0 * x1 - x0 * z1;
  out[8] = x0 * y1 - y0 * x1;
  const det = x0 * out[0] + y0 * out[1] + z0 * out[2];
  if (det < 0) for (let i = 0; i < 9; i++) out[i] = -out[i];
  return out;
}
