import type { InstancedBufferAttribute, InstancedMesh } from 'three';

/**
 * How far from orthogonal two columns of an instance matrix may be, squared: |aᵢ·aⱼ| / (|aᵢ||aⱼ|) (the cosine of
 * their angle) up to 1e-6, ten times what float32 rounding leaves in a matrix that three's `Matrix4.compose` made
 * from a rotation and a scale. The normal A·diag(1/|aᵢ|²)·n then differs from A⁻ᵀn by about that angle (1e-6
 * rad), far below what changes an 8-bit pixel.
 */
const COSINE2 = 1e-6 * 1e-6;
/**
 * The squared column lengths for which the vertex stage's A·(n / |aᵢ|²) stays in float32's range before it is
 * normalised (a normal between 1e-9 and 1e9 times |n|): scales from 1e-9 to 1e9.
 */
const MIN_LENGTH2 = 1e-18;
const MAX_LENGTH2 = 1e18;

type Verdict = { version: number; count: number; orthogonal: boolean };
const verdicts = new WeakMap<InstancedBufferAttribute, Verdict>();

/**
 * Whether every drawn instance matrix of `mesh` (the first `mesh.count`) is a rotation times a scale, mirrored or
 * not: its columns orthogonal (a cosine of at most 1e-6) and each column's length between 1e-9 and 1e9, all finite.
 * For such a matrix A the normal matrix is A·diag(1/|aᵢ|²) = A⁻ᵀ, a positive multiple of sign(det A)·cof(A),
 * so ShadingMaterial's vertex stage turns normals with one matrix product and three dot products
 * (`SHADING_INSTANCE_ORTHOGONAL`) instead of the cofactor of the scaled matrix (three cross products, a
 * determinant and two rescalings), which any other instance (sheared, singular, 1e20) still takes. Checked in
 * float64 on the CPU once per change of the matrices (`instanceMatrix.version`) or of `count`.
 */
export function hasOrthogonalInstances(mesh: InstancedMesh): boolean {
  const attribute = mesh.instanceMatrix;
  const known = verdicts.get(attribute);
  if (known !== undefined && known.version === attribute.version && known.count === mesh.count) {
    return known.orthogonal;
  }
  const orthogonal = check(attribute, mesh.count);
  verdicts.set(attribute, { version: attribute.version, count: mesh.count, orthogonal });
  return orthogonal;
}

function check(attribute: InstancedBufferAttribute, count: number): boolean {
  // A matrix attribute as three makes it (16 floats an instance); anything else takes the cofactor.
  if (attribute.itemSize !== 16) return false;
  const e = attribute.array;
  const n = Math.min(count, Math.floor(e.length / 16));
  for (let i = 0; i < n; i++) {
    const o = 16 * i;
    const x0 = e[o];
    const y0 = e[o + 1];
    const z0 = e[o + 2];
    const x1 = e[o + 4];
    const y1 = e[o + 5];
    const z1 = e[o + 6];
    const x2 = e[o + 8];
    const y2 = e[o + 9];
    const z2 = e[o + 10];
    const l0 = x0 * x0 + y0 * y0 + z0 * z0;
    const l1 = x1 * x1 + y1 * y1 + z1 * z1;
    const l2 = x2 * x2 + y2 * y2 + z2 * z2;
    // NaN fails every comparison: a non-finite matrix takes the cofactor.
    if (!(l0 >= MIN_LENGTH2 && l0 <= MAX_LENGTH2)) return false;
    if (!(l1 >= MIN_LENGTH2 && l1 <= MAX_LENGTH2)) return false;
    if (!(l2 >= MIN_LENGTH2 && l2 <= MAX_LENGTH2)) return false;
    const d01 = x0 * x1 + y0 * y1 + z0 * z1;
    const d12 = x1 * x2 + y1 * y2 + z1 * z2;
    const d20 = x2 * x0 + y2 * y0 + z2 * z0;
    if (d01 * d01 > COSINE2 * l0 * l1 || d12 * d12 > COSINE2 * l1 * l2 || d20 * d20 > COSINE2 * l2 * l0) {
      return false;
    }
  }
  return true;
}
