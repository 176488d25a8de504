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
import { fragmentShader, vertexShader } from './OutlineMaterial.glsl.js';
import {
  checkThickness,
  OUTLINE_DEFAULTS,
  type OutlineMaterialOptions,
  outlineSphereNormals,
  setOutlineColor,
} from './outlineOptions.js';
import type { ColorInput } from './validate.js';

export type { OutlineMaterialOptions } from './outlineOptions.js';

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
  constructor({
    thickness = OUTLINE_DEFAULTS.thickness,
    color = OUTLINE_DEFAULTS.color,
  }: OutlineMaterialOptions = {}) {
    super({
      vertexShader,
      fragmentShader,
      uniforms: {
        shadingNormalMatrix: { value: new Matrix3() },
        thickness: { value: OUTLINE_DEFAULTS.thickness },
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
    this.uniforms.thickness.value = checkThickness('OutlineMaterial', value);
  }

  /** Outline colour (linear RGB; set it with a {@link ColorInput}, a number being a grey level in 0 … 1). @default Color(0, 0, 0) */
  get color(): Color {
    return this.#color;
  }
  set color(value: ColorInput) {
    setOutlineColor('OutlineMaterial', this.#color, value);
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
    const sphere = outlineSphereNormals(geometry);
    if (sphere !== (this.defines.SPHERE_NORMALS !== undefined)) {
      this.defines = sphere ? { SPHERE_NORMALS: '' } : {};
      this.needsUpdate = true;
    }
    computeNormalMatrix(object.matrixWorld, this.uniforms.shadingNormalMatrix.value);
    this.uniforms.outlineColor.value.copy(this.#color);
    this.uniformsNeedUpdate = true;
  }
}
