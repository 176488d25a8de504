// GLSL of SphereImpostorMaterial: a screen-aligned quad whose fragments ray-cast the unit sphere in model
// space. Composed of ShadingMaterial's chunks: the lighting equation is its `lightingChunk`
// (lightingChunks.glsl.ts), and the hit is clipped, tone-mapped, converted and fogged by the same chunks as a mesh
// (shadingChunks.glsl.ts). These are the material's only shaders (set once; the light count is a define).
import { lightingChunk } from './lightingChunks.glsl.js';
import {
  clippingFragment,
  fogUniforms,
  instanceChunk,
  outputFragment,
  sceneFeatures,
} from './shadingChunks.glsl.js';

/**
 * Vertex stage: the quad's corners (position.xy = ±1) go to the projected ellipsoid's screen bounds. For an
 * `InstancedMesh` (three's USE_INSTANCING), each instance's bounds are computed here from T = P·V·M·I as the
 * CPU computes one object's (`projectedBounds`: the rows scaled so that T's largest element is 1, which leaves
 * the bounds as they are and keeps the products in range), and the fragment stage gets T⁻¹ and M·I per instance.
 * T⁻¹ = diag(1/c)·(T·diag(1/c))⁻¹ with c the columns' largest elements, so that the inverse stays in range
 * for an instance scaled by 1e±20 (whose determinant would overflow or underflow), then scaled so that its w
 * row's largest element is 1 (the ray does not change; the fragment's products of w stay in range). A zero
 * column or determinant, or a non-finite inverse (a zero scale), puts the quad off screen: nothing is drawn,
 * as for one impostor.
 */
export const impostorVertexShader = /* glsl */ `
uniform vec4 impostorBounds; // NDC min x, min y, max x, max y
#ifdef USE_INSTANCING
uniform mat4 impostorMvp;
uniform vec4 impostorViewport;
flat out mat4 vImpostorInverse;
flat out mat4 vImpostorModel;
#ifdef USE_INSTANCING_COLOR
flat out vec3 vImpostorTint;
#endif
float impostorDotD(vec4 a, vec4 b) { return dot(a.xyz, b.xyz) - a.w * b.w; }
vec2 impostorInterval(vec4 r, vec4 r4, float w4) {
  float b = impostorDotD(r, r4);
  float s = sqrt(max(b * b - w4 * impostorDotD(r, r), 0.0));
  vec2 a = vec2(b + s, b - s) / w4;
  return vec2(min(a.x, a.y), max(a.x, a.y));
}
float impostorMax(vec4 v) { v = abs(v); return max(max(v.x, v.y), max(v.z, v.w)); }
#endif
void main() {
  vec2 corner = position.xy * 0.5 + 0.5;
#ifdef USE_INSTANCING
  mat4 t = impostorMvp * instanceMatrix;
  vImpostorModel = modelMatrix * instanceMatrix;
#ifdef USE_INSTANCING_COLOR
  vImpostorTint = instanceColor;
#endif
  vec4 c = vec4(impostorMax(t[0]), impostorMax(t[1]), impostorMax(t[2]), impostorMax(t[3]));
  mat4 n = mat4(t[0] / c.x, t[1] / c.y, t[2] / c.z, t[3] / c.w);
  mat4 inv = inverse(n);
  vec4 k = 1.0 / c;
  float w = impostorMax(vec4(inv[0].w, inv[1].w, inv[2].w, inv[3].w) * k.w);
  k /= w > 0.0 ? w : 1.0;
  vImpostorInverse = mat4(inv[0] * k, inv[1] * k, inv[2] * k, inv[3] * k);
  float sum = dot(vec4(1.0), vImpostorInverse * vec4(1.0));
  vec4 bounds = vec4(2.0);
  if (all(greaterThan(c, vec4(0.0))) && abs(determinant(n)) > 0.0 && !isinf(sum) && !isnan(sum)) {
    float m = max(max(c.x, c.y), max(c.z, c.w));
    vec4 r4 = vec4(t[0].w, t[1].w, t[2].w, t[3].w) / m;
    float w4 = impostorDotD(r4, r4);
    bounds = vec4(-1.0, -1.0, 1.0, 1.0);
    if (w4 < 0.0 && r4.w > 0.0) {
      vec2 x = impostorInterval(vec4(t[0].x, t[1].x, t[2].x, t[3].x) / m, r4, w4);
      vec2 y = impostorInterval(vec4(t[0].y, t[1].y, t[2].y, t[3].y) / m, r4, w4);
      vec4 b = vec4(x.x, y.x, x.y, y.y) + vec4(-2.0, -2.0, 2.0, 2.0) / impostorViewport.zwzw;
      if (!any(isinf(b)) && !any(isnan(b))) bounds = clamp(b, -1.0, 1.0);
    }
  }
  gl_Position = vec4(mix(bounds.xy, bounds.zw, corner), 0.0, 1.0);
#else
  gl_Position = vec4(mix(impostorBounds.xy, impostorBounds.zw, corner), 0.0, 1.0);
#endif
}
`;

