// The lecture's equation as three's lighting model for ShadingNodeMaterial, and PhongLights as light nodes beside
// three's own lights.
import {
  cameraViewMatrix,
  float,
  lightViewPosition,
  max,
  min,
  mix,
  positionView,
  select,
  uniform,
  vec3,
  vec4,
} from 'three/tsl';
import { AnalyticLightNode, Color, type Light, LightingModel, NodeUpdateType, Vector3 } from 'three/webgpu';
import type { ShadowTerms } from './nodeShadows.js';
import type { ShadingOutput } from './options.js';
import { PhongLight } from './PhongLight.js';
import { type Lighting, MIN_ATTENUATION_DENOMINATOR } from './shade.js';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

const OWNER = 'ShadingNodeMaterial';

/** 1/π: three's factor of every light's colour (BRDF_Lambert); see `shade()`. */
export const RECIPROCAL_PI = 1 / Math.PI;

/** A PhongLight's uniforms, refreshed once per frame (its world position is read by three's light nodes). */
export class PhongLightNode extends AnalyticLightNode<Light> {
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

  /**
   * A PhongLight casts no shadow (as on `WebGLRenderer`, where `ShadingMaterial` lights with it): its
   * `castShadow` is ignored here, so that no shadow map is made for it and no material is built with one
   * (three's `AnalyticLightNode` reads a `shadow` a PhongLight does not have).
   */
  override setupShadow(): void {}

  override setupDirect(builder: N): N {
    const lightVector = (lightViewPosition(this.phongLight as never) as N).sub(
      builder.context.positionView ?? positionView,
    );
    return { lightDirection: vec3(0, 0, 1), lightColor: vec3(0), phong: { lightVector, node: this } };
  }
}

// three builds a PhongLight in the rendered scene with this node, as it builds its own lights with theirs.
(PhongLight.prototype as unknown as { _lightNode: typeof PhongLightNode })._lightNode = PhongLightNode;

/** The nodes of the PhongLights listed in a material's `lights` (the scene's are three's). */
const _lightNodes = /* @__PURE__ */ new WeakMap<PhongLight, PhongLightNode>();

export function phongLightNode(light: PhongLight): PhongLightNode {
  let node = _lightNodes.get(light);
  if (node === undefined) {
    node = new PhongLightNode(light);
    _lightNodes.set(light, node);
  }
  return node;
}

/** The surface point the lighting model lights, in view space, in the stage it is built in. */
export interface Surface {
  /** Unit normal. */
  n: N;
  /** Unit vector towards the viewer. */
  v: N;
  /**
   * A vec3 variable (`toVar()`, starting at 0) that receives the colour of the other side, lit with −n, in the
   * same pass (two lighting passes cannot share three's light nodes in one shader).
   */
  back?: N;
  /**
   * With `back`, a vec3 variable that receives the other side's ks part instead of `back` (see
   * {@link LightingSplit}).
   */
  backSpecular?: N;
  /**
   * The terms of three's shadow-casting lights, recorded apart for the fragment stage to shadow (lighting in the
   * vertex stage: gouraud, exact flat); see `nodeShadows.ts`.
   */
  shadows?: ShadowTerms;
  /**
   * Values the lights read that the lighting model computes first, once, in the main flow of the stage it is built
   * in (the vertex stage's v and lit point; made not on a stack, unlike `toVar()`): a node first used inside a
   * block (each light's specular branch) is computed there, again in every block that uses it.
   */
  hoisted?: readonly N[];
}

/**
 * How a lit colour is split for a texel applied per fragment after vertex lighting (gouraud, exact flat), as
 * `ShadingMaterial`'s SHADING_SPLIT: the lighting returns the ka/kd part, and `specular` (a vec3 variable,
 * `toVar()`, starting at 0) receives the ks part.
 */
export interface LightingSplit {
  /** What multiplies ka and kd (not ks): instance colour × batch colour × vertex colour × texel. @default none */
  tint?: N;
  /** A vec3 variable receiving the ks part (the lighting then returns the ka/kd part only). */
  specular?: N;
}

/** What the lighting model compiles in: the material's variant. */
export interface LightingVariant {
  /** The listed PhongLights (empty: the scene's). */
  readonly phongLights: readonly PhongLight[];
  readonly lighting: Lighting;
  readonly celBands: number;
  /** What is drawn: the colour, or one term (see `ShadingOutput`; the normal is not lit, so not built here). */
  readonly output: ShadingOutput;
}

/** Whether `node` is one of the direct lights the attenuation output averages over. */
function isDirectLight(node: N): boolean {
  const light = node.light ?? {};
  return (
    node instanceof PhongLightNode ||
    light.isDirectionalLight === true ||
    light.isPointLight === true ||
    light.isSpotLight === true
  );
}

