// ShadingMaterial's shading on three's WebGPURenderer (both of its backends): a node material with a lighting
// model of the lecture's equation, PhongLights as light nodes beside three's own lights.
import {
  cameraViewMatrix,
  float,
  ivec2,
  lightingContext,
  lightViewPosition,
  max,
  min,
  mix,
  modelViewMatrix,
  normalLocal,
  normalView,
  positionLocal,
  positionView,
  select,
  textureLoad,
  transformNormalToView,
  uniform,
  varying,
  vec3,
  vec4,
  vertexIndex,
} from 'three/tsl';
import {
  AnalyticLightNode,
  type BufferGeometry,
  Color,
  DataTexture,
  FloatType,
  type Light,
  LightingModel,
  NearestFilter,
  NodeMaterial,
  NodeUpdateType,
  type Object3D,
  RGBAFormat,
  type Scene,
  Vector3,
} from 'three/webgpu';
import { checkCelBands, checkLighting, checkPhongLights, checkShading, SHADING_DEFAULTS } from './options.js';
import { PhongLight } from './PhongLight.js';
import { type Shading, SPHERE_FLAG } from './ShadingMaterial.js';
import { type Lighting, MIN_ATTENUATION_DENOMINATOR } from './shade.js';
import { type ColorInput, checkColorChannels, checkNonNegative, setColor } from './validate.js';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

const OWNER = 'ShadingNodeMaterial';

/** Options of {@link ShadingNodeMaterial}: those of `ShadingMaterial` that the node material has so far. */
export interface ShadingNodeMaterialOptions {
  /** Where the lighting is evaluated. @default 'phong' */
  shading?: Shading;
  /** The lighting equation. @default 'phong' */
  lighting?: Lighting;
  /** 0 = off; N in 2 … 255 = cel shading with N diffuse shades and a hard-edged highlight. @default 0 */
  celBands?: number;
  /** ka, ambient reflectance, linear; a number is a grey level (see `ColorInput`). @default [0.6, 0.35, 0.2] */
  ka?: ColorInput;
  /** kd, diffuse reflectance, linear; a number is a grey level (see `ColorInput`). @default [0.6, 0.35, 0.2] */
  kd?: ColorInput;
  /** ks, specular reflectance, linear; a number is a grey level (see `ColorInput`). @default 0.5 */
  ks?: ColorInput;
  /** α, the specular exponent: finite, ≥ 0 (0⁰ = 1). @default 32 */
  shininess?: number;
  /** The PhongLights that light the material. Empty: every visible PhongLight in the rendered scene. @default [] */
  lights?: readonly PhongLight[];
}

/** A PhongLight's uniforms, refreshed once per frame (its world position is read by three's light nodes). */
class PhongLightNode extends AnalyticLightNode<Light> {
  static get type(): string {
    return 'PhongLightNode';
  }
  readonly ambient = uniform(new Color());
  readonly diffuse = uniform(new Color());
  readonly specular = uniform(new Color());
  readonly attenuation = uniform(new Vector3(1, 0, 0));
  readonly phongLight: PhongLight;
  #reported: string | null = null;

  constructor(light: PhongLight) {
    // AnalyticLightNode reads `color`, `intensity` and `shadow` only from three's lights.
    super(light as never);
    this.phongLight = light;
    // Refreshed for every render call (three's lights: once per animation frame), so that a change between two
    // renders of one frame is seen.
    this.updateType = NodeUpdateType.RENDER;
  }

  override update(): undefined {
    const light = this.phongLight;
    try {
      light.validate();
    } catch (error) {
      // Edited in place to a bad value: reported once, drawn with the last valid values.
      const message = (error as Error).message;
      if (message !== this.#reported) {
        console.error(`${OWNER}: ${message} (edited in place; drawing with the last valid values)`);
      }
      this.#reported = message;
      return;
    }
    this.#reported = null;
    (this.ambient.value as Color).copy(light.ambient);
    (this.diffuse.value as Color).copy(light.diffuse);
    (this.specular.value as Color).copy(light.specular);
    const { a, b, c } = light.attenuation;
    (this.attenuation.value as { set(x: number, y: number, z: number): void }).set(a, b, c);
  }

