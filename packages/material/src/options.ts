// The options both shading materials take (ShadingMaterial for WebGLRenderer, ShadingNodeMaterial for
// WebGPURenderer), defined once: their types and documentation, their defaults and their checks, each error
// naming the owner's class, the parameter, the value and the allowed range.
import { PhongLight } from './PhongLight.js';
import { LIGHTINGS, type Lighting } from './shade.js';
import { type ColorInput, checkOneOf } from './validate.js';

/**
 * Where the lighting equation is evaluated (the lecture's shading):
 * - `'flat'`: once per face, at the triangle's centroid with its face normal; one colour per face (a plain
 *   indexed geometry: per fragment, with its triangle's face normal from screen-space derivatives);
 * - `'gouraud'`: per vertex, colours interpolated;
 * - `'phong'`: per fragment, normals interpolated and renormalised.
 */
export type Shading = 'flat' | 'gouraud' | 'phong';

/** Every value of {@link Shading}, in documentation order. */
export const SHADINGS: readonly Shading[] = ['flat', 'gouraud', 'phong'];

/** Largest accepted `celBands`. */
export const MAX_CEL_BANDS = 255;

/** The lecture's options, taken alike by `ShadingMaterial` and `ShadingNodeMaterial`. */
export interface ShadingOptions {
  /** Where the lighting is evaluated. @default 'phong' */
  shading?: Shading;
  /** The lighting equation. @default 'phong' */
  lighting?: Lighting;
  /** 0 = off; N in 2 … 255 = cel shading with N diffuse shades and a hard-edged highlight. @default 0 */
  celBands?: number;
  /**
   * ka, ambient reflectance, linear. A number is a grey level (`0.5` = (0.5, 0.5, 0.5)), never a hex colour; a
   * colour is a CSS string (sRGB), a `THREE.Color` or linear `[r, g, b]` (see {@link ColorInput}).
   * @default [0.6, 0.35, 0.2]
   */
  ka?: ColorInput;
  /** kd, diffuse reflectance, linear; a number is a grey level (see {@link ColorInput}). @default [0.6, 0.35, 0.2] */
  kd?: ColorInput;
  /** ks, specular reflectance, linear; a number is a grey level (see {@link ColorInput}). @default 0.5 */
  ks?: ColorInput;
  /** α, the specular exponent: finite, ≥ 0 (0⁰ = 1: shininess 0 gives a uniform highlight). @default 32 */
  shininess?: number;
  /**
   * The PhongLights that light the material; any number. Empty: every visible PhongLight in the rendered
   * scene. @default []
   */
  lights?: readonly PhongLight[];
}

/** The defaults of {@link ShadingOptions} (the lecture's material). */
export const SHADING_DEFAULTS = Object.freeze({
  shading: 'phong' as Shading,
  lighting: 'phong' as Lighting,
  celBands: 0,
  ka: Object.freeze([0.6, 0.35, 0.2]) as readonly [number, number, number],
  kd: Object.freeze([0.6, 0.35, 0.2]) as readonly [number, number, number],
  ks: Object.freeze([0.5, 0.5, 0.5]) as readonly [number, number, number],
  shininess: 32,
});

/** `owner.shading`: one of {@link SHADINGS}, else a TypeError. */
export function checkShading(owner: string, value: unknown): Shading {
  return checkOneOf(`${owner}.shading`, value, SHADINGS);
}

/** `owner.lighting`: one of {@link LIGHTINGS}, else a TypeError. */
export function checkLighting(owner: string, value: unknown): Lighting {
  return checkOneOf(`${owner}.lighting`, value, LIGHTINGS);
}

/** `owner.celBands`: 0 (off) or an integer in 2 … {@link MAX_CEL_BANDS}; a TypeError or RangeError otherwise. */
export function checkCelBands(owner: string, value: unknown): number {
  if (typeof value !== 'number') {
    throw new TypeError(`${owner}.celBands must be a number, got ${String(value)}`);
  }
  if (!Number.isInteger(value) || value === 1 || value < 0 || value > MAX_CEL_BANDS) {
    throw new RangeError(
      `${owner}.celBands must be 0 (off) or an integer in 2 … ${MAX_CEL_BANDS}, got ${value}`,
    );
  }
  return value;
}

/** `owner.lights`: an array of PhongLight, else a TypeError naming the bad entry; returns a frozen copy. */
export function checkPhongLights(owner: string, value: unknown): readonly PhongLight[] {
  if (!Array.isArray(value)) {
    throw new TypeError(`${owner}.lights must be an array of PhongLight, got ${String(value)}`);
  }
  value.forEach((light, i) => {
    if (!(light instanceof PhongLight)) {
      throw new TypeError(`${owner}.lights[${i}] must be a PhongLight, got ${String(light)}`);
    }
  });
  return Object.freeze([...value]);
}
