// The lighting equation on the CPU, three-free: the reference the GPU shaders are tested against.
import { dot, length, normalizeOr, sub, type Vec3, type Vec3Like, type Vec4Like } from './vec3.js';

/**
 * The lighting equation (the lecture's names):
 * - `'phong'`: specular = max(v·r, 0)^α with r = 2(l·n)n − l;
 * - `'blinn-phong'`: specular = max(n·h, 0)^α with h = normalize(l + v).
 */
export type Lighting = 'phong' | 'blinn-phong';

/** Every value of {@link Lighting}, in documentation order. */
export const LIGHTINGS: readonly Lighting[] = ['phong', 'blinn-phong'];

/** Attenuation constants: the light's diffuse and specular terms are divided by a + b·t + c·t², t = distance. */
export interface Attenuation {
  /** Constant term. @default 1 */
  readonly a: number;
  /** Linear term, per world unit. @default 0 */
  readonly b: number;
  /** Quadratic term, per world unit². @default 0 */
  readonly c: number;
}

/**
 * The attenuation denominator a + b·t + c·t² is clamped to at least this value, so a light at the surface
 * (t = 0) with a = 0 stays finite: the attenuation factor never exceeds 1 / 1e-6 = 10⁶.
 */
export const MIN_ATTENUATION_DENOMINATOR = 1e-6;

/** A light as `shade` sees it: world position and the lecture's Ia, Id, Is (linear RGB). */
export interface ShadeLight {
  /** World-space position. */
  readonly position: Vec3Like;
  /** Ia: ambient intensity, linear RGB. */
  readonly ambient: Vec3Like;
  /** Id: diffuse intensity, linear RGB. */
  readonly diffuse: Vec3Like;
  /** Is: specular intensity, linear RGB. */
  readonly specular: Vec3Like;
  /** Attenuation constants. @default { a: 1, b: 0, c: 0 } (none) */
  readonly attenuation?: Attenuation;
}

/**
 * One of three's lights as `shade` (and `ShadingMaterial`) maps it onto the lecture's equation, as three's own
 * materials receive it: with three's factor 1/π (`BRDF_Lambert`), Id = Is = `color` / π (three's colour ×
 * intensity, linear), three's own falloff in place of 1/(a + b·t + c·t²), and ambient and hemisphere lights as
 * Ia (their irradiance / π). So `{ ka: c, kd: c, ks: 0 }` lights a point as `MeshLambertMaterial({ color: c })`
 * and `MeshPhongMaterial({ color: c, specular: 0 })` do:
 * - `'ambient'`: Ia = color / π;
 * - `'hemisphere'`: Ia = mix(groundColor, color, 0.5·(n·direction) + 0.5) / π (three's sky/ground blend);
 * - `'directional'`: l = direction, no falloff;
 * - `'point'`: falloff 1/max(t^decay, 0.01), times (1 − (t/distance)⁴)² clamped to 0 … 1 when distance > 0;
 * - `'spot'`: the point light's falloff times smoothstep(coneCos, penumbraCos, l·direction).
 */
export interface ShadeThreeLight {
  /** Which of three's lights. */
  readonly type: 'ambient' | 'hemisphere' | 'directional' | 'point' | 'spot';
  /**
   * Colour × intensity, linear RGB (a hemisphere light's sky colour × intensity). A point in the light's shadow
   * takes its colour × three's shadow factor (1 − `shadow.intensity` in full shadow), as `ShadingMaterial` does.
   */
  readonly color: Vec3Like;
  /** World position (point, spot). @default [0, 0, 0] */
  readonly position?: Vec3Like;
  /**
   * Unit world direction towards the light, from its target (directional, spot), or the sky direction
   * (hemisphere: the light's position, normalised). @default [0, 1, 0]
   */
  readonly direction?: Vec3Like;
  /** Cut-off distance, world units; 0 = none (point, spot). @default 0 */
  readonly distance?: number;
  /** Decay exponent of the distance falloff (point, spot). @default 2 */
  readonly decay?: number;
  /** cos(angle) (spot). @default 0 */
  readonly coneCos?: number;
  /** cos(angle·(1 − penumbra)) (spot). @default 0 */
  readonly penumbraCos?: number;
  /** Ground colour × intensity, linear RGB (hemisphere). @default [0, 0, 0] */
  readonly groundColor?: Vec3Like;
}

