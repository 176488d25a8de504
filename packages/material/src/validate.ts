// Internal argument checks shared by ShadingMaterial, PhongLight and OutlineMaterial: errors name the parameter,
// the value and the allowed range.
import { Color } from 'three';

/**
 * A colour or an intensity, as this package reads it (the rule is stated once in the package README,
 * "Colours and intensities"):
 * - a number is a **grey level**: the same linear value on r, g and b, as the lecture writes its intensities
 *   (Ia = 0.2 is `0.2`); never a hex colour;
 * - a string is a CSS colour, sRGB (`'#ff8000'`, `'orange'`, `'rgb(255, 128, 0)'`): write hex colours so;
 * - a `THREE.Color` is copied as is (linear: `new Color(0xff8000)` is three's sRGB hex converted);
 * - `[r, g, b]` is linear RGB.
 */
export type ColorInput = number | string | Color | readonly [number, number, number];

function show(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (Array.isArray(value)) return `[${value.map(show).join(', ')}]`;
  if (value instanceof Color) return `Color(${value.r}, ${value.g}, ${value.b})`;
  return String(value);
}

/**
 * Largest coefficient, colour channel or exponent accepted: 1e18, so that every product the material uploads
 * (kd·Id, ks·Is, the ambient sum over the lights) stays finite in float32 uniforms (largest ≈ 3.4e38).
 */
export const MAX_COEFFICIENT = 1e18;

/** Throws unless `value` is a finite number in 0 … {@link MAX_COEFFICIENT}. */
export function checkNonNegative(name: string, value: unknown): number {
  if (typeof value !== 'number') throw new TypeError(`${name} must be a number, got ${show(value)}`);
  if (!Number.isFinite(value) || value < 0) {
    throw new RangeError(`${name} must be a finite number ≥ 0, got ${show(value)}`);
  }
  if (value > MAX_COEFFICIENT) {
    throw new RangeError(`${name} must be at most 1e18 (float32 uniforms), got ${show(value)}`);
  }
  return value;
}

/** Throws unless `value` is a number in 0 … 1 (opacity, alphaTest). */
export function checkUnit(name: string, value: unknown): number {
  if (typeof value !== 'number') throw new TypeError(`${name} must be a number, got ${show(value)}`);
  if (!(value >= 0 && value <= 1)) throw new RangeError(`${name} must be in 0 … 1, got ${show(value)}`);
  return value;
}

/** Throws unless `value` is null or a three.js Texture. */
export function checkTexture<T>(name: string, value: T): T {
  if (
    value !== null &&
    (typeof value !== 'object' || (value as { isTexture?: unknown }).isTexture !== true)
  ) {
    throw new TypeError(`${name} must be a THREE.Texture or null, got ${show(value)}`);
  }
  return value;
}

/** Throws unless `value` is one of `allowed`. */
export function checkOneOf<T extends string>(name: string, value: unknown, allowed: readonly T[]): T {
  if (!allowed.includes(value as T)) {
    throw new TypeError(
      `${name} must be one of ${allowed.map((a) => `'${a}'`).join(', ')}, got ${show(value)}`,
    );
  }
  return value as T;
}

/** Throws unless every channel of `color` is finite, ≥ 0 and at most {@link MAX_COEFFICIENT}. */
export function checkColorChannels(name: string, color: Color): Color {
  if (![color.r, color.g, color.b].every((c) => Number.isFinite(c) && c >= 0)) {
    throw new RangeError(`${name} must have finite channels ≥ 0 (linear RGB), got ${show(color)}`);
  }
  if (![color.r, color.g, color.b].every((c) => c <= MAX_COEFFICIENT)) {
    throw new RangeError(`${name} must have channels at most 1e18 (float32 uniforms), got ${show(color)}`);
  }
  return color;
}

/** What `setColor` accepts, for its error messages. */
const FORMS = "a grey level (number), a CSS colour string ('#rrggbb'), a Color or linear [r, g, b]";

/**
 * Parse `value` (a {@link ColorInput}) into `target` (linear working space) after checking it; `target` is left
 * untouched on error. A number is a grey level in 0 … `maxGrey`: the outline colour, shown as is, takes 0 … 1
 * so that a three-style hex number (0xff8000) is refused, not read as a grey.
 */
export function setColor(name: string, target: Color, value: ColorInput, maxGrey = MAX_COEFFICIENT): Color {
  const parsed = new Color();
  if (Array.isArray(value)) {
    if (value.length !== 3 || !value.every((c) => typeof c === 'number')) {
      throw new TypeError(`${name} must be ${FORMS}, got ${show(value)}`);
    }
    parsed.setRGB(value[0], value[1], value[2]);
  } else if (value instanceof Color || (typeof value === 'object' && value !== null && 'isColor' in value)) {
    parsed.copy(value as Color);
  } else if (typeof value === 'number') {
    if (!(Number.isFinite(value) && value >= 0 && value <= maxGrey)) {
      const range = maxGrey === MAX_COEFFICIENT ? '0 … 1e18' : `0 … ${maxGrey}`;
      const hex =
        Number.isInteger(value) && value > maxGrey && value <= 0xffffff
          ? ` (a hex colour is written '#${value.toString(16).padStart(6, '0')}' or new Color(0x${value.toString(16).padStart(6, '0')}))`
          : '';
      throw new RangeError(
        `${name} as a number is a grey level (the same linear value on r, g and b) in ${range}${hex}, got ${show(value)}`,
      );
    }
    parsed.setRGB(value, value, value);
  } else if (typeof value === 'string') {
    parsed.setRGB(Number.NaN, 0, 0);
    parsed.setStyle(value);
    if (Number.isNaN(parsed.r)) {
      throw new TypeError(`${name} must be a CSS colour string three understands, got ${show(value)}`);
    }
  } else {
    throw new TypeError(`${name} must be ${FORMS}, got ${show(value)}`);
  }
  checkColorChannels(name, parsed);
  return target.copy(parsed);
}
