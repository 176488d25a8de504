// GLSL of SphereImpostorMaterial: a screen-aligned quad whose fragments ray-cast the unit sphere in model
// space. The lighting equation is ShadingMaterial's own (the same chunk, not a copy): see `lightingChunk`.
import { fragmentShader as shadingFragmentShader } from './ShadingMaterial.glsl.js';

const BEFORE = 'in vec3 vNormal;\n';
const AFTER = '#endif\n\nvoid main()';

/**
 * The lighting chunk (uniforms, `lightTerm`, `shadeColor`) of ShadingMaterial's fragment shader, which it
 * includes in its per-fragment (phong) variant between the `vNormal` input and `main`.
 * @throws Error when ShadingMaterial's shader no longer has that layout (caught by the tests).
 */
export function lightingChunk(source: string): string {
  const start = source.indexOf(BEFORE);
  const end = source.indexOf(AFTER, start);
  if (start < 0 || end < 0) {
    throw new Error(
      'SphereImpostorMaterial: cannot find the lighting chunk in ShadingMaterial.glsl fragmentShader',
    );
  }
  return source.slice(start + BEFORE.length, end);
}

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
${/* @__PURE__ */ lightingChunk(shadingFragmentShader)}
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
  #include <colorspace_fragment>
}
`;