/** three's distance falloff of a point or spot light at distance `t` (see {@link ShadeThreeLight}). */
export function threeDistanceFalloff(t: number, distance: number, decay: number): number {
  let falloff = 1 / Math.max(t ** decay, 0.01);
  if (distance > 0) {
    const k = Math.min(Math.max(1 - (t / distance) ** 4, 0), 1);
    falloff *= k * k;
  }
  return falloff;
}

/** GLSL's smoothstep (three's spot cone). Internal (explainShade.ts shares it): not re-exported. */
export function smoothstep(e0: number, e1: number, x: number): number {
  const t = Math.min(Math.max((x - e0) / (e1 - e0), 0), 1);
  return t * t * (3 - 2 * t);
}

/** A material as `shade` sees it: the lecture's ka, kd, ks (linear RGB) and α. */
export interface ShadeMaterial {
  /** ka: ambient reflectance, linear RGB. */
  readonly ka: Vec3Like;
  /** kd: diffuse reflectance, linear RGB. */
  readonly kd: Vec3Like;
  /** ks: specular reflectance, linear RGB. */
  readonly ks: Vec3Like;
  /** α (Phong) or β (Blinn-Phong): the specular exponent, ≥ 0. 0⁰ is taken as 1 (see {@link specularPower}). */
  readonly shininess: number;
  /** The lighting equation. @default 'phong' */
  readonly lighting?: Lighting;
  /** Cel bands: 0 = off, N ≥ 2 = N diffuse shades and a hard-edged highlight (see {@link celDiffuse}). @default 0 */
  readonly celBands?: number;
  /**
   * Emitted colour, linear RGB, added to the sum outside the lighting (three's `emissive`; with an
   * `emissiveMap`, pass emissive × its texel). @default [0, 0, 0]
   */
  readonly emissive?: Vec3Like;
}

/** The point being lit, all in world space. */
export interface ShadeSample {
  /** World-space position of the point. */
  readonly position: Vec3Like;
  /**
   * World-space normal, any length: it is normalised here. A zero normal (degenerate transform or face)
   * falls back to the direction towards the viewer, so the result stays finite.
   */
  readonly normal: Vec3Like;
  /**
   * The eye as a homogeneous point: `[x, y, z, 1]` is a perspective camera's position; `[x, y, z, 0]` is an
   * orthographic camera's backward (+w) axis, the constant direction towards the viewer. A 3-element eye
   * is taken as a position (w = 1).
   */
  readonly eye: Vec4Like;
  /**
   * A colour that multiplies ka and kd (not ks), linear RGB: what `ShadingMaterial` does with an
   * `InstancedMesh`'s `instanceColor`, a `BatchedMesh`'s colour, a vertex colour and a texel of `map` (pass
   * their product). @default [1, 1, 1]
   */
  readonly tint?: Vec3Like;
}

/**
 * x^α for the specular term, with x = max(cosine, 0). GLSL leaves pow(0, 0) undefined; here 0⁰ = 1, so
 * shininess 0 gives a constant specular ks·Is over the whole lit side (l·n > 0). For α > 0, 0^α = 0.
 */
export function specularPower(x: number, shininess: number): number {
  if (x > 0) return x ** shininess;
  return shininess === 0 ? 1 : 0;
}

/**
 * The cel diffuse shade: the cosine max(l·n, 0) in [0, 1] quantised to `bands` shades
 * 0, 1/(N−1), …, 1: shade = min(floor(cosine·N), N−1) / (N−1).
 */
