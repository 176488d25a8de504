import { Color, Object3D } from 'three';
import type { Attenuation } from './shade.js';
import { type ColorInput, checkColorChannels, checkNonNegative, setColor } from './validate.js';

/** Options of {@link PhongLight}. */
export interface PhongLightOptions {
  /**
   * Ia: ambient intensity, linear. A number is a grey level (`0.2` = (0.2, 0.2, 0.2)), never a hex colour; a
   * colour is a CSS string (sRGB), a `THREE.Color` or linear `[r, g, b]` (see {@link ColorInput}).
   * @default 0.2 (the lecture's)
   */
  ambient?: ColorInput;
  /** Id: diffuse intensity, linear; a number is a grey level (see {@link ColorInput}). @default 1 (the lecture's) */
  diffuse?: ColorInput;
  /** Is: specular intensity, linear; a number is a grey level (see {@link ColorInput}). @default 0.8 (the lecture's) */
  specular?: ColorInput;
  /**
   * Attenuation a, b, c: diffuse and specular are divided by a + b·t + c·t² (t = distance in world units).
   * Finite, ≥ 0, not all zero. @default { a: 1, b: 0, c: 0 } (no attenuation)
   */
  attenuation?: Partial<Attenuation>;
}

const NO_ATTENUATION: Attenuation = Object.freeze({ a: 1, b: 0, c: 0 });

/**
 * A point light of the Phong model with separate ambient, diffuse and specular intensities (the lecture's
 * Ia, Id, Is) and attenuation 1 / (a + b·t + c·t²). Place it anywhere in the scene graph: its world
 * position (`matrixWorld`) is read every frame by the `ShadingMaterial`s that list it, so it can be
 * parented and moved. Keep it in the rendered scene (or call `updateMatrixWorld()` yourself) so that
 * `matrixWorld` is current. The default light is the lecture's: Ia 0.2, Id 1, Is 0.8, no attenuation.
 *
 * @example
 * const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 }); // the lecture's Ia, Id, Is (greys)
 * const warm = new PhongLight({ diffuse: [1, 0.9, 0.8], specular: '#ffe0c0', attenuation: { a: 1, b: 0.05, c: 0 } });
 * light.position.set(-5, 10, 20);
 * scene.add(light);
 */
export class PhongLight extends Object3D {
  /** Always true: lets code tell a PhongLight from other objects without `instanceof`. */
  readonly isPhongLight = true;
  /**
   * Always true: three's renderers list a PhongLight with the scene's lights. `WebGPURenderer` lights node
   * materials with it through the light node that `@shadelab/material/webgpu` registers; `WebGLRenderer`
   * passes over light types it does not know (ShadingMaterial finds PhongLights itself).
   */
  readonly isLight = true;
  /** three's type name: `'PhongLight'`. */
  override type = 'PhongLight';

  readonly #ambient = new Color(0.2, 0.2, 0.2);
  readonly #diffuse = new Color(1, 1, 1);
  readonly #specular = new Color(0.8, 0.8, 0.8);
  #attenuation: Attenuation = NO_ATTENUATION;

  /**
   * @param options - Ia, Id, Is and the attenuation; each one omitted is the lecture's (see
   *   {@link PhongLightOptions}).
   */
  constructor({ ambient, diffuse, specular, attenuation }: PhongLightOptions = {}) {
    super();
    // three's shadow maps are for three's lights: a PhongLight casts none. Setting castShadow says so once
    // (three's WebGLShadowMap would otherwise warn on every frame) and leaves it false.
    let warned = false;
    Object.defineProperty(this, 'castShadow', {
      get: () => false,
      set: (value: unknown) => {
        if (value !== true || warned) return;
        warned = true;
        console.warn(
          'PhongLight.castShadow: a PhongLight casts no shadow (three’s shadow maps need one of three’s lights); put a PointLight with castShadow at its position for a shadow. castShadow stays false.',
        );
      },
      enumerable: true,
      configurable: true,
    });
    if (ambient !== undefined) this.ambient = ambient;
    if (diffuse !== undefined) this.diffuse = diffuse;
    if (specular !== undefined) this.specular = specular;
    if (attenuation !== undefined) this.attenuation = attenuation;
  }

  /**
   * Ia, the ambient intensity (linear RGB, channels finite ≥ 0). Set it with a {@link ColorInput} (a number is
   * a grey level); setting validates and copies, and the returned Color may be edited in place (it is
   * re-checked before every draw).
   * @default Color(0.2, 0.2, 0.2)
   */
  get ambient(): Color {
    return this.#ambient;
  }
  set ambient(value: ColorInput) {
    setColor('PhongLight.ambient', this.#ambient, value);
  }

  /** Id, the diffuse intensity (linear RGB, channels finite ≥ 0; set a number as a grey level). @default Color(1, 1, 1) */
  get diffuse(): Color {
    return this.#diffuse;
  }
  set diffuse(value: ColorInput) {
    setColor('PhongLight.diffuse', this.#diffuse, value);
  }

  /** Is, the specular intensity (linear RGB, channels finite ≥ 0; set a number as a grey level). @default Color(0.8, 0.8, 0.8) */
  get specular(): Color {
    return this.#specular;
  }
  set specular(value: ColorInput) {
    setColor('PhongLight.specular', this.#specular, value);
  }

  /**
   * Attenuation constants (frozen; assign a new object to change them). Missing fields take the defaults
   * a = 1, b = 0, c = 0. Each must be finite and ≥ 0, and a = b = c = 0 is refused (RangeError): it would
   * divide by zero everywhere.
   * @default { a: 1, b: 0, c: 0 }
   */
  get attenuation(): Attenuation {
    return this.#attenuation;
  }
  set attenuation(value: Partial<Attenuation>) {
    if (typeof value !== 'object' || value === null) {
      throw new TypeError(`PhongLight.attenuation must be an object { a, b, c }, got ${String(value)}`);
    }
    const { a = 1, b = 0, c = 0 } = value;
    checkNonNegative('PhongLight.attenuation.a', a);
    checkNonNegative('PhongLight.attenuation.b', b);
    checkNonNegative('PhongLight.attenuation.c', c);
    if (a === 0 && b === 0 && c === 0) {
      throw new RangeError(
        'PhongLight.attenuation must not have a = b = c = 0 (1/(a + b·t + c·t²) would be infinite), got { a: 0, b: 0, c: 0 }',
      );
    }
    this.#attenuation = Object.freeze({ a, b, c });
  }

  /** Whether this light needs the attenuation code: b or c ≠ 0, or a ≠ 1. */
  get attenuates(): boolean {
    const { a, b, c } = this.#attenuation;
    return a !== 1 || b !== 0 || c !== 0;
  }

  /**
   * Throws a RangeError if a colour was edited in place to a non-finite or negative value. Called by
   * `ShadingMaterial` before every draw, so no NaN reaches a uniform.
   */
  validate(): void {
    checkColorChannels('PhongLight.ambient', this.#ambient);
    checkColorChannels('PhongLight.diffuse', this.#diffuse);
    checkColorChannels('PhongLight.specular', this.#specular);
  }

  /** Copy every option of `source` (lights are shared, not cloned). @returns `this`. */
  override copy(source: this, recursive?: boolean): this {
    super.copy(source, recursive);
    this.#ambient.copy(source.ambient);
    this.#diffuse.copy(source.diffuse);
    this.#specular.copy(source.specular);
    this.#attenuation = source.attenuation;
    return this;
  }
}
