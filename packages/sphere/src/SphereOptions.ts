import { assertSphereBase, type SphereBase } from './SphereBase.js';
import { assertLevel, fail, mustBe } from './validate.js';

/** Which normals a subdivision sphere carries. */
export type SphereNormals = 'smooth' | 'flat' | 'none';

/** Default memory limit of `subdivideSphere` and `SubdivisionSphereGeometry`: 512 MiB. */
export const DEFAULT_SPHERE_MAX_BYTES = 512 * 1024 * 1024;

/** Smallest radius accepted: 1e-30 (positions are float32; much smaller ones lose precision, then vanish). */
export const MIN_SPHERE_RADIUS = 1e-30;

/** Largest radius accepted: 1e30 (positions are float32, whose largest value is about 3.4e38). */
export const MAX_SPHERE_RADIUS = 1e30;

/** Options of `subdivideSphere` and `SubdivisionSphereGeometry`. */
export interface SubdivideSphereOptions {
  /**
   * Subdivision level: how many times every triangle is split into four. An integer ≥ 0; the cost grows 4× per
   * level, bounded only by `maxBytes`.
   * @default 6 (the lecture's `Sphere(6)`)
   */
  level?: number;
  /**
   * Base solid. `'tetrahedron'` is the lecture's (a vertex at (0, 0, 1)); `'octahedron'` and `'icosahedron'`
   * are three.js's `OctahedronGeometry` and `IcosahedronGeometry` at detail 0.
   * @default 'tetrahedron'
   */
  base?: SphereBase;
  /**
   * Sphere radius, in scene units: every vertex lies at this distance from the origin. From 1e-30 to 1e30
   * ({@link MIN_SPHERE_RADIUS}, {@link MAX_SPHERE_RADIUS}): positions are float32.
   * @default 1
   */
  radius?: number;
  /**
   * `'smooth'`: the exact sphere normal, position / radius. `'flat'`: each triangle's face normal on its three
   * corners (needs non-indexed output, since a corner shared by several faces has several normals).
   * `'none'`: no normal array (shaders can use the normalised position).
   * @default 'smooth'
   */
  normals?: SphereNormals;
  /**
   * Indexed output (shared vertices, V = 2 + T/2, Uint16 indices while V ≤ 65,536, else Uint32) or a plain
   * triangle soup (3 vertices per triangle). `normals: 'flat'` with `indexed: true` is a RangeError.
   * @default true, or false when `normals` is 'flat'
   */
  indexed?: boolean;
  /**
   * Memory limit in bytes for everything the build allocates (outputs and scratch), checked against
   * `estimateSphereBytes` before anything is allocated. > 0; `Infinity` disables the check.
   * @default 536870912 (512 MiB, {@link DEFAULT_SPHERE_MAX_BYTES})
   */
  maxBytes?: number;
}

/** Options with every default applied and every value validated. */
export interface SphereParameters {
  /** Subdivision level, an integer ≥ 0. */
  readonly level: number;
  /** Base solid. */
  readonly base: SphereBase;
  /** Radius in scene units, > 0. */
  readonly radius: number;
  /** Normals carried. */
  readonly normals: SphereNormals;
  /** Whether vertices are shared through an index. */
  readonly indexed: boolean;
  /** Memory limit in bytes. */
  readonly maxBytes: number;
}

const NORMALS: readonly SphereNormals[] = ['smooth', 'flat', 'none'];

/**
 * Apply defaults and validate. Throws RangeError / TypeError naming the option, the value and the allowed
 * range.
 * @internal
 */
export function resolveSphereOptions(caller: string, options: SubdivideSphereOptions): SphereParameters {
  if (options === null || typeof options !== 'object') {
    throw new TypeError(mustBe(caller, 'options', 'an object', options));
  }
  const {
    level = 6,
    base = 'tetrahedron',
    radius = 1,
    normals = 'smooth',
    maxBytes = DEFAULT_SPHERE_MAX_BYTES,
  } = options;
  assertLevel(caller, 'level', level);
  assertSphereBase(caller, 'base', base);
  if (typeof radius !== 'number' || !(radius >= MIN_SPHERE_RADIUS && radius <= MAX_SPHERE_RADIUS)) {
    fail(caller, 'radius', 'a number from 1e-30 to 1e30', radius, 'number');
  }
  if (!NORMALS.includes(normals)) fail(caller, 'normals', "'smooth', 'flat' or 'none'", normals, 'string');
  const indexed = options.indexed ?? normals !== 'flat';
  if (typeof indexed !== 'boolean') fail(caller, 'indexed', 'true or false', indexed, 'boolean');
  if (indexed && normals === 'flat') {
    throw new RangeError(
      `${caller}: normals 'flat' needs indexed: false (a vertex shared by several faces has several face normals); got indexed: true`,
    );
  }
  if (typeof maxBytes !== 'number' || !(maxBytes > 0)) {
    fail(caller, 'maxBytes', 'a number > 0 (Infinity allowed)', maxBytes, 'number');
  }
  return { level, base, radius, normals, indexed, maxBytes };
}
