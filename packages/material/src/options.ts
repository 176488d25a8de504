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

/**
 * What the material draws, a debugging aid for app developers (the lecture's terms one at a time). With the
 * material's emissive E, the lit colour before fog, tone mapping and the output clamp is
 * colour = E + ambient + diffuse + specular, each term summed over the lights:
 * - `'color'`: the lit colour (the default; the only output whose program is the material's usual one);
 * - `'ambient'`: Σ ka·Ia (three's ambient and hemisphere lights: ka × their irradiance / π), × the tint;
 * - `'diffuse'`: Σ att·kd·Id·max(l·n, 0), × the tint (three's lights: Id = colour / π × falloff × shadow);
 * - `'specular'`: Σ att·ks·Is·spec (Phong or Blinn-Phong, cel-quantised when `celBands` > 0);
 * - `'attenuation'`: grey, the mean over the direct lights (PhongLights and three's directional, point and spot
 *   lights; not ambient or hemisphere lights) of each light's factor: 1/max(a + b·t + c·t², 1e-6) for a
 *   PhongLight, three's distance falloff × spot cone × shadow factor for three's lights (three's 1/π is part of
 *   Id and Is, not of the attenuation). 1 = unattenuated, values above 1 show as white; no direct light: 0;
 * - `'normal'`: the unit normal the lighting uses (the face's in flat shading, the vertex's interpolated in
 *   Gouraud, the fragment's in Phong; a back face's turned round), in view space, as three's
 *   `MeshNormalMaterial` shows it: rgb = n·0.5 + 0.5.
 *
 * The three terms are evaluated exactly as in the colour (shading, lighting, cel bands, the tint, shadows) with
 * the other terms left out, and leave out the emissive and the fog, but keep the tone mapping and output
 * colour space: with three's default `NoToneMapping`, decoding each to linear and adding them gives the
 * colour (less E) where it is not clamped. `'attenuation'` and `'normal'` are data, written without tone
 * mapping, colour-space conversion or fog (as `MeshNormalMaterial` writes its normal). Each non-default output
 * is a variant of its own (a define on `WebGLRenderer`, a build-time branch on `WebGPURenderer`): the colour's
 * program does not change.
 */
export type ShadingOutput = 'color' | 'ambient' | 'diffuse' | 'specular' | 'attenuation' | 'normal';

/** Every value of {@link ShadingOutput}, in documentation order. */
export const SHADING_OUTPUTS: readonly ShadingOutput[] = [
  'color',
  'ambient',
  'diffuse',
  'specular',
  'attenuation',
  'normal',
];

/**
 * How object normals are transformed to world space, a teaching aid (the lecture's slide on the normal
 * matrix):
 * - `'inverse-transpose'`: by the normal matrix (M⁻¹)ᵀ of the model matrix M's 3 × 3 part (computed as
 *   sign(det M)·cof(M), the same direction, finite for a singular M: see `computeNormalMatrix`): normals stay
 *   perpendicular to the surface under any scale (the default, and the right way);
 * - `'model'`: by M itself, the lecture's wrong way: under a non-uniform scale the normals lean towards the
 *   stretched axis and are no longer perpendicular to the surface (under a uniform scale or a rotation they are
 *   the same as the default's, once normalised). Only the object's model matrix is affected (an
 *   InstancedMesh's instance matrices and an object-space `normalMap` keep their normal matrix).
 *   Compiled only when chosen (a define on `WebGLRenderer`, a build-time branch on `WebGPURenderer`).
 */
export type NormalMatrixMode = 'inverse-transpose' | 'model';

/** Every value of {@link NormalMatrixMode}, in documentation order. */
export const NORMAL_MATRIX_MODES: readonly NormalMatrixMode[] = ['inverse-transpose', 'model'];

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
  /**
   * What the material draws: the lit colour, or one term of the lecture's equation, the attenuation or the
   * normal alone, for debugging a look (see {@link ShadingOutput} for exactly what each shows). Compiled only
   * when not `'color'`. @default 'color'
   */
  output?: ShadingOutput;
  /**
   * How normals go to world space: `'inverse-transpose'` (right) or `'model'` (the model matrix itself, the
   * lecture's wrong way under a non-uniform scale): a teaching aid (see {@link NormalMatrixMode}). Compiled only
   * when `'model'`. @default 'inverse-transpose'
   */
  normalMatrix?: NormalMatrixMode;
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
  output: 'color' as ShadingOutput,
  normalMatrix: 'inverse-transpose' as NormalMatrixMode,
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

/**
 * `owner.name` one of `allowed`: a TypeError when not a string, a RangeError naming the parameter, the value
 * and the allowed values when a string outside them.
 */
function checkChoice<T extends string>(
  owner: string,
  name: string,
  value: unknown,
  allowed: readonly T[],
): T {
  const list = allowed.map((a) => `'${a}'`).join(', ');
  if (typeof value !== 'string') {
    throw new TypeError(`${owner}.${name} must be one of ${list}, got ${String(value)}`);
  }
  if (!allowed.includes(value as T)) {
    throw new RangeError(`${owner}.${name} must be one of ${list}, got ${JSON.stringify(value)}`);
  }
  return value as T;
}

/** `owner.output`: one of {@link SHADING_OUTPUTS}; a TypeError (not a string) or RangeError otherwise. */
export function checkOutput(owner: string, value: unknown): ShadingOutput {
  return checkChoice(owner, 'output', value, SHADING_OUTPUTS);
}

/** `owner.normalMatrix`: one of {@link NORMAL_MATRIX_MODES}; a TypeError (not a string) or RangeError otherwise. */
export function checkNormalMatrix(owner: string, value: unknown): NormalMatrixMode {
  return checkChoice(owner, 'normalMatrix', value, NORMAL_MATRIX_MODES);
}
