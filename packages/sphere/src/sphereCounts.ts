import { assertSphereBase, baseSolid, type SphereBase } from './SphereBase.js';
import { assertLevel, fail } from './validate.js';

/** Element counts of a subdivision sphere. */
export interface SphereCounts {
  /** Triangles: T = F0 · 4^level, with F0 = 4, 8 or 20 for the tetrahedron, octahedron or icosahedron. */
  readonly triangles: number;
  /** Distinct vertices (the indexed vertex count): V = 2 + T / 2 (Euler, V − E + F = 2). */
  readonly vertices: number;
  /** Distinct edges: E = 3T / 2. */
  readonly edges: number;
}

/**
 * Exact element counts of the sphere `subdivideSphere({ base, level })` builds, without building it.
 *
 * @param base - Base solid.
 * @param level - Subdivision level, an integer ≥ 0 (counts past 2^53 lose precision, as numbers do) whose
 * triangle count is a finite number: up to 509 (icosahedron) or 510 (tetrahedron, octahedron).
 * @throws RangeError / TypeError for an unknown base or a level that is not an integer ≥ 0, and RangeError for a
 * level whose counts would be infinite.
 */
export function sphereCounts(base: SphereBase, level: number): SphereCounts {
  assertSphereBase('sphereCounts', 'base', base);
  assertLevel('sphereCounts', 'level', level);
  const triangles = (baseSolid(base).faces.length / 3) * 4 ** level;
  if (triangles === Number.POSITIVE_INFINITY) {
    fail('sphereCounts', 'level', 'an integer ≥ 0 whose counts are finite (at most 509 or 510)', level);
  }
  return { triangles, vertices: 2 + triangles / 2, edges: (3 * triangles) / 2 };
}
