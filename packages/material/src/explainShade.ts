// The lecture's equation at one point, term by term: what `shade()` sums, kept apart. Three-free.
import { linearToSrgb8 } from './linearToSrgb8.js';
import {
  halfVector,
  lightFactors,
  newLightFactors,
  RECIPROCAL_PI,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeSample,
  type ShadeThreeLight,
  viewAndNormal,
} from './shade.js';
import { length, type Vec3, type Vec3Like } from './vec3.js';

/** `h` normalised; zero where it is zero (l = −v). */
function unitOrZero(h: Vec3): Vec3 {
  const hl = length(h);
  return hl > 0 ? [h[0] / hl, h[1] / hl, h[2] / hl] : [0, 0, 0];
}

/** One light's part of the lecture's equation at a point (all vectors world space, unit length). */
export interface LightExplanation {
  /** `'phong'` for a {@link ShadeLight} (a `PhongLight`), else the type of three's light. */
  readonly kind: 'phong' | ShadeThreeLight['type'];
  /** l: the unit vector from the point towards the light; null for ambient and hemisphere lights. */
  readonly l: Vec3 | null;
  /** t: the distance from the point to the light, world units; null for directional, ambient and hemisphere lights. */
  readonly t: number | null;
  /**
   * The attenuation that multiplies the light's diffuse and specular terms: 1 / max(a + b·t + c·t², 1e-6) for a
   * `PhongLight` (1 without attenuation), three's distance falloff (× the spot cone) for three's point and spot
   * lights, 1 for a directional light and 0 for ambient and hemisphere lights (they have only Ia).
   */
  readonly attenuation: number;
  /** v: the unit vector from the point towards the eye (the same for every light). */
  readonly v: Vec3;
  /** r = 2(l·n)n − l, the mirrored light direction (`'phong'` lighting); null otherwise. */
  readonly r: Vec3 | null;
  /** h = (l + v)/|l + v|, the half vector (`'blinn-phong'` lighting; [0, 0, 0] when l = −v); null otherwise. */
  readonly h: Vec3 | null;
  /** l·n (before the max); null without l. */
  readonly lDotN: number | null;
  /** The specular cosine before the power: max(v·r, 0) or max(n·h, 0); 0 where l·n ≤ 0. */
  readonly cosine: number;
  /** The diffuse factor max(l·n, 0), quantised to its band when lighting is cel. */
  readonly diffuseFactor: number;
  /** The specular factor cosine^α (0⁰ = 1, 0 where l·n ≤ 0), 0 or 1 when lighting is cel. */
  readonly specularFactor: number;
  /** The cel band of max(l·n, 0): 0 (darkest) … celBands − 1; null when cel is off or the light has no l. */
  readonly band: number | null;
  /** Ia, the ambient intensity as the equation uses it (linear RGB; three's ambient and hemisphere lights: irradiance / π). */
  readonly ia: Vec3;
  /** Id, the diffuse intensity as the equation uses it (linear RGB; three's lights: colour × intensity / π). */
  readonly id: Vec3;
  /** Is, the specular intensity as the equation uses it (linear RGB; three's lights: colour × intensity / π). */
  readonly is: Vec3;
  /** The ambient term ka·Ia (× the sample's tint), linear RGB. */
  readonly ambient: Vec3;
  /** The diffuse term att·kd·Id·max(l·n, 0) (× the tint), linear RGB. */
  readonly diffuse: Vec3;
  /** The specular term att·ks·Is·spec, linear RGB. */
  readonly specular: Vec3;
}

/** The lecture's equation at a point, light by light, and what the screen shows of it. */
export interface ShadeExplanation {
  /** n: the unit normal `shade` lit with (a zero normal falls back to v). */
  readonly n: Vec3;
  /** v: the unit vector towards the eye. */
  readonly v: Vec3;
  /** Each light's vectors and terms, in the order of the `lights` given. */
  readonly lights: readonly LightExplanation[];
  /** The material's emissive colour, added once outside the sum (linear RGB). */
  readonly emissive: Vec3;
  /** The sum: exactly `shade(sample, material, lights)` (linear RGB, not clamped). */
  readonly sum: Vec3;
  /** The sum clamped to [0, 1] per channel (what the 8-bit colour buffer keeps). */
  readonly clamped: Vec3;
  /** The displayed colour: 8-bit sRGB codes 0 … 255, as `linearToSrgb8` of the sum. */
  readonly srgb8: [number, number, number];
}

const WHITE: Vec3Like = [1, 1, 1];

const copy = (a: Vec3Like): Vec3 => [a[0], a[1], a[2]];

function checkVector(name: string, value: unknown, size: number): void {
  const a = value as ArrayLike<unknown> | null | undefined;
  if (a === null || typeof a !== 'object' || typeof a.length !== 'number' || a.length < size) {
    throw new TypeError(`explainShade: ${name} must be an array of ${size} numbers, got ${String(value)}`);
  }
  for (let i = 0; i < size; i++) {
    if (typeof a[i] !== 'number' || !Number.isFinite(a[i])) {
      throw new RangeError(`explainShade: ${name}[${i}] must be a finite number, got ${String(a[i])}`);
    }
  }
}

