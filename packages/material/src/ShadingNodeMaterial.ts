// ShadingMaterial's shading on three's WebGPURenderer (both of its backends): a node material with a lighting
// model of the lecture's equation, PhongLights as light nodes beside three's own lights.
import {
  batchColor,
  cameraViewMatrix,
  colorSpaceToWorking,
  diffuseColor,
  frontFacing,
  instanceColor,
  instancedMesh,
  lightingContext,
  materialReference,
  max,
  modelViewMatrix,
  morphReference,
  negateOnBackSide,
  normalLocal,
  positionLocal,
  positionView,
  select,
  skinning,
  subBuild,
  uniform,
  varying,
  vec3,
  vec4,
  vertexColor,
  vertexIndex,
} from 'three/tsl';
import {
  BackSide,
  type BufferGeometry,
  Color,
  DoubleSide,
  Matrix3,
  NodeMaterial,
  SRGBColorSpace,
} from 'three/webgpu';
import { computeNormalMatrix } from './computeNormalMatrix.js';
import { SPHERE_FLAG } from './geometryFlags.js';
import { faceTexel, faceTexture, flatFace } from './nodeFlat.js';
import { cofactorTimes, instanceMatrixOf, instanceThroughReference, once, rescale } from './nodeInstance.js';
import {
  LectureLightingModel,
  type LightingSplit,
  PhongLightNode,
  phongLightNode,
  type Surface,
} from './nodeLighting.js';
import { normalMapped } from './nodeNormalMap.js';
import { removeShadowed, shadowingLightNodes, shadowTerms, unshadowed } from './nodeShadows.js';
import { SHADING_DEFAULTS } from './options.js';
import type { PhongLight } from './PhongLight.js';
import * as shared from './shadingProperties.js';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

export type { LightingSplit, Surface } from './nodeLighting.js';

/**
 * Options of {@link ShadingNodeMaterial}: `ShadingMaterial`'s, defined once (the lecture's options and three's
 * surface properties by their names: `map`, `vertexColors`, `emissive`, `emissiveMap`, `opacity`,
 * `transparent`, `alphaTest`, `alphaMap`, `normalMap`, `normalScale`), with the same defaults and checks.
 */
export type ShadingNodeMaterialOptions = shared.ShadingMaterialOptions;

/** An InstancedMesh's instance colour or a BatchedMesh's colour, or null. */
function instanceTint(builder: N): N {
  const object = builder.object ?? {};
  if (object.instanceColor != null) return instanceColor;
  if (object.isBatchedMesh === true && object._colorsTexture != null) return (batchColor as N).rgb;
  return null;
}

/** The unit vector from view-space point `p` towards a perspective eye at the origin; +z at the eye. */
export function towardsEye(p: N): N {
  const d = p.length();
  return select(d.greaterThan(0), p.negate().div(max(d, 1e-30)), vec3(0, 0, 1));
}

/**
 * `node` as a variable computed once, in the main flow of the stage being built, before the lighting: three
 * compiles a select() to an if/else block, and a node first used inside a block is computed there, and again in
 * every block that uses it (each light's specular branch).
 */
function onStack(node: N): N {
  const variable = node.toVar();
  variable.toStack();
  return variable;
}

/** `n` normalised; `fallback` where `n` is zero. */
export function unitOr(n: N, fallback: N): N {
  // Computed once, not again in the branch that divides it.
  const vector = once(n);
  const d = vector.length();
  return select(d.greaterThan(0), vector.div(max(d, 1e-30)), fallback);
}

/**
 * The robust normal matrix of the drawn object (sign(det)·cof of its world matrix, see `computeNormalMatrix`):
 * finite for a zero or extreme scale, where three's inverse transpose is not.
 */
const _robustNormalMatrix = /* @__PURE__ */ new Matrix3();
const robustNormalMatrix = /* @__PURE__ */ uniform(_robustNormalMatrix).onObjectUpdate(({ object }) => {
  if (object) computeNormalMatrix(object.matrixWorld, _robustNormalMatrix);
});

