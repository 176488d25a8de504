import { fail, mustBe } from './validate.js';

/** How `computeVertexNormals` weights the face normals meeting at a vertex. */
export type NormalWeighting = 'average' | 'area' | 'angle';

const WEIGHTINGS: readonly NormalWeighting[] = ['average', 'area', 'angle'];

/**
 * Vertex normals of any triangle mesh: at each vertex, the normalised sum of the normals of the faces using it.
 *
 * - `'average'`: the lecture's Gouraud rule, n = (n₁ + n₂ + …) / |n₁ + n₂ + …| with unit face normals.
 * - `'area'`: each face normal weighted by the face's area (the plain sum of cross products).
 * - `'angle'`: each unit face normal weighted by the face's interior angle at the vertex.
 *
 * Face normals follow the winding: counter-clockwise triangles give outward normals. Zero-area faces (repeated
 * indices, coincident or collinear positions) have no normal and add nothing. A vertex whose weighted sum
 * vanishes or is not finite falls back, in order, to the area-weighted sum, then to the direction of its
 * position from the origin, then to (0, 0, 1): every normal returned is finite and of unit length, even for
 * unused vertices.
 *
 * @param positions - x, y, z per vertex (length a multiple of 3), finite.
 * @param indices - 3 vertex indices per triangle, each an integer in [0, vertex count); `null` or omitted:
 * the positions are a triangle soup (vertices 0, 1, 2 form the first triangle, and so on).
 * @param weighting - Weighting of the face normals. @default 'average'
 * @returns Unit normals, x, y, z per vertex (a new array, as long as `positions`).
 * @throws RangeError / TypeError naming the parameter for a length that is not a multiple of 3, an index out of
 * range or not an integer, or an unknown weighting.
 */