  override setupDirect(builder: N): N {
    const lightVector = (lightViewPosition(this.phongLight as never) as N).sub(
      builder.context.positionView ?? positionView,
    );
    return { lightDirection: vec3(0, 0, 1), lightColor: vec3(0), phong: { lightVector, node: this } };
  }
}

const _lightNodes = /* @__PURE__ */ new WeakMap<PhongLight, PhongLightNode>();

function phongLightNode(light: PhongLight): PhongLightNode {
  let node = _lightNodes.get(light);
  if (node === undefined) {
    node = new PhongLightNode(light);
    _lightNodes.set(light, node);
  }
  return node;
}

/** The surface point the lighting model lights, in view space, in the stage it is built in. */
interface Surface {
  /** Unit normal. */
  n: N;
  /** Unit vector towards the viewer. */
  v: N;
}

/** The lecture's equation as three's lighting model: one direct() per light, ambient through indirect(). */
class LectureLightingModel extends LightingModel {
  constructor(
    private readonly material: ShadingNodeMaterial,
    private readonly surface: Surface,
    private readonly uniforms: { ka: N; kd: N; ks: N; shininess: N },
  ) {
    super();
  }

  /**
   * three's lights (and the PhongLights, as material lightings), then the ambient. Hemisphere lights are
   * evaluated here with the variant's normal: three's hemisphere node reads three's normalWorld, which the
   * vertex stage (gouraud, flat) cannot give (no front-facing test there) and which is not the face's normal.
   */
  override start(builder: N): void {
    const lightsNode = builder.lightsNode;
    const nodes: N[] = lightsNode.getLightNodes(builder);
    const hemispheres = nodes.filter((node) => node.light?.isHemisphereLight === true);
    lightsNode.setupLights(
      builder,
      nodes.filter((node) => !hemispheres.includes(node)),
    );
    for (const node of hemispheres) {
      // Registered for its per-frame update (colours, direction); its own setup is not built.
      builder.addNode(node);
      const direction = (cameraViewMatrix as N).mul(vec4(node.lightDirectionNode, 0)).xyz;
      const weight = this.surface.n.dot(direction).mul(0.5).add(0.5);
      builder.context.irradiance.addAssign(mix(node.groundColorNode, node.colorNode, weight));
    }
    this.indirect(builder);
  }

  override direct(data: N): void {
    const { n, v } = this.surface;
    const { ka, kd, ks, shininess } = this.uniforms;
    const { reflectedLight } = data;
    let l: N;
    let id: N;
    let is: N;
    let att: N = float(1);
    if (data.phong !== undefined) {
      const { lightVector, node } = data.phong as { lightVector: N; node: PhongLightNode };
      const t = lightVector.length();
      // A light at the point lights it head-on (l = n).
      l = select(t.greaterThan(0), lightVector.div(max(t, 1e-30)), n);
      const abc = node.attenuation as N;
      att = float(1).div(max(abc.x.add(abc.y.mul(t)).add(abc.z.mul(t).mul(t)), MIN_ATTENUATION_DENOMINATOR));
      id = node.diffuse;
      is = node.specular;
      reflectedLight.indirectDiffuse.addAssign(ka.mul(node.ambient));
    } else {
      // three's lights: Id = Is = colour × intensity × three's falloff.
      l = data.lightDirection;
      id = data.lightColor;
      is = data.lightColor;
    }
    const ndl = n.dot(l);
    let diffuse: N = max(ndl, 0);
    let x: N;
    if (this.material.lighting === 'blinn-phong') {
      const h = l.add(v);
      const hl = h.length();
      x = select(hl.greaterThan(0), max(n.dot(h).div(max(hl, 1e-30)), 0), float(0));
    } else {
      // r = 2(l·n)n − l, so v·r = 2(l·n)(v·n) − v·l.
      x = max(ndl.mul(2).mul(v.dot(n)).sub(v.dot(l)), 0);
    }
    // 0⁰ = 1: shininess 0 gives a uniform highlight over the lit side.
    const power = select(x.greaterThan(0), x.pow(shininess), select(shininess.equal(0), float(1), float(0)));
    let spec: N = select(ndl.greaterThan(0), power, float(0));
    const bands = this.material.celBands;
    if (bands > 0) {
      diffuse = min(diffuse.mul(bands).floor(), bands - 1).div(bands - 1);
      spec = select(spec.greaterThanEqual(0.5), float(1), float(0));
    }
    reflectedLight.directDiffuse.addAssign(kd.mul(id).mul(diffuse.mul(att)));
    reflectedLight.directSpecular.addAssign(ks.mul(is).mul(spec.mul(att)));
  }