/**
 * The lecture's equation at one point, term by term, for the same inputs as {@link shade}:
 *
 * I = Σ_L ka·Ia_L + att_L(t)·( kd·Id_L·max(l·n, 0) + ks·Is_L·spec )  (+ emissive)
 *
 * For each light: l, t, the attenuation, v, r (Phong lighting) or h (Blinn-Phong), l·n, the specular cosine, the
 * cel band, and each term (ka·Ia, att·kd·Id·max(l·n, 0), att·ks·Is·spec); then the sum, which is exactly what
 * `shade()` returns (the same operations in the same order), the sum clamped to [0, 1] and the displayed 8-bit
 * sRGB colour. The terms are rounded as `shade` rounds them inside its sum, so their total may differ from
 * `sum` in the last bits only. Degenerate inputs follow `shade`'s rules (a light at the point: l = n; an eye at
 * the point: v = n; a zero normal: n = v).
 *
 * For teaching and debugging, not a hot path: unlike `shade`, it validates the sample.
 *
 * @param sample - The point, its normal and the eye (world space), and the tint (see {@link ShadeSample}).
 * @param material - ka, kd, ks, shininess, lighting, cel bands, emissive (see {@link ShadeMaterial}).
 * @param lights - `PhongLight`s as {@link ShadeLight}s and three's lights as {@link ShadeThreeLight}s.
 * @returns the explanation; `sum` equals `shade(sample, material, lights)`.
 * @throws TypeError when the sample's position, normal or eye is not an array of numbers, or `lights` is not an
 *   array; RangeError when one of their components is not finite.
 */
export function explainShade(
  sample: ShadeSample,
  material: ShadeMaterial,
  lights: readonly (ShadeLight | ShadeThreeLight)[],
): ShadeExplanation {
  checkVector('sample.position', sample?.position, 3);
  checkVector('sample.normal', sample?.normal, 3);
  checkVector('sample.eye', sample?.eye, 3);
  if (!Array.isArray(lights))
    throw new TypeError(`explainShade: lights must be an array, got ${String(lights)}`);
  const { position: p, tint = WHITE } = sample;
  const { ka, kd, ks, lighting = 'phong', celBands = 0 } = material;
  const v: Vec3 = [0, 0, 0];
  const n: Vec3 = [0, 0, 0];
  viewAndNormal(sample, v, n);
  const f = newLightFactors();
  const explained: LightExplanation[] = [];
  let r = 0;
  let g = 0;
  let b = 0;
  for (const light of lights) {
    lightFactors(light, p, n, v, material, f);
    const { ia, id, is, l, ndl } = f;
    if (f.ambientOnly) {
      // The same operations as shade()'s, so that the sum is its sum to the bit.
      const ambient: Vec3 = [
        tint[0] * ka[0] * ia[0] * RECIPROCAL_PI,
        tint[1] * ka[1] * ia[1] * RECIPROCAL_PI,
        tint[2] * ka[2] * ia[2] * RECIPROCAL_PI,
      ];
      r += ambient[0];
      g += ambient[1];
      b += ambient[2];
      explained.push({
        kind: (light as ShadeThreeLight).type,
        l: null,
        t: null,
        attenuation: 0,
        v: copy(v),
        r: null,
        h: null,
        lDotN: null,
        cosine: 0,
        diffuseFactor: 0,
        specularFactor: 0,
        band: null,
        ia: [ia[0] * RECIPROCAL_PI, ia[1] * RECIPROCAL_PI, ia[2] * RECIPROCAL_PI],
        id: [0, 0, 0],
        is: [0, 0, 0],
        ambient,
        diffuse: [0, 0, 0],
        specular: [0, 0, 0],
      });
      continue;
    }
    const dTerm = f.att * f.diffuse;
    const sTerm = f.att * f.spec;
    r += tint[0] * (ka[0] * ia[0] + dTerm * kd[0] * id[0]) + sTerm * ks[0] * is[0];
    g += tint[1] * (ka[1] * ia[1] + dTerm * kd[1] * id[1]) + sTerm * ks[1] * is[1];
    b += tint[2] * (ka[2] * ia[2] + dTerm * kd[2] * id[2]) + sTerm * ks[2] * is[2];
    // three's lights carry three's 1/π in att; the explanation puts it into Id and Is, where the lecture has it.
    const scale = 'type' in light ? RECIPROCAL_PI : 1;
    explained.push({
      kind: 'type' in light ? light.type : 'phong',
      l: copy(l),
      t: Number.isNaN(f.t) ? null : f.t,
      attenuation: f.falloff,
      v: copy(v),
      r:
        lighting === 'blinn-phong'
          ? null
          : [2 * ndl * n[0] - l[0], 2 * ndl * n[1] - l[1], 2 * ndl * n[2] - l[2]],
      h: lighting === 'blinn-phong' ? unitOrZero(halfVector(l, v)) : null,
      lDotN: ndl,
      cosine: f.x,
      diffuseFactor: f.diffuse,
      specularFactor: f.spec,
      band: celBands > 0 ? Math.min(Math.floor(Math.max(ndl, 0) * celBands), celBands - 1) : null,
      ia: copy(ia),
      id: [id[0] * scale, id[1] * scale, id[2] * scale],
      is: [is[0] * scale, is[1] * scale, is[2] * scale],
      ambient: [tint[0] * ka[0] * ia[0], tint[1] * ka[1] * ia[1], tint[2] * ka[2] * ia[2]],
      diffuse: [
        tint[0] * dTerm * kd[0] * id[0],
        tint[1] * dTerm * kd[1] * id[1],
        tint[2] * dTerm * kd[2] * id[2],
      ],
      specular: [sTerm * ks[0] * is[0], sTerm * ks[1] * is[1], sTerm * ks[2] * is[2]],
    });
  }
  const e = material.emissive;
  const sum: Vec3 = e === undefined ? [r, g, b] : [r + e[0], g + e[1], b + e[2]];
  const clamp = (c: number) => (Number.isNaN(c) ? 0 : Math.min(Math.max(c, 0), 1));
  return {
    n,
    v,
    lights: explained,
    emissive: e === undefined ? [0, 0, 0] : copy(e),
    sum,
    clamped: [clamp(sum[0]), clamp(sum[1]), clamp(sum[2])],
    srgb8: linearToSrgb8(sum),
  };
}
