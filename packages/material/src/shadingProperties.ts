// The options of both shading materials as live properties, written once: ShadingMaterial (WebGLRenderer) and
// ShadingNodeMaterial (WebGPURenderer) install these accessors on their prototypes and are told of each change
// through one hook (a define to set, a uniform to fill, a rebuild to ask for); the options' defaults and checks
// (options.ts), the constructor's options, copy() and the report of values edited in place live here too.
import { Color, Material, type NormalMapTypes, TangentSpaceNormalMap, type Texture, Vector2 } from 'three';
import {
  checkCelBands,
  checkLighting,
  checkNormalMatrix,
  checkOutput,
  checkPhongLights,
  checkShading,
  type NormalMatrixMode,
  SHADING_DEFAULTS,
  type Shading,
  type ShadingOptions,
  type ShadingOutput,
} from './options.js';
import type { PhongLight } from './PhongLight.js';
import type { Lighting } from './shade.js';
import {
  type ColorInput,
  checkColorChannels,
  checkNonNegative,
  checkTexture,
  checkUnit,
  setColor,
} from './validate.js';

/**
 * The options of `ShadingMaterial` and `ShadingNodeMaterial` (the lecture's options and three's surface
 * properties by their names), with their types, units and defaults.
 */
export interface ShadingMaterialOptions extends ShadingOptions {
  /**
   * three's `map`: a colour texture whose texel (linear, decoded as three decodes its `colorSpace`) multiplies
   * ka and kd, never ks; its alpha multiplies the opacity. @default null
   */
  map?: Texture | null;
  /** three's `vertexColors`: the `color` attribute (RGB or RGBA, linear) multiplies ka and kd. @default false */
  vertexColors?: boolean;
  /**
   * three's `emissive`: linear RGB added to the lit colour, outside the lighting (before fog and tone mapping);
   * a number is a grey level (see {@link ColorInput}). @default 0 (black)
   */
  emissive?: ColorInput;
  /** three's `emissiveMap`: its texel (linear) multiplies `emissive`. @default null */
  emissiveMap?: Texture | null;
  /** three's `opacity`, in 0 … 1: the fragment's alpha (with `transparent`, blended as three blends). @default 1 */
  opacity?: number;
  /** three's `transparent`: blend by alpha (else alpha is 1). @default false */
  transparent?: boolean;
  /** three's `alphaTest`, in 0 … 1: fragments with alpha below it are discarded; 0 = off. @default 0 */
  alphaTest?: number;
  /** three's `alphaMap`: its green channel multiplies the alpha. @default null */
  alphaMap?: Texture | null;
  /**
   * three's `normalMap` (tangent space by default, see `normalMapType`): perturbs the normal per fragment, in
   * phong shading only (gouraud and flat have no per-fragment normal: a console warning, once). @default null
   */
  normalMap?: Texture | null;
  /** three's `normalScale`: scales the normal map's x and y. @default Vector2(1, 1) */
  normalScale?: Vector2;
}

/**
 * The options as live properties of both materials: each one validated when set (a `TypeError` or `RangeError`
 * naming the parameter, the value and the allowed range, changing nothing), read back as set (colours as linear
 * `THREE.Color`s). Changing one that is part of the material's variant (`shading`, `lighting`, `celBands`,
 * `output`, `normalMatrix`, `phongLights`) recompiles it; the others are uniforms.
 */
