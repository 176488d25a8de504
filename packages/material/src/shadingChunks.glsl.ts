// The lecture's equation and the shading stages as named GLSL chunks, included by ShadingMaterial, the
// impostor and the outline (as three's meshphong.glsl.js includes its chunks). three's own chunks
// (`#include <…>`) do the standard parts: instancing, batching, skinning, morph targets, clipping, fog, tone
// mapping and colour space, each compiled only when three's program parameters define its USE_* macro. Every
// chunk here compiles to nothing unless its feature is on, so a scene without them compiles the same code as
// before (tests/material-scene.spec.ts checks the active lines of every lecture program).

import { shadowedLight, shadowLightMacros } from './shadowChunks.glsl.js';

/**
 * Which of three's scene features this draw uses, from the USE_* macros three defines per program:
 * - `SHADING_SCENE` (vertex): the vertex goes through three's chunks (`transformed`, `mvPosition`);
 * - `SHADING_INSTANCE`: an InstancedMesh or BatchedMesh matrix moves the vertex (and its normal);
 * - `SHADING_DEFORM`: morph targets or skinning move the vertex;
 * - `SHADING_TINT`: an instance (or batch) colour, a vertex colour or a texel of `map` multiplies ka and kd.
 */
export const sceneFeatures = /* glsl */ `
#if defined( USE_INSTANCING ) || defined( USE_BATCHING ) || defined( USE_SKINNING ) || defined( USE_MORPHTARGETS ) || defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0 || defined( USE_SHADOWMAP )
#define SHADING_SCENE
#endif
#if defined( USE_INSTANCING ) || defined( USE_BATCHING )
#define SHADING_INSTANCE
#endif
#if defined( USE_MORPHTARGETS ) || defined( USE_SKINNING )
#define SHADING_DEFORM
#endif
#if defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR ) || defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_MAP )
#define SHADING_TINT
#endif
`;

/**
 * The surface's textures and alpha, three's way (ShadingMaterial only), from three's USE_* macros:
 * - `SHADING_SPLIT` (both stages): a texture with vertex lighting (gouraud, exact flat) — the vertex stage passes
 *   the ka/kd part and the ks part of the colour separately, the fragment multiplies only the first by the texel;
 * - `SHADING_SURFACE` (fragment): `diffuseColor` = (texel, opacity × texel alpha × vertex alpha × alphaMap.g),
 *   alpha-tested and, unless opaque, written as the fragment's alpha;
 * - `SHADING_NORMALMAP` (fragment, phong shading only): three's normal map perturbs the normal, in world space,
 *   with three's derivative tangent frame (`getTangentFrame`; a `tangent` attribute is not used).
 */
export const surfaceVertexPars = /* glsl */ `
#if defined( USE_MAP ) && ! defined( SHADING_PHONG ) && ! defined( FLAT_DERIVATIVES )
#define SHADING_SPLIT
#endif
#include <uv_pars_vertex>
#ifdef USE_COLOR_ALPHA
out float vShadingAlpha;
#endif
`;

/** Fragment declarations of the surface (see {@link surfaceVertexPars}). */
export const surfaceFragmentPars = /* glsl */ `
#if defined( USE_MAP ) && ! defined( SHADING_PHONG ) && ! defined( FLAT_DERIVATIVES )
#define SHADING_SPLIT
#endif
#if defined( USE_MAP ) || defined( USE_ALPHAMAP ) || defined( USE_ALPHATEST ) || ! defined( OPAQUE )
#define SHADING_SURFACE
uniform float opacity;
#endif
#if defined( SHADING_EMISSIVE ) || defined( USE_EMISSIVEMAP )
uniform vec3 emissive;
#endif
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <emissivemap_pars_fragment>
#ifdef USE_COLOR_ALPHA
in float vShadingAlpha;
#endif
#if defined( USE_NORMALMAP ) && defined( SHADING_PHONG )
#define SHADING_NORMALMAP
#undef USE_TANGENT
#ifdef SHADING_VIEW_SPACE
#define normalMatrix ( mat3( viewMatrix ) * shadingNormalMatrix )
#else
#define normalMatrix shadingNormalMatrix
#endif
#endif
#include <normalmap_pars_fragment>
`;

/**
 * Fragment stage, phong shading with a normal map: the normal (`vNormal`, turned to the drawn side) through
 * three's tangent frame and `normal_fragment_maps` (tangent space, or object space through the object's normal
 * matrix), in world space, then lit.
 */