/** The lecture's equation as three's lighting model: one direct() per light, ambient through indirect(). */
export class LectureLightingModel extends LightingModel {
  /** How many direct lights light the material (found in start(), before their direct() calls). */
  #directLights = 0;
  /**
   * Whether anything but direct lights lights the material (an ambient or hemisphere light, a light probe, a
   * light map, the environment): otherwise three's irradiance stays zero, and its term is left out.
   */
  #irradiance = true;
  /**
   * three's direct lights on the front side, summed as their diffuse and specular factors × colour / π and
   * multiplied by kd and ks once after the last light (four vector operations a light fewer, as ShadingMaterial
   * sums them); vec3 variables made in start(), null for the attenuation output (which adds its factor as is).
   */
  #sums: { diffuse: N; specular: N } | null = null;

  /** Whether the output keeps the ambient term (the colour and the ambient output). */
  get #ambient(): boolean {
    const { output } = this.material;
    return output === 'color' || output === 'ambient';
  }

  constructor(
    private readonly material: LightingVariant,
    private readonly surface: Surface,
    private readonly uniforms: { ka: N; kd: N; ks: N; shininess: N },
    private readonly specular?: N,
  ) {
    super();
  }

  /**
   * three's lights (and the PhongLights, as material lightings), then the ambient. Hemisphere lights are
   * evaluated here with the variant's normal: three's hemisphere node reads three's normalWorld, which the
   * vertex stage (gouraud, flat) cannot give (no front-facing test there) and which is not the face's normal.
   */
  override start(builder: N): void {
    for (const node of this.surface.hoisted ?? []) node.toStack();
    const lightsNode = builder.lightsNode;
    const listed = this.material.phongLights.length > 0;
    // With a list of PhongLights, only their nodes light the material (not the scene's PhongLights).
    const nodes: N[] = (lightsNode.getLightNodes(builder) as N[]).filter(
      (node) => !(node instanceof PhongLightNode) || !listed || _lightNodes.get(node.phongLight) === node,
    );
    const hemispheres = nodes.filter((node) => node.light?.isHemisphereLight === true);
    this.#directLights = nodes.filter(isDirectLight).length;
    this.#irradiance = this.#directLights < nodes.length;
    const { kd, ks } = this.uniforms;
    const { reflectedLight } = builder.context;
    // Only where three's direct lights light the material (a PhongLight-only program is as it was).
    const threeDirect = nodes.some((node) => isDirectLight(node) && !(node instanceof PhongLightNode));
    const sums =
      threeDirect && this.material.output !== 'attenuation'
        ? { diffuse: vec3(0).toVar(), specular: vec3(0).toVar() }
        : null;
    this.#sums = sums;
    lightsNode.setupLights(
      builder,
      nodes.filter((node) => !hemispheres.includes(node)),
    );
    if (sums !== null) {
      reflectedLight.directDiffuse.addAssign(sums.diffuse.mul(kd));
      (this.specular ?? reflectedLight.directSpecular).addAssign(sums.specular.mul(ks));
    }
    const { n, back } = this.surface;
    const { ka } = this.uniforms;
    const ambient = this.#ambient && this.#irradiance;
    // The ambient lights' irradiance is the same on both sides; the hemispheres' is not.
    if (ambient) back?.addAssign(builder.context.irradiance.mul(ka).mul(RECIPROCAL_PI));
    for (const node of hemispheres) {
      // Registered for its per-frame update (colours, direction); its own setup is not built.
      builder.addNode(node);
      const direction = (cameraViewMatrix as N).mul(vec4(node.lightDirectionNode, 0)).xyz;
      const weight = n.dot(direction).mul(0.5);
      builder.context.irradiance.addAssign(mix(node.groundColorNode, node.colorNode, weight.add(0.5)));
      if (ambient) {
        back?.addAssign(
          mix(node.groundColorNode, node.colorNode, weight.negate().add(0.5)).mul(ka).mul(RECIPROCAL_PI),
        );
      }
    }
    this.indirect(builder);
  }

  override direct(data: N, builder: N): void {
    const { n, v, back, backSpecular } = this.surface;
    const { ka, kd, ks, shininess } = this.uniforms;
    let ambient: N = null;
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
      if (this.#ambient) {
        ambient = ka.mul(node.ambient);
        reflectedLight.indirectDiffuse.addAssign(ambient);
      }
    } else {
      // three's lights: Id = Is = colour × intensity / π × three's falloff (as three's materials receive them).
      l = data.lightDirection;
      id = data.lightColor.mul(RECIPROCAL_PI);
      is = id;
    }
    const { output } = this.material;
    // The attenuation output: this light's factor (a PhongLight's att; three's: its colour's falloff × cone ×
    // shadow, as the ratio of the light's colour to its unshadowed base colour), over the direct lights' count.
    let attenuation: N = null;
    if (output === 'attenuation') {
      let factor: N = att;
      if (data.phong === undefined) {
        const base: N = data.lightNode?.baseColorNode || data.lightNode?.colorNode;
        factor =
          base == null ? float(1) : data.lightColor.dot(vec3(1)).div(max((base as N).dot(vec3(1)), 1e-30));
      }
      attenuation = vec3(factor.div(Math.max(this.#directLights, 1)));
    }
    const ndl = n.dot(l);
    const h = this.material.lighting === 'blinn-phong' ? l.add(v) : null;
    const masks = builder?.renderer?.backend?.isWebGLBackend === true;
    // One side's diffuse and specular factors, for the normal n·sign (the back side: −n).
    const side = (sign: number): [N, N] => {
      const cos = sign > 0 ? ndl : ndl.negate();
      let diffuse: N = max(cos, 0);
      let x: N;
      if (h !== null) {
        const hl = h.length();
        const nh = sign > 0 ? n.dot(h) : n.dot(h).negate();
        // h = 0 gives n·h = 0, so x = 0 with no test.
        x = max(nh.div(max(hl, 1e-30)), 0);
      } else {
        // r = 2(l·n)n − l, so v·r = 2(l·n)(v·n) − v·l (the same for −n).
        x = max(ndl.mul(2).mul(v.dot(n)).sub(v.dot(l)), 0);
      }
      // 0⁰ = 1: shininess 0 gives a uniform highlight over the lit side. On the WebGL2 backend as 0/1 masks (exact:
      // the power is finite, at most 1): three compiles a select() to an if/else block, which costs SwiftShader's
      // GLSL more than the products, while its WGSL runs the selects faster (bench/webgpu.bench.mjs, the
      // realistic scene).
      let spec: N;
      if (masks) {
        const positive = float(x.greaterThan(0));
        const power = max(x, 1e-30)
          .pow(shininess)
          .mul(positive)
          .add(float(shininess.equal(0)).mul(float(1).sub(positive)));
        spec = power.mul(float(cos.greaterThan(0)));
      } else {
        const power = select(
          x.greaterThan(0),
          x.pow(shininess),
          select(shininess.equal(0), float(1), float(0)),
        );
        spec = select(cos.greaterThan(0), power, float(0));
      }
      const bands = this.material.celBands;
      if (bands > 0) {
        diffuse = min(diffuse.mul(bands).floor(), bands - 1).div(bands - 1);
        spec = float(spec.greaterThanEqual(0.5));
      }
      // The term outputs leave the other terms out.
      if (output === 'ambient' || output === 'specular') diffuse = float(0);
      if (output === 'ambient' || output === 'diffuse') spec = float(0);
      return [diffuse, spec];
    };
    // A shadow-casting light of three's, lit in the vertex stage: its term is also recorded apart.
    const shadow = data.lightNode === undefined ? undefined : this.surface.shadows?.get(data.lightNode);
    // One side's diffuse and specular terms (the attenuation output: its factor, as the diffuse term).
    const terms = (sign: number): [N, N] => {
      if (attenuation !== null) return [attenuation, vec3(0)];
      const [diffuse, spec] = side(sign);
      return [kd.mul(id).mul(diffuse.mul(att)), ks.mul(is).mul(spec.mul(att))];
    };
    let diffuseTerm: N;
    let specularTerm: N;
    const sums = this.#sums;
    if (data.phong === undefined && sums !== null) {
      // three's light: its factors × colour / π into the sums (× kd and ks in start(), after the last light).
      const [diffuse, spec] = side(1);
      const diffuseLit = id.mul(diffuse);
      const specularLit = is.mul(spec);
      sums.diffuse.addAssign(diffuseLit);
      sums.specular.addAssign(specularLit);
      if (shadow !== undefined) [diffuseTerm, specularTerm] = [kd.mul(diffuseLit), ks.mul(specularLit)];
    } else {
      [diffuseTerm, specularTerm] = terms(1);
      reflectedLight.directDiffuse.addAssign(diffuseTerm);
      // The ks part: with the lighting split (a texel per fragment after vertex lighting), into its own variable.
      (this.specular ?? reflectedLight.directSpecular).addAssign(specularTerm);
    }
    if (shadow !== undefined) {
      if (shadow.specular === undefined) shadow.term.addAssign(diffuseTerm.add(specularTerm));
      else {
        shadow.term.addAssign(diffuseTerm);
        shadow.specular.addAssign(specularTerm);
      }
    }
    if (back !== undefined) {
      const [backDiffuseTerm, backSpecularTerm] = terms(-1);
      if (backSpecular === undefined) back.addAssign(backDiffuseTerm.add(backSpecularTerm));
      else {
        back.addAssign(backDiffuseTerm);
        backSpecular.addAssign(backSpecularTerm);
      }
      if (shadow?.back !== undefined) {
        if (shadow.backSpecular === undefined) shadow.back.addAssign(backDiffuseTerm.add(backSpecularTerm));
        else {
          shadow.back.addAssign(backDiffuseTerm);
          shadow.backSpecular.addAssign(backSpecularTerm);
        }
      }
      if (ambient !== null) back.addAssign(ambient);
    }
  }

  override indirect(builder: N): void {
    // three's ambient and hemisphere lights: Ia = their irradiance / π.
    if (!this.#ambient || !this.#irradiance) return;
    const { irradiance, reflectedLight } = builder.context;
    reflectedLight.indirectDiffuse.addAssign(irradiance.mul(this.uniforms.ka).mul(RECIPROCAL_PI));
  }
}
