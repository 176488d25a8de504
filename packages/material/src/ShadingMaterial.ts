import {
  BackSide,
  type BufferGeometry,
  type Camera,
  Color,
  type Group,
  type InstancedMesh,
  type Light,
  Matrix3,
  type Matrix4,
  type Object3D,
  type PointLight,
  type Scene,
  ShaderMaterial,
  type SkinnedMesh,
  type SpotLight,
  type Texture,
  UniformsLib,
  UniformsUtils,
  Vector2,
  Vector4,
  type WebGLRenderer,
} from 'three';
import { computeNormalMatrix } from './computeNormalMatrix.js';
import { eyeOf } from './eyeOf.js';
import { facePositionTexture, faceSkinTexture } from './facePositionTexture.js';
import { FLAT_CORNER_INDEX, FLAT_CORNERS, FLAT_PROVOKING_VERTEX, SPHERE_FLAG } from './geometryFlags.js';
import type { ShadingOutput } from './options.js';
import { hasOrthogonalInstances } from './orthogonalInstances.js';
import { PhongLight } from './PhongLight.js';
import { fragmentShader, vertexShader } from './ShadingMaterial.glsl.js';
import {
  applyShadingOptions,
  checkEditedInPlace,
  copyShadingOptions,
  installShadingProperties,
  type PropertyChange,
  type ShadingMaterialOptions,
  type ShadingProperties,
} from './shadingProperties.js';

export type { ShadingMaterialOptions } from './shadingProperties.js';

/**
 * The defines of each `output` (see outputChunks.glsl.ts): its own, and which terms the lighting leaves out; none
 * for the colour.
 */
const OUTPUT_DEFINES: Record<ShadingOutput, readonly string[]> = {
  color: [],
  ambient: ['SHADING_OUTPUT_AMBIENT', 'SHADING_OUTPUT_TERM', 'SHADING_NO_DIFFUSE', 'SHADING_NO_SPECULAR'],
  diffuse: ['SHADING_OUTPUT_DIFFUSE', 'SHADING_OUTPUT_TERM', 'SHADING_NO_AMBIENT', 'SHADING_NO_SPECULAR'],
  specular: ['SHADING_OUTPUT_SPECULAR', 'SHADING_OUTPUT_TERM', 'SHADING_NO_AMBIENT', 'SHADING_NO_DIFFUSE'],
  attenuation: [
    'SHADING_OUTPUT_ATTENUATION',
    'SHADING_OUTPUT_TERM',
    'SHADING_OUTPUT_DATA',
    'SHADING_NO_AMBIENT',
  ],
  normal: ['SHADING_OUTPUT_NORMAL', 'SHADING_OUTPUT_TERM', 'SHADING_OUTPUT_DATA', 'SHADING_NO_AMBIENT'],
};

/** The geometries already warned about their provoking vertex. */
const _warnedProvoking = /* @__PURE__ */ new WeakSet<BufferGeometry>();

/** The class named in error messages. */
const OWNER = 'ShadingMaterial';

/** 1/π: three's factor of every light's colour (BRDF_Lambert), as `shade()` applies it to three's lights. */
const RECIPROCAL_PI = 1 / Math.PI;

/** What a scene holds for the material, found once per frame (see {@link sceneLightsOf}). */
interface SceneLights {
  /** three's renderer frame it was found in. */
  frame: number;
  /** Some visible three.js light (AmbientLight, HemisphereLight, PointLight, DirectionalLight, SpotLight, …). */
  threeLights: boolean;
  /** The visible PhongLights, in traversal order. */
  phong: PhongLight[];
  /** Some visible PointLight or SpotLight has a cut-off `distance` > 0 (three's falloff window is needed). */
  cutoff: boolean;
  /** Every visible PointLight and SpotLight has `decay` 2 (three's default): the falloff is 1/max(t², 0.01). */
  inverseSquare: boolean;
}

