// The lecture's lighting equation in GLSL, written once: `lightFactors` is one light's diffuse and specular
// factors (l·n, the Phong r or the Blinn h, 0⁰ = 1, cel quantisation), included in `lightTerm` (a PhongLight,
// with the lecture's attenuation: `lightReturn` makes its kd and ks parts) and in `threeDirect` (one of three's
// lights, whose falloff is in its colour: the factors × colour are summed over the lights, and the sums
// multiplied by kd·tint and ks once, four vector operations a light fewer). `shade()` (shade.ts) is the CPU
// truth both are tested against. Statement chunks rather than a function of their own: a PhongLight program then
// compiles exactly the code it compiled before (tests/material-scene.spec.ts compares the active lines of every
// lecture program).

import { directLightCount, outputFactors, outputNormal } from './outputChunks.glsl.js';
import { shadowedLight, shadowLightMacros } from './shadowChunks.glsl.js';

/**
 * One light's factors, from the unit normal `n`, view vector `v` and light direction `l`: `ndl` = l·n,
 * `diffuse` = max(l·n, 0), `spec` = (r·v)^α (Phong, r = 2(l·n)n − l) or (n·h)^α (Blinn-Phong, h = (l + v)/|l + v|),
 * with 0⁰ = 1 (shininess 0 lights the whole lit side), 0^α = 0 and no highlight where l·n ≤ 0; cel shading
 * quantises both (CEL_BANDS diffuse shades, the highlight on or off). `blinn` is the statement that sets the
 * Blinn-Phong x = max(n·h, 0) from `h` = l + v and `h2` = |h|².
 */
function lightFactors(blinn: string): string {
  return /* glsl */ `
  float ndl = dot(n, l);
  float diffuse = max(ndl, 0.0);
#ifdef LIGHTING_BLINN
  vec3 h = l + v;
  float h2 = dot(h, h);
  ${blinn}
#else
  // v·r with r = 2(l·n)n − l
  float x = max(2.0 * ndl * dot(v, n) - dot(v, l), 0.0);
#endif
  // pow(0, 0) is undefined in GLSL: 0^0 = 1 (shininess 0 lights the whole lit side), 0^α = 0 for α > 0. Selects
  // between computed values, not a branch around pow (cheaper: see bench/lighting.bench.mjs).
  float spec = pow(max(x, 1e-30), shininess);
  spec = x > 0.0 ? spec : step(shininess, 0.0);
  spec = ndl > 0.0 ? spec : 0.0;
#if CEL_BANDS > 0
  diffuse = min(floor(diffuse * float(CEL_BANDS)), float(CEL_BANDS - 1)) / float(CEL_BANDS - 1);
  spec = step(0.5, spec);
#endif
${outputFactors}`;
}

/** A PhongLight's Blinn-Phong factor: no highlight where l = −v (h = 0), selected (the lecture's text). */
const lectureBlinn = 'float x = h2 > 0.0 ? max(dot(n, h) * inversesqrt(h2), 0.0) : 0.0;';
/**
 * One of three's lights': the same value with one instruction less, as cost is compared with three's materials
 * here. |l + v|² of unit vectors is 0 or far above 1e-30 (unless the vectors are denormal-close to opposite, where
 * both forms give x below 1e-15), so max(h², 1e-30) changes no result: h = 0 gives 0 · 1e15 = 0.
 */
const threeBlinn = 'float x = max(dot(n, h) * inversesqrt(max(h2, 1e-30)), 0.0);';

/**
 * The light's term from its factors and `kdId` = kd·Id (× tint), `ksIs` = ks·Is: their sum, or, with a texture on
 * vertex lighting (SHADING_SPLIT), the ka/kd part, its ks part added to `shadingSpecular`.
 */
const lightReturn = /* glsl */ `
#ifdef SHADING_SPLIT
  shadingSpecular += spec * ksIs;
  return diffuse * kdId;
#else
  return diffuse * kdId + spec * ksIs;
#endif
`;

/** How many PhongLights are added one by one (`#if NUM_LIGHTS > k`); a loop adds the rest. */
const UNROLLED_LIGHTS = 8;

