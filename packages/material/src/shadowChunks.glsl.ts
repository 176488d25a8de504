// Shadows of three's lights on ShadingMaterial, compiled only when three's program parameters define
// USE_SHADOWMAP (the renderer's shadowMap is enabled and some light casts a shadow) and the scene has three's
// lights. Each shadow-casting light's term of the lecture's equation (its diffuse + specular, never ambient) is
// multiplied by three's shadow factor at the fragment, as three's own materials multiply the light's colour:
// - phong shading (lit per fragment): inside the light loop (`SHADING_SHADOW_FACTOR`);
// - flat and gouraud shading (lit per face or vertex): the vertex stage records each shadow-casting light's term
//   (`SHADING_SHADOW_TERMS`) in a varying of its own, and the fragment removes (1 − factor) of it, so the shadow
//   edge is as sharp as three's while the lighting stays per face or per vertex.
// `receiveShadow` is three's uniform (false: factor 1). PhongLights cast no shadow.

/** One kind of three's shadow-casting light: its count macro, the term arrays' name and its shadow factor at `[ k ]`. */
interface ShadowKind {
  count: string;
  name: string;
  /** Extra condition three puts on the factor (point shadows need a PCF or basic shadow map). */
  guard: string;
  factor: (k: string) => string;
}

const KINDS: readonly ShadowKind[] = [
  {
    count: 'NUM_DIR_LIGHT_SHADOWS',
    name: 'Dir',
    guard: '1',
    factor: (k) =>
      `getShadow( directionalShadowMap[ ${k} ], directionalLightShadows[ ${k} ].shadowMapSize, directionalLightShadows[ ${k} ].shadowIntensity, directionalLightShadows[ ${k} ].shadowBias, directionalLightShadows[ ${k} ].shadowRadius, vDirectionalShadowCoord[ ${k} ] )`,
  },
  {
    count: 'NUM_SPOT_LIGHT_SHADOWS',
    name: 'Spot',
    guard: '1',
    factor: (k) =>
      `getShadow( spotShadowMap[ ${k} ], spotLightShadows[ ${k} ].shadowMapSize, spotLightShadows[ ${k} ].shadowIntensity, spotLightShadows[ ${k} ].shadowBias, spotLightShadows[ ${k} ].shadowRadius, vSpotLightCoord[ ${k} ] )`,
  },
  {
    count: 'NUM_POINT_LIGHT_SHADOWS',
    name: 'Point',
    guard: '( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )',
    factor: (k) =>
      `getPointShadow( pointShadowMap[ ${k} ], pointLightShadows[ ${k} ].shadowMapSize, pointLightShadows[ ${k} ].shadowIntensity, pointLightShadows[ ${k} ].shadowBias, pointLightShadows[ ${k} ].shadowRadius, vPointShadowCoord[ ${k} ], pointLightShadows[ ${k} ].shadowCameraNear, pointLightShadows[ ${k} ].shadowCameraFar )`,
  },
];

const each = (f: (kind: ShadowKind) => string): string => KINDS.map(f).join('');

/**
 * `SHADING_SHADOWS` when three's shadow map applies, and how: `SHADING_SHADOW_FACTOR` where the lighting is per
 * fragment (the lighting chunk applies the factor) or `SHADING_SHADOW_TERMS` where it is per vertex or face (it
 * records the terms), with `SHADING_INTERPOLATION` (`flat` or nothing) for the recorded terms' varyings.
 */
export const shadowFeatures = /* glsl */ `
#if defined( USE_SHADOWMAP ) && defined( SHADING_THREE_LIGHTS ) && ! defined( SHADING_OUTPUT_NORMAL )
#define SHADING_SHADOWS
#if defined( SHADING_PHONG ) || defined( FLAT_DERIVATIVES )
#define SHADING_SHADOW_FACTOR
#else
#define SHADING_SHADOW_TERMS
#endif
#if defined( SHADING_FLAT ) && ! defined( FLAT_DERIVATIVES )
#define SHADING_INTERPOLATION flat
#else
#define SHADING_INTERPOLATION
#endif
#endif
`;

