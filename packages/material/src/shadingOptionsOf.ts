// What a three.js mesh material becomes in the lecture's equation, defined once for both shading materials
// (toShadingMaterial for WebGLRenderer, toShadingNodeMaterial for WebGPURenderer): the options carried over and
// the Material properties copied, and the one conversion both run.
import { Color, type Material, type Texture, Vector2 } from 'three';
import type { ShadingMaterialOptions } from './ShadingMaterial.js';
import type { Lighting } from './shade.js';

/**
 * Minimum roughness three's punctual lights use (`lights_physical_pars_fragment`: "punctual lights need a
 * minimum roughness to show a highlight").
 */
export const MIN_ROUGHNESS = 0.045;

/** three's F0 of a dielectric with its default ior 1.5: ((1.5 − 1) / (1.5 + 1))². */
export const DIELECTRIC_F0 = 0.04;

/**
 * The Blinn-Phong exponent whose lobe matches GGX's for three's `roughness` (Walter et al. 2007, as three's
 * `D_GGX` takes α = roughness²): shininess = 2/α² − 2, so that the normalised Blinn-Phong distribution
 * (s + 2)/(2π)·(n·h)^s has GGX's peak 1/(π α²). `roughness` is clamped to three's 0.045 … 1 first.
 */
export function ggxShininess(roughness: number): number {
  const r = Math.min(Math.max(roughness, MIN_ROUGHNESS), 1);
  const alpha = r * r;
  return 2 / (alpha * alpha) - 2;
}

/**
 * The factor from three's specular colour to ks for a Blinn-Phong exponent s, (s + 2)/8: three's direct
 * specular at normal incidence (l = v = n) is colour/π × F0 × (s + 2)/8 for both `BRDF_BlinnPhong` (its D is
 * (s/2 + 1)/π·(n·h)^s, G/4 = 1/4) and `BRDF_GGX` (V = 1/4, D = 1/(π α²) = (s + 2)/(2π)); the lecture's term is
 * ks × colour/π × (n·h)^s.
 */
export function specularScale(shininess: number): number {
  return (shininess + 2) / 8;
}

/**
 * The shininess that gives the lecture's `lighting` the highlight of a Blinn-Phong exponent s: s itself for
 * `'blinn-phong'` ((n·h)^s), s/4 for `'phong'` ((v·r)^(s/4)): in the plane of the light and the eye the angle
 * between v and r is twice the angle between n and h, and cos(2θ)^(s/4) ≈ (1 − 2θ²)^(s/4) ≈ e^(−sθ²/2) ≈ cos(θ)^s,
 * so the two lobes have one peak and one width. Both peak at 1 where l = v = n, so ks is the same.
 */
export function lobeShininess(blinnShininess: number, lighting: Lighting): number {
  return lighting === 'phong' ? blinnShininess / 4 : blinnShininess;
}

/** Every option of `ShadingMaterial`'s constructor, in documentation order. */
export const SHADING_MATERIAL_OPTION_KEYS = [
  'shading',
  'lighting',
  'celBands',
  'ka',
  'kd',
  'ks',
  'shininess',
  'lights',
  'map',
  'vertexColors',
  'emissive',
  'emissiveMap',
  'opacity',
  'transparent',
  'alphaTest',
  'alphaMap',
  'normalMap',
  'normalScale',
  'output',
  'normalMatrix',
] as const satisfies readonly (keyof ShadingMaterialOptions)[];
// An option missing from the list is a type error here.
const _complete: [
  Exclude<keyof ShadingMaterialOptions, (typeof SHADING_MATERIAL_OPTION_KEYS)[number]>,
] extends [never]
  ? true
  : never = true;
void _complete;

/** The three.js mesh materials that convert, by three's type flags (node materials carry the same flags). */
export type ConvertibleKind = 'basic' | 'lambert' | 'phong' | 'standard' | 'physical' | 'toon';

interface ThreeMaterialLike extends Material {
  [key: string]: unknown;
}

/** The kind of `material` by three's flags, or null when it is not one of three's six convertible materials. */
export function kindOf(material: Material): ConvertibleKind | null {
  const m = material as ThreeMaterialLike;
  if (m.isShadingMaterial === true || m.isShadingNodeMaterial === true) return null;
  if (m.isMeshPhysicalMaterial === true) return 'physical';
  if (m.isMeshStandardMaterial === true) return 'standard';
  if (m.isMeshPhongMaterial === true) return 'phong';
  if (m.isMeshLambertMaterial === true) return 'lambert';
  if (m.isMeshToonMaterial === true) return 'toon';
  if (m.isMeshBasicMaterial === true) return 'basic';
  return null;
}

/** Why `material` does not convert (for TypeErrors and `skipped`), by what it is. */
export function unsupportedReason(material: Material): string {
  const m = material as ThreeMaterialLike;
  const type = String(m.type);
  if (m.isShadingMaterial === true || m.isShadingNodeMaterial === true) {
    return `${type} is already a shading material`;
  }
  if (m.isShaderMaterial === true || m.isRawShaderMaterial === true) {
    return `${type} has its own shaders: nothing to carry over`;
  }
  if (m.isNodeMaterial === true && kindOf(material) === null) {
    return `${type} is a node material of no convertible kind (its nodes cannot be carried over)`;
  }
  return `${type} is not one of three's lit or basic mesh materials (MeshBasic, MeshLambert, MeshPhong, MeshStandard, MeshPhysical, MeshToon)`;
}