export const normalMapFragment = /* glsl */ `
  float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#if defined( DOUBLE_SIDED )
  vec3 normal = normalize( vNormal ) * faceDirection;
#elif defined( FLIP_SIDED )
  vec3 normal = - normalize( vNormal );
#else
  vec3 normal = normalize( vNormal );
#endif
#ifdef USE_NORMALMAP_TANGENTSPACE
  mat3 tbn = getTangentFrame( vWorldPosition, normal, vNormalMapUv );
#ifdef DOUBLE_SIDED
  tbn[ 0 ] *= faceDirection;
  tbn[ 1 ] *= faceDirection;
#endif
#endif
  #include <normal_fragment_maps>
  vec3 color = shadeColor( vWorldPosition, normal );
`;

/**
 * Fragment stage, after clipping: three's map, vertex alpha, alpha map and alpha test on `diffuseColor`
 * (declared by {@link clippingFragment}).
 */
export const surfaceFragment = /* glsl */ `
#ifdef SHADING_SURFACE
  #include <map_fragment>
#ifdef USE_COLOR_ALPHA
  diffuseColor.a *= vShadingAlpha;
#endif
  #include <alphamap_fragment>
  #include <alphatest_fragment>
#endif
`;

/** Fragment stage: emissive (× emissiveMap, three's chunk) added to the lit colour, outside the lighting. */
export const emissiveFragment = /* glsl */ `
#if defined( SHADING_EMISSIVE ) || defined( USE_EMISSIVEMAP )
  vec3 totalEmissiveRadiance = emissive;
  #include <emissivemap_fragment>
  color += totalEmissiveRadiance;
#endif
`;

/**
 * The lighting equation (uniforms, `lightTerm`, `shadeColor`), shared by the vertex (flat, gouraud) and
 * fragment (phong, impostor) stages. `LIGHT_COUNT_LITERAL` is replaced by the number of lights.
 */
