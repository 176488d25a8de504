// The outline's options, defaults and checks: one definition for OutlineMaterial (WebGLRenderer) and
// OutlineNodeMaterial (WebGPURenderer), which differ only in how they draw the hull.
import type { BufferGeometry, Color } from 'three';
import { SPHERE_FLAG } from './geometryFlags.js';
import { type ColorInput, checkNonNegative, setColor } from './validate.js';

/** Options of `OutlineMaterial` and `OutlineNodeMaterial` (and of `createOutline` and `createOutlineNode`). */
export interface OutlineMaterialOptions {
  /** Outline width in world units, measured along the surface normal. Finite, ≥ 0. @default 0.03 */
  thickness?: number;
  /**
   * Outline colour, read like every colour of this package (see {@link ColorInput}): a CSS string is sRGB
   * (`'#f2f2f2'`), a `THREE.Color` or `[r, g, b]` is linear, and a number is a grey level in 0 … 1 (so a
   * three-style hex number such as `0xff8000` is refused with its `'#ff8000'` spelling, never misread).
   * @default 0 (black)
   */
  color?: ColorInput;
}

/** The defaults of {@link OutlineMaterialOptions}. */
export const OUTLINE_DEFAULTS = {
  thickness: 0.03,
  color: 0,
} as const satisfies Required<OutlineMaterialOptions>;

/** `value` checked as the outline width of `owner` (`'OutlineMaterial'`, …): finite, ≥ 0 (a RangeError names it). */
export function checkThickness(owner: string, value: number): number {
  return checkNonNegative(`${owner}.thickness`, value);
}

/** `value` checked as the outline colour of `owner` (a grey number in 0 … 1) and copied into `target`. */
export function setOutlineColor(owner: string, target: Color, value: ColorInput): Color {
  return setColor(`${owner}.color`, target, value, 1);
}

/**
 * Whether the outline of `geometry` is pushed along analytic sphere normals (normal = position): it has no
 * `normal` attribute and is a sphere centred at its origin (`SubdivisionSphereGeometry`, or `userData.isSphere`),
 * as `ShadingMaterial` reads it.
 */
export function outlineSphereNormals(geometry: BufferGeometry): boolean {
  return (
    geometry.getAttribute('normal') === undefined &&
    (geometry.type === 'SubdivisionSphereGeometry' || geometry.userData?.[SPHERE_FLAG] === true)
  );
}