/**
 * Fragment stage (NUM_LIGHTS PhongLights, a define as in ShadingMaterial). three defines
 * USE_INSTANCING in the vertex stage only: `SphereImpostorMaterial.onBeforeCompile` defines IMPOSTOR_INSTANCED
 * (and IMPOSTOR_INSTANCED_COLOR) here for an instanced program, which takes the instance's matrices from the
 * vertex stage under the names of one impostor's uniforms (T⁻¹, M·I, P·V·M·I, the normal matrix
 * sign(det)·cof(M·I) made by `shadingCofactor`) and its colour as the tint (× ka and kd); the same ray casting
 * follows, with the ray direction d and the product s of the w's rescaled together (neither the length nor
 * the direction changes) so that |d|² stays in range for an instance scaled by 1e±20.
 */
export const impostorFragmentShader = /* glsl */ `
${sceneFeatures}
#ifdef IMPOSTOR_INSTANCED
flat in mat4 vImpostorInverse;
flat in mat4 vImpostorModel;
#ifdef IMPOSTOR_INSTANCED_COLOR
flat in vec3 vImpostorTint;
#endif
uniform mat4 impostorViewProjection;
#ifndef SHADING_INSTANCE
#define SHADING_INSTANCE
#endif
${instanceChunk}
#else
uniform mat4 impostorMvp; // P·V·M
uniform mat4 impostorInverseMvp; // (P·V·M)⁻¹
uniform mat4 impostorModelMatrix;
#endif
uniform vec4 impostorViewport; // x, y, width, height in framebuffer pixels
#ifndef IMPOSTOR_INSTANCED
uniform mat3 shadingNormalMatrix; // sign(det)·cof(M)
#endif
#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
uniform float logDepthBufFC; // three's 2 / log2(far + 1)
#endif
#if ( defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0 ) && ! defined( IMPOSTOR_INSTANCED )
uniform mat4 modelViewMatrix;
#endif
#ifdef USE_FOG
// three's fog uniforms; the depth is the hit's (a mesh interpolates it from its vertices).
float vFogDepth;
${fogUniforms}
#endif
#if NUM_CLIPPING_PLANES > 0
vec3 vClipPosition; // the hit in view space, negated (as three's clipping chunks read it)
uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif
${lightingChunk}
void main() {
#ifdef IMPOSTOR_INSTANCED
  mat4 impostorInverseMvp = vImpostorInverse;
  mat4 impostorModelMatrix = vImpostorModel;
  mat4 impostorMvp = impostorViewProjection * vImpostorModel;
  mat3 shadingNormalMatrix = shadingCofactor( mat3( vImpostorModel ) );
#if defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0
  mat4 modelViewMatrix = viewMatrix * vImpostorModel;
#endif
#ifdef IMPOSTOR_INSTANCED_COLOR
  shadingTint = vImpostorTint;
#endif
#endif
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
#ifdef IMPOSTOR_INSTANCED
  float dScale = max(max(abs(d.x), abs(d.y)), abs(d.z));
  dScale = dScale > 0.0 ? dScale : 1.0;
  d /= dScale;
  float s = nearH.w * (farH.w / dScale);
#else
  float s = nearH.w * farH.w;
#endif
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
