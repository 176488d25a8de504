import {
  BackSide,
  type BufferGeometry,
  type Camera,
  Color,
  type Group,
  Matrix3,
  type Object3D,
  type Scene,
  ShaderMaterial,
  UniformsLib,
  UniformsUtils,
  type WebGLRenderer,
} from 'three';
import { computeNormalMatrix } from './computeNormalMatrix.js';
import { SPHERE_FLAG } from './geometryFlags.js';
import { fragmentShader, vertexShader } from './OutlineMaterial.glsl.js';
import { type ColorInput, checkNonNegative, setColor } from './validate.js';

/** Options of {@link OutlineMaterial}. */
export interface OutlineMaterialOptions {
  /** Outline width in world units, measured along the surface normal. Finite, ≥ 0. @default 0.03 */
  thickness?: number;
  /**
   * Outline colour, read like every colour of this package (see {@link ColorInput}): a CSS string is sRGB
   * (`'#f2f2f2'`), a `THREE.Color` or `[r, g, b]` is linear, and a number is a grey level in 0 … 1 (so a
   * three-style hex number such as `0xff8000` is refused with its `'#ff8000'` spelling, never misread).
   * @default 0 (black)
   */
  color?: ColorInput;
}

/**
 * The inverted-hull outline for cel shading: draws the back faces of a mesh pushed out by `thickness`
 * along the (robust, world-space) normal, in one colour. Use it on a second mesh sharing the geometry, or
 * through `createOutline`. Reads the `normal` attribute, or the position on a sphere flagged like for
 * `ShadingMaterial` (`SubdivisionSphereGeometry` or `userData.isSphere`). Clipped, fogged and tone-mapped
 * like three's materials (`clippingPlanes`, `fog`, `toneMapped`). On an `InstancedMesh`, a `SkinnedMesh` or a
 * mesh with morph targets (`createOutline` makes the outline that kind of object), three's instancing, skinning
 * and morph target chunks move each vertex and its normal first, so the hull surrounds the deformed surface of
 * every instance; they are compiled only into the programs of objects that use them. The instance's normal
 * matrix is made like `ShadingMaterial`'s (finite for a singular instance matrix). Not for a `BatchedMesh`.
 */
export class OutlineMaterial extends ShaderMaterial {
  /** Always true. */
  readonly isOutlineMaterial = true;
  /** three's type name: `'OutlineMaterial'`. */
  override type = 'OutlineMaterial';
  /** Apply `scene.fog`, like the `ShadingMaterial` it outlines. @default true */
  override fog = true;
  /**
   * Clip by `clippingPlanes` and the renderer's, like the mesh it outlines (`createOutline` shares the mesh
   * material's planes). @default true
   */
  override clipping = true;
  readonly #color = new Color(0, 0, 0);

  /** @param options - The thickness and the colour (see {@link OutlineMaterialOptions}). */
  constructor({ thickness = 0.03, color = 0 }: OutlineMaterialOptions = {}) {
    super({
      vertexShader,
      fragmentShader,
      uniforms: {
        shadingNormalMatrix: { value: new Matrix3() },
        thickness: { value: 0.03 },
        outlineColor: { value: new Color() },
        ...UniformsUtils.clone(UniformsLib.fog),
      },
      side: BackSide,
    });
    this.thickness = thickness;
    this.color = color;
  }

  /** Outline width in world units (finite, ≥ 0). @default 0.03 */
  get thickness(): number {
    return this.uniforms.thickness.value;
  }
  set thickness(value: number) {
    this.uniforms.thickness.value = checkNonNegative('OutlineMaterial.thickness', value);
  }

  /** Outline colour (linear RGB; set it with a {@link ColorInput}, a number being a grey level in 0 … 1). @default Color(0, 0, 0) */
  get color(): Color {
    return this.#color;
  }
  set color(value: ColorInput) {
    setColor('OutlineMaterial.color', this.#color, value, 1);
    this.uniforms.outlineColor.value.copy(this.#color);
  }

  /** Per draw: the robust normal matrix, and analytic sphere normals when the geometry has none. */
  override onBeforeRender(
    _renderer: WebGLRenderer,
    _scene: Scene,
    _camera: Camera,
    geometry: BufferGeometry,
    object: Object3D,
    _group: Group,
  ): void {
    const sphere =
      geometry.getAttribute('normal') === undefined &&
      (geometry.type === 'SubdivisionSphereGeometry' || geometry.userData[SPHERE_FLAG] === true);
    if (sphere !== (this.defines.SPHERE_NORMALS !== undefined)) {
      this.defines = sphere ? { SPHERE_NORMALS: '' } : {};
      this.needsUpdate = true;
    }
    computeNormalMatrix(object.matrixWorld, this.uniforms.shadingNormalMatrix.value);
    this.uniforms.outlineColor.value.copy(this.#color);
    this.uniformsNeedUpdate = true;
  }
}