const _sceneLights = /* @__PURE__ */ new WeakMap<Object3D, SceneLights>();

/**
 * The lights of `scene`, found by one traversal per rendered frame (`renderer.info.render.frame`), shared by
 * every draw of every ShadingMaterial in that frame; every draw when the renderer has no frame counter.
 */
function sceneLightsOf(renderer: WebGLRenderer | null, scene: Scene | null): SceneLights {
  const frame = renderer?.info?.render?.frame ?? Number.NaN;
  if (scene === null || scene === undefined) {
    return { frame, threeLights: false, phong: [], cutoff: false, inverseSquare: true };
  }
  const cached = _sceneLights.get(scene);
  if (cached !== undefined && cached.frame === frame) return cached;
  const found: SceneLights = { frame, threeLights: false, phong: [], cutoff: false, inverseSquare: true };
  scene.traverseVisible((object) => {
    if (object instanceof PhongLight) found.phong.push(object);
    else if ((object as Light).isLight === true) {
      found.threeLights = true;
      const point = object as PointLight;
      if (point.isPointLight === true || (object as SpotLight).isSpotLight === true) {
        if (point.distance > 0) found.cutoff = true;
        if (point.decay !== 2) found.inverseSquare = false;
      }
    }
  });
  _sceneLights.set(scene, found);
  return found;
}

/** A map's uniforms as three's refreshTransformUniform sets them: the texture and its uv transform. */
function refreshMap(
  texture: { value: Texture | null },
  transform: { value: Matrix3 },
  map: Texture | null,
): void {
  texture.value = map;
  if (map === null) return;
  if (map.matrixAutoUpdate) map.updateMatrix();
  transform.value.copy(map.matrix);
}

/** Whether `m`'s upper 3 × 3 is a rotation (or a reflection): orthonormal columns, within float32 rounding. */
function isRigid(m: Matrix4): boolean {
  const e = m.elements;
  const dot = (a: number, b: number) => e[a] * e[b] + e[a + 1] * e[b + 1] + e[a + 2] * e[b + 2];
  const near = (x: number, y: number) => Math.abs(x - y) < 1e-5;
  return (
    near(dot(0, 0), 1) &&
    near(dot(4, 4), 1) &&
    near(dot(8, 8), 1) &&
    near(dot(0, 4), 0) &&
    near(dot(0, 8), 0) &&
    near(dot(4, 8), 0)
  );
}

/** The options' properties of {@link ShadingMaterial} (installed from shadingProperties.ts). */
export interface ShadingMaterial extends ShadingProperties {}

