import { baseSolid } from './SphereBase.js';
import { resolveSphereOptions, type SphereParameters, type SubdivideSphereOptions } from './SphereOptions.js';

/**
 * Bytes `subdivideSphere` allocates for these options: the sum of the byte lengths of every typed array it
 * creates (outputs and scratch), exactly; computed without allocating.
 *
 * Per triangle T of the final mesh (V = 2 + T/2 vertices): positions 12V ≈ 6T; Uint32 indices (V > 65,536) 12T,
 * with the scratch (edge tables, triangle edge ids) inside them, so nothing more; Uint16 indices (smaller
 * meshes) 6T plus a 12T scratch array. Smooth indexed normals add 12V; non-indexed output adds 36T of positions
 * and 36T of normals (unless `normals: 'none'`), built from the indexed mesh.
 *
 * Under the default 512 MiB limit every base builds indexed up to level 10 with any normals (the icosahedron
 * at level 10 with smooth normals takes 503,316,528 bytes); non-indexed level 10 fits only for the
 * tetrahedron, and for the octahedron with `normals: 'none'`.
 *
 * @param options - Same options as `subdivideSphere` (defaults applied, validated; `maxBytes` is ignored).
 * @returns Bytes; `Infinity` for absurd levels (past about 509), whose counts overflow a double: more than any
 * limit, so they are refused by size.
 */
export function estimateSphereBytes(options: SubdivideSphereOptions = {}): number {
  return bytesFor(resolveSphereOptions('estimateSphereBytes', options));
}

/** {@link estimateSphereBytes} for resolved options. @internal */
export function bytesFor({ base, level, normals, indexed }: SphereParameters): number {
  // Counts as in sphereCounts, but Infinity (not an error) past 2^1024: an absurd level is then refused by size.
  const T = (baseSolid(base).faces.length / 3) * 4 ** level;
  const V = 2 + T / 2;
  let bytes = 12 * V; // positions of the shared vertices
  if (level === 0)
    bytes += 6 * T; // Uint16 indices of the base solid
  else bytes += V <= 65536 ? 18 * T : 12 * T; // Uint16 indices + Uint32 scratch, or Uint32 indices holding it
  if (indexed) {
    if (normals === 'smooth') bytes += 12 * V;
  } else {
    bytes += 36 * T;
    if (normals !== 'none') bytes += 36 * T;
  }
  return bytes;
}