  override indirect(builder: N): void {
    // three's ambient and hemisphere lights: Ia = their irradiance.
    const { irradiance, reflectedLight } = builder.context;
    reflectedLight.indirectDiffuse.addAssign(irradiance.mul(this.uniforms.ka));
  }
}

/** Texels per row of the face texture. */
const FACE_TEXTURE_WIDTH = 2048;
const _faceTextures = /* @__PURE__ */ new WeakMap<
  BufferGeometry,
  { texture: DataTexture; version: number }
>();

/** Vertex i's object-space position at texel i (RGBA float: WebGPU has no RGB float textures). */
function faceTexture(geometry: BufferGeometry): DataTexture {
  const position = geometry.getAttribute('position');
  const version = 'version' in position ? (position.version as number) : 0;
  const cached = _faceTextures.get(geometry);
  if (cached !== undefined && cached.version === version) return cached.texture;
  const height = Math.max(1, Math.ceil(position.count / FACE_TEXTURE_WIDTH));
  const data = new Float32Array(4 * FACE_TEXTURE_WIDTH * height);
  for (let i = 0; i < position.count; i++) {
    data[4 * i] = position.getX(i);
    data[4 * i + 1] = position.getY(i);
    data[4 * i + 2] = position.getZ(i);
    data[4 * i + 3] = 1;
  }
  const texture = cached?.texture ?? new DataTexture(data, FACE_TEXTURE_WIDTH, height, RGBAFormat, FloatType);
  if (cached !== undefined) texture.image = { data, width: FACE_TEXTURE_WIDTH, height } as never;
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  if (cached === undefined) geometry.addEventListener('dispose', () => texture.dispose());
  _faceTextures.set(geometry, { texture, version });
  return texture;
}

/** The visible PhongLights of `scene`, in traversal order. */
function scenePhongLights(scene: Object3D | null | undefined): PhongLight[] {
  const found: PhongLight[] = [];
  scene?.traverseVisible((object) => {
    if (object instanceof PhongLight) found.push(object);
  });
  return found;
}

