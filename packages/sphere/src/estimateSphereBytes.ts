import { baseSolid } from './SphereBase.js';
import { resolveSphereOptions, type SphereParameters, type SubdivideSphereOptions } from './SphereOptions.js';

/**
 * Bytes `subdivideSphere` allocates for these options: the output arrays plus its scratch (an edge table and
 * per-triangle edge ids for the last two levels before the final one), summed over every typed array it
 * creates. Exact to within a few hundred bytes; computed without allocating.
 *
 * Per triangle T of the final mesh, roughly: indexed without normals 24–26 bytes (positions 6, indices 6 or 12,
 * scratch 7.5), smooth normals +6; non-indexed adds 36 for positions and 36 for normals.
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
  bytes += V <= 65536 ? 6 * T : 12 * T; // indices
  if (level >= 1) bytes += 6 * T; // edge table + triangle edge ids of level L − 1
  if (level >= 2) bytes += 1.5 * T; // … of level L − 2 (levels alternate between the two)
  if (indexed) {
    if (normals === 'smooth') bytes += 12 * V;
  } else {
    bytes += 36 * T;
    if (normals !== 'none') bytes += 36 * T;
  }
  return bytes;
}