export function celDiffuse(cosine: number, bands: number): number {
  return Math.min(Math.floor(cosine * bands), bands - 1) / (bands - 1);
}

/** The cel highlight: 1 where the specular power is ≥ 0.5, else 0 (a hard edge). */
export function celSpecular(power: number): number {
  return power >= 0.5 ? 1 : 0;
}

/** three's factor of a light's colour (`BRDF_Lambert`): see {@link ShadeThreeLight}. Internal: not re-exported. */
export const RECIPROCAL_PI = 1 / Math.PI;

const AXIS_Z: Vec3Like = [0, 0, 1];
const WHITE: Vec3Like = [1, 1, 1];
const ZERO: Vec3Like = [0, 0, 0];
const UP: Vec3Like = [0, 1, 0];
/** shade()'s per-light scratch: the hot path allocates nothing per light. */
const scratch = newLightFactors();
const HALF: Vec3 = [0, 0, 0];

/** l + v, Blinn-Phong's half vector before normalisation, into `out`. @internal */
export function halfVector(l: Vec3Like, v: Vec3Like, out: Vec3 = [0, 0, 0]): Vec3 {
  out[0] = l[0] + v[0];
  out[1] = l[1] + v[1];
  out[2] = l[2] + v[2];
  return out;
}

/**
 * The unit view vector `v` and unit normal `n` of a sample, as `shade` lights it: an eye at the point uses v = n,
 * a zero normal n = v (+z when the eye is at the point too). @internal
 */
export function viewAndNormal(sample: ShadeSample, v: Vec3, n: Vec3): void {
  const { position: p, normal, eye } = sample;
  const eyeW = eye.length > 3 ? eye[3] : 1;
  const toEye: Vec3 = [eye[0] - p[0] * eyeW, eye[1] - p[1] * eyeW, eye[2] - p[2] * eyeW];
  const hasView = normalizeOr(v, toEye, AXIS_Z);
  normalizeOr(n, normal, v); // a zero normal falls back to v (+z when the eye is at the point)
  if (!hasView) {
    v[0] = n[0];
    v[1] = n[1];
    v[2] = n[2];
  }
}

/**
 * One light's part of the equation at a point, as `lightFactors` leaves it: what `shade` sums and `explainShade`
 * shows. @internal
 */
export interface LightFactors {
  /** three's ambient or hemisphere light: only `ia` (its irradiance, three's 1/π not applied) counts. */
  ambientOnly: boolean;
  /** Ia, Id, Is as given (a PhongLight's; three's direct lights: colour × intensity for Id and Is, Ia = 0). */
  ia: Vec3Like;
  id: Vec3Like;
  is: Vec3Like;
  /** What multiplies the diffuse and specular factors: a PhongLight's attenuation, three's 1/π × falloff. */
  att: number;
  /** The attenuation without three's 1/π: att for a PhongLight, three's falloff (× the spot cone), 1. */
  falloff: number;
  /** The distance to the light; NaN for directional, ambient and hemisphere lights. */
  t: number;
  /** The unit vector towards the light (the light's direction for a directional one). */
  readonly l: Vec3;
  /** l·n, the specular cosine (v·r or n·h, 0 where l·n ≤ 0), and the diffuse and specular factors (after cel). */
  ndl: number;
  x: number;
  diffuse: number;
  spec: number;
}

/** A new, zeroed {@link LightFactors} to pass to {@link lightFactors}. @internal */
export function newLightFactors(): LightFactors {
  return {
    ambientOnly: false,
    ia: ZERO,
    id: ZERO,
    is: ZERO,
    att: 1,
    falloff: 1,
    t: Number.NaN,
    l: [0, 0, 0],
    ndl: 0,
    x: 0,
    diffuse: 0,
    spec: 0,
  };
}