/**
 * Classic lighting on three.js: the lecture's flat, Gouraud and Phong shading crossed with Phong,
 * Blinn-Phong and cel lighting, lit by {@link PhongLight}s. Lighting is done in world space with the
 * equation of `shade` (which is the CPU reference of this material): per light L,
 * I = ka·Ia + att(t)·(kd·Id·max(l·n, 0) + ks·Is·spec), att(t) = 1 / (a + b·t + c·t²).
 *
 * Only what the scene needs is compiled: the variant is a set of `defines` (shading, lighting, cel bands,
 * number of lights, attenuation when some light has b or c ≠ 0 or a ≠ 1, analytic sphere normals), three
 * caches one program per variant, and `needsUpdate` is raised only when the variant changes.
 *
 * Geometry: gouraud and phong read the `normal` attribute, or, when a geometry has none and is a sphere
 * centred at its origin (`geometry.type === 'SubdivisionSphereGeometry'` or `geometry.userData.isSphere
 * === true`), use the exact normal = position. Flat shading lights each face once, at its centroid with its
 * face normal, and takes either a {@link flatShadingGeometry} (indexed; each face's last vertex carries the
 * face: the cheaper way) or a non-indexed geometry (each triangle owns its three vertices; the vertex shader
 * fetches them from a float texture, 12 bytes per vertex, cached per geometry); any other indexed geometry is
 * drawn without preparation, each fragment lit at its world position with the face normal from screen-space
 * derivatives (`FLAT_DERIVATIVES`, what three's `flatShading` does: no exact one colour per face).
 *
 * In any three.js scene, through three's own program parameters and shader chunks, each compiled only when
 * the scene uses it: `InstancedMesh` (its `instanceColor` multiplies ka and kd) and `BatchedMesh`,
 * `SkinnedMesh` and morph targets (every shading; flat shading moves a face's corners as three moves its
 * vertices), `scene.fog` (`fog`), clipping planes (`clippingPlanes`, the renderer's, `clipIntersection`), tone
 * mapping (`toneMapped`) and the output colour space. Instance normals use the instance matrix's robust
 * normal matrix, as the object's do. three's lights in the scene (AmbientLight, HemisphereLight, PointLight,
 * DirectionalLight, SpotLight) light it through the same equation with three's light uniforms, as they light
 * three's own materials (with three's 1/π): Id = Is = colour × intensity / π, three's distance and cone falloff in
 * place of the attenuation, ambient and hemisphere lights as Ia = irradiance / π (see `ShadeThreeLight`), so
 * `{ ka: c, kd: c, ks: 0 }` draws `MeshLambertMaterial({ color: c })`'s pixels; compiled only when the scene has one of three's lights (the scene is
 * searched once per frame); with `receiveShadow`, three's shadow factor multiplies each shadow-casting light's
 * term per fragment in every shading. three's surface properties by their names, through three's chunks, each compiled
 * only when set: `map` and `vertexColors` multiply ka and kd (never ks), `emissive` (× `emissiveMap`) is added
 * outside the lighting, alpha is `opacity` × map alpha × vertex alpha × `alphaMap` green (blended when
 * `transparent`, discarded below `alphaTest`), and `normalMap` perturbs the normal in phong shading.
 *
 * Colours are linear (three's working colour space), tone-mapped when the renderer asks for it and written
 * through three's output colour space conversion. The object's normal matrix is sign(det)·cof(M) of its world matrix (see
 * `computeNormalMatrix`), finite for singular matrices; the view vector is right for perspective and
 * orthographic cameras alike (taken from the camera's projection: a point or a direction).
 *
 * @example
 * const light = new PhongLight();
 * light.position.set(-5, 10, 20);
 * const material = new ShadingMaterial({ shading: 'gouraud', lighting: 'blinn-phong', lights: [light] });
 * scene.add(light, new THREE.Mesh(new THREE.IcosahedronGeometry(1, 5), material));
 */
// biome-ignore lint/suspicious/noUnsafeDeclarationMerging: the options' accessors are installed on the prototype (installShadingProperties), typed by the interface.
export class ShadingMaterial extends ShaderMaterial {
  /** Always true: lets code tell a ShadingMaterial from other materials without `instanceof`. */
  readonly isShadingMaterial = true;
  /** three's type name: `'ShadingMaterial'`. */
  override type = 'ShadingMaterial';
  /**
   * Apply `scene.fog` (three's `Fog` or `FogExp2`), as three's `MeshPhongMaterial` does: blended in the output
   * colour space by three's fog factor (fog near = far is a step at that depth). Compiled only when the scene
   * has fog. @default true
   */
  override fog = true;
  /**
   * Clip by `clippingPlanes` (with `clipIntersection`) and the renderer's `clippingPlanes`, as three's
   * materials do; compiled only when some plane applies. @default true
   */
  override clipping = true;