export interface ShadingProperties {
  /** Where the lighting is evaluated: `'flat'`, `'gouraud'` or `'phong'` (see {@link Shading}). @default 'phong' */
  get shading(): Shading;
  set shading(value: Shading);
  /** The lighting equation: `'phong'` or `'blinn-phong'`. @default 'phong' */
  get lighting(): Lighting;
  set lighting(value: Lighting);
  /**
   * Cel shading: 0 = off; N in 2 … 255 quantises each light's diffuse cosine to N shades
   * (min(⌊cos·N⌋, N−1)/(N−1)) and its specular to a hard-edged highlight (1 where spec ≥ 0.5, else 0). With
   * gouraud shading the quantised vertex colours are interpolated (soft band edges); with phong shading the
   * bands are crisp. @default 0
   */
  get celBands(): number;
  set celBands(value: number);
  /**
   * What the material draws: `'color'`, or `'ambient'`, `'diffuse'`, `'specular'`, `'attenuation'` or
   * `'normal'` alone, a debugging aid (exactly what each shows: {@link ShadingOutput}). Compiled only when not
   * `'color'` (a define on `ShadingMaterial`, a branch when three builds `ShadingNodeMaterial`).
   * @default 'color'
   */
  get output(): ShadingOutput;
  set output(value: ShadingOutput);
  /**
   * How normals go to world space: `'inverse-transpose'` (the normal matrix, right) or `'model'` (the model
   * matrix itself, the lecture's wrong way under a non-uniform scale), a teaching aid (see
   * {@link NormalMatrixMode}). Compiled only when `'model'`. @default 'inverse-transpose'
   */
  get normalMatrix(): NormalMatrixMode;
  set normalMatrix(value: NormalMatrixMode);
  /**
   * ka, ambient reflectance (linear RGB, channels finite ≥ 0). Set it with a {@link ColorInput} (a number is a
   * grey level); setting validates and copies. @default Color(0.6, 0.35, 0.2)
   */
  get ka(): Color;
  set ka(value: ColorInput);
  /** kd, diffuse reflectance (linear RGB, channels finite ≥ 0; set with a `ColorInput`). @default Color(0.6, 0.35, 0.2) */
  get kd(): Color;
  set kd(value: ColorInput);
  /** ks, specular reflectance (linear RGB, channels finite ≥ 0; set with a `ColorInput`). @default Color(0.5, 0.5, 0.5) */
  get ks(): Color;
  set ks(value: ColorInput);
  /** α, the specular exponent (finite, ≥ 0; 0⁰ = 1). A uniform: changing it never recompiles. @default 32 */
  get shininess(): number;
  set shininess(value: number);
  /**
   * The PhongLights (the `lights` option; named so because three's `Material.lights` is the flag for three's
   * own lights). Empty (the default): every visible PhongLight in the rendered scene lights the material; not
   * empty: only these do. A frozen copy; assign a new array to change it (the number of lights is part of the
   * variant). @default []
   */
  get phongLights(): readonly PhongLight[];
  set phongLights(value: readonly PhongLight[]);
  /**
   * three's `emissive`: linear RGB added to the lit colour outside the lighting, before fog and tone mapping
   * (channels finite ≥ 0; set it with a {@link ColorInput}, a number being a grey level). A uniform.
   * @default Color(0, 0, 0)
   */
  get emissive(): Color;
  set emissive(value: ColorInput);
  /**
   * three's `map`: a colour texture (its `colorSpace` decoded to linear as three decodes it) whose texel
   * multiplies ka and kd (not ks); its alpha multiplies the opacity. Sampled per fragment in every shading
   * (gouraud and flat pass the ka/kd part and the ks part of their colours separately). @default null
   */
  map: Texture | null;
  /** three's `alphaMap`: its green channel multiplies the alpha. @default null */
  alphaMap: Texture | null;
  /** three's `emissiveMap`: its texel (linear) multiplies `emissive`. @default null */
  emissiveMap: Texture | null;
  /**
   * three's `normalMap` (tangent space by default, see `normalMapType`): perturbs the material's own normal per
   * fragment through three's tangent frame from screen-space derivatives (a `tangent` attribute is not used);
   * phong shading only (gouraud and flat shading ignore it, with one console warning). @default null
   */
  normalMap: Texture | null;
  /** three's `normalMapType`: `TangentSpaceNormalMap` or `ObjectSpaceNormalMap`. @default TangentSpaceNormalMap */
  normalMapType: NormalMapTypes;
  /** three's `normalScale`: scales the tangent-space normal map's x and y (finite). @default Vector2(1, 1) */
  readonly normalScale: Vector2;
}

/** Which kind of option changed, for the material's hook. */
export type PropertyChange = 'variant' | 'shininess' | 'lights' | 'emissive';

/**
 * What a material tells the shared accessors: its class name for errors, and what to do when an option
 * changes (`changed`: whether the value differs from the last one).
 */
export interface PropertyHooks {
  owner(material: Material): string;
  change(material: Material, kind: PropertyChange, changed: boolean): void;
}

