// GLSL of SphereImpostorMaterial: a screen-aligned quad whose fragments ray-cast the unit sphere in model
// space. The lighting equation is ShadingMaterial's own chunk (`lightingChunk` of shadingChunks.glsl.ts,
// included by both), and the hit is clipped, tone-mapped, converted and fogged by the same chunks as a mesh.
import { clippingFragment, lightingChunk, outputFragment } from './shadingChunks.glsl.js';

/** Vertex stage: the quad's corners (position.xy = ±1) go to the projected ellipsoid's screen bounds. */
export const impostorVertexShader = /* glsl */ `
uniform vec4 impostorBounds; // NDC min x, min y, max x, max y
void main() {
  vec2 corner = position.xy * 0.5 + 0.5;
  gl_Position = vec4(mix(impostorBounds.xy, impostorBounds.zw, corner), 0.0, 1.0);
}
`;

/** Fragment stage; `LIGHT_COUNT_LITERAL` is replaced by the number of lights (`withLightCount`). */
export const impostorFragmentShader = /* glsl */ `
uniform mat4 impostorMvp; // P·V·M
uniform mat4 impostorInverseMvp; // (P·V·M)⁻¹
uniform mat4 impostorModelMatrix;
uniform vec4 impostorViewport; // x, y, width, height in framebuffer pixels
uniform mat3 shadingNormalMatrix; // sign(det)·cof(M)
#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
uniform float logDepthBufFC; // three's 2 / log2(far + 1)
#endif
#if defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0
uniform mat4 modelViewMatrix;
#endif
#ifdef USE_FOG
// three's fog uniforms; the depth is the hit's (a mesh interpolates it from its vertices).
uniform vec3 fogColor;
float vFogDepth;
#ifdef FOG_EXP2
uniform float fogDensity;
#else
uniform float fogNear;
uniform float fogFar;
#endif
#endif
#if NUM_CLIPPING_PLANES > 0
vec3 vClipPosition; // the hit in view space, negated (as three's clipping chunks read it)
uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif
${lightingChunk}
void main() {
  // The pixel's ray between the near and far planes, in model space (perspective and orthographic alike).
  // (P·V·M)⁻¹·(x, y, z, 1) = x·c0 + y·c1 + c3 + z·c2 with c the columns: one shared part, two points, at
  // NDC z = −1 (near) and 1 (far), or, with three's reversed depth (clip z in [0, 1]), z = 1 (near) and 0 (far).
  vec2 ndc = (gl_FragCoord.xy - impostorViewport.xy) / impostorViewport.zw * 2.0 - 1.0;
  vec4 through = impostorInverseMvp[0] * ndc.x + impostorInverseMvp[1] * ndc.y + impostorInverseMvp[3];
#ifdef USE_REVERSED_DEPTH_BUFFER
  vec4 nearH = through + impostorInverseMvp[2];
  vec4 farH = through;
#else
  vec4 nearH = through - impostorInverseMvp[2];
  vec4 farH = through + impostorInverseMvp[2];
#endif
  vec3 o = nearH.xyz / nearH.w;
  // far − near = (farH.xyz·nearH.w − nearH.xyz·farH.w) / (nearH.w·farH.w): nothing is divided by farH.w, about
  // near/far, which rounds to 0 or below at large far/near (the far point at infinity): the direction stays
  // exact and the ray unbounded.
  vec3 d = farH.xyz * nearH.w - nearH.xyz * farH.w;
  float s = nearH.w * farH.w;
  float len = s > 0.0 ? length(d) / s : 1e38;
  d = normalize(d) * sign(nearH.w);
  // Ray Tracing Gems ch. 7: b' = o·d, Δ = 1 − |o − b'd|², q = −b' − sign(b')√Δ, t0 = c/q, t1 = q.
  float b = dot(o, d);
  vec3 f = o - b * d;
  float delta = 1.0 - dot(f, f);
  if (delta < 0.0) discard;
  float c = dot(o, o) - 1.0;
  float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(delta);
  float t0 = q == 0.0 ? 0.0 : min(c / q, q);
  if (t0 < 0.0 || t0 > len) discard; // front surface between the near and far planes only
  vec3 p = o + t0 * d; // model space; the exact normal is p itself
#if defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0
  vec4 mvPosition = modelViewMatrix * vec4( p, 1.0 );
#endif
#if NUM_CLIPPING_PLANES > 0
  vClipPosition = - mvPosition.xyz;
#endif
#ifdef USE_FOG
  vFogDepth = - mvPosition.z;
#endif
${clippingFragment}
  // The exact depth of the hit, in the renderer's depth mode (as three's materials write theirs).
  vec4 clip = impostorMvp * vec4(p, 1.0);
#if defined(USE_REVERSED_DEPTH_BUFFER)
  gl_FragDepth = clamp(clip.z / clip.w, 0.0, 1.0);
#else
  gl_FragDepth = clamp((clip.z / clip.w) * 0.5 + 0.5, 0.0, 1.0);
#endif
#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
  if (!isOrthographic) gl_FragDepth = log2(1.0 + clip.w) * logDepthBufFC * 0.5;
#endif
  vec3 worldPosition = (impostorModelMatrix * vec4(p, 1.0)).xyz;
  gl_FragColor = vec4(shadeColor(worldPosition, shadingNormalMatrix * p), 1.0);
${outputFragment}
}
`;
