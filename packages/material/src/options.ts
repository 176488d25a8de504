// Internal: the options both shading materials take (ShadingMaterial for WebGLRenderer, ShadingNodeMaterial for
// WebGPURenderer), defined once: their defaults and their checks, each error naming the owner's class, the
// parameter, the value and the allowed range.
import { PhongLight } from './PhongLight.js';
import { MAX_CEL_BANDS, SHADINGS, type Shading } from './ShadingMaterial.js';
import { LIGHTINGS, type Lighting } from './shade.js';
import { checkOneOf } from './validate.js';

/** The defaults of the shading options (the lecture's material). */
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