  // The PhongLights that light the last draw: the list when it is not empty, else the scene's.
  #active: readonly PhongLight[] = [];
  // What the last drawn geometry and lights asked for (part of the variant).
  #sphereNormals = false;
  #flatCorners = false;
  #flatDerivatives = false;
  #attenuation = false;
  #threeLights = false;
  // What three's point and spot lights in the scene need of their falloff (see SceneLights).
  #lightCutoff = false;
  #inverseSquare = true;
  // Per-fragment lighting with three's lights (whose uniforms are in view space) runs in view space.
  #viewSpace = false;
  // Every instance matrix of the drawn InstancedMesh is a rotation × a scale (see hasOrthogonalInstances).
  #orthogonalInstances = false;
  /**
   * Whether per-fragment lighting with three's lights may run in view space (see `onBeforeRender`); false for
   * a subclass whose fragment stage lights in world space itself (the impostor). @internal
   */
  protected readonly viewSpaceLighting: boolean = true;
  // What of the surface three compiles (its program parameters), to raise needsUpdate when it changes.
  #surfaceKey = '';
  // The normal map was set with a shading that cannot use it, and the warning was given.
  #warnedNormalMap = false;

  /**
   * @param options - Shading, lighting, reflectances and lights; each one omitted takes its default (see
   *   {@link ShadingMaterialOptions}).
   */
  constructor(options: ShadingMaterialOptions = {}) {
    super({
      vertexShader,
      fragmentShader,
      uniforms: {
        shadingNormalMatrix: { value: new Matrix3() },
        shadingEye: { value: new Vector4(0, 0, 1, 0) },
        ambientTerm: { value: new Float32Array(3) },
        shininess: { value: 32 },
        lightPosition: { value: new Float32Array(0) },
        lightDiffuse: { value: new Float32Array(0) },
        lightSpecular: { value: new Float32Array(0) },
        lightAttenuation: { value: new Float32Array(0) },
        facePositions: { value: null },
        faceSkin: { value: null },
        shadingKa: { value: new Color() },
        shadingKd: { value: new Color() },
        shadingKs: { value: new Color() },
        map: { value: null },
        mapTransform: { value: new Matrix3() },
        alphaMap: { value: null },
        alphaMapTransform: { value: new Matrix3() },
        emissive: { value: new Color() },
        emissiveMap: { value: null },
        emissiveMapTransform: { value: new Matrix3() },
        opacity: { value: 1 },
        alphaTest: { value: 0 },
        normalMap: { value: null },
        normalMapTransform: { value: new Matrix3() },
        normalScale: { value: new Vector2(1, 1) },
        ...UniformsUtils.clone(UniformsLib.fog),
        ...UniformsUtils.clone(UniformsLib.lights),
      },
    });
    applyShadingOptions(this, OWNER, options);
    this.#syncDefines();
  }

  static {
    // The options' accessors (shadingProperties.ts), and what a change does here: the variant's defines, the
    // shininess uniform, the lights' part of the variant.
    installShadingProperties(ShadingMaterial, {
      owner: () => OWNER,
      change: (material, kind) => (material as ShadingMaterial).#optionChanged(kind),
    });
  }

