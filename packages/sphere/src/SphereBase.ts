import { fail } from './fail.js';

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