/** PhongLight `k` (a digit literal, or the loop's `i`) added to `color` in `shadeColor`. */
function phongLight(k: string): string {
  return /* glsl */ `
#ifdef SHADING_TINT
    color += lightTerm(p, n, v, lightPosition[ ${k} ], lightDiffuse[ ${k} ] * shadingTint, lightSpecular[ ${k} ], LIGHT_ATTENUATION(${k}));
#else
    color += lightTerm(p, n, v, lightPosition[ ${k} ], lightDiffuse[ ${k} ], lightSpecular[ ${k} ], LIGHT_ATTENUATION(${k}));
#endif`;
}

/**
 * The PhongLights: NUM_LIGHTS is a define, the light count is never pasted into the source. The first
 * {@link UNROLLED_LIGHTS} are added one by one under `#if NUM_LIGHTS > k` (what three's `unroll_loop` would make of
 * a loop, which it unrolls only over a digit literal), the rest by a loop bounded by NUM_LIGHTS.
 */
const phongLights = /* glsl */ `${Array.from(
  { length: UNROLLED_LIGHTS },
  (_, k) => `
#if NUM_LIGHTS > ${k}${phongLight(String(k))}
#endif`,
).join('')}
#if NUM_LIGHTS > ${UNROLLED_LIGHTS}
  for ( int i = ${UNROLLED_LIGHTS}; i < NUM_LIGHTS; i ++ ) {${phongLight('i')}
  }
#endif
`;

/**
 * One kind of three's direct lights, in its unrolled loop (as three's own loops, which three unrolls: a shadow
 * map array needs a constant index): `toLight` sets the unit direction `l` (and `t`, `t2`) when the light has a
 * position, `colour` is its colour and `falloff` (none: 1) its falloff; `threeDirect` adds the light's factors ×
 * `light` to the sums, shadowed when the light casts a shadow (see shadowChunks.glsl.ts). The attenuation output's
 * light is the falloff (over the direct lights' count), added as is.
 */
function threeLightLoop(
  kind: 'Dir' | 'Point' | 'Spot',
  count: string,
  toLight: string,
  color: string,
  falloff?: string,
): string {
  const colour = falloff === undefined ? color : `${color} * ${falloff}`;
  return /* glsl */ `
#if ${count} > 0
  #pragma unroll_loop_start
  for ( int i = 0; i < ${count}; i ++ ) {
    ${toLight}
#ifdef SHADING_OUTPUT_ATTENUATION
    light = vec3( ${falloff ?? '1.0'} ) / float( SHADING_DIRECT_LIGHTS );
#else
    light = ${colour};
#endif
${shadowedLight(kind, 'threeDirect( n, v, l, light, litDiffuse, litSpecular );')}
  }
  #pragma unroll_loop_end
#endif`;
}

/** three's lights (SHADING_THREE_LIGHTS): their uniforms, `threeDirect` and their loops in `threeLights`. */
const threeLights = /* glsl */ `
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
// One of three's direct lights (colour × falloff; three's 1/π is in shadingKa/Kd/Ks): its factors × light summed.
void threeDirect(vec3 n, vec3 v, vec3 l, vec3 light, inout vec3 litDiffuse, inout vec3 litSpecular) {
#ifdef SHADING_OUTPUT_ATTENUATION
  litDiffuse += light;
#else
${lightFactors(threeBlinn)}
  litDiffuse += diffuse * light;
  litSpecular += spec * light;
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
  vec3 c = ambientLightColor, l, light;
  float t, t2;
#if NUM_HEMI_LIGHTS > 0
  for (int i = 0; i < NUM_HEMI_LIGHTS; i++) c += getHemisphereLightIrradiance(hemisphereLights[i], n);
#endif
  c *= shadingKa * shadingTint;
#ifdef SHADING_NO_AMBIENT
  c = vec3( 0.0 );
#endif
  vec3 litDiffuse = vec3( 0.0 ), litSpecular = vec3( 0.0 ), kdTint = shadingKd * shadingTint;
${threeLightLoop('Dir', 'NUM_DIR_LIGHTS', 'l = directionalLights[ i ].direction;', 'directionalLights[ i ].color')}
${threeLightLoop(
  'Point',
  'NUM_POINT_LIGHTS',
  'l = threeToLight( pointLights[ i ].position, p, n, t, t2 );',
  'pointLights[ i ].color',
  'threeFalloff( t, t2, pointLights[ i ].distance, pointLights[ i ].decay )',
)}
${threeLightLoop(
  'Spot',
  'NUM_SPOT_LIGHTS',
  'l = threeToLight( spotLights[ i ].position, p, n, t, t2 );',
  'spotLights[ i ].color',
  'getSpotAttenuation( spotLights[ i ].coneCos, spotLights[ i ].penumbraCos, dot( l, spotLights[ i ].direction ) ) * threeFalloff( t, t2, spotLights[ i ].distance, spotLights[ i ].decay )',
)}
#if defined( SHADING_OUTPUT_ATTENUATION )
  return c + litDiffuse;
#elif defined( SHADING_SPLIT )
  shadingSpecular += litSpecular * shadingKs;
  return c + litDiffuse * kdTint;
#else
  return c + litDiffuse * kdTint + litSpecular * shadingKs;
#endif
}
#endif
`;