/** The 3 × 3 part of the drawn object's world matrix M (`normalMatrix: 'model'`, the lecture's wrong way). */
const _modelMatrix3 = /* @__PURE__ */ new Matrix3();
const modelMatrix3 = /* @__PURE__ */ uniform(_modelMatrix3).onObjectUpdate(({ object }) => {
  if (object) _modelMatrix3.setFromMatrix4(object.matrixWorld);
});

/** An object-space normal in view space, unnormalised (zero where the world matrix flattens it away). */
function normalToViewRobust(n: N): N {
  return (cameraViewMatrix as N).mul(vec4((robustNormalMatrix as N).mul(n), 0)).xyz;
}

/** An object-space normal in view space through M instead of the normal matrix (`normalMatrix: 'model'`). */
function normalToViewByModel(n: N): N {
  return (cameraViewMatrix as N).mul(vec4((modelMatrix3 as N).mul(n), 0)).xyz;
}

/** A unit view-space normal as three's MeshNormalMaterial packs it (n·0.5 + 0.5). */
function packNormal(n: N): N {
  return n.mul(0.5).add(0.5);
}

/** The options' properties of {@link ShadingNodeMaterial} (installed from shadingProperties.ts). */
export interface ShadingNodeMaterial extends shared.ShadingProperties {}

/** A sphere lit with analytic normals (its normal is its position): the subdivided sphere, or one flagged so. */
const isSphere = (geometry: BufferGeometry): boolean =>
  geometry.type === 'SubdivisionSphereGeometry' || geometry.userData?.[SPHERE_FLAG] === true;

/**
 * `ShadingMaterial`'s shading for three's `WebGPURenderer` (`three/webgpu`), on its WebGPU and its WebGL2
 * backend: the lecture's flat, Gouraud and Phong shading × Phong and Blinn-Phong lighting × cel bands, with the
 * same options, defaults, validation and equation as `ShadingMaterial` (the CPU `shade()` is the reference of
 * both). A node material: three's lighting model interface evaluates I = Σ ka·Ia + att·(kd·Id·max(l·n, 0) +
 * ks·Is·spec) per light, for {@link PhongLight}s (per-light Ia, Id, Is and 1/max(a + b·t + c·t², 1e-6)) and
 * three's lights (Id = Is = colour × intensity / π with three's falloff; ambient and hemisphere lights as Ia =
 * irradiance / π: as three's own materials receive them), in
 * view space (the camera's rigid transform keeps every dot product).
 *
 * Shading: `'phong'` per fragment; `'gouraud'` in the vertex stage, colours interpolated; `'flat'` once per face
 * at its centroid with its face normal, exactly one colour per face on both backends, for a triangle soup (each
 * vertex of a triangle reads its three corners from a float texture and computes the same colour, so the
 * provoking vertex, the first on WebGPU and the last on WebGL2, does not matter) and for a `flatShadingGeometry`
 * made for the backend's provoking vertex (`provokingVertex: 'first'` for WebGPU, the default `'last'` for
 * WebGL2; one made for the other is drawn as below, with a warning), skinned, morphed and instanced meshes
 * included (the corners moved and placed as three moves the vertices); else (another indexed geometry, a
 * BatchedMesh) per fragment with the face normal from screen-space derivatives (as three's `flatShading`). A geometry without `normal` that is a sphere centred at its origin
 * (`SubdivisionSphereGeometry` or `userData.isSphere`) uses normal = position. Normals go to view space through
 * the robust normal matrix sign(det)·cof(M) (`computeNormalMatrix`), finite for a zero or extreme scale; an
 * `InstancedMesh`'s instance matrix turns them as sign(det A)·cof(A) of its linear part A, as `ShadingMaterial`
 * does (not three's inverse transpose, which a zero or 1e20 instance scale breaks).
 *
 * Lights: the PhongLights of `lights`, else every PhongLight in the rendered scene (three lists them with its
 * own lights, through the light node this entry registers, so adding or removing one rebuilds the material as
 * adding a three.js light does), and three's lights. The variant (shading, lighting, cel bands, the lights) is
 * compiled in; changing it through the setters recompiles. ka, kd, ks, emissive and the PhongLights' colours
 * edited in place (bypassing the setters) to a non-finite or negative value are reported once with
 * console.error, as `ShadingMaterial` reports them, and drawn with their last valid values.
 *
 * Surface, with three's property names and `ShadingMaterial`'s options and checks, through three's
 * `setupDiffuseColor`: `map` and `vertexColors` (with an instance's or batch's colour) multiply ka and kd, never
 * ks, the texel per fragment in every shading (gouraud and exact flat shading pass the ka/kd part and the ks
 * part apart); `emissive` (× `emissiveMap`) is added outside the lighting; alpha is `opacity` × texel alpha ×
 * vertex alpha × `alphaMap` green (blended when `transparent`, discarded by `alphaTest`). `scene.fog` is three's
 * node fog (blended in linear before the output conversion, as three's node materials blend it). With
 * `receiveShadow`, three's shadow-casting lights shadow their term of the equation (never the ambient) in every
 * shading, per fragment; a PhongLight casts no shadow (its `castShadow` is ignored).
 * `normalMap` perturbs the normal in phong shading.
 *
 * @example
 * const light = new PhongLight();
 * light.position.set(-5, 10, 20);
 * const material = new ShadingNodeMaterial({ shading: 'gouraud', lighting: 'blinn-phong', lights: [light] });
 */
