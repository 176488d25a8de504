import type { SphereBase } from './SphereBase.js';

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

// The lecture's tetrahedron: a = (0, 0, 1), b = (0, 2√2/3, −1/3), c = (−√6/3, −√2/3, −1/3),
// d = (√6/3, −√2/3, −1/3); faces (d, c, b), (a, b, c), (a, d, b), (a, c, d).
const TETRAHEDRON: BaseSolid = {
  vertices: /* @__PURE__ */ Float64Array.of(
    0,
    0,
    1,
    0,
    (2 * S2) / 3,
    -1 / 3,
    -S6 / 3,
    -S2 / 3,
    -1 / 3,
    S6 / 3,
    -S2 / 3,
    -1 / 3,
  ),
  faces: /* @__PURE__ */ Uint8Array.of(3, 2, 1, 0, 1, 2, 0, 3, 1, 0, 2, 3),
};

// three.js's OctahedronGeometry: same vertices, same faces.
const OCTAHEDRON: BaseSolid = {
  vertices: /* @__PURE__ */ Float64Array.of(1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1),
  faces: /* @__PURE__ */ Uint8Array.of(
    0,
    2,
    4,
    0,
    4,
    3,
    0,
    3,
    5,
    0,
    5,
    2,
    1,
    2,
    5,
    1,
    5,
    3,
    1,
    3,
    4,
    1,
    4,
    2,
  ),
};

// three.js's IcosahedronGeometry: its vertices (±1, ±φ, 0) and cyclic permutations, normalised; same faces.
const ICOSAHEDRON: BaseSolid = {
  vertices: /* @__PURE__ */ normalized([
    -1,
    PHI,
    0,
    1,
    PHI,
    0,
    -1,
    -PHI,
    0,
    1,
    -PHI,
    0,
    0,
    -1,
    PHI,
    0,
    1,
    PHI,
    0,
    -1,
    -PHI,
    0,
    1,
    -PHI,
    PHI,
    0,
    -1,
    PHI,
    0,
    1,
    -PHI,
    0,
    -1,
    -PHI,
    0,
    1,
  ]),
  faces: /* @__PURE__ */ Uint8Array.of(
    0,
    11,
    5,
    0,
    5,
    1,
    0,
    1,
    7,
    0,
    7,
    10,
    0,
    10,
    11,
    1,
    5,
    9,
    5,
    11,
    4,
    11,
    10,
    2,
    10,
    7,
    6,
    7,
    1,
    8,
    3,
    9,
    4,
    3,
    4,
    2,
    3,
    2,
    6,
    3,
    6,
    8,
    3,
    8,
    9,
    4,
    9,
    5,
    2,
    4,
    11,
    6,
    2,
    10,
    8,
    6,
    7,
    9,
    8,
    1,
  ),
};

function normalized(xyz: number[]): Float64Array {
  const out = new Float64Array(xyz);
  for (let i = 0; i < out.length; i += 3) {
    const s = 1 / Math.hypot(out[i], out[i + 1], out[i + 2]);
    out[i] *= s;
    out[i + 1] *= s;
    out[i + 2] *= s;
  }
  return out;
}

/** The base solid named `base` (already validated). @internal */
export function baseSolid(base: SphereBase): BaseSolid {
  return base === 'tetrahedron' ? TETRAHEDRON : base === 'octahedron' ? OCTAHEDRON : ICOSAHEDRON;
}