/**
 * The `Material` properties every material has, copied as they are onto the converted material (the source's
 * `clippingPlanes` array is shared, not cloned, so that moving a plane moves both).
 */
export const MATERIAL_PROPERTIES = [
  'name',
  'side',
  'shadowSide',
  'fog',
  'toneMapped',
  'clippingPlanes',
  'clipIntersection',
  'clipShadows',
  'depthTest',
  'depthWrite',
  'depthFunc',
  'blending',
  'blendSrc',
  'blendDst',
  'blendEquation',
  'blendSrcAlpha',
  'blendDstAlpha',
  'blendEquationAlpha',
  'premultipliedAlpha',
  'colorWrite',
  'visible',
  'polygonOffset',
  'polygonOffsetFactor',
  'polygonOffsetUnits',
  'alphaToCoverage',
  'dithering',
] as const;

/** The options of both shading materials' constructors that are also three's `Material` properties. */
export const MATERIAL_OPTIONS = ['opacity', 'transparent', 'alphaTest', 'vertexColors'] as const;

/** What a three.js material carries over: the shading options and the Material properties to copy. */
export interface CarriedOver {
  /** The kind the material was recognised as. */
  readonly kind: ConvertibleKind;
  /** `ShadingMaterial`'s options (every one set). */
  readonly options: ShadingMaterialOptions;
  /** The {@link MATERIAL_PROPERTIES} the source has (`fog` only when it has one). */
  readonly properties: Readonly<Record<string, unknown>>;
}

const colorOf = (value: unknown, fallback = 1): Color =>
  value instanceof Color ? value.clone() : new Color(fallback, fallback, fallback);
const numberOf = (value: unknown, fallback: number): number => (typeof value === 'number' ? value : fallback);
const textureOf = (value: unknown): Texture | null =>
  typeof value === 'object' && value !== null && (value as Texture).isTexture === true
    ? (value as Texture)
    : null;

/** Cel bands from a toon material's gradient map: its width in texels (2 … 255), 2 without one (three's two tones). */
export function celBandsOf(gradientMap: unknown): number {
  const texture = textureOf(gradientMap);
  const width = (texture?.image as { width?: unknown } | null | undefined)?.width;
  if (typeof width !== 'number' || !Number.isFinite(width)) return 2;
  return Math.min(Math.max(Math.round(width), 2), 255);
}

/**
 * The mapping from a three.js mesh material to the lecture's equation (the rules are stated on
 * `toShadingMaterial`), or null when `material` is not one of the six convertible materials. `lighting` is the
 * lighting the material will draw with (the shininess is carried over for it: {@link lobeShininess}).
 */
export function shadingOptionsOf(material: Material, lighting: Lighting = 'blinn-phong'): CarriedOver | null {
  const kind = kindOf(material);
  if (kind === null) return null;
  const m = material as ThreeMaterialLike;
  const color = colorOf(m.color);
  const map = textureOf(m.map);
  const options: ShadingMaterialOptions = {
    lighting,
    celBands: 0,
    shading: m.flatShading === true ? 'flat' : 'phong',
    ka: color,
    kd: color,
    ks: 0,
    shininess: 0,
    map,
    vertexColors: m.vertexColors === true,
    emissive: colorOf(m.emissive, 0).multiplyScalar(numberOf(m.emissiveIntensity, 1)),
    emissiveMap: textureOf(m.emissiveMap),
    opacity: numberOf(m.opacity, 1),
    transparent: m.transparent === true,
    alphaTest: numberOf(m.alphaTest, 0),
    alphaMap: textureOf(m.alphaMap),
    normalMap: textureOf(m.normalMap),
    normalScale: m.normalScale instanceof Vector2 ? m.normalScale.clone() : new Vector2(1, 1),
  };
  if (kind === 'basic') {
    // Unlit: nothing reflects; the colour (× the map's texel) is emitted, and the map stays for its alpha.
    options.ka = 0;
    options.kd = 0;
    options.emissive = color;
    options.emissiveMap = map;
    options.normalMap = null;
  } else if (kind === 'phong') {
    const shininess = Math.max(numberOf(m.shininess, 30), 0);
    options.shininess = lobeShininess(shininess, lighting);
    options.ks = colorOf(m.specular).multiplyScalar(specularScale(shininess));
  } else if (kind === 'toon') {
    options.celBands = celBandsOf(m.gradientMap);
  } else if (kind === 'standard' || kind === 'physical') {
    const metalness = Math.min(Math.max(numberOf(m.metalness, 0), 0), 1);
    const shininess = ggxShininess(numberOf(m.roughness, 1));
    // three's F0: the dielectric's (0.04, or from ior × specularColor × specularIntensity on a physical
    // material), blended towards the colour by metalness.
    let dielectric = new Color(DIELECTRIC_F0, DIELECTRIC_F0, DIELECTRIC_F0);
    if (kind === 'physical') {
      const ior = numberOf(m.ior, 1.5);
      const f = ((ior - 1) / (ior + 1)) ** 2;
      const tint = colorOf(m.specularColor).multiplyScalar(f);
      dielectric = new Color(Math.min(tint.r, 1), Math.min(tint.g, 1), Math.min(tint.b, 1)).multiplyScalar(
        numberOf(m.specularIntensity, 1),
      );
    }
    const f0 = dielectric.clone().lerp(color, metalness);
    // three's diffuse: colour × (1 − metalness) (its diffuseContribution) × (1 − F) of the dielectric F0 at
    // normal incidence (glTF's fresnel_mix: light reflected by the specular interface is not diffused).
    const diffuse = color
      .clone()
      .multiplyScalar(1 - metalness)
      .multiply(new Color(1 - dielectric.r, 1 - dielectric.g, 1 - dielectric.b));
    options.ka = diffuse;
    options.kd = diffuse;
    options.shininess = lobeShininess(shininess, lighting);
    options.ks = f0.multiplyScalar(specularScale(shininess));
  }
  const properties: Record<string, unknown> = {};
  for (const key of MATERIAL_PROPERTIES) {
    if (m[key] !== undefined) properties[key] = m[key];
  }
  return { kind, options, properties };
}