export const lightingChunk = /* glsl */ `
uniform vec4 shadingEye; // homogeneous eye: (position, 1) perspective, (backward axis, 0) orthographic
uniform vec3 ambientTerm; // Σ ka·Ia over the lights (ambient is never attenuated)
uniform float shininess;
#if NUM_LIGHTS > 0
uniform vec3 lightPosition[NUM_LIGHTS];
uniform vec3 lightDiffuse[NUM_LIGHTS]; // kd·Id
uniform vec3 lightSpecular[NUM_LIGHTS]; // ks·Is
#ifdef USE_ATTENUATION
uniform vec3 lightAttenuation[NUM_LIGHTS]; // a, b, c
#endif
#endif
#ifdef SHADING_TINT
vec3 shadingTint = vec3( 1.0 ); // instance colour: multiplies ka and kd
#endif
#ifdef SHADING_SPLIT
vec3 shadingSpecular = vec3( 0.0 ); // the ks part of the last shadeColor (which then returns the ka/kd part)
#endif

#ifdef USE_ATTENUATION
#define LIGHT_ATTENUATION(i) lightAttenuation[i]
#else
#define LIGHT_ATTENUATION(i) vec3(1.0, 0.0, 0.0)
#endif

// One light's attenuated diffuse + specular term (kdId = kd·Id, ksIs = ks·Is, k = (a, b, c)).
vec3 lightTerm(vec3 p, vec3 n, vec3 v, vec3 lightPos, vec3 kdId, vec3 ksIs, vec3 k) {
  // inversesqrt and multiplies instead of length and divisions (cheaper on every GPU); the selects keep
  // the degenerate cases of shade(): a light at the point lights it head-on.
  vec3 toLight = lightPos - p;
  float t2 = dot(toLight, toLight);
  float invT = inversesqrt(t2);
  vec3 l = t2 > 0.0 ? toLight * invT : n;
  float ndl = dot(n, l);
  float diffuse = max(ndl, 0.0);
#ifdef LIGHTING_BLINN
  vec3 h = l + v;
  float h2 = dot(h, h);
  float x = h2 > 0.0 ? max(dot(n, h) * inversesqrt(h2), 0.0) : 0.0;
#else
  // v·r with r = 2(l·n)n − l
  float x = max(2.0 * ndl * dot(v, n) - dot(v, l), 0.0);
#endif
  // pow(0, 0) is undefined in GLSL: 0^0 = 1 (shininess 0 lights the whole lit side), 0^α = 0 for α > 0.
  float spec = x > 0.0 ? pow(x, shininess) : step(shininess, 0.0);
  spec = ndl > 0.0 ? spec : 0.0;
#if CEL_BANDS > 0
  diffuse = min(floor(diffuse * float(CEL_BANDS)), float(CEL_BANDS - 1)) / float(CEL_BANDS - 1);
  spec = step(0.5, spec);
#endif
#ifdef USE_ATTENUATION
  float t = t2 > 0.0 ? t2 * invT : 0.0;
  float att = 1.0 / max(k.x + k.y * t + k.z * t2, 1e-6);
  diffuse *= att;
  spec *= att;
#endif
#ifdef SHADING_SPLIT
  shadingSpecular += spec * ksIs;
  return diffuse * kdId;
#else
  return diffuse * kdId + spec * ksIs;
#endif
}

#ifdef SHADING_THREE_LIGHTS
#ifndef PI
#include <common>
#endif
#include <lights_pars_begin>
uniform vec3 shadingKa, shadingKd, shadingKs;
#ifndef SHADING_TINT
#define shadingTint 1.0
#endif
${shadowLightMacros}
vec3 threeDirect(vec3 n, vec3 v, vec3 l, vec3 c) {
  float d = dot(n, l);
#ifdef LIGHTING_BLINN
  vec3 h = l + v;
  float h2 = dot(h, h);
  float x = h2 > 0.0 ? max(dot(n, h) * inversesqrt(h2), 0.0) : 0.0;
#else
  float x = max(2.0 * d * dot(v, n) - dot(v, l), 0.0);
#endif
  // Selects between computed values, not branches around pow (1.13× cheaper in the realistic scene); the same
  // rules: 0⁰ = 1, 0^α = 0, no highlight where l·n ≤ 0.
  float s = pow(max(x, 1e-30), shininess);
  s = x > 0.0 ? s : step(shininess, 0.0);
  s = d > 0.0 ? s : 0.0;
  d = max(d, 0.0);
#if CEL_BANDS > 0
  d = min(floor(d * float(CEL_BANDS)), float(CEL_BANDS - 1)) / float(CEL_BANDS - 1);
  s = step(0.5, s);
#endif
#ifdef SHADING_SPLIT
  shadingSpecular += c * s * shadingKs;
  return c * d * shadingKd * shadingTint;
#else
  return c * (d * shadingKd * shadingTint + s * shadingKs);
#endif
}
// three's getDistanceAttenuation at distance t (t2 = t²), compiled for what the scene's lights use: the cut-off
// window only when some light has a distance, 1/max(t², 0.01) when every decay is 2 (no pow).
float threeFalloff(float t, float t2, float cutoff, float decay) {
#ifdef SHADING_INVERSE_SQUARE
  float f = 1.0 / max(t2, 0.01);
#else
  float f = 1.0 / max(pow(t, decay), 0.01);
#endif
#ifdef SHADING_LIGHT_CUTOFF
  if (cutoff > 0.0) f *= pow2(saturate(1.0 - pow4(t / cutoff)));
#endif
  return f;
}
// The unit direction from p to a light at q, its distance t and t² (one inversesqrt); a light at p lights it
// head-on (l = n), as in lightTerm.
vec3 threeToLight(vec3 q, vec3 p, vec3 n, out float t, out float t2) {
  vec3 l = q - p;
  t2 = dot(l, l);
  float r = inversesqrt(t2);
  t = t2 > 0.0 ? t2 * r : 0.0;
  return t2 > 0.0 ? l * r : n;
}
vec3 threeLights(vec3 p, vec3 n, vec3 v) {
#ifndef SHADING_VIEW_SPACE
  // three's light uniforms are in view space (SHADING_VIEW_SPACE: p, n and v are already).
  p = (viewMatrix * vec4(p, 1.0)).xyz;
  n = normalize((viewMatrix * vec4(n, 0.0)).xyz);
  v = normalize((viewMatrix * vec4(v, 0.0)).xyz);
#endif
  vec3 c = ambientLightColor, l, term;
  float t, t2;
#if NUM_HEMI_LIGHTS > 0
  for (int i = 0; i < NUM_HEMI_LIGHTS; i++) c += getHemisphereLightIrradiance(hemisphereLights[i], n);
#endif
  c *= shadingKa * shadingTint;
  // Unrolled, as three's own light loops are (cheaper, and a shadow map array needs a constant index). A
  // shadow-casting light's term is shadowed per fragment (see shadowChunks.glsl.ts).
#if NUM_DIR_LIGHTS > 0
  #pragma unroll_loop_start
  for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
    SHADING_SHADOW_BEGIN
    term = threeDirect( n, v, directionalLights[ i ].direction, directionalLights[ i ].color );
${shadowedLight('Dir')}
    c += term;
  }
  #pragma unroll_loop_end
#endif
#if NUM_POINT_LIGHTS > 0
  #pragma unroll_loop_start
  for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
    l = threeToLight( pointLights[ i ].position, p, n, t, t2 );
    SHADING_SHADOW_BEGIN
    term = threeDirect( n, v, l, pointLights[ i ].color * threeFalloff( t, t2, pointLights[ i ].distance, pointLights[ i ].decay ) );
${shadowedLight('Point')}
    c += term;
  }
  #pragma unroll_loop_end
#endif
#if NUM_SPOT_LIGHTS > 0
  #pragma unroll_loop_start
  for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
    l = threeToLight( spotLights[ i ].position, p, n, t, t2 );
    SHADING_SHADOW_BEGIN
    term = threeDirect( n, v, l, spotLights[ i ].color * getSpotAttenuation( spotLights[ i ].coneCos, spotLights[ i ].penumbraCos, dot( l, spotLights[ i ].direction ) ) * threeFalloff( t, t2, spotLights[ i ].distance, spotLights[ i ].decay ) );
${shadowedLight('Spot')}
    c += term;
  }
  #pragma unroll_loop_end
#endif
  return c;
}
#endif

vec3 shadeColor(vec3 p, vec3 normal) {
#ifdef SHADING_SPLIT
  shadingSpecular = vec3( 0.0 );
#endif
  vec3 toEye = shadingEye.xyz - p * shadingEye.w;
  float e2 = dot(toEye, toEye);
  vec3 v = e2 > 0.0 ? toEye * inversesqrt(e2) : vec3(0.0, 0.0, 1.0);
  float n2 = dot(normal, normal);
  vec3 n = n2 > 0.0 ? normal * inversesqrt(n2) : v;
  v = e2 > 0.0 ? v : n;
#ifdef SHADING_TINT
  vec3 color = ambientTerm * shadingTint;
#else
  vec3 color = ambientTerm;
#endif
#if NUM_LIGHTS > 0
  // Unrolled by three (LIGHT_COUNT_LITERAL is replaced by the number of lights before compiling).
  #pragma unroll_loop_start
  for ( int i = 0; i < LIGHT_COUNT_LITERAL; i ++ ) {
#ifdef SHADING_TINT
    color += lightTerm(p, n, v, lightPosition[ i ], lightDiffuse[ i ] * shadingTint, lightSpecular[ i ], LIGHT_ATTENUATION(UNROLLED_LOOP_INDEX));
#else
    color += lightTerm(p, n, v, lightPosition[ i ], lightDiffuse[ i ], lightSpecular[ i ], LIGHT_ATTENUATION(UNROLLED_LOOP_INDEX));
#endif
  }
  #pragma unroll_loop_end
#endif
#ifdef SHADING_THREE_LIGHTS
  color += threeLights(p, n, v);
#endif
  return color;
}
`;