/**
 * `ShadingMaterial`'s shading for three's `WebGPURenderer` (`three/webgpu`), on its WebGPU and its WebGL2
 * backend: the lecture's flat, Gouraud and Phong shading × Phong and Blinn-Phong lighting × cel bands, with the
 * same options, defaults, validation and equation as `ShadingMaterial` (the CPU `shade()` is the reference of
 * both). A node material: three's lighting model interface evaluates I = Σ ka·Ia + att·(kd·Id·max(l·n, 0) +
 * ks·Is·spec) per light, for {@link PhongLight}s (per-light Ia, Id, Is and 1/max(a + b·t + c·t², 1e-6)) and
 * three's lights (Id = Is = colour × intensity with three's falloff; ambient and hemisphere lights as Ia), in
 * view space (the camera's rigid transform keeps every dot product).
 *
 * Shading: `'phong'` per fragment; `'gouraud'` in the vertex stage, colours interpolated; `'flat'` once per face
 * at its centroid with its face normal when the geometry is non-indexed (each vertex of a triangle reads its
 * three corners from a float texture and computes the same colour, so the provoking vertex, the first on WebGPU
 * and the last on WebGL2, does not matter: exactly one colour per face on both), else (an indexed geometry, an
 * instanced, batched, skinned or morphed mesh) per fragment with the face normal from screen-space derivatives
 * (as three's `flatShading`). A geometry without `normal` that is a sphere
 * centred at its origin (`SubdivisionSphereGeometry` or `userData.isSphere`) uses normal = position.
 *
 * The variant (shading, lighting, cel bands, the lights) is compiled in; changing it through the setters
 * recompiles. ka, kd, ks and the PhongLights' colours edited in place (bypassing the setters) to a non-finite or
 * negative value are reported once with console.error, as `ShadingMaterial` reports them, and drawn with their
 * last valid values. With `lights` empty, the scene's PhongLights are found when the material is compiled: after
 * adding or removing one, set `needsUpdate = true`.
 *
 * @example
 * const light = new PhongLight();
 * light.position.set(-5, 10, 20);
 * const material = new ShadingNodeMaterial({ shading: 'gouraud', lighting: 'blinn-phong', lights: [light] });
 */
export class ShadingNodeMaterial extends NodeMaterial {
  /** three's type name. */
  static override get type(): string {
    return 'ShadingNodeMaterial';
  }
  /** Always true: lets code tell a ShadingNodeMaterial from other materials without `instanceof`. */
  readonly isShadingNodeMaterial = true;