/**
 * Writes into `f` one light's part of the equation at the point `p` with unit normal `n` and unit view vector `v`
 * (see {@link shade} for the rules): the one evaluation `shade` and `explainShade` share. @internal
 */
export function lightFactors(
  light: ShadeLight | ShadeThreeLight,
  p: Vec3Like,
  n: Vec3Like,
  v: Vec3Like,
  material: ShadeMaterial,
  f: LightFactors,
): LightFactors {
  const { shininess, lighting = 'phong', celBands = 0 } = material;
  const l = f.l;
  f.ambientOnly = false;
  f.ia = ZERO;
  f.att = 1;
  f.t = Number.NaN;
  if ('type' in light) {
    const { type, color, position = ZERO, direction = UP, distance = 0, decay = 2 } = light;
    if (type === 'ambient' || type === 'hemisphere') {
      f.ambientOnly = true;
      if (type === 'ambient') f.ia = color;
      else {
        const ground = light.groundColor ?? ZERO;
        const w = 0.5 * dot(n, direction) + 0.5;
        f.ia = [0, 1, 2].map((k) => ground[k] + (color[k] - ground[k]) * w);
      }
      f.id = ZERO;
      f.is = ZERO;
      f.att = 0;
      f.falloff = 0;
      f.ndl = 0;
      f.x = 0;
      f.diffuse = 0;
      f.spec = 0;
      return f;
    }
    f.id = color;
    f.is = color;
    f.falloff = 1;
    if (type === 'directional') {
      l[0] = direction[0];
      l[1] = direction[1];
      l[2] = direction[2];
    } else {
      sub(l, position, p);
      f.t = length(l);
      normalizeOr(l, l, n);
      f.falloff = threeDistanceFalloff(f.t, distance, decay);
    }
    f.att = RECIPROCAL_PI * f.falloff; // three's 1/π, times the falloff
    if (type === 'spot') {
      const cone = smoothstep(light.coneCos ?? 0, light.penumbraCos ?? 0, dot(l, direction));
      f.att *= cone;
      f.falloff *= cone;
    }
  } else {
    f.ia = light.ambient;
    f.id = light.diffuse;
    f.is = light.specular;
    const { attenuation } = light;
    sub(l, light.position, p);
    f.t = length(l);
    normalizeOr(l, l, n);
    if (attenuation !== undefined) {
      f.att =
        1 /
        Math.max(
          attenuation.a + attenuation.b * f.t + attenuation.c * f.t * f.t,
          MIN_ATTENUATION_DENOMINATOR,
        );
    }
    f.falloff = f.att;
  }
  const ndl = dot(n, l);
  f.ndl = ndl;
  f.x = 0;
  f.diffuse = Math.max(ndl, 0);
  f.spec = 0;
  if (ndl > 0) {
    if (lighting === 'blinn-phong') {
      const h = halfVector(l, v, HALF);
      const hl = length(h);
      f.x = hl > 0 ? Math.max(dot(n, h) / hl, 0) : 0;
    }
    // r = 2(l·n)n − l, so v·r = 2(l·n)(v·n) − v·l.
    else f.x = Math.max(2 * ndl * dot(v, n) - dot(v, l), 0);
    f.spec = specularPower(f.x, shininess);
  }
  if (celBands > 0) {
    f.diffuse = celDiffuse(f.diffuse, celBands);
    f.spec = celSpecular(f.spec);
  }
  return f;
}