/**
 * Vertex declarations for instancing and batching: the instance's normal matrix, made as `computeNormalMatrix`
 * makes the object's (sign(det A)·cof(A) of A / max|A|: finite for a singular or huge instance matrix, outward
 * under mirroring, right under shear), and the rescaling that keeps a product of normal matrices in range.
 */
export const instanceChunk = /* glsl */ `
#ifdef SHADING_INSTANCE
vec3 shadingRescale( vec3 v ) {
  float m = max( max( abs( v.x ), abs( v.y ) ), abs( v.z ) );
  return m > 0.0 ? v / m : vec3( 0.0 );
}
mat3 shadingCofactor( mat3 a ) {
  vec3 e = max( max( abs( a[ 0 ] ), abs( a[ 1 ] ) ), abs( a[ 2 ] ) );
  float s = max( max( e.x, e.y ), e.z );
  if ( ! ( s > 0.0 ) ) return mat3( 0.0 );
  vec3 a0 = a[ 0 ] / s;
  vec3 a1 = a[ 1 ] / s;
  vec3 a2 = a[ 2 ] / s;
  mat3 c = mat3( cross( a1, a2 ), cross( a2, a0 ), cross( a0, a1 ) );
  return dot( a0, c[ 0 ] ) < 0.0 ? - c : c;
}
#endif
`;

/**
 * Vertex stage, first lines of `main`: three's chunks move the vertex (batching, instanced morph weights,
 * morph targets, skinning, instancing: `transformed`, `mvPosition`, `gl_Position`), then clipping and fog
 * read its view position; the lecture's scene (none of them) keeps its one-line projection.
 */
