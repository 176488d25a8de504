/**
 * The attenuation plot's pure part: the lecture's factor 1/(a + b·t + c·t²) of each light, the distances t from a
 * light to the object (from the object's bounding sphere), and the curve over the distances the scene spans.
 */
import { MIN_ATTENUATION_DENOMINATOR } from '@shadelab/material';
import type { LightState, Vec3 } from '../state/schema';

/** A bounding sphere in world units. */
export interface BoundingSphere {
  readonly center: Vec3;
  /** Radius, world units (≥ 0). */
  readonly radius: number;
}

/** One light's curve: samples of the factor over [0, tMax], and the object's range of t from this light. */
export interface AttenuationCurve {
  /** `[t, factor]` pairs, t from 0 to the plot's tMax, world units. */
  readonly points: [number, number][];
  /** Nearest and farthest t from the light to the object's bounding sphere, world units. */
  readonly range: readonly [near: number, far: number];
  /** The factor at the range's ends. */
  readonly atRange: readonly [near: number, far: number];
}

/** What the plot draws: every light's curve over [0, tMax] and the y axis's top. */
export interface AttenuationPlotData {
  /** Largest distance plotted, world units: 1.15 × the farthest point of the object from any light. */
  readonly tMax: number;
  /** Top of the y axis. */
  readonly yMax: number;
  readonly curves: AttenuationCurve[];
}

/**
 * The lecture's attenuation factor 1/(a + b·t + c·t²), its denominator clamped to at least
 * `MIN_ATTENUATION_DENOMINATOR` as `shade()` and the materials clamp it.
 *
 * @param attenuation - The light's a, b, c (≥ 0).
 * @param t - Distance from the light, world units (≥ 0).
 */
export function attenuationFactor({ a, b, c }: LightState['attenuation'], t: number): number {
  if (!(t >= 0 && Number.isFinite(t)))
    throw new RangeError(`attenuationFactor: t ${t} is not a finite number ≥ 0`);
  return 1 / Math.max(a + b * t + c * t * t, MIN_ATTENUATION_DENOMINATOR);
}

/**
 * The distances from a light to the points of a bounding sphere: [max(0, d − r), d + r], d the distance to its
 * centre (0 at the near end when the light is inside the sphere).
 *
 * @param light - The light's world position.
 * @param sphere - The object's bounding sphere.
 */
export function distanceRange(light: Vec3, sphere: BoundingSphere): [number, number] {
  if (!(sphere.radius >= 0)) throw new RangeError(`distanceRange: radius ${sphere.radius} is not ≥ 0`);
  const d = Math.hypot(light[0] - sphere.center[0], light[1] - sphere.center[1], light[2] - sphere.center[2]);
  return [Math.max(0, d - sphere.radius), d + sphere.radius];
}

/**
 * Every light's curve over the distances the scene spans (0 to 1.15 × the farthest range end), `samples` + 1
 * points each, with the object's range of t; the y axis tops at 1.1 × the largest factor shown (at most 4 × the
 * factor at the near end of the object's range, and at least 1, so that a light with a = 0, whose factor grows
 * without bound towards t = 0, does not flatten the others).
 *
 * @param lights - The lights (position and attenuation).
 * @param sphere - The object's bounding sphere.
 * @param samples - Intervals per curve (integer ≥ 1). @default 96
 */
export function attenuationPlot(
  lights: readonly Pick<LightState, 'position' | 'attenuation'>[],
  sphere: BoundingSphere,
  samples = 96,
): AttenuationPlotData {
  if (!Number.isInteger(samples) || samples < 1) {
    throw new RangeError(`attenuationPlot: samples ${samples} is not an integer ≥ 1`);
  }
  const ranges = lights.map((l) => distanceRange(l.position, sphere));
  const tMax = Math.max(1e-6, 1.15 * Math.max(0, ...ranges.map((r) => r[1])));
  let top = 0;
  const curves = lights.map((light, i) => {
    const f = (t: number) => attenuationFactor(light.attenuation, t);
    const range = ranges[i]!;
    top = Math.max(top, Math.min(f(0), Math.max(1, 4 * f(range[0]))));
    const points: [number, number][] = [];
    for (let k = 0; k <= samples; k++) {
      const t = (tMax * k) / samples;
      points.push([t, f(t)]);
    }
    return { points, range, atRange: [f(range[0]), f(range[1])] as const };
  });
  return { tMax, yMax: 1.1 * Math.max(top, 1e-6), curves };
}
