import { assertSphereBase, SPHERE_BASES, type SphereBase } from './SphereBase.js';
import { sphereCounts } from './sphereCounts.js';
import { MAX_SPHERE_ERROR_LEVEL, sphereError } from './sphereError.js';
import { assertLevel, fail, mustBe } from './validate.js';

/** Options of {@link chooseSphereDetail}. */
export interface ChooseSphereDetailOptions {
  /** The sphere's radius on screen, in pixels. Finite and ≥ 0. */
  radiusPx: number;
  /** Largest acceptable radial error on screen, in pixels. Finite and > 0. */
  maxErrorPx: number;
  /**
   * Base solids to choose from (a non-empty list).
   * @default ['tetrahedron', 'octahedron', 'icosahedron']
   */
  bases?: readonly SphereBase[];
  /**
   * Highest level considered, an integer from 0 to 20.
   * @default 10
   */
  maxLevel?: number;
}

/** The cheapest subdivision sphere meeting a screen-space error budget. */
export interface SphereDetail {
  /** Base solid. */
  readonly base: SphereBase;
  /** Subdivision level. */
  readonly level: number;
  /** Triangles drawn: F0 · 4^level. */
  readonly triangles: number;
  /**
   * Largest radial error on screen, in pixels: radiusPx · sphereError(base, level) ≤ maxErrorPx, for the
   * exact-vertex mesh (float32 positions add up to about radiusPx · 2^-24, not budgeted).
   */
  readonly errorPx: number;
}

/**
 * The cheapest base and level whose largest radial error on screen, errorPx = radiusPx · sphereError(base,
 * level), is at most `maxErrorPx`. Cheapest means fewest triangles. Ties cannot happen between bases (their
 * triangle counts are 4^(level+1), 2·4^(level+1) and 5·4^(level+1), never equal); if a caller's base list
 * repeated a base, the first wins.
 *
 * `errorPx` is the error of the exact-vertex mesh. The float32 mesh `subdivideSphere` returns may differ from it
 * by up to about radiusPx · 2^-24 (6e-8 of the radius: see `sphereError`); that is deliberately not budgeted,
 * since it stays below 1e-4 px for any radiusPx up to 1000 and below 1e-3 px up to 16,000, far under any
 * budget a display can show, and the GPU's own float32 vertex transform rounds by the same order.
 *
 * @example
 * ```ts
 * chooseSphereDetail({ radiusPx: 300, maxErrorPx: 0.5 });
 * // → { base: 'icosahedron', level: 4, triangles: 5120, errorPx: 0.341… }
 * ```
 * @throws RangeError / TypeError naming the option for a bad radiusPx, maxErrorPx, bases or maxLevel.
 * @throws RangeError when no base in `bases` meets the budget at `maxLevel` or below (it gives the smallest
 * error reachable).
 */
export function chooseSphereDetail(options: ChooseSphereDetailOptions): SphereDetail {
  const caller = 'chooseSphereDetail';
  if (options === null || typeof options !== 'object') {
    throw new TypeError(mustBe(caller, 'options', 'an object', options));
  }
  const { radiusPx, maxErrorPx, bases = SPHERE_BASES, maxLevel = 10 } = options;
  if (typeof radiusPx !== 'number' || !(radiusPx >= 0) || !Number.isFinite(radiusPx)) {
    fail(caller, 'radiusPx', 'a finite number ≥ 0', radiusPx, 'number');
  }
  if (typeof maxErrorPx !== 'number' || !(maxErrorPx > 0) || !Number.isFinite(maxErrorPx)) {
    fail(caller, 'maxErrorPx', 'a finite number > 0', maxErrorPx, 'number');
  }
  if (!Array.isArray(bases)) throw new TypeError(mustBe(caller, 'bases', 'an array of base names', bases));
  if (bases.length === 0) throw new RangeError(`${caller}: bases must name at least one base; got []`);
  bases.forEach((b, i) => {
    assertSphereBase(caller, `bases[${i}]`, b);
  });
  assertLevel(caller, 'maxLevel', maxLevel, MAX_SPHERE_ERROR_LEVEL);

  let best: SphereDetail | undefined;
  for (const base of bases) {
    // Errors fall with the level, so the first level that fits is this base's cheapest.
    for (let level = 0; level <= maxLevel; level++) {
      const { triangles } = sphereCounts(base, level);
      if (best && triangles >= best.triangles) break;
      const errorPx = radiusPx * sphereError(base, level);
      if (errorPx <= maxErrorPx) {
        best = { base, level, triangles, errorPx };
        break;
      }
    }
  }
  if (!best) {
    const reachable = Math.min(...bases.map((b) => radiusPx * sphereError(b, maxLevel)));
    throw new RangeError(
      `${caller}: no base in [${bases.join(', ')}] up to maxLevel ${maxLevel} keeps the error within maxErrorPx = ${maxErrorPx}; the smallest is ${reachable} px (raise maxLevel or maxErrorPx)`,
    );
  }
  return best;
}