/** One material's option values. */
interface State {
  shading: Shading;
  lighting: Lighting;
  celBands: number;
  output: ShadingOutput;
  normalMatrix: NormalMatrixMode;
  shininess: number;
  lights: readonly PhongLight[];
  readonly ka: Color;
  readonly kd: Color;
  readonly ks: Color;
  readonly emissive: Color;
  opacity: number;
  /** The message of the in-place problem last reported (null once the values are valid again). */
  reported: string | null;
}

const _states = /* @__PURE__ */ new WeakMap<object, State>();

/** `material`'s option values, made with the defaults on first use (three's constructor sets `opacity` first). */
function stateOf(material: object): State {
  let state = _states.get(material);
  if (state === undefined) {
    state = {
      shading: SHADING_DEFAULTS.shading,
      lighting: SHADING_DEFAULTS.lighting,
      celBands: SHADING_DEFAULTS.celBands,
      output: SHADING_DEFAULTS.output,
      normalMatrix: SHADING_DEFAULTS.normalMatrix,
      shininess: SHADING_DEFAULTS.shininess,
      lights: Object.freeze([]),
      ka: new Color(...SHADING_DEFAULTS.ka),
      kd: new Color(...SHADING_DEFAULTS.kd),
      ks: new Color(...SHADING_DEFAULTS.ks),
      emissive: new Color(0, 0, 0),
      opacity: 1,
      reported: null,
    };
    _states.set(material, state);
  }
  return state;
}

/** three's `Material.alphaTest` accessor (it recompiles when alphaTest crosses 0). */
const materialAlphaTest = Object.getOwnPropertyDescriptor(Material.prototype, 'alphaTest');

type Key = 'shading' | 'lighting' | 'celBands' | 'output' | 'normalMatrix';
const CHECKS: Record<Key, (owner: string, value: unknown) => string | number> = {
  shading: checkShading,
  lighting: checkLighting,
  celBands: checkCelBands,
  output: checkOutput,
  normalMatrix: checkNormalMatrix,
};

/**
 * Installs the {@link ShadingProperties} accessors (and checked `opacity` and `alphaTest`) on `target`'s
 * prototype; `hooks` is told of each change.
 */
export function installShadingProperties(target: { prototype: Material }, hooks: PropertyHooks): void {
  const properties: PropertyDescriptorMap = {};
  for (const key of Object.keys(CHECKS) as Key[]) {
    properties[key] = {
      get(this: Material) {
        return stateOf(this)[key];
      },
      set(this: Material, value: unknown) {
        const state = stateOf(this) as unknown as Record<Key, unknown>;
        const checked = CHECKS[key](hooks.owner(this), value);
        const changed = checked !== state[key];
        state[key] = checked;
        hooks.change(this, 'variant', changed);
      },
    };
  }
  for (const key of ['ka', 'kd', 'ks', 'emissive'] as const) {
    properties[key] = {
      get(this: Material) {
        return stateOf(this)[key];
      },
      set(this: Material, value: ColorInput) {
        setColor(`${hooks.owner(this)}.${key}`, stateOf(this)[key], value);
        // Whether the emissive is compiled in depends on it being black (see the materials).
        if (key === 'emissive') hooks.change(this, 'emissive', true);
      },
    };
  }
  properties.shininess = {
    get(this: Material) {
      return stateOf(this).shininess;
    },
    set(this: Material, value: number) {
      stateOf(this).shininess = checkNonNegative(`${hooks.owner(this)}.shininess`, value);
      hooks.change(this, 'shininess', true);
    },
  };
  properties.phongLights = {
    get(this: Material) {
      return stateOf(this).lights;
    },
    set(this: Material, value: readonly PhongLight[]) {
      stateOf(this).lights = checkPhongLights(hooks.owner(this), value);
      hooks.change(this, 'lights', true);
    },
  };
  properties.opacity = {
    get(this: Material) {
      return stateOf(this).opacity;
    },
    set(this: Material, value: number) {
      stateOf(this).opacity = checkUnit(`${hooks.owner(this)}.opacity`, value);
    },
  };
  properties.alphaTest = {
    get(this: Material) {
      return materialAlphaTest?.get?.call(this);
    },
    set(this: Material, value: number) {
      materialAlphaTest?.set?.call(this, checkUnit(`${hooks.owner(this)}.alphaTest`, value));
    },
  };
  for (const descriptor of Object.values(properties)) descriptor.configurable = true;
  Object.defineProperties(target.prototype, properties);
}