/** `options` without its undefined entries, checked to be an object (a TypeError naming `name` otherwise). */
export function definedOptions<O extends object>(name: string, options: O | undefined): Partial<O> {
  if (options === undefined || options === null) return {};
  if (typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError(`${name} must be an options object, got ${String(options)}`);
  }
  const out: Record<string, unknown> = {};
  for (const [key, value] of Object.entries(options)) {
    if (value !== undefined) out[key] = value;
  }
  return out as Partial<O>;
}

/**
 * Sets `options` on a shading material as properties (`lights` is its `phongLights`, `normalScale` is copied);
 * only the keys in `keys`. Validated beforehand by the caller (a material made from the same options).
 */
export function setOptions(material: Material, options: object, keys: readonly string[]): void {
  const target = material as ThreeMaterialLike;
  for (const [key, value] of Object.entries(options)) {
    if (value === undefined || !keys.includes(key)) continue;
    if (key === 'lights') target.phongLights = value;
    else if (key === 'normalScale') (target.normalScale as Vector2).copy(value as Vector2);
    else target[key] = value;
  }
}

/** What {@link convertWith} needs of one shading material class. */
export interface ShadingMaterialKind<M extends Material, O extends object> {
  /** The function named in errors (`toShadingMaterial`). */
  readonly owner: string;
  /** Makes the material from its options (validating them). */
  make(options: O): M;
  /** The constructor options it takes; the carried-over options it does not take are dropped. */
  readonly optionKeys: readonly string[];
  /** Why it cannot draw a kind (refused with a TypeError), or undefined when it can. */
  refused?(kind: ConvertibleKind): string | undefined;
}

/** Throws a TypeError naming `owner`'s `material` parameter unless it is a three.js Material. */
export function checkMaterial(owner: string, material: unknown): Material {
  if (typeof material !== 'object' || material === null || (material as Material).isMaterial !== true) {
    throw new TypeError(`${owner}: material must be a THREE.Material, got ${String(material)}`);
  }
  return material as Material;
}

/**
 * The conversion both shading materials run: the carried-over options with `overrides` on top (undefined
 * entries ignored), the keys the class takes passed to its constructor, three's Material options it does not
 * take (opacity, transparent, alphaTest, vertexColors) and the Material properties copied onto it.
 */
export function convertWith<M extends Material, O extends object>(
  kind: ShadingMaterialKind<M, O>,
  material: unknown,
  overrides: O | undefined,
): M {
  const source = checkMaterial(kind.owner, material);
  const own = definedOptions(`${kind.owner}: options`, overrides);
  const carried = shadingOptionsOf(
    source,
    (own as { lighting?: unknown }).lighting === 'phong' ? 'phong' : 'blinn-phong',
  );
  if (carried === null) {
    throw new TypeError(`${kind.owner}: cannot convert material ${unsupportedReason(source)}`);
  }
  const refused = kind.refused?.(carried.kind);
  if (refused !== undefined) {
    throw new TypeError(`${kind.owner}: cannot convert material ${String(source.type)}: ${refused}`);
  }
  const merged: Record<string, unknown> = { ...carried.options, ...own };
  const options: Record<string, unknown> = {};
  for (const key of kind.optionKeys) if (merged[key] !== undefined) options[key] = merged[key];
  const made = kind.make(options as O);
  const target = made as unknown as Record<string, unknown>;
  // three's Material has them: set on a class whose constructor does not take them (already checked otherwise).
  for (const key of MATERIAL_OPTIONS) target[key] = merged[key];
  for (const [key, value] of Object.entries(carried.properties)) target[key] = value;
  return made;
}
