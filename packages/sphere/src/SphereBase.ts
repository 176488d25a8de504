import { fail } from './validate.js';

/** The solid a subdivision sphere starts from: the lecture's tetrahedron, or three.js's octahedron or icosahedron. */
export type SphereBase = 'tetrahedron' | 'octahedron' | 'icosahedron';

/** Every base solid, in the order `chooseSphereDetail` lists and tie-breaks them. */
export const SPHERE_BASES: readonly SphereBase[] = /* @__PURE__ */ Object.freeze([
  'tetrahedron',
  'octahedron',
  'icosahedron',
]);

/**
 * Throw unless `base` names a base solid: a TypeError for a non-string, a RangeError for an unknown name.
 * @param caller - Function name for the message.
 * @param name - Parameter name for the message.
 * @internal
 */
export function assertSphereBase(caller: string, name: string, base: unknown): asserts base is SphereBase {
  if (!(SPHERE_BASES as readonly unknown[]).includes(base)) {
    fail(caller, name, "'tetrahedron', 'octahedron' or 'icosahedron'", base, 'string');
  }
}

/** A base solid: unit vertices and outward counter-clockwise triangles. @internal */
export interface BaseSolid {
  /** Unit vertex positions, x, y, z per vertex. */
  readonly vertices: Float64Array;
  /** Vertex indices, 3 per triangle, counter-clockwise seen from outside. */
  readonly faces: Uint8Array;
}

const S2 = Math.SQRT2;
const S6 = Math.sqrt(6);
const PHI = (1 + Math.sqrt(5)) / 2;
// The icosahedron's (±1, ±φ, 0) normalised: (±A, ±B, 0).
const A = 1 / Math.hypot(1, PHI, 0);
const B = PHI * A;

// (Float64Array.of / Uint8Array.of rather than array literals: the bundled output keeps them on one line.)
const SOLIDS: Readonly<Record<SphereBase, BaseSolid>> = {
  // The lecture's tetrahedron: a = (0, 0, 1), b = (0, 2√2/3, −1/3), c = (−√6/3, −√2/3, −1/3),
  // d = (√6/3, −√2/3, −1/3); faces (d, c, b), (a, b, c), (a, d, b), (a, c, d).
  tetrahedron: {
    // biome-ignore format: x, y, z per vertex
    vertices: /* @__PURE__ */ Float64Array.of(0, 0, 1, 0, (2 * S2) / 3, -1 / 3, -S6 / 3, -S2 / 3, -1 / 3, S6 / 3, -S2 / 3, -1 / 3),
    faces: /* @__PURE__ */ Uint8Array.of(3, 2, 1, 0, 1, 2, 0, 3, 1, 0, 2, 3),
  },
  // three.js's OctahedronGeometry: same vertices, same faces.
  octahedron: {
    vertices: /* @__PURE__ */ Float64Array.of(1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1),
    // biome-ignore format: 3 per face
    faces: /* @__PURE__ */ Uint8Array.of(0, 2, 4, 0, 4, 3, 0, 3, 5, 0, 5, 2, 1, 2, 5, 1, 5, 3, 1, 3, 4, 1, 4, 2),
  },
  // three.js's IcosahedronGeometry: its vertices (±1, ±φ, 0) and cyclic permutations, normalised; same faces.
  icosahedron: {
    // biome-ignore format: x, y, z per vertex
    vertices: /* @__PURE__ */ Float64Array.of(-A, B, 0, A, B, 0, -A, -B, 0, A, -B, 0, 0, -A, B, 0, A, B, 0, -A, -B, 0, A, -B, B, 0, -A, B, 0, A, -B, 0, -A, -B, 0, A),
    // biome-ignore format: 3 per face
    faces: /* @__PURE__ */ Uint8Array.of(0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1),
  },
};

/** The base solid named `base` (already validated). @internal */
export function baseSolid(base: SphereBase): BaseSolid {
  return SOLIDS[base];
}
