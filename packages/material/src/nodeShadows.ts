// Shadows of three's lights on ShadingNodeMaterial where the lighting is evaluated in the vertex stage (gouraud
// and exact flat shading), as ShadingMaterial's SHADING_SHADOW_TERMS: the vertex stage lights with each
// shadow-casting light unshadowed and records that light's term (diffuse + specular, never ambient) in variables
// of its own; the fragment stage removes (1 − three's shadow factor) of each term, so the shadow's edge is as sharp
// as three's while the lighting stays per vertex or per face. Phong shading (and flat shading by derivatives)
// lights per fragment and takes three's shadowed light colour as it is.
import { vec3 } from 'three/tsl';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

/** One shadow-casting light's recorded term, per side and part (vec3 variables, `toVar()`, starting at 0). */
export interface ShadowTerm {
  /** three's shadow factor of the light at the fragment (1 lit, 1 − shadow.intensity in full shadow). */
  factor: N;
  /** The front side's term (its ka/kd part when the lighting is split). */
  term: N;
  /** The front side's ks part, when the lighting is split. */
  specular?: N;
  /** The back side's term, when both sides are lit in one pass. */
  back?: N;
  /** The back side's ks part, when both sides are lit and the lighting is split. */
  backSpecular?: N;
}

/** The recorded terms of a build, by light node. */
export type ShadowTerms = Map<unknown, ShadowTerm>;

/**
 * The light nodes of three's lights that shadow this object in this build (as three's `AnalyticLightNode.setup`
 * decides: the renderer's shadow map on, the light's `castShadow`, the object's `receiveShadow`), each with its
 * shadow node made (`setupShadow`, idempotent: three makes one shadow node per light and shares it), so that the
 * fragment stage can read its factor. `exclude` leaves light nodes out (the PhongLights', which cast none).
 */
export function shadowingLightNodes(builder: N, exclude: (node: N) => boolean): N[] {
  if (builder.renderer?.shadowMap?.enabled !== true || builder.object?.receiveShadow !== true) return [];
  const lightsNode = builder.lightsNode;
  if (lightsNode == null) return [];
  // The scene's light nodes (three keeps one per light), listed without the lighting context's material
  // lightings and without caching the list (the lighting context lists them again, with its own).
  const context = builder.getContext();
  builder.setContext({ ...context, materialLightings: [] });
  let nodes: N[];
  try {
    nodes = lightsNode.setupLightsNode(builder);
  } finally {
    builder.setContext(context);
  }
  const shadowing = nodes.filter(
    (node) =>
      !exclude(node) &&
      node.isAnalyticLightNode === true &&
      node.light?.castShadow === true &&
      node.light?.shadow != null,
  );
  for (const node of shadowing) {
    // Makes node.shadowNode once; the light's colour for this build is reset by the light node's own setup.
    if (node.shadowNode === null) node.setupShadow(builder);
  }
  return shadowing.filter((node) => node.shadowNode !== null);
}

/** Variables for each shadowing light's term: the front (and `double`: back) side, split or not. */
export function shadowTerms(nodes: readonly N[], double: boolean, split: boolean): ShadowTerms {
  const terms: ShadowTerms = new Map();
  for (const node of nodes) {
    terms.set(node, {
      factor: node.shadowNode,
      term: vec3(0).toVar(),
      specular: split ? vec3(0).toVar() : undefined,
      back: double ? vec3(0).toVar() : undefined,
      backSpecular: double && split ? vec3(0).toVar() : undefined,
    });
  }
  return terms;
}

/**
 * three's `getShadow` context hook for the vertex-stage lighting: the shadowing lights light unshadowed there (their
 * shadow is applied per fragment from the recorded terms).
 */
export function unshadowed(lightNode: N): N {
  return lightNode.baseColorNode ?? lightNode.colorNode;
}

/**
 * `colour` (one side's, after the texel) without the shadowed part of each recorded term: colour − Σ (1 − factor)
 * × term, with `part(term, specular)` giving a term's colour (its ka/kd part × the texel + its ks part when split).
 */
export function removeShadowed(
  colour: N,
  terms: ShadowTerms,
  side: 'front' | 'back',
  part: (term: N, specular: N | undefined) => N,
): N {
  let result = colour;
  for (const t of terms.values()) {
    const term = side === 'front' ? t.term : t.back;
    const specular = side === 'front' ? t.specular : t.backSpecular;
    result = result.sub(part(term, specular).mul(t.factor.oneMinus()));
  }
  return result;
}
