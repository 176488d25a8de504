import { describeValue } from './describeValue.js';

/** The solid a subdivision sphere starts from: the lecture's tetrahedron, or three.js's octahedron or icosahedron. */
export type SphereBase = 'tetrahedron' | 'octahedron' | 'icosahedron';

/** Every base solid, in the order `chooseSphereDetail` lists and tie-breaks them. */
export const SPHERE_BASES: readonly SphereBase[] = /* @__PURE__ */ Object.freeze([
  'tetrahedron',
  'octahedron',
  'icosahedron',
]);

const ALLOWED = "'tetrahedron', 'octahedron' or 'icosahedron'";

/**
 * Throw unless `base` names a base solid: a TypeError for a non-string, a RangeError for an unknown name.
 * @param caller - Function name for the message.
 * @param name - Parameter name for the message.
 * @internal
 */
export function assertSphereBase(caller: string, name: string, base: unknown): asserts base is SphereBase {
  if (typeof base !== 'string') {
    throw new TypeError(`${caller}: ${name} must be ${ALLOWED}; got ${describeValue(base)}`);
  }
  if (!(SPHERE_BASES as readonly string[]).includes(base)) {
    throw new RangeError(`${caller}: ${name} must be ${ALLOWED}; got '${base}'`);
  }
}
