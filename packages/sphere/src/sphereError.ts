import { assertSphereBase, baseSolid, type SphereBase } from './SphereBase.js';
import { assertLevel } from './validate.js';

/** Highest level `sphereError` accepts: 20 (error about 4e-12 of the radius; double rounding in the vertices limits the relative precision there to about 1e-4, and deeper levels only get worse). */
export const MAX_SPHERE_ERROR_LEVEL = 20;

/** Computed errors, per base, per level. */
const memo = /* @__PURE__ */ new Map<SphereBase, number[]>();

/**
 * The exact maximum radial error of the unit subdivision sphere: the largest 1 − |p| over all points p on
 * the flat triangles of `subdivideSphere({ base, level, radius: 1 })` (vertices in double precision). Scale by
 * the radius for other spheres: error = radius · sphereError(base, level).
 *
 * Derivation. For a triangle with unit vertices and p = Σ wᵢXᵢ (wᵢ ≥ 0, Σ wᵢ = 1),
 * |p|² = 1 − Σᵢ<ⱼ wᵢwⱼ cᵢⱼ² with cᵢⱼ the chords. Its minimum is at the foot of the perpendicular from the
 * centre, which is the circumcentre: 1 − |p|² = ρ² (ρ the planar circumradius) when the triangle is acute;
 * when the circumcentre falls outside (a right or obtuse triangle) the minimum is at the midpoint of the
 * longest edge: 1 − |p|² = c_max²/4. So a face's error is 1 − √(1 − ρ²) or 1 − √(1 − c_max²/4). On a
 * near-equilateral face (ρ² = c²/3) that is about c²/6, 4/3 of the edge sagitta (about c²/8): the sagitta alone
 * understates it.
 *
 * Float32. The mesh `subdivideSphere` returns stores float32 coordinates, which adds to this exact error up to
 * about radius · 2^-24 (rounding a coordinate moves it by at most half an ulp, 2^-24 of its size; a face moves
 * with its corners), either sign: tested within radius · 2^-23 at levels 6–10, measured at most
 * 0.43 · 2^-24 · radius (6e-8 of the radius at worst, but 0.5 % of the error itself at tetrahedron level 10,
 * where the error is 3.8e-6). `chooseSphereDetail` does not budget it: see there.
 *
 * Search. All base faces are congruent under the solid's rotations and subdivision commutes with rotations,
 * so one base face is searched, depth first, centre child first. A subtree is skipped when no descendant can
 * beat the best face so far: a face's error is at most 1 − √(1 − c_max²/3), and a child's longest chord is at
 * most c/√(4 − c²) for a parent's longest chord c (from the haversine law: the arc between two edge midpoints
 * is at most half the third side over the cosine of half the longest side). Memoised per base and level; the
 * first call at level 10 takes milliseconds.
 *
 * @param base - Base solid.
 * @param level - Subdivision level, an integer from 0 to {@link MAX_SPHERE_ERROR_LEVEL}.
 * @returns The error as a fraction of the radius, in (0, 1).
 * @throws RangeError / TypeError naming `base` or `level` for an unknown base or a bad level.
 */
export function sphereError(base: SphereBase, level: number): number {
  assertSphereBase('sphereError', 'base', base);
  assertLevel('sphereError', 'level', level, MAX_SPHERE_ERROR_LEVEL);
  let errors = memo.get(base);
  if (!errors) {
    errors = [];
    memo.set(base, errors);
  }
  const known = errors[level];
  if (known !== undefined) return known;
  const { vertices: v, faces } = baseSolid(base);
  const a = 3 * faces[0];
  const b = 3 * faces[1];
  const c = 3 * faces[2];
  const search = new Search(level);
  search.visit(v[a], v[a + 1], v[a + 2], v[b], v[b + 1], v[b + 2], v[c], v[c + 1], v[c + 2], level);
  errors[level] = search.best;
  return search.best;
}

/**
 * The error 1 − min |p| of the flat triangle with unit vertices a, b, c, given its squared chords (exact, see
 * {@link sphereError}).
 * @internal
 */
export function faceError(ab2: number, bc2: number, ca2: number, cross2: number): number {
  const longest = Math.max(ab2, bc2, ca2);
  // x = 1 − min |p|²: the circumradius² when acute, else a quarter of the longest chord².
  const x = 2 * longest >= ab2 + bc2 + ca2 ? longest / 4 : (ab2 * bc2 * ca2) / (4 * cross2);
  return x / (1 + Math.sqrt(1 - x));
}

/** Depth-first branch and bound over one base face. */
class Search {
  best = 0;
  /** Squared chord a face `k` levels above the leaves must exceed to possibly hold a better leaf. */
  readonly threshold: Float64Array;

  constructor(level: number) {
    this.threshold = new Float64Array(level + 1);
  }

  /** Record a leaf error; recompute the pruning thresholds when it is the new best. */
  private found(error: number): void {
    if (error <= this.best) return;
    this.best = error;
    // Leaf bound 1 − √(1 − c²/3) equals `best` at c² = 3·best·(2 − best); invert c ↦ c/√(4 − c²) upwards.
    let y2 = 3 * error * (2 - error);
    const t = this.threshold;
    for (let k = 0; k < t.length; k++) {
      t[k] = y2 * (1 - 1e-9); // a little slack for rounding: never skip a face that could win
      y2 = (4 * y2) / (1 + y2);
    }
  }

  visit(
    ax: number,
    ay: number,
    az: number,
    bx: number,
    by: number,
    bz: number,
    cx: number,
    cy: number,
    cz: number,
    k: number,
  ): void {
    const ux = bx - ax;
    const uy = by - ay;
    const uz = bz - az;
    const vx = cx - bx;
    const vy = cy - by;
    const vz = cz - bz;
    const wx = ax - cx;
    const wy = ay - cy;
    const wz = az - cz;
    const ab2 = ux * ux + uy * uy + uz * uz;
    const bc2 = vx * vx + vy * vy + vz * vz;
    const ca2 = wx * wx + wy * wy + wz * wz;
    if (k === 0) {
      const nx = uy * vz - uz * vy;
      const ny = uz * vx - ux * vz;
      const nz = ux * vy - uy * vx;
      this.found(faceError(ab2, bc2, ca2, nx * nx + ny * ny + nz * nz));
      return;
    }
    if (Math.max(ab2, bc2, ca2) <= this.threshold[k]) return;
    let x = ax + bx;
    let y = ay + by;
    let z = az + bz;
    let s = 1 / Math.sqrt(x * x + y * y + z * z);
    const m0x = x * s;
    const m0y = y * s;
    const m0z = z * s;
    x = bx + cx;
    y = by + cy;
    z = bz + cz;
    s = 1 / Math.sqrt(x * x + y * y + z * z);
    const m1x = x * s;
    const m1y = y * s;
    const m1z = z * s;
    x = cx + ax;
    y = cy + ay;
    z = cz + az;
    s = 1 / Math.sqrt(x * x + y * y + z * z);
    const m2x = x * s;
    const m2y = y * s;
    const m2z = z * s;
    const j = k - 1;
    this.visit(m0x, m0y, m0z, m1x, m1y, m1z, m2x, m2y, m2z, j);
    this.visit(ax, ay, az, m0x, m0y, m0z, m2x, m2y, m2z, j);
    this.visit(m0x, m0y, m0z, bx, by, bz, m1x, m1y, m1z, j);
    this.visit(m2x, m2y, m2z, m1x, m1y, m1z, cx, cy, cz, j);
  }
}