  #shading: Shading = SHADING_DEFAULTS.shading;
  #lighting: Lighting = SHADING_DEFAULTS.lighting;
  #celBands: number = SHADING_DEFAULTS.celBands;
  #lights: readonly PhongLight[] = Object.freeze([]);
  readonly #ka = new Color(...SHADING_DEFAULTS.ka);
  readonly #kd = new Color(...SHADING_DEFAULTS.kd);
  readonly #ks = new Color(...SHADING_DEFAULTS.ks);
  // What the GPU draws with: ka, kd, ks as last found valid, checked and copied once per render.
  readonly #uniforms = {
    ka: uniform(new Color(...SHADING_DEFAULTS.ka)),
    kd: uniform(new Color(...SHADING_DEFAULTS.kd)),
    ks: uniform(new Color(...SHADING_DEFAULTS.ks)),
  };
  // The message of the in-place problem last reported (null once the values are valid again).
  #reported: string | null = null;
  readonly #shininessNode = uniform(SHADING_DEFAULTS.shininess);

  /**
   * @param options - Shading, lighting, reflectances and lights; each one omitted takes its default (see
   *   {@link ShadingNodeMaterialOptions}).
   */
  constructor({
    shading = SHADING_DEFAULTS.shading,
    lighting = SHADING_DEFAULTS.lighting,
    celBands = SHADING_DEFAULTS.celBands,
    ka = SHADING_DEFAULTS.ka,
    kd = SHADING_DEFAULTS.kd,
    ks = SHADING_DEFAULTS.ks,
    shininess = SHADING_DEFAULTS.shininess,
    lights = [],
  }: ShadingNodeMaterialOptions = {}) {
    super();
    this.lights = true;
    this.colorNode = vec3(1) as never;
    this.shading = shading;
    this.lighting = lighting;
    this.celBands = celBands;
    this.ka = ka;
    this.kd = kd;
    this.ks = ks;
    this.shininess = shininess;
    this.phongLights = lights;
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
    try {
      checkColorChannels(`${OWNER}.ka`, this.#ka);
      checkColorChannels(`${OWNER}.kd`, this.#kd);
      checkColorChannels(`${OWNER}.ks`, this.#ks);
    } catch (error) {
      if (!(error instanceof RangeError)) throw error;
      if (error.message !== this.#reported) {
        console.error(`${error.message} (edited in place; drawing with the last valid values)`);
      }
      this.#reported = error.message;
      return;
    }
    this.#reported = null;
    (this.#uniforms.ka.value as Color).copy(this.#ka);
    (this.#uniforms.kd.value as Color).copy(this.#kd);
    (this.#uniforms.ks.value as Color).copy(this.#ks);
  }

  /** Where the lighting is evaluated: `'flat'`, `'gouraud'` or `'phong'`. @default 'phong' */
  get shading(): Shading {
    return this.#shading;
  }
  set shading(value: Shading) {
    const checked = checkShading(OWNER, value);
    if (checked !== this.#shading) this.needsUpdate = true;
    this.#shading = checked;
  }

  /** The lighting equation: `'phong'` or `'blinn-phong'`. @default 'phong' */
  get lighting(): Lighting {
    return this.#lighting;
  }
  set lighting(value: Lighting) {
    const checked = checkLighting(OWNER, value);
    if (checked !== this.#lighting) this.needsUpdate = true;
    this.#lighting = checked;
  }

  /**
   * Cel shading: 0 = off; N in 2 … 255 quantises each light's diffuse cosine to N shades
   * (min(⌊cos·N⌋, N−1)/(N−1)) and its specular to a hard-edged highlight (1 where spec ≥ 0.5). @default 0
   */
  get celBands(): number {
    return this.#celBands;
  }
  set celBands(value: number) {
    const checked = checkCelBands(OWNER, value);
    if (checked !== this.#celBands) this.needsUpdate = true;
    this.#celBands = checked;
  }

  /** ka, ambient reflectance (linear RGB, channels finite ≥ 0; set with a `ColorInput`). @default Color(0.6, 0.35, 0.2) */
  get ka(): Color {
    return this.#ka;
  }
  set ka(value: ColorInput) {
    setColor(`${OWNER}.ka`, this.#ka, value);
  }

  /** kd, diffuse reflectance (linear RGB, channels finite ≥ 0; set with a `ColorInput`). @default Color(0.6, 0.35, 0.2) */
  get kd(): Color {
    return this.#kd;
  }
  set kd(value: ColorInput) {
    setColor(`${OWNER}.kd`, this.#kd, value);
  }

  /** ks, specular reflectance (linear RGB, channels finite ≥ 0; set with a `ColorInput`). @default Color(0.5, 0.5, 0.5) */
  get ks(): Color {
    return this.#ks;
  }
  set ks(value: ColorInput) {
    setColor(`${OWNER}.ks`, this.#ks, value);
  }

  /** α, the specular exponent (finite, ≥ 0; 0⁰ = 1). A uniform: changing it never recompiles. @default 32 */
  get shininess(): number {
    return this.#shininessNode.value as number;
  }
  set shininess(value: number) {
    this.#shininessNode.value = checkNonNegative(`${OWNER}.shininess`, value);
  }

  /**
   * The PhongLights (the `lights` option; three's `Material.lights` is the flag for three's lights). Empty (the
   * default): every visible PhongLight in the scene when the material is compiled. A frozen copy; assigning
   * recompiles. @default []
   */
  get phongLights(): readonly PhongLight[] {
    return this.#lights;
  }
  set phongLights(value: readonly PhongLight[]) {
    this.#lights = checkPhongLights(OWNER, value);
    this.needsUpdate = true;
  }

  /** Builds the lighting of the variant (three calls it when it compiles the material). */
  override setupLighting(builder: N): N {
    const geometry: BufferGeometry = builder.geometry;
    const phong = this.#lights.length > 0 ? this.#lights : scenePhongLights(builder.scene as Scene);
    const lightNodes = phong.map(phongLightNode);
    const uniforms = {
      ...this.#uniforms,
      shininess: this.#shininessNode,
    };
    const lightsNode = builder.lightsNode;
    const light = (surface: Surface, context: Record<string, N> = {}): N =>
      (
        lightingContext(
          lightsNode,
          new LectureLightingModel(this, surface, uniforms),
          lightNodes as never,
        ) as N
      ).context(context);
    const orthographic = builder.camera?.isOrthographicCamera === true;
    const towardsViewer = (p: N): N => {
      if (orthographic) return vec3(0, 0, 1);
      const d = p.length();
      return select(d.greaterThan(0), p.negate().div(max(d, 1e-30)), vec3(0, 0, 1));
    };
    const unitOr = (n: N, fallback: N): N => {
      const d = n.length();
      return select(d.greaterThan(0), n.div(max(d, 1e-30)), fallback);
    };
    const hasNormal = geometry.getAttribute('normal') !== undefined;
    const sphere = geometry.type === 'SubdivisionSphereGeometry' || geometry.userData?.[SPHERE_FLAG] === true;
    if (this.#shading !== 'flat' && !hasNormal && !sphere) {
      throw new TypeError(
        `${OWNER}: ${this.#shading} shading needs a normal attribute on ${geometry.type} (or a sphere flagged with userData.${SPHERE_FLAG})`,
      );
    }
    const localNormal: N = hasNormal ? normalLocal : positionLocal;
    if (this.#shading === 'phong') {
      const v = towardsViewer(positionView);
      const n = unitOr(hasNormal ? normalView : varying(transformNormalToView(localNormal)), v);
      return light({ n, v });
    }
    if (this.#shading === 'gouraud') {
      const v = towardsViewer(positionView);
      const n = unitOr(transformNormalToView(localNormal), v);
      return varying(light({ n, v }));
    }
    const object = builder.object ?? {};
    // The corner texture holds rest positions: an instanced, batched, skinned or morphed mesh is drawn by
    // derivatives, whose positions are the ones three moved.
    const deformed =
      object.isInstancedMesh === true ||
      object.isBatchedMesh === true ||
      object.isSkinnedMesh === true ||
      geometry.morphAttributes.position !== undefined;
    if (geometry.index === null && !deformed) {
      // Every vertex of a triangle reads the triangle's three corners and lights its centroid: the same colour
      // from whichever vertex provokes.
      const texture = faceTexture(geometry);
      const first = (vertexIndex as N).div(3).mul(3);
      const corner = (k: number): N => {
        const i = first.add(k);
        return (textureLoad(texture, ivec2(i.mod(FACE_TEXTURE_WIDTH), i.div(FACE_TEXTURE_WIDTH))) as N).xyz;
      };
      const [a, b, c] = [corner(0), corner(1), corner(2)];
      const centroid = a.add(b).add(c).div(3);
      const view = (modelViewMatrix as N).mul(vec4(centroid, 1)).xyz;
      const v = towardsViewer(view);
      const n = unitOr(transformNormalToView(b.sub(a).cross(c.sub(a))), v);
      return varying(light({ n, v }, { positionView: view })).setInterpolation('flat');
    }
    const v = towardsViewer(positionView);
    const n = unitOr((positionView as N).dFdx().cross((positionView as N).dFdy()), v);
    return light({ n, v });
  }

  /** Copy every option of `source` (lights are shared, not cloned). @returns `this`. */
  override copy(source: ShadingNodeMaterial): this {
    super.copy(source);
    this.#shading = source.shading;
    this.#lighting = source.lighting;
    this.#celBands = source.celBands;
    this.#lights = source.phongLights;
    this.#ka.copy(source.ka);
    this.#kd.copy(source.kd);
    this.#ks.copy(source.ks);
    this.#refresh();
    this.#shininessNode.value = source.shininess;
    return this;
  }
}