/**
 * The lighting equation (uniforms, `lightTerm`, three's lights, `shadeColor`), shared by the vertex (flat,
 * gouraud) and fragment (phong, impostor) stages: `shadeColor(p, normal)` is ka·Ia plus every light's term at
 * the point p with that normal (world space, or view space with SHADING_VIEW_SPACE).
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

${directLightCount}
#ifdef USE_ATTENUATION
#define LIGHT_ATTENUATION(i) lightAttenuation[i]
#else
#define LIGHT_ATTENUATION(i) vec3(1.0, 0.0, 0.0)
#endif

// One PhongLight's attenuated term (kdId = kd·Id, ksIs = ks·Is, k = (a, b, c)).
vec3 lightTerm(vec3 p, vec3 n, vec3 v, vec3 lightPos, vec3 kdId, vec3 ksIs, vec3 k) {
  // inversesqrt and multiplies instead of length and divisions (cheaper on every GPU); the selects keep
  // the degenerate cases of shade(): a light at the point lights it head-on.
  vec3 toLight = lightPos - p;
  float t2 = dot(toLight, toLight);
  float invT = inversesqrt(t2);
  vec3 l = t2 > 0.0 ? toLight * invT : n;
${lightFactors(lectureBlinn)}
#ifdef USE_ATTENUATION
  float t = t2 > 0.0 ? t2 * invT : 0.0;
  float att = 1.0 / max(k.x + k.y * t + k.z * t2, 1e-6);
  diffuse *= att;
  spec *= att;
#endif
#if defined( SHADING_OUTPUT_ATTENUATION ) && defined( USE_ATTENUATION )
  return vec3( att / float( SHADING_DIRECT_LIGHTS ) );
#elif defined( SHADING_OUTPUT_ATTENUATION )
  return vec3( 1.0 / float( SHADING_DIRECT_LIGHTS ) );
#endif
${lightReturn}}
${threeLights}
vec3 shadeColor(vec3 p, vec3 normal) {
#ifdef SHADING_SPLIT
  shadingSpecular = vec3( 0.0 );
#endif
  vec3 toEye = shadingEye.xyz - p * shadingEye.w;
  float e2 = dot(toEye, toEye);
#if defined( SHADING_THREE_LIGHTS ) && ( defined( SHADING_PHONG ) || defined( FLAT_DERIVATIVES ) )
  // Lit at a drawn fragment, which lies beyond the near plane: never at the eye (e2 > 0), as three's materials
  // assume. Two selects less where cost is compared with theirs; the lecture's programs keep the guard.
  vec3 v = toEye * inversesqrt(e2);
  float n2 = dot(normal, normal);
  vec3 n = n2 > 0.0 ? normal * inversesqrt(n2) : v;
#else
  vec3 v = e2 > 0.0 ? toEye * inversesqrt(e2) : vec3(0.0, 0.0, 1.0);
  float n2 = dot(normal, normal);
  vec3 n = n2 > 0.0 ? normal * inversesqrt(n2) : v;
  v = e2 > 0.0 ? v : n;
#endif
${outputNormal}
#ifdef SHADING_TINT
  vec3 color = ambientTerm * shadingTint;
#else
  vec3 color = ambientTerm;
#endif
#ifdef SHADING_NO_AMBIENT
  color = vec3( 0.0 );
#endif
${phongLights}
#ifdef SHADING_THREE_LIGHTS
  color += threeLights(p, n, v);
#endif
  return color;
}
`;
