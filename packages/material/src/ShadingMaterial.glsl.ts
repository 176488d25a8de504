// GLSL of ShadingMaterial. Variants are chosen with defines (see ShadingMaterial.defines):
//   SHADING_FLAT | SHADING_GOURAUD | SHADING_PHONG  where the lighting is evaluated
//   LIGHTING_BLINN                                 Blinn-Phong specular (else Phong)
//   CEL_BANDS n                                    0 = off, n ≥ 2 = cel shading with n diffuse shades
//   NUM_LIGHTS n                                   number of PhongLights
//   USE_ATTENUATION                                some light has b or c ≠ 0 or a ≠ 1
//   SPHERE_NORMALS                                 object normal = position (no normal attribute)
//   FLAT_CORNERS                                   flat shading of a flatShadingGeometry (indexed, per-vertex face)
// Everything is in world space. The rules for degenerate inputs match `shade()` in shade.ts exactly.

/** The lighting equation, shared by the vertex (flat, gouraud) and fragment (phong) stages. */
const lighting = /* glsl */ `
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
  return diffuse * kdId + spec * ksIs;
}

vec3 shadeColor(vec3 p, vec3 normal) {
  vec3 toEye = shadingEye.xyz - p * shadingEye.w;
  float e2 = dot(toEye, toEye);
  vec3 v = e2 > 0.0 ? toEye * inversesqrt(e2) : vec3(0.0, 0.0, 1.0);
  float n2 = dot(normal, normal);
  vec3 n = n2 > 0.0 ? normal * inversesqrt(n2) : v;
  v = e2 > 0.0 ? v : n;
  vec3 color = ambientTerm;
#if NUM_LIGHTS > 0
  // Unrolled by three (LIGHT_COUNT_LITERAL is replaced by the number of lights before compiling).
  #pragma unroll_loop_start
  for ( int i = 0; i < LIGHT_COUNT_LITERAL; i ++ ) {
    color += lightTerm(p, n, v, lightPosition[ i ], lightDiffuse[ i ], lightSpecular[ i ], LIGHT_ATTENUATION(UNROLLED_LOOP_INDEX));
  }
  #pragma unroll_loop_end
#endif
  return color;
}
`;

/** Vertex stage; `LIGHT_COUNT_LITERAL` is replaced by the number of lights (see {@link withLightCount}). */
export const vertexShader = /* glsl */ `
#include <common>
#include <logdepthbuf_pars_vertex>
uniform mat3 shadingNormalMatrix; // sign(det)·cof(modelMatrix), see computeNormalMatrix

#if defined(SHADING_FLAT)
flat out vec3 vColor;
#ifdef FLAT_CORNERS
// flatShadingGeometry: this vertex provokes one face; these are its other two corners (object space).
in vec3 flatCornerA;
in vec3 flatCornerB;
#else
uniform highp sampler2D facePositions; // object-space positions of the non-indexed geometry, one texel each
vec3 fetchPosition(int i) {
  int width = textureSize(facePositions, 0).x;
  return texelFetch(facePositions, ivec2(i % width, i / width), 0).xyz;
}
#endif
#elif defined(SHADING_GOURAUD)
out vec3 vColor;
#else
out vec3 vWorldPosition;
out vec3 vNormal;
#endif

#if !defined(SHADING_PHONG)
${lighting}
#endif

void main() {
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
  // three's logarithmic depth buffer (when the renderer has one), like its own materials.
  #include <logdepthbuf_vertex>
#if defined(SHADING_FLAT)
  // Once per face: at the centroid of the triangle this vertex belongs to (or provokes), with the face normal.
#ifdef FLAT_CORNERS
  vec3 p0 = flatCornerA;
  vec3 p1 = flatCornerB;
  vec3 p2 = position;
#else
  int first = gl_VertexID - gl_VertexID % 3;
  vec3 p0 = fetchPosition(first);
  vec3 p1 = fetchPosition(first + 1);
  vec3 p2 = fetchPosition(first + 2);
#endif
  vec3 faceCentre = (modelMatrix * vec4((p0 + p1 + p2) / 3.0, 1.0)).xyz;
  vec3 faceNormal = cross(p1 - p0, p2 - p0);
  float m = max(max(abs(faceNormal.x), abs(faceNormal.y)), abs(faceNormal.z));
  faceNormal = m > 0.0 ? faceNormal / m : vec3(0.0); // rescaled so it neither overflows nor underflows
  vColor = shadeColor(faceCentre, shadingNormalMatrix * faceNormal);
#else
#ifdef SPHERE_NORMALS
  vec3 objectNormal = position;
#else
  vec3 objectNormal = normal;
#endif
  vec3 worldPosition = (modelMatrix * vec4(position, 1.0)).xyz;
  vec3 worldNormal = shadingNormalMatrix * objectNormal;
#if defined(SHADING_GOURAUD)
  vColor = shadeColor(worldPosition, worldNormal);
#else
  float normalLength = length(worldNormal);
  vNormal = normalLength > 0.0 ? worldNormal / normalLength : vec3(0.0);
  vWorldPosition = worldPosition;
#endif
#endif
}
`;

/** Fragment stage; `LIGHT_COUNT_LITERAL` is replaced by the number of lights. */
export const fragmentShader = /* glsl */ `
#include <logdepthbuf_pars_fragment>
#if defined(SHADING_FLAT)
flat in vec3 vColor;
#elif defined(SHADING_GOURAUD)
in vec3 vColor;
#else
in vec3 vWorldPosition;
in vec3 vNormal;
${lighting}
#endif

void main() {
  #include <logdepthbuf_fragment>
#if defined(SHADING_PHONG)
  vec3 color = shadeColor(vWorldPosition, vNormal);
#else
  vec3 color = vColor;
#endif
  gl_FragColor = vec4(color, 1.0);
  #include <colorspace_fragment>
}
`;

/** `source` with its light loop bound set to `count`, so that three unrolls the loop. */
export function withLightCount(source: string, count: number): string {
  return source.replace(/LIGHT_COUNT_LITERAL/g, String(count));
}
