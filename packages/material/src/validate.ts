// Internal argument checks shared by ShadingMaterial and PhongLight: errors name the parameter, the value
// and the allowed range.
import { Color, type ColorRepresentation } from 'three';

/** A colour input: anything `THREE.Color.set` takes (hex and CSS strings are sRGB), or linear `[r, g, b]`. */
export type ColorInput = ColorRepresentation | readonly [number, number, number];

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

/** Parse `value` into `target` (linear working space) after checking it; `target` is left untouched on error. */
export function setColor(name: string, target: Color, value: ColorInput): Color {
  const parsed = new Color();
  if (Array.isArray(value)) {
    if (value.length !== 3 || !value.every((c) => typeof c === 'number')) {
      throw new TypeError(
        `${name} must be a Color, a hex number, a CSS string or [r, g, b], got ${show(value)}`,
      );
    }
    parsed.setRGB(value[0], value[1], value[2]);
  } else if (value instanceof Color || (typeof value === 'object' && value !== null && 'isColor' in value)) {
    parsed.copy(value as Color);
  } else if (typeof value === 'number') {
    if (!Number.isInteger(value) || value < 0 || value > 0xffffff) {
      throw new RangeError(`${name} as a hex number must be an integer in 0 … 0xffffff, got ${show(value)}`);
    }
    parsed.setHex(value);
  } else if (typeof value === 'string') {
    parsed.setRGB(Number.NaN, 0, 0);
    parsed.setStyle(value);
    if (Number.isNaN(parsed.r)) {
      throw new TypeError(`${name} must be a CSS colour string three understands, got ${show(value)}`);
    }
  } else {
    throw new TypeError(
      `${name} must be a Color, a hex number, a CSS string or [r, g, b], got ${show(value)}`,
    );
  }
  checkColorChannels(name, parsed);
  return target.copy(parsed);
}