/**
 * The lighting chunk's unrolled loop, light `UNROLLED_LOOP_INDEX` of `kind`: `call` (which adds the light's
 * diffuse and specular factors × `light` to the loop's sums), with its shadow when that light casts one (three sorts
 * the shadow-casting lights first): `light` multiplied by three's factor, or the light's term recorded.
 */
export function shadowedLight(kind: 'Dir' | 'Spot' | 'Point', call: string): string {
  const k = KINDS.find((candidate) => candidate.name === kind) as ShadowKind;
  const shadowed = `defined( SHADING_SHADOWS ) && ( UNROLLED_LOOP_INDEX < ${k.count} ) && ${k.guard}`;
  return `#if ${shadowed}
    SHADING_SHADOW_BEFORE( ${k.factor('UNROLLED_LOOP_INDEX')} )
#endif
    ${call}
#if ${shadowed}
    SHADING_SHADOW_AFTER( shading${kind}Term[ UNROLLED_LOOP_INDEX ], shading${kind}Spec[ UNROLLED_LOOP_INDEX ] )
#endif`;
}

/** The recorded terms' varyings (`qualifier` 'out' in the vertex stage, 'in' in the fragment stage). */
function termVaryings(kind: ShadowKind, qualifier: 'out' | 'in'): string {
  const declare = (name: string) => `SHADING_INTERPOLATION ${qualifier} vec3 ${name}[ ${kind.count} ];
#ifdef DOUBLE_SIDED
SHADING_INTERPOLATION ${qualifier} vec3 ${name}Back[ ${kind.count} ];
#endif`;
  return `${declare(`v${kind.name}ShadowTerm`)}
#ifdef SHADING_SPLIT
${declare(`v${kind.name}ShadowSpec`)}
#endif`;
}

/** Vertex declarations: three's shadow coordinates, and the recorded terms for flat and gouraud shading. */
export const shadowVertexPars = /* glsl */ `
#ifdef SHADING_SHADOWS
#include <shadowmap_pars_vertex>
#ifdef SHADING_SHADOW_TERMS
${each(
  (kind) => `#if ${kind.count} > 0
vec3 shading${kind.name}Term[ ${kind.count} ];
#ifdef SHADING_SPLIT
vec3 shading${kind.name}Spec[ ${kind.count} ];
#endif
${termVaryings(kind, 'out')}
#endif
`,
)}#endif
#endif
`;

/**
 * The macros the lighting chunk's loops call around a shadow-casting light's call (see {@link shadowedLight}):
 * per fragment, `light` × three's factor before; per vertex or face, the sums before, then the light's term (the
 * sums' change × kd·tint and ks; its ks part apart with a texture, SHADING_SPLIT) recorded after. They use the
 * loop's `light`, `litDiffuse`, `litSpecular` and `kdTint` (see `threeLights` in lightingChunks.glsl.ts).
 */
export const shadowLightMacros = /* glsl */ `
#if defined( SHADING_SHADOW_FACTOR ) && defined( SHADING_SHADOWS )
#define SHADING_SHADOW_BEFORE( factor ) light *= receiveShadow ? factor : 1.0;
#define SHADING_SHADOW_AFTER( term, spec )
#elif defined( SHADING_SHADOW_TERMS ) && defined( SHADING_SHADOWS )
vec3 shadingDiffuseBefore, shadingSpecularBefore;
#define SHADING_SHADOW_BEFORE( factor ) shadingDiffuseBefore = litDiffuse; shadingSpecularBefore = litSpecular;
#define SHADING_LIT_SPECULAR ( ( litSpecular - shadingSpecularBefore ) * shadingKs )
#if defined( SHADING_OUTPUT_ATTENUATION )
#define SHADING_SHADOW_AFTER( term, spec ) term = litDiffuse - shadingDiffuseBefore;
#elif defined( SHADING_SPLIT )
#define SHADING_SHADOW_AFTER( term, spec ) term = ( litDiffuse - shadingDiffuseBefore ) * kdTint; spec = SHADING_LIT_SPECULAR;
#else
#define SHADING_SHADOW_AFTER( term, spec ) term = ( litDiffuse - shadingDiffuseBefore ) * kdTint + SHADING_LIT_SPECULAR;
#endif
#endif
`;

