import type { Vector3, Vector3Like } from 'three';
import { finite } from './validateProjection.js';

/**
 * A point or direction: a three.js `Vector3`, any `{ x, y, z }`, an `[x, y, z]` tuple (the lecture's vec3) or a
 * 3-element `Float32Array`/`Float64Array`.
 */
export type Vec3Input = Vector3Like | readonly [number, number, number] | Float32Array | Float64Array;

/**
 * Copy `input` into `target`, refusing what is not three finite numbers.
 * @throws TypeError when `input` is neither `{ x, y, z }` nor a 3-element array; RangeError on NaN or ±Infinity.
 * @internal
 */
export function readVector3(input: unknown, name: string, target: Vector3): Vector3 {
  let x: unknown;
  let y: unknown;
  let z: unknown;
  if (
    (Array.isArray(input) || input instanceof Float32Array || input instanceof Float64Array) &&
    input.length === 3
  ) {
    [x, y, z] = input;
  } else if (typeof input === 'object' && input !== null && 'x' in input && 'y' in input && 'z' in input) {
    ({ x, y, z } = input as Vector3Like);
  } else {
    throw new TypeError(
      `${name} must be a Vector3, {x, y, z}, [x, y, z] or 3-element typed array, got ${String(input)}`,
    );
  }
  if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') {
    throw new TypeError(`${name} must have numeric x, y, z, got (${typeof x}, ${typeof y}, ${typeof z})`);
  }
  if (!finite(x) || !finite(y) || !finite(z)) {
    throw new RangeError(`${name} must be finite, got (${x}, ${y}, ${z}); allowed: finite numbers`);
  }
  return target.set(x, y, z);
}

/**
 * `v`, unless a coordinate is beyond ±1e30 world units (or NaN): then a RangeError naming `name`. Camera positions
 * stay within this bound so that view matrices stay finite in float32, as they are uploaded.
 * @internal
 */
export function checkCoordinates(v: Vector3, name: string): Vector3 {
  if (!(Math.max(Math.abs(v.x), Math.abs(v.y), Math.abs(v.z)) <= 1e30)) {
    throw new RangeError(`${name} must be within ±1e30, got (${v.x}, ${v.y}, ${v.z})`);
  }
  return v;
}

/**
 * Normalise `v` in place without underflow or overflow (scales by its largest component first).
 * @returns false, leaving `v` unchanged, when `v` is the zero vector.
 * @internal
 */
export function safeNormalize(v: Vector3): boolean {
  const m = Math.max(Math.abs(v.x), Math.abs(v.y), Math.abs(v.z));
  if (m === 0) return false;
  // Divide (three's divideScalar multiplies by 1/m, which overflows to Infinity for a subnormal m).
  v.set(v.x / m, v.y / m, v.z / m).normalize(); // length now in [1, √3]
  return true;
}