// biome-ignore lint/suspicious/noUnsafeDeclarationMerging: the options' accessors are installed on the prototype (installShadingProperties), typed by the interface.
export class ShadingNodeMaterial extends NodeMaterial {
  /** three's type name. */
  static override get type(): string {
    return 'ShadingNodeMaterial';
  }
  /** Always true: lets code tell a ShadingNodeMaterial from other materials without `instanceof`. */
  readonly isShadingNodeMaterial = true;

  /** The class named in error messages (a subclass's own name). */
  get #owner(): string {
    return (this.constructor as typeof ShadingNodeMaterial).type;
  }

  // What the GPU draws with: ka, kd, ks as last found valid, checked and copied once per render.
  readonly #uniforms = {
    ka: uniform(new Color(...SHADING_DEFAULTS.ka)),
    kd: uniform(new Color(...SHADING_DEFAULTS.kd)),
    ks: uniform(new Color(...SHADING_DEFAULTS.ks)),
  };
  readonly #shininessNode = uniform(SHADING_DEFAULTS.shininess);
  // What the GPU adds: emissive as last found valid.
  readonly #emissiveNode: N = uniform(new Color(0, 0, 0));
  // Whether the last build added the emissive (see #emits); null until this class's setupLighting has run (a
  // subclass's own lighting, the impostor's, adds none).
  #emissiveBuilt: boolean | null = null;
  // The warning that normalMap needs phong shading was given.
  #warnedNormalMap = false;
  /** Per build of an InstancedMesh of a sphere without a normal attribute: its normal, turned by the instance. */
  readonly #instancedSphereNormals = new WeakMap<object, N>();

  /**
   * @param options - Shading, lighting, reflectances and lights; each one omitted takes its default (see
   *   {@link ShadingNodeMaterialOptions}).
   */
  constructor(options: ShadingNodeMaterialOptions = {}) {
    super();
    this.lights = true;
    shared.applyShadingOptions(this, this.#owner, options);
    this.#uniforms.ka.onRenderUpdate(() => {
      this.#refresh();
    });
    this.#refresh();
  }

  /**
   * Copies ka, kd and ks to their uniforms. A value edited in place (bypassing the setters) to a non-finite or
   * negative channel is reported once with console.error, as `ShadingMaterial` reports it, and the draw keeps
   * the last valid values instead of uploading a NaN.
   */
  #refresh(): undefined {
    if (!shared.checkEditedInPlace(this, this.#owner)) return;
    (this.#uniforms.ka.value as Color).copy(this.ka);
    (this.#uniforms.kd.value as Color).copy(this.kd);
    (this.#uniforms.ks.value as Color).copy(this.ks);
    (this.#emissiveNode.value as Color).copy(this.emissive);
    // Edited in place from black: built in from the next frame on (the setter rebuilds at once).
    this.#emissiveChanged();
  }

  /**
   * Whether the colour output adds the emissive (its last valid value): only when it is not black or an
   * `emissiveMap` is set, as ShadingMaterial compiles it (SHADING_EMISSIVE); a black one costs nothing per
   * fragment.
   */
  #emits(): boolean {
    const e = this.#emissiveNode.value as Color;
    return this.output === 'color' && (this.emissiveMap !== null || e.r > 0 || e.g > 0 || e.b > 0);
  }

  #emissiveChanged(): void {
    if (this.#emissiveBuilt !== null && this.#emits() !== this.#emissiveBuilt) this.needsUpdate = true;
  }

  static {
    // The options' accessors (shadingProperties.ts), and what a change does here: a rebuild for the variant and
    // the lights, the shininess uniform.
    shared.installShadingProperties(ShadingNodeMaterial, {
      owner: (material) => (material.constructor as typeof ShadingNodeMaterial).type,
      change: (material, kind, changed) => (material as ShadingNodeMaterial).#optionChanged(kind, changed),
    });
  }

  #optionChanged(kind: shared.PropertyChange, changed: boolean): void {
    if (kind === 'shininess') this.#shininessNode.value = this.shininess;
    else if (kind === 'emissive') {
      // Set through the setter (so valid): the uniform now, and a rebuild when it turns black or stops being so.
      (this.#emissiveNode.value as Color).copy(this.emissive);
      this.#emissiveChanged();
    } else if (changed) this.needsUpdate = true;
  }

  /**
   * The lit colour of a surface point, as three's lighting node of this material's lights (the PhongLights of
   * `lights`, else the scene's, and three's lights) with the lecture's lighting model. For subclasses that
   * light another surface (the impostor's ray-cast hit).
   * @param surface - Unit normal `n` and unit vector towards the viewer `v`, view space, nodes.
   * @param positionView - The lit point in view space, when it is not three's `positionView`.
   * @param split - What multiplies ka and kd (default: an InstancedMesh's instance colour or a BatchedMesh's
   *   colour), and a variable for the ks part when it is kept apart (see {@link LightingSplit}).
   */
  protected lightSurface(builder: N, surface: Surface, positionView?: N, split: LightingSplit = {}): N {
    // An InstancedMesh's instanceColor and a BatchedMesh's colours multiply ka and kd (not ks), as on
    // ShadingMaterial; three puts them in diffuseColor, which this lighting model does not read.
    const tint: N = split.tint !== undefined ? split.tint : instanceTint(builder);
    const { ka, kd, ks } = this.#uniforms;
    const model = new LectureLightingModel(
      this,
      surface,
      {
        ka: tint === null ? ka : (ka as N).mul(tint),
        kd: tint === null ? kd : (kd as N).mul(tint),
        ks,
        shininess: this.#shininessNode,
      },
      split.specular,
    );
    // The scene's PhongLights come with three's lights (their registered light node); the listed ones, which
    // need not be in the scene, as the material's own lightings (the model keeps only them then).
    const node = lightingContext(
      builder.lightsNode,
      model,
      this.phongLights.map(phongLightNode) as never,
    ) as N;
    const context: Record<string, unknown> = {};
    if (positionView !== undefined) context.positionView = positionView;
    // Lit in the vertex stage, three's shadow-casting lights light unshadowed; the fragment stage shadows them.
    if (surface.shadows !== undefined) context.getShadow = unshadowed;
    return Object.keys(context).length === 0 ? node : node.context(context);
  }

  /**
   * The vertex moved as three's NodeMaterial moves it (morph targets, skinning, the instance matrix, then
   * `positionNode`), but on an InstancedMesh its normal turned by sign(det A)·cof(A) of the instance's linear part
   * A, as `ShadingMaterial` turns it (finite for a zero or 1e20 instance scale, outward for a mirrored instance),
   * not by three's inverse transpose (made from A's column lengths: infinite or NaN there). Where three shares the
   * build between instanced meshes, the vertices, the normal and exact flat shading read one instance matrix node.
   */
  override setupPosition(builder: N): N {
    const { object, geometry } = builder;
    if (object.isInstancedMesh !== true || object.instanceMatrix?.isInstancedBufferAttribute !== true) {
      return super.setupPosition(builder);
    }
    const morphs = geometry.morphAttributes;
    if (morphs.position || morphs.normal || morphs.color) (morphReference as N)(object);
    if (object.isSkinnedMesh === true) (skinning as N)(object);
    // The object-space normal after morph targets and skinning, before three's instance node turns it: the normal
    // attribute, or a sphere's position (its normal, which the instance node is about to move).
    const hasNormal = geometry.hasAttribute('normal') === true;
    const normal: N = hasNormal
      ? (normalLocal as N).toVar()
      : isSphere(geometry)
        ? (positionLocal as N).toVar()
        : null;
    if (normal !== null) normal.toStack();
    if (!instanceThroughReference(builder, object)) (instancedMesh as N)(object);
    if (normal !== null) {
      const turned: N = rescale(cofactorTimes(instanceMatrixOf(builder, object), normal));
      if (hasNormal) (normalLocal as N).assign(turned);
      else this.#instancedSphereNormals.set(builder, turned);
    }
    if (this.positionNode !== null) {
      (positionLocal as N).assign((subBuild as N)(this.positionNode, 'POSITION', 'vec3'));
    }
    return positionLocal;
  }

  /**
   * three's `diffuseColor` as three's NodeMaterial builds it (vertex colours, instance and batch colours,
   * opacity, alpha test, opaque alpha), from this material's surface: rgb = the texel of `map` (or `colorNode`)
   * × vertex colour × instance colour, a = `opacity` × texel alpha × vertex alpha × `alphaMap` green (three's
   * WebGL channel, as `ShadingMaterial` reads it).
   */
  override setupDiffuseColor(builder: N): void {
    const { colorNode, opacityNode } = this;
    if (colorNode === null) {
      this.colorNode = (this.map !== null ? materialReference('map', 'texture') : vec4(1)) as never;
    }
    if (opacityNode === null && this.alphaMap !== null) {
      this.opacityNode = (materialReference('opacity', 'float') as N).mul(
        (materialReference('alphaMap', 'texture') as N).g,
      );
    }
    try {
      super.setupDiffuseColor(builder);
    } finally {
      this.colorNode = colorNode;
      this.opacityNode = opacityNode;
    }
  }

  /** Builds the lighting of the variant (three calls it when it compiles the material), plus the emissive. */
  override setupLighting(builder: N): N {
    this.#emissiveBuilt = this.#emits();
    if (this.normalMap !== null && this.shading !== 'phong' && !this.#warnedNormalMap) {
      this.#warnedNormalMap = true;
      console.warn(
        `${this.#owner}: normalMap needs a per-fragment normal (shading 'phong'); ${this.shading} shading ignores it`,
      );
    }
    if (this.output !== 'color') {
      const lit = this.#lit(builder);
      // The data outputs are written as is, as three's MeshNormalNodeMaterial writes its normal (decoded from
      // sRGB here so that the output conversion gives the value back); the terms leave the emissive out.
      const data = this.output === 'normal' || this.output === 'attenuation';
      return data ? (colorSpaceToWorking as N)(vec4(lit, 1), SRGBColorSpace).rgb : lit;
    }
    if (!this.#emissiveBuilt) return this.#lit(builder);
    const emissive: N =
      this.emissiveMap !== null
        ? this.#emissiveNode.mul((materialReference('emissiveMap', 'texture') as N).rgb)
        : this.#emissiveNode;
    return this.#lit(builder).add(emissive);
  }

  /** three's fog, on the colour only (the term, attenuation and normal outputs are not fogged). */
  override setupFog(builder: N, outputNode: N): N {
    return this.output === 'color' ? super.setupFog(builder, outputNode) : outputNode;
  }

  /** The lit colour of the variant: phong or flat by derivatives per fragment, gouraud and flat per vertex. */
  #lit(builder: N): N {
    const geometry: BufferGeometry = builder.geometry;
    const orthographic = builder.camera?.isOrthographicCamera === true;
    const towardsViewer = (p: N): N => (orthographic ? vec3(0, 0, 1) : towardsEye(p));
    const hasNormal = geometry.getAttribute('normal') !== undefined;
    const sphere = isSphere(geometry);
    if (this.shading !== 'flat' && !hasNormal && !sphere) {
      throw new TypeError(
        `${this.#owner}: ${this.shading} shading needs a normal attribute on ${geometry.type} (or a sphere flagged with userData.${SPHERE_FLAG})`,
      );
    }
    // Per fragment, diffuseColor.rgb (texel × vertex colour × instance colour) multiplies ka and kd. Without a
    // texel or vertex colours it is the instance's (or batch's) colour or 1: lightSurface's own default, which
    // multiplies nothing when there is none.
    const vertexColours =
      this.vertexColors && (geometry.hasAttribute('color') || geometry.morphAttributes.color !== undefined);
    const fragmentTint =
      this.colorNode !== null || this.map !== null || vertexColours ? { tint: (diffuseColor as N).rgb } : {};
    // A sphere's normal is its position: on an InstancedMesh, as it was before the instance moved it, turned by the
    // instance's normal matrix (setupPosition).
    const localNormal: N = hasNormal
      ? normalLocal
      : (this.#instancedSphereNormals.get(builder) ?? positionLocal);
    const normalToView = this.normalMatrix === 'model' ? normalToViewByModel : normalToViewRobust;
    const packed = this.output === 'normal';
    if (this.shading === 'phong') {
      const v = onStack(towardsViewer(positionView));
      // Unit vertex normals interpolated (zero where the matrix flattens the surface away); a back face
      // (DoubleSide, BackSide) is lit with its normal turned round, as three's normalView does.
      let n: N = unitOr(negateOnBackSide(varying(unitOr(normalToView(localNormal), vec3(0)))), v);
      // A normal map perturbs that normal (as ShadingMaterial does: not three's normalView).
      if (this.normalMap !== null) n = onStack(normalMapped(this, n, positionView, normalToViewRobust));
      if (packed) return packNormal(n);
      return this.lightSurface(builder, { n, v }, undefined, fragmentTint);
    }
    // Per vertex: the instance and vertex colours multiply ka and kd there; a texel (of `map`, or `colorNode`)
    // multiplies the interpolated ka/kd part per fragment, the ks part passed apart (ShadingMaterial's split).
    // (Not diffuseColor.rgb, which holds the interpolated vertex and instance colours too.)
    const texel: N =
      this.colorNode !== null
        ? vec4(this.colorNode as never).rgb
        : this.map !== null
          ? (materialReference('map', 'texture') as N).rgb
          : null;
    const face = this.shading === 'flat' ? flatFace(builder, geometry, this.#owner) : null;
    const vertexTint = this.#vertexTint(builder, face !== null && geometry.index === null);
    // The vertex stage cannot tell a front face from a back one: it lights the side(s) the material draws, the
    // back with the normal turned round, and the fragment takes the colour of the side it is on.
    // Both sides (DoubleSide) are lit in one pass, the back into variables of its own.
    // three's shadow-casting lights are recorded apart and shadowed per fragment (nodeShadows.ts).
    const shadowing = shadowingLightNodes(builder, (node) => node instanceof PhongLightNode);
    const sided = (surface: (sign: number) => Surface, view: N, interpolate: (node: N) => N): N => {
      const double = this.side === DoubleSide;
      const frontSign = double || this.side !== BackSide ? 1 : -1;
      if (packed) {
        // The normal output: the side's unit normal, packed per vertex and interpolated.
        const front = interpolate(packNormal(surface(frontSign).n));
        return double ? select(frontFacing, front, interpolate(packNormal(surface(-1).n))) : front;
      }
      const front = surface(frontSign);
      const specular = texel !== null ? vec3(0).toVar() : undefined;
      if (double) {
        front.back = vec3(0).toVar();
        if (texel !== null) front.backSpecular = vec3(0).toVar();
      }
      const shadows = shadowing.length > 0 ? shadowTerms(shadowing, double, texel !== null) : undefined;
      front.shadows = shadows;
      const lit = interpolate(this.lightSurface(builder, front, view, { tint: vertexTint, specular }));
      const colour = (part: N, ks: N | undefined): N =>
        ks === undefined ? part : part.mul(texel).add(interpolate(ks));
      const shadowed = (c: N, side: 'front' | 'back'): N =>
        shadows === undefined ? c : removeShadowed(c, shadows, side, (t, ks) => colour(interpolate(t), ks));
      const frontColour = shadowed(colour(lit, specular), 'front');
      if (!double) return frontColour;
      const backColour = shadowed(colour(interpolate(front.back), front.backSpecular), 'back');
      return select(frontFacing, frontColour, backColour);
    };
    if (this.shading === 'gouraud') {
      const v = once(towardsViewer(positionView));
      const n = unitOr(normalToView(localNormal), v);
      return sided((sign) => ({ n: n.mul(sign), v, hoisted: [v] }), undefined, varying);
    }
    if (face !== null) {
      // The vertex stage lights the face's centroid with its normal; every vertex that can provoke computes it.
      const [a, b, c] = face.corners;
      const centroid = vec4(a.add(b).add(c).div(3), 1);
      const view = once(
        (modelViewMatrix as N).mul(face.instance === null ? centroid : face.instance.mul(centroid)).xyz,
      );
      const v = once(towardsViewer(view));
      const normal = rescale(b.sub(a).cross(c.sub(a)));
      const n = unitOr(
        normalToView(face.instance === null ? normal : rescale(cofactorTimes(face.instance, normal))),
        v,
      );
      return sided(
        (sign) => ({ n: n.mul(sign), v, hoisted: [view, v] }),
        view,
        (node) => varying(node).setInterpolation('flat'),
      );
    }
    // The derivatives' normal faces the viewer: the visible side's, whichever it is.
    const v = onStack(towardsViewer(positionView));
    const n = unitOr((positionView as N).dFdx().cross((positionView as N).dFdy()), v);
    if (packed) return packNormal(n);
    return this.lightSurface(builder, { n, v }, undefined, fragmentTint);
  }

  /**
   * What multiplies ka and kd in the vertex stage (gouraud, exact flat): instance colour × batch colour × the
   * vertex colour (with `vertexColors` and a `color` attribute); null when none.
   */
  #vertexTint(builder: N, soup: boolean): N {
    const tints: N[] = [];
    const instance = instanceTint(builder);
    if (instance !== null) tints.push(instance);
    const geometry: BufferGeometry = builder.geometry;
    if (this.vertexColors && geometry.hasAttribute('color')) {
      // Exact flat shading of a triangle soup: the colour of the triangle's last vertex (WebGL's provoking
      // vertex, ShadingMaterial's colour) on either backend, read from a face texture as the corners are.
      tints.push(
        soup
          ? faceTexel(faceTexture(geometry, 'color'), (vertexIndex as N).div(3).mul(3).add(2)).rgb
          : (vertexColor() as N).rgb,
      );
    }
    return tints.length === 0 ? null : tints.reduce((a, b) => a.mul(b));
  }

  /**
   * three's program cache key, made this material's own: its uniforms (ka, kd, ks, emissive, the listed lights'
   * nodes) are its own nodes, so two materials never share a node build (their pipelines are still shared when
   * the generated code is the same); and whether the emissive is built in.
   */
  override customProgramCacheKey(): string {
    return `${super.customProgramCacheKey()},${this.id},${this.#emits()}`;
  }

  /**
   * three's observer of this material, told that the material holds nodes: its uniforms (ka, kd, ks,
   * emissive, shininess) are nodes of its own, not material properties three compares, so three refreshes
   * its bindings on every frame as it does for a material with node properties.
   */
  override setupObserver(builder: N): N {
    const observer = super.setupObserver(builder) as N;
    observer.hasNode = true;
    return observer;
  }

  /** Copy every option of `source` (lights are shared, not cloned). @returns `this`. */
  override copy(source: ShadingNodeMaterial): this {
    super.copy(source);
    shared.copyShadingOptions(this, source);
    this.#refresh();
    this.#shininessNode.value = this.shininess;
    return this;
  }
}