/**
 * The lighting equation at one point, summed over `lights` (linear RGB, not clamped):
 *
 * I = Σ_L ka·Ia_L + att_L(t)·( kd·Id_L·max(l·n, 0) + ks·Is_L·spec ),  att(t) = 1 / max(a + b·t + c·t², 1e-6)
 *
 * with l the unit vector to the light, t its distance, v the unit vector to the eye, spec 0 where l·n ≤ 0;
 * a sample's `tint` (instance colour × vertex colour × texel) multiplies the ka and kd terms, and the material's
 * `emissive` is added once, outside the sum. three's lights ({@link ShadeThreeLight})
 * enter the same sum as three's materials receive them: Id = Is = colour × intensity / π, three's falloff as
 * att and no Ia; ambient and hemisphere lights with Ia = irradiance / π only.
 * Degenerate inputs stay finite: a light at the point (t = 0) lights it head-on (l = n); an eye at the
 * point uses v = n; a zero normal uses n = v (or +z when the eye is at the point too); h = 0 (l = −v) gives
 * no Blinn-Phong highlight. The GPU shaders of `ShadingMaterial` implement exactly these rules.
 *
 * Inputs are not validated (this is the hot reference path); `ShadingMaterial` and `PhongLight` validate theirs.
 *
 * @param out receives the colour; a new array when omitted.
 * @returns `out`, linear RGB ≥ 0.
 */
export function shade(
  sample: ShadeSample,
  material: ShadeMaterial,
  lights: readonly (ShadeLight | ShadeThreeLight)[],
  out: Vec3 = [0, 0, 0],
): Vec3 {
  const { position: p, tint = WHITE } = sample;
  const { ka, kd, ks } = material;
  const v: Vec3 = [0, 0, 0];
  const n: Vec3 = [0, 0, 0];
  viewAndNormal(sample, v, n);
  const f = scratch;
  let r = 0;
  let g = 0;
  let b = 0;
  for (const light of lights) {
    lightFactors(light, p, n, v, material, f);
    const { ia, id, is } = f;
    if (f.ambientOnly) {
      r += tint[0] * ka[0] * ia[0] * RECIPROCAL_PI;
      g += tint[1] * ka[1] * ia[1] * RECIPROCAL_PI;
      b += tint[2] * ka[2] * ia[2] * RECIPROCAL_PI;
      continue;
    }
    const dTerm = f.att * f.diffuse;
    const sTerm = f.att * f.spec;
    r += tint[0] * (ka[0] * ia[0] + dTerm * kd[0] * id[0]) + sTerm * ks[0] * is[0];
    g += tint[1] * (ka[1] * ia[1] + dTerm * kd[1] * id[1]) + sTerm * ks[1] * is[1];
    b += tint[2] * (ka[2] * ia[2] + dTerm * kd[2] * id[2]) + sTerm * ks[2] * is[2];
  }
  const emissive = material.emissive;
  out[0] = emissive === undefined ? r : r + emissive[0];
  out[1] = emissive === undefined ? g : g + emissive[1];
  out[2] = emissive === undefined ? b : b + emissive[2];
  return out;
}

/** three's fog, as `fogFactor` reads it: a `Fog` (`near`, `far`) or a `FogExp2` (`density`). */
export type FogParameters =
  | {
      /** Fog: the view depth where the fog starts, world units. */
      readonly near: number;
      /** Fog: the view depth where everything is fog colour, world units. */
      readonly far: number;
    }
  | {
      /** FogExp2: the density, per world unit. */
      readonly density: number;
    };

/**
 * How much of the fog colour a point at view depth `depth` (distance along the camera's axis) gets, in 0 … 1,
 * as `ShadingMaterial` blends three's fog: `Fog` smoothstep(near, far, depth), and where near ≥ far (where
 * smoothstep is undefined) a step: 0 before near, 1 from near on; `FogExp2` 1 − exp(−(density·depth)²). The
 * blend is done in the output colour space, after tone mapping: out = mix(encoded colour, fog colour, factor).
 */
export function fogFactor(fog: FogParameters, depth: number): number {
  if ('density' in fog) return 1 - Math.exp(-fog.density * fog.density * depth * depth);
  const { near, far } = fog;
  if (!(far > near)) return depth >= near ? 1 : 0;
  const t = Math.min(Math.max((depth - near) / (far - near), 0), 1);
  return t * t * (3 - 2 * t);
}