/**
 * Vertex stage, end of `main`: three's shadow coordinates at the vertex's world position, offset along the
 * world normal (`SHADING_SHADOW_NORMAL`: the face's, the vertex's, none from derivatives) by the light's
 * normalBias. (The terms flat and gouraud shading record are copied per side by {@link shadowTermsCopy}.)
 */
export const shadowVertex = /* glsl */ `
#ifdef SHADING_SHADOWS
#if defined( SHADING_FLAT ) && ! defined( FLAT_DERIVATIVES )
#define SHADING_SHADOW_NORMAL ( shadingNormalMatrix * faceNormal )
#elif defined( FLAT_DERIVATIVES )
#undef HAS_NORMAL // no vertex normal: three's normalBias is not applied
#define SHADING_SHADOW_NORMAL vec3( 0.0 )
#else
#define SHADING_SHADOW_NORMAL worldNormal
#endif
  {
    vec3 shadowNormal = SHADING_SHADOW_NORMAL;
    float shadowNormal2 = dot( shadowNormal, shadowNormal );
    // A zero normal (singular transform) offsets along an arbitrary unit vector instead of making a NaN.
    vec3 transformedNormal = shadowNormal2 > 0.0 ? ( viewMatrix * vec4( shadowNormal * inversesqrt( shadowNormal2 ), 0.0 ) ).xyz : vec3( 0.0, 0.0, 1.0 );
    #include <worldpos_vertex>
    #include <shadowmap_vertex>
  }
#endif
`;

/** Copies the terms just recorded by shadeColor into the front (`suffix` '') or back ('Back') varyings. */
export function shadowTermsCopy(suffix: '' | 'Back'): string {
  return /* glsl */ `
#if defined( SHADING_SHADOWS ) && defined( SHADING_SHADOW_TERMS )
${each(
  (kind) => `#if ${kind.count} > 0
  for ( int k = 0; k < ${kind.count}; k ++ ) v${kind.name}ShadowTerm${suffix}[ k ] = shading${kind.name}Term[ k ];
#ifdef SHADING_SPLIT
  for ( int k = 0; k < ${kind.count}; k ++ ) v${kind.name}ShadowSpec${suffix}[ k ] = shading${kind.name}Spec[ k ];
#endif
#endif
`,
)}#endif
`;
}

/** Fragment declarations: three's shadow maps and factors, and the recorded terms' varyings. */
export const shadowFragmentPars = /* glsl */ `
#ifdef SHADING_SHADOWS
#ifndef PI
#include <common>
#endif
#include <packing>
#include <shadowmap_pars_fragment>
#ifdef SHADING_SHADOW_TERMS
uniform bool receiveShadow;
${each(
  (kind) => `#if ${kind.count} > 0
${termVaryings(kind, 'in')}
#endif
`,
)}#endif
#endif
`;

/**
 * Fragment stage (flat and gouraud), after the texel: `color` loses (1 − factor) of each shadow-casting light's
 * recorded term (its ka/kd part times the texel, plus its ks part, when the colour is split).
 */
export const shadowTermsFragment = /* glsl */ `
#if defined( SHADING_SHADOWS ) && defined( SHADING_SHADOW_TERMS )
  if ( receiveShadow ) {
    vec3 shadowTerm;
${each((kind) => {
  const side = (array: string) =>
    `\n#ifdef DOUBLE_SIDED\n      ( gl_FrontFacing ? ${array}[ i ] : ${array}Back[ i ] )\n#else\n      ${array}[ i ]\n#endif\n`;
  return `#if ${kind.count} > 0 && ${kind.guard}
    #pragma unroll_loop_start
    for ( int i = 0; i < ${kind.count}; i ++ ) {
      shadowTerm = ${side(`v${kind.name}ShadowTerm`)};
#ifdef SHADING_SPLIT
      shadowTerm = shadowTerm * diffuseColor.rgb + ${side(`v${kind.name}ShadowSpec`)};
#endif
      color -= ( 1.0 - ${kind.factor('i')} ) * shadowTerm;
    }
    #pragma unroll_loop_end
#endif
`;
})}  }
#endif
`;