  #optionChanged(kind: PropertyChange): void {
    if (kind === 'shininess') {
      this.uniforms.shininess.value = this.shininess;
      return;
    }
    if (kind === 'lights') {
      this.#active = this.phongLights;
      this.#attenuation = this.#active.some((light) => light.attenuates);
    }
    this.#syncDefines();
  }

  /**
   * Per-draw work: pick the variant for this geometry and these lights (raising `needsUpdate` only when it
   * changes), then fill the per-object uniforms. Called by three before each draw.
   */
  override onBeforeRender(
    _renderer: WebGLRenderer,
    _scene: Scene,
    camera: Camera,
    geometry: BufferGeometry,
    object: Object3D,
    _group: Group,
  ): void {
    const u = this.uniforms;
    const hasNormal = geometry.getAttribute('normal') !== undefined;
    if (this.shading === 'flat') {
      const skinned = (object as SkinnedMesh).isSkinnedMesh === true;
      const indexed = geometry.index !== null;
      const deformed = skinned || geometry.morphAttributes.position !== undefined;
      // An indexed geometry without the corners its deformation needs: per-fragment lighting with the face
      // normal from screen-space derivatives (no preparation step, not one exact colour per face).
      // A flatShadingGeometry made for WebGPU's provoking vertex (the first) puts each face on a vertex WebGL
      // does not take its flat varyings from: the same, with a warning (once per geometry).
      const firstProvoking = geometry.userData[FLAT_PROVOKING_VERTEX] === 'first';
      if (firstProvoking && !_warnedProvoking.has(geometry)) {
        _warnedProvoking.add(geometry);
        console.warn(
          "ShadingMaterial: this flatShadingGeometry was made with provokingVertex 'first' (WebGPU's); WebGL's is the last, so flat shading lights it per fragment with the face normal. Make it with flatShadingGeometry(geometry) for WebGLRenderer",
        );
      }
      this.#flatDerivatives =
        indexed &&
        (firstProvoking ||
          geometry.getAttribute(FLAT_CORNERS[0]) === undefined ||
          (deformed && geometry.getAttribute(FLAT_CORNER_INDEX) === undefined));
      this.#flatCorners = indexed && !this.#flatDerivatives;
      u.facePositions.value = indexed ? null : facePositionTexture(geometry);
      u.faceSkin.value = skinned && !this.#flatDerivatives ? faceSkinTexture(geometry) : null;
    } else {
      const sphere = geometry.type === 'SubdivisionSphereGeometry' || geometry.userData[SPHERE_FLAG] === true;
      if (!hasNormal && !sphere) {
        throw new TypeError(
          `ShadingMaterial: ${this.shading} shading needs a normal attribute on ${geometry.type} (or a sphere flagged with userData.${SPHERE_FLAG})`,
        );
      }
      this.#sphereNormals = !hasNormal;
      u.facePositions.value = null;
      u.faceSkin.value = null;
    }
    const seen = sceneLightsOf(_renderer, _scene);
    this.#active = this.phongLights.length > 0 ? this.phongLights : seen.phong;
    this.#attenuation = this.#active.some((light) => light.attenuates);
    this.#threeLights = seen.threeLights;
    this.#lightCutoff = seen.cutoff;
    this.#inverseSquare = seen.inverseSquare;
    // three's lights are uniforms in view space: a fragment lit by them is lit in view space (the PhongLights and
    // the eye go there on the CPU), instead of carrying its position, normal and view vector there per fragment.
    // Only for a rigid view matrix (a camera without scale), where lengths and angles are those of world space.
    const view = camera.matrixWorldInverse;
    this.#viewSpace =
      this.viewSpaceLighting &&
      this.#threeLights &&
      (this.shading === 'phong' || (this.shading === 'flat' && this.#flatDerivatives)) &&
      isRigid(view);
    // Instance normals from the vertex normal: the cheaper normal matrix when every instance allows it.
    this.#orthogonalInstances =
      (object as InstancedMesh).isInstancedMesh === true &&
      !(this.shading === 'flat' && this.#flatDerivatives) &&
      hasOrthogonalInstances(object as InstancedMesh);
    this.#updateSurface();
    this.#syncDefines();
    this.#updateLightUniforms(this.#viewSpace ? view : null);
    computeNormalMatrix(object.matrixWorld, u.shadingNormalMatrix.value);
    eyeOf(camera, u.shadingEye.value);
    if (this.#viewSpace) u.shadingEye.value.applyMatrix4(view);
    this.uniformsNeedUpdate = true;
  }

  #syncDefines(): void {
    const defines: Record<string, number | string> = {};
    defines[`SHADING_${this.shading.toUpperCase()}`] = '';
    if (this.lighting === 'blinn-phong') defines.LIGHTING_BLINN = '';
    defines.CEL_BANDS = this.celBands;
    defines.NUM_LIGHTS = this.#active.length;
    if (this.#attenuation) defines.USE_ATTENUATION = '';
    if (this.#sphereNormals && this.shading !== 'flat') defines.SPHERE_NORMALS = '';
    if (this.#flatCorners && this.shading === 'flat') defines.FLAT_CORNERS = '';
    if (this.#flatDerivatives && this.shading === 'flat') defines.FLAT_DERIVATIVES = '';
    if (this.#threeLights) defines.SHADING_THREE_LIGHTS = '';
    // three's distance falloff, only what the scene's point and spot lights use: the cut-off window when some
    // light has a distance, pow(t, decay) unless every decay is 2 (then t², exact and without pow).
    if (this.#threeLights && this.#lightCutoff) defines.SHADING_LIGHT_CUTOFF = '';
    if (this.#threeLights && this.#inverseSquare) defines.SHADING_INVERSE_SQUARE = '';
    if (this.#viewSpace) defines.SHADING_VIEW_SPACE = '';
    const e = this.emissive;
    if (e.r > 0 || e.g > 0 || e.b > 0) defines.SHADING_EMISSIVE = '';
    for (const name of OUTPUT_DEFINES[this.output]) defines[name] = '';
    if (this.normalMatrix === 'model') defines.SHADING_MODEL_NORMALS = '';
    if (this.#orthogonalInstances) defines.SHADING_INSTANCE_ORTHOGONAL = '';
    const old = this.defines ?? {};
    const keys = Object.keys(defines);
    const same = keys.length === Object.keys(old).length && keys.every((k) => old[k] === defines[k]);
    if (same) return;
    this.defines = defines;
    // three's `ShaderMaterial.lights`: upload three's light uniforms (only when the scene has three's lights).
    this.lights = this.#threeLights;
    this.needsUpdate = true;
  }

  /**
   * three's program parameters read the maps, `vertexColors`, `transparent` and `alphaTest` from the material,
   * but for a ShaderMaterial three neither notices their change nor refreshes their uniforms: raise
   * `needsUpdate` when what is compiled changes, and copy the uniforms (a few references and 3 × 3 copies).
   */
  #updateSurface(): void {
    const u = this.uniforms;
    const key = `${this.map !== null},${this.alphaMap !== null},${this.emissiveMap !== null},${this.normalMap !== null},${this.normalMapType},${this.vertexColors},${this.transparent},${this.alphaTest > 0}`;
    if (key !== this.#surfaceKey) {
      if (this.#surfaceKey !== '') this.needsUpdate = true;
      this.#surfaceKey = key;
    }
    u.opacity.value = this.opacity;
    u.alphaTest.value = this.alphaTest;
    refreshMap(u.map, u.mapTransform, this.map);
    refreshMap(u.alphaMap, u.alphaMapTransform, this.alphaMap);
    refreshMap(u.emissiveMap, u.emissiveMapTransform, this.emissiveMap);
    refreshMap(u.normalMap, u.normalMapTransform, this.normalMap);
    if (this.normalMap !== null) {
      // As three's refreshUniformsCommon: a BackSide material's tangent frame is turned round.
      const { x, y } = this.normalScale;
      const sign = this.side === BackSide ? -1 : 1;
      // Not finite: reported by the in-place check, drawn with the last finite scale.
      if (Number.isFinite(x) && Number.isFinite(y)) u.normalScale.value.set(sign * x, sign * y);
      if (this.shading !== 'phong' && !this.#warnedNormalMap) {
        this.#warnedNormalMap = true;
        console.warn(
          `ShadingMaterial: normalMap needs a per-fragment normal (shading 'phong'); ${this.shading} shading ignores it`,
        );
      }
    }
  }

  /** Throws a RangeError when a light was edited in place to a bad value (its colours, its world position). */
  #checkLightsInPlace(): void {
    this.#active.forEach((light, i) => {
      try {
        light.validate();
      } catch (error) {
        throw error instanceof RangeError ? new RangeError(`${OWNER}.lights[${i}]: ${error.message}`) : error;
      }
      const e = light.matrixWorld.elements;
      // Finite in float32, as uploaded (|coordinate| < 3.4e38).
      if (![e[12], e[13], e[14]].every((c) => Number.isFinite(Math.fround(c)))) {
        throw new RangeError(
          `${OWNER}.lights[${i}] world position must be finite (in float32), got (${e[12]}, ${e[13]}, ${e[14]})`,
        );
      }
    });
  }

  /** Uploads the lights' uniforms; their positions in world space, or through `view` (world → view) when given. */
  #updateLightUniforms(view: Matrix4 | null): void {
    const lights = this.#active;
    const n = lights.length;
    const u = this.uniforms;
    const resized = u.lightPosition.value.length !== 3 * n;
    if (resized) {
      u.lightPosition.value = new Float32Array(3 * n);
      u.lightDiffuse.value = new Float32Array(3 * n);
      u.lightSpecular.value = new Float32Array(3 * n);
      u.lightAttenuation.value = new Float32Array(3 * n);
    }
    // A value edited in place (bypassing the setters, as React Three Fiber does) is reported once, with
    // console.error as three reports its own errors, and the draw keeps the last good uniforms (lights new
    // since then are off) instead of uploading a NaN or throwing on every frame. Once fixed, the next problem
    // is reported again.
    if (!checkEditedInPlace(this, OWNER, () => this.#checkLightsInPlace())) return;
    // three's lights light the material as they light three's own (BRDF_Lambert's 1/π, folded in here, once).
    u.shadingKa.value.copy(this.ka).multiplyScalar(RECIPROCAL_PI);
    u.shadingKd.value.copy(this.kd).multiplyScalar(RECIPROCAL_PI);
    u.shadingKs.value.copy(this.ks).multiplyScalar(RECIPROCAL_PI);
    u.emissive.value.copy(this.emissive);
    const position: Float32Array = u.lightPosition.value;
    const diffuse: Float32Array = u.lightDiffuse.value;
    const specular: Float32Array = u.lightSpecular.value;
    const attenuation: Float32Array = u.lightAttenuation.value;
    const ambient: Float32Array = u.ambientTerm.value;
    const ka = this.ka;
    const kd = this.kd;
    const ks = this.ks;
    let ar = 0;
    let ag = 0;
    let ab = 0;
    for (let i = 0; i < n; i++) {
      const light = lights[i];
      const e = light.matrixWorld.elements;
      const j = 3 * i;
      if (view === null) {
        position[j] = e[12];
        position[j + 1] = e[13];
        position[j + 2] = e[14];
      } else {
        const v = view.elements;
        position[j] = v[0] * e[12] + v[4] * e[13] + v[8] * e[14] + v[12];
        position[j + 1] = v[1] * e[12] + v[5] * e[13] + v[9] * e[14] + v[13];
        position[j + 2] = v[2] * e[12] + v[6] * e[13] + v[10] * e[14] + v[14];
      }
      diffuse[j] = kd.r * light.diffuse.r;
      diffuse[j + 1] = kd.g * light.diffuse.g;
      diffuse[j + 2] = kd.b * light.diffuse.b;
      specular[j] = ks.r * light.specular.r;
      specular[j + 1] = ks.g * light.specular.g;
      specular[j + 2] = ks.b * light.specular.b;
      const { a, b, c } = light.attenuation;
      attenuation[j] = a;
      attenuation[j + 1] = b;
      attenuation[j + 2] = c;
      ar += ka.r * light.ambient.r;
      ag += ka.g * light.ambient.g;
      ab += ka.b * light.ambient.b;
    }
    ambient[0] = ar;
    ambient[1] = ag;
    ambient[2] = ab;
  }

  /** Copy every option of `source` (lights are shared, not cloned). @returns `this`. */
  override copy(source: ShadingMaterial): this {
    super.copy(source);
    copyShadingOptions(this, source);
    this.#active = this.phongLights;
    this.#attenuation = this.#active.some((light) => light.attenuates);
    this.defines = { ...source.defines };
    return this;
  }
}
