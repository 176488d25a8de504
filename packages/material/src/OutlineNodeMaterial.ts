// OutlineMaterial's inverted hull on three's WebGPURenderer (both of its backends): a node material whose vertex
// stage moves the vertex with three's morph target and skinning nodes, applies the instance matrix to the position
// and (as sign(det)·cofactor, like OutlineMaterial's GLSL) to the normal, and pushes the world position out along
// the unit robust world normal by `thickness`; one colour.
import {
  cameraViewMatrix,
  diffuseColor,
  materialReference,
  max,
  modelWorldMatrix,
  morphReference,
  normalLocal,
  positionLocal,
  referenceAttribute,
  select,
  skinning,
  uniform,
  vec3,
  vec4,
} from 'three/tsl';
import { BackSide, Color, Matrix3, NodeMaterial } from 'three/webgpu';
import { computeNormalMatrix } from './computeNormalMatrix.js';
import { cofactorTimes, rescale } from './nodeInstance.js';
import {
  checkThickness,
  OUTLINE_DEFAULTS,
  type OutlineMaterialOptions,
  outlineSphereNormals,
  setOutlineColor,
} from './outlineOptions.js';
import type { ColorInput } from './validate.js';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

const OWNER = 'OutlineNodeMaterial';

/** Options of {@link OutlineNodeMaterial}: those of `OutlineMaterial` (the same defaults and checks). */
export type OutlineNodeMaterialOptions = OutlineMaterialOptions;

/**
 * The robust normal matrix of the drawn object (sign(det)·cof of its world matrix, see `computeNormalMatrix`):
 * finite for a zero or extreme scale, where three's inverse transpose is not.
 */
const _normalMatrix = /* @__PURE__ */ new Matrix3();
const objectNormalMatrix = /* @__PURE__ */ uniform(_normalMatrix).onObjectUpdate(({ object }) => {
  if (object) computeNormalMatrix(object.matrixWorld, _normalMatrix);
});

/** The world-space offset of each build's vertex (thickness × the unit robust world normal). */
const _offsets = /* @__PURE__ */ new WeakMap<object, N>();

/**
 * `OutlineMaterial` for three's `WebGPURenderer` (`three/webgpu`), on its WebGPU and its WebGL2 backend: the
 * inverted-hull outline for cel shading. It draws the back faces of a mesh pushed out by `thickness` world units
 * along the robust world normal (sign(det)·cof of the world matrix, `computeNormalMatrix`), in one colour. Use it
 * on a second mesh sharing the geometry, or through `createOutlineNode`. Reads the `normal` attribute, or the
 * position on a sphere flagged like for `ShadingMaterial` (`SubdivisionSphereGeometry` or `userData.isSphere`);
 * a geometry with neither is drawn unmoved.
 *
 * Same options, defaults and checks as `OutlineMaterial` (a bad value throws the same error class with the same
 * message, naming `OutlineNodeMaterial`). On a `SkinnedMesh` or a mesh with morph targets, three's skinning and
 * morph nodes move each vertex and its normal first; on an `InstancedMesh` (`createOutlineNode` makes the outline
 * that kind of object), the instance matrix moves the vertex and sign(det)·cof of it the normal, as
 * `OutlineMaterial` and `ShadingMaterial` make it (finite for a zero or 1e20 instance scale, outward for a mirrored
 * instance, where three's inverse transpose is not). So the hull surrounds the deformed surface of every instance.
 * Fogged by `scene.fog` (`fog`, as three's node materials) at the pushed position; clipped by a `ClippingGroup`
 * (WebGPURenderer's clipping). Materials share one pipeline per kind of object (the width and colour are read
 * from the material at each draw, as three's material properties). Not for a `BatchedMesh`.
 *
 * @example
 * const outline = new Mesh(mesh.geometry, new OutlineNodeMaterial({ thickness: 0.05, color: '#000000' }));
 * mesh.add(outline);
 */
export class OutlineNodeMaterial extends NodeMaterial {
  /** three's type name. */
  static override get type(): string {
    return 'OutlineNodeMaterial';
  }
  /** Always true. */
  readonly isOutlineNodeMaterial = true;
  #thickness: number = OUTLINE_DEFAULTS.thickness;
  readonly #color = new Color(0, 0, 0);

  /** @param options - The thickness and the colour (see {@link OutlineNodeMaterialOptions}). */
  constructor({
    thickness = OUTLINE_DEFAULTS.thickness,
    color = OUTLINE_DEFAULTS.color,
  }: OutlineNodeMaterialOptions = {}) {
    super();
    this.side = BackSide;
    this.fog = true;
    this.thickness = thickness;
    this.color = color;
  }

  /** Outline width in world units (finite, ≥ 0). @default 0.03 */
  get thickness(): number {
    return this.#thickness;
  }
  set thickness(value: number) {
    this.#thickness = checkThickness(OWNER, value);
  }

  /** Outline colour (linear RGB; set it with a {@link ColorInput}, a number being a grey level in 0 … 1). @default Color(0, 0, 0) */
  get color(): Color {
    return this.#color;
  }
  set color(value: ColorInput) {
    setOutlineColor(OWNER, this.#color, value);
  }

  /**
   * The vertex moved as `OutlineMaterial` moves it: morph targets, then skinning (three's nodes), then the
   * instance matrix; the offset (thickness × the unit robust world normal of the moved normal) is kept for
   * {@link OutlineNodeMaterial.setupPositionView}.
   */
  override setupPosition(builder: N): N {
    const { object, geometry } = builder;
    const morphs = geometry.morphAttributes;
    if (morphs.position || morphs.normal || morphs.color) (morphReference as N)(object);
    if (object.isSkinnedMesh === true) (skinning as N)(object);
    // The object-space normal after morph targets and skinning, read here (before the instance matrix).
    let normal: N = vec3(0);
    if (geometry.hasAttribute('normal')) normal = normalLocal;
    else if (outlineSphereNormals(geometry)) normal = positionLocal;
    normal = (normal as N).toVar();
    normal.toStack();
    if (object.isInstancedMesh === true && object.instanceMatrix?.isInstancedBufferAttribute === true) {
      // As a variable: element(i) of the reference itself would read it as an array of matrices.
      const instance: N = (referenceAttribute as N)('instanceMatrix', 'mat4').toVar();
      (positionLocal as N).assign(instance.mul(vec4(positionLocal, 1)).xyz);
      normal.assign(rescale(cofactorTimes(instance, normal)));
    }
    const world: N = (objectNormalMatrix as N).mul(normal);
    const length = world.length();
    const unit = select(length.greaterThan(0), world.div(max(length, 1e-30)), vec3(0));
    const thickness: N = (materialReference as N)('thickness', 'float');
    _offsets.set(builder, unit.mul(thickness));
    return positionLocal;
  }

  /** The view position of the pushed vertex: V · (M · position + offset), read by the projection, fog and clipping. */
  override setupPositionView(builder: N): N {
    const offset = _offsets.get(builder) ?? vec3(0);
    const world = (modelWorldMatrix as N).mul(vec4(positionLocal, 1)).xyz.add(offset);
    return (cameraViewMatrix as N).mul(vec4(world, 1)).xyz;
  }

  /** One opaque colour: the material's `color` (no map, vertex or instance colour). */
  override setupDiffuseColor(): void {
    const color: N = (materialReference as N)('color', 'color');
    (diffuseColor as N).assign(vec4(color, 1));
  }

  /** Copies the thickness and the colour of `source` (and three's material properties). */
  override copy(source: this): this {
    super.copy(source);
    this.thickness = source.thickness;
    this.#color.copy(source.color);
    return this;
  }
}