export function computeVertexNormals(
  positions: ArrayLike<number>,
  indices?: ArrayLike<number> | null,
  weighting: NormalWeighting = 'average',
): Float32Array {
  const caller = 'computeVertexNormals';
  if (positions == null || typeof positions.length !== 'number') {
    throw new TypeError(mustBe(caller, 'positions', 'an array of numbers', positions));
  }
  if (positions.length % 3 !== 0) fail(caller, 'positions.length', 'a multiple of 3', positions.length);
  const vertexCount = positions.length / 3;
  if (indices != null && typeof indices.length !== 'number') {
    throw new TypeError(mustBe(caller, 'indices', 'an array of integers or null', indices));
  }
  const cornerCount = indices == null ? vertexCount : indices.length;
  if (cornerCount % 3 !== 0) {
    const what = indices == null ? 'positions.length / 3 (a triangle soup)' : 'indices.length';
    fail(caller, what, 'a multiple of 3', cornerCount);
  }
  if (!WEIGHTINGS.includes(weighting))
    fail(caller, 'weighting', "'average', 'area' or 'angle'", weighting, 'string');
  if (indices != null) {
    for (let i = 0; i < indices.length; i++) {
      const v = indices[i];
      if (!Number.isInteger(v) || v < 0 || v >= vertexCount) {
        fail(caller, `indices[${i}]`, `an integer from 0 to ${vertexCount - 1} (vertex count − 1)`, v);
      }
    }
  }

  // Normals do not depend on scale: work on a copy scaled by a power of two near 1 / max |coordinate|, so that
  // meshes at 1e-150 or 1e150 neither underflow nor overflow in the cross products and their sums.
  let largest = 0;
  for (let i = 0; i < positions.length; i++) {
    const x = Math.abs(positions[i]);
    if (x > largest && x !== Number.POSITIVE_INFINITY) largest = x;
  }
  const scale = largest > 0 ? 2 ** -Math.round(Math.log2(largest)) : 1;
  const p = Float64Array.from(positions, (x) => x * scale);
  const sum = new Float64Array(positions.length); // weighted sums
  const area = new Float64Array(positions.length); // area-weighted sums, the first fallback
  const corner = (c: number) => 3 * (indices == null ? c : indices[c]);
  for (let c = 0; c < cornerCount; c += 3) {
    const a = corner(c);
    const b = corner(c + 1);
    const d = corner(c + 2);
    const abx = p[b] - p[a];
    const aby = p[b + 1] - p[a + 1];
    const abz = p[b + 2] - p[a + 2];
    const adx = p[d] - p[a];
    const ady = p[d + 1] - p[a + 1];
    const adz = p[d + 2] - p[a + 2];
    const nx = aby * adz - abz * ady;
    const ny = abz * adx - abx * adz;
    const nz = abx * ady - aby * adx;
    // Scale by the largest component so tiny and huge faces keep their direction.
    const m = Math.max(Math.abs(nx), Math.abs(ny), Math.abs(nz));
    if (!(m > 0) || !Number.isFinite(m)) continue; // zero-area (or overflowing) face: no normal
    const length = m * Math.sqrt((nx / m) ** 2 + (ny / m) ** 2 + (nz / m) ** 2);
    const ux = nx / length;
    const uy = ny / length;
    const uz = nz / length;
    add(area, a, nx, ny, nz);
    add(area, b, nx, ny, nz);
    add(area, d, nx, ny, nz);
    if (weighting === 'average') {
      add(sum, a, ux, uy, uz);
      add(sum, b, ux, uy, uz);
      add(sum, d, ux, uy, uz);
    } else if (weighting === 'angle') {
      const wa = angle(p, a, b, d);
      const wb = angle(p, b, d, a);
      const wd = Math.max(0, Math.PI - wa - wb);
      add(sum, a, wa * ux, wa * uy, wa * uz);
      add(sum, b, wb * ux, wb * uy, wb * uz);
      add(sum, d, wd * ux, wd * uy, wd * uz);
    }
  }

  const out = new Float32Array(positions.length);
  const primary = weighting === 'area' ? area : sum;
  for (let i = 0; i < out.length; i += 3) {
    if (
      !(
        writeUnit(out, i, primary[i], primary[i + 1], primary[i + 2]) ||
        writeUnit(out, i, area[i], area[i + 1], area[i + 2]) ||
        writeUnit(out, i, positions[i], positions[i + 1], positions[i + 2])
      )
    ) {
      out[i] = 0;
      out[i + 1] = 0;
      out[i + 2] = 1;
    }
  }
  return out;
}

/** The interior angle at vertex `a` of the triangle (a, b, c), in radians (atan2: accurate at 0 and π). */
function angle(p: ArrayLike<number>, a: number, b: number, c: number): number {
  const ux = p[b] - p[a];
  const uy = p[b + 1] - p[a + 1];
  const uz = p[b + 2] - p[a + 2];
  const vx = p[c] - p[a];
  const vy = p[c + 1] - p[a + 1];
  const vz = p[c + 2] - p[a + 2];
  const cx = uy * vz - uz * vy;
  const cy = uz * vx - ux * vz;
  const cz = ux * vy - uy * vx;
  return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz);
}

/** Write (x, y, z) / |(x, y, z)| at out[i] when that is finite and non-zero; tell whether it was. */
function writeUnit(out: Float32Array, i: number, x: number, y: number, z: number): boolean {
  // Scale first so tiny (1e-200) and huge (1e200) vectors normalise without underflow or overflow.
  const m = Math.max(Math.abs(x), Math.abs(y), Math.abs(z));
  if (!(m > 0) || !Number.isFinite(m)) return false;
  const sx = x / m;
  const sy = y / m;
  const sz = z / m;
  const length = Math.sqrt(sx * sx + sy * sy + sz * sz);
  out[i] = sx / length;
  out[i + 1] = sy / length;
  out[i + 2] = sz / length;
  return true;
}

/** sums[v‥v+2] += (x, y, z). */
function add(sums: Float64Array, v: number, x: number, y: number, z: number): void {
  sums[v] += x;
  sums[v + 1] += y;
  sums[v + 2] += z;
}