/** A material with the shared properties. */
type Shaded = Material & ShadingProperties & { vertexColors: boolean };

/** Sets every option of `options` on `material` (each omitted one takes its default), validated. */
export function applyShadingOptions(
  material: Shaded,
  owner: string,
  {
    shading = SHADING_DEFAULTS.shading,
    lighting = SHADING_DEFAULTS.lighting,
    celBands = SHADING_DEFAULTS.celBands,
    ka = SHADING_DEFAULTS.ka,
    kd = SHADING_DEFAULTS.kd,
    ks = SHADING_DEFAULTS.ks,
    shininess = SHADING_DEFAULTS.shininess,
    lights = [],
    map = null,
    vertexColors = false,
    emissive = 0,
    emissiveMap = null,
    opacity = 1,
    transparent = false,
    alphaTest = 0,
    alphaMap = null,
    normalMap = null,
    normalScale = new Vector2(1, 1),
    output = SHADING_DEFAULTS.output,
    normalMatrix = SHADING_DEFAULTS.normalMatrix,
  }: ShadingMaterialOptions,
): void {
  material.shading = shading;
  material.lighting = lighting;
  material.celBands = celBands;
  material.output = output;
  material.normalMatrix = normalMatrix;
  material.ka = ka;
  material.kd = kd;
  material.ks = ks;
  material.shininess = shininess;
  material.phongLights = lights;
  material.map = checkTexture(`${owner}.map`, map);
  material.vertexColors = vertexColors === true;
  material.emissive = emissive;
  material.emissiveMap = checkTexture(`${owner}.emissiveMap`, emissiveMap);
  material.opacity = opacity;
  material.transparent = transparent === true;
  material.alphaTest = alphaTest;
  material.alphaMap = checkTexture(`${owner}.alphaMap`, alphaMap);
  material.normalMap = checkTexture(`${owner}.normalMap`, normalMap);
  material.normalMapType = TangentSpaceNormalMap;
  if (!(normalScale instanceof Vector2)) {
    throw new TypeError(`${owner}.normalScale must be a THREE.Vector2, got ${String(normalScale)}`);
  }
  (material as { normalScale: Vector2 }).normalScale = normalScale.clone();
}

/** Copies every option of `source` into `target`, without the change hooks (lights are shared, not cloned). */
export function copyShadingOptions(target: Shaded, source: Shaded): void {
  const to = stateOf(target);
  const from = stateOf(source);
  to.shading = from.shading;
  to.lighting = from.lighting;
  to.celBands = from.celBands;
  to.output = from.output;
  to.normalMatrix = from.normalMatrix;
  to.shininess = from.shininess;
  to.lights = from.lights;
  to.ka.copy(from.ka);
  to.kd.copy(from.kd);
  to.ks.copy(from.ks);
  to.emissive.copy(from.emissive);
  to.opacity = from.opacity;
  target.map = source.map;
  target.alphaMap = source.alphaMap;
  target.emissiveMap = source.emissiveMap;
  target.normalMap = source.normalMap;
  target.normalMapType = source.normalMapType;
  target.normalScale.copy(source.normalScale);
}

/**
 * What may have been edited in place, bypassing the setters (ka, kd, ks, emissive, normalScale; `more` checks the
 * rest), reported once with console.error as three reports its own errors: the first problem is reported, and
 * while it stays the material draws silently with its last valid values; once fixed, a new problem is reported
 * again. @returns whether the values are valid (draw with them), or not (keep the last valid ones).
 */
export function checkEditedInPlace(material: Shaded, owner: string, more?: () => void): boolean {
  const state = stateOf(material);
  try {
    checkColorChannels(`${owner}.ka`, state.ka);
    checkColorChannels(`${owner}.kd`, state.kd);
    checkColorChannels(`${owner}.ks`, state.ks);
    checkColorChannels(`${owner}.emissive`, state.emissive);
    const { x, y } = material.normalScale;
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      throw new RangeError(`${owner}.normalScale must be finite, got (${x}, ${y})`);
    }
    more?.();
  } catch (error) {
    if (!(error instanceof RangeError)) throw error;
    if (error.message !== state.reported) {
      state.reported = error.message;
      console.error(`${error.message} (edited in place; drawing with the last valid values)`);
    }
    return false;
  }
  state.reported = null;
  return true;
}