export const projectVertex = /* glsl */ `
#ifdef SHADING_SCENE
  #include <batching_vertex>
  #include <morphinstance_vertex>
  #include <skinbase_vertex>
  vec3 transformed = vec3( position );
  #include <morphtarget_vertex>
  #include <skinning_vertex>
  #include <project_vertex>
  #include <clipping_planes_vertex>
  #include <fog_vertex>
#else
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
#endif
`;

/**
 * Vertex stage: the instance (or batch) matrix and its normal matrix (`shadingInstance`,
 * `shadingInstanceNormal`), and the tint: instance colour × vertex colour (`tint`).
 */
export const instanceVertex = /* glsl */ `
#ifdef SHADING_INSTANCE
  mat4 shadingInstance = mat4( 1.0 );
#ifdef USE_BATCHING
  shadingInstance = batchingMatrix;
#endif
#ifdef USE_INSTANCING
  shadingInstance = instanceMatrix;
#endif
  mat3 shadingInstanceNormal = shadingCofactor( mat3( shadingInstance ) );
#endif
#ifdef SHADING_TINT
  vec3 tint = vec3( 1.0 );
#ifdef USE_INSTANCING_COLOR
  tint *= instanceColor;
#endif
#ifdef USE_BATCHING_COLOR
  tint *= getBatchingColor( getIndirectIndex( gl_DrawID ) ).rgb;
#endif
#if defined( USE_COLOR_ALPHA )
  tint *= color.rgb;
#elif defined( USE_COLOR )
  tint *= color;
#endif
#endif
`;

/**
 * Flat shading's corners moved like their vertices (morph targets, then skinning, as three's chunks move a
 * vertex): `cornerIndex` holds their vertex indices, `faceSkin` their skin indices and weights.
 */
export const flatDeformVertex = /* glsl */ `
#ifdef SHADING_DEFORM
  vec3 corners[ 3 ] = vec3[ 3 ]( p0, p1, p2 );
  for ( int k = 0; k < 3; k ++ ) {
    vec3 c = corners[ k ];
#ifdef USE_MORPHTARGETS
    c *= morphTargetBaseInfluence;
    for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
      if ( morphTargetInfluences[ i ] != 0.0 ) c += getMorph( cornerIndex[ k ], i, 0 ).xyz * morphTargetInfluences[ i ];
    }
#endif
#ifdef USE_SKINNING
    int t = 2 * cornerIndex[ k ];
    int w = textureSize( faceSkin, 0 ).x;
    vec4 bones = texelFetch( faceSkin, ivec2( t % w, t / w ), 0 );
    vec4 weights = texelFetch( faceSkin, ivec2( t % w + 1, t / w ), 0 );
    vec4 bound = bindMatrix * vec4( c, 1.0 );
    vec4 skinned = getBoneMatrix( bones.x ) * bound * weights.x + getBoneMatrix( bones.y ) * bound * weights.y
      + getBoneMatrix( bones.z ) * bound * weights.z + getBoneMatrix( bones.w ) * bound * weights.w;
    c = ( bindMatrixInverse * skinned ).xyz;
#endif
    corners[ k ] = c;
  }
  p0 = corners[ 0 ];
  p1 = corners[ 1 ];
  p2 = corners[ 2 ];
#endif
`;

/**
 * Fragment: `diffuseColor` (the surface's, see {@link surfaceFragmentPars}, or for three's clipping chunk, which
 * scales its alpha with alpha to coverage), then three's clipping.
 */
export const clippingFragment = /* glsl */ `
#if defined( SHADING_SURFACE )
  vec4 diffuseColor = vec4( vec3( 1.0 ), opacity );
#elif NUM_CLIPPING_PLANES > 0 && defined( ALPHA_TO_COVERAGE )
  vec4 diffuseColor = vec4( 1.0 );
#endif
  #include <clipping_planes_fragment>
`;

/**
 * Fragment stage, last lines: three's tone mapping and output colour space, then fog as three's
 * `fog_fragment` blends it (in the output colour space), except that fog near = far (where `smoothstep` is
 * undefined) is a step at that depth: no fog before it, all fog beyond.
 */
export const outputFragment = /* glsl */ `
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
#ifdef USE_FOG
#ifdef FOG_EXP2
  float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
#else
  float fogFactor = fogFar > fogNear ? smoothstep( fogNear, fogFar, vFogDepth ) : step( fogNear, vFogDepth );
#endif
  gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif
`;
