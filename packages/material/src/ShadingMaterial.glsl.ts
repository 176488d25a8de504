// GLSL of ShadingMaterial. Variants are chosen with defines (see ShadingMaterial.defines):
//   SHADING_FLAT | SHADING_GOURAUD | SHADING_PHONG  where the lighting is evaluated
//   LIGHTING_BLINN                                 Blinn-Phong specular (else Phong)
//   CEL_BANDS n                                    0 = off, n ≥ 2 = cel shading with n diffuse shades
//   NUM_LIGHTS n                                   number of PhongLights
//   USE_ATTENUATION                                some light has b or c ≠ 0 or a ≠ 1
//   SPHERE_NORMALS                                 object normal = position (no normal attribute)
//   FLAT_CORNERS                                   flat shading of a flatShadingGeometry (indexed, per-vertex face)
// three's DOUBLE_SIDED / FLIP_SIDED (side): a back face is lit with its flipped normal (gl_FrontFacing).
// and by three's program parameters (USE_INSTANCING, USE_SKINNING, USE_FOG, NUM_CLIPPING_PLANES, …: see
// shadingChunks.glsl.ts). Everything is in world space. The rules for degenerate inputs match `shade()` in
// shade.ts exactly. The shaders are lists of chunks: the lecture's equation and stages from shadingChunks,
// the standard parts from three's.
import {
  clippingFragment,
  flatDeformVertex,
  instanceChunk,
  instanceVertex,
  lightingChunk as lighting,
  outputFragment,
  projectVertex,
  sceneFeatures,
} from './shadingChunks.glsl.js';

/** Vertex stage; `LIGHT_COUNT_LITERAL` is replaced by the number of lights (see {@link withLightCount}). */
export const vertexShader = /* glsl */ `
#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
${sceneFeatures}
uniform mat3 shadingNormalMatrix; // sign(det)·cof(modelMatrix), see computeNormalMatrix
${instanceChunk}

#if defined(SHADING_FLAT)
flat out vec3 vColor;
#ifdef DOUBLE_SIDED
flat out vec3 vColorBack; // the back face's colour, lit with the flipped normal
#endif
#ifdef FLAT_CORNERS
// flatShadingGeometry: this vertex provokes one face; these are its other two corners (object space).
in vec3 flatCornerA;
in vec3 flatCornerB;
#ifdef SHADING_DEFORM
in vec2 flatCornerIndex; // the vertex indices of flatCornerA and flatCornerB (for morph targets and skinning)
#endif
#else
uniform highp sampler2D facePositions; // object-space positions of the non-indexed geometry, one texel each
vec3 fetchPosition(int i) {
  int width = textureSize(facePositions, 0).x;
  return texelFetch(facePositions, ivec2(i % width, i / width), 0).xyz;
}
#endif
#ifdef USE_SKINNING
uniform highp sampler2D faceSkin; // per vertex: skinIndex, skinWeight (two texels)
#endif
#elif defined(SHADING_GOURAUD)
out vec3 vColor;
#ifdef DOUBLE_SIDED
out vec3 vColorBack;
#endif
#else
out vec3 vWorldPosition;
out vec3 vNormal;
#ifdef SHADING_TINT
out vec3 vShadingTint;
#endif
#endif

#if !defined(SHADING_PHONG)
${lighting}
#endif

void main() {
${projectVertex}
  // three's logarithmic depth buffer (when the renderer has one), like its own materials.
  #include <logdepthbuf_vertex>
${instanceVertex}
#if defined(SHADING_TINT) && defined(SHADING_PHONG)
  vShadingTint = tint;
#elif defined(SHADING_TINT)
  shadingTint = tint;
#endif
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
#ifdef SHADING_DEFORM
#ifdef FLAT_CORNERS
  ivec3 cornerIndex = ivec3( int( flatCornerIndex.x ), int( flatCornerIndex.y ), gl_VertexID );
#else
  ivec3 cornerIndex = ivec3( first, first + 1, first + 2 );
#endif
#endif
${flatDeformVertex}
#ifdef SHADING_INSTANCE
  vec3 faceCentre = (modelMatrix * (shadingInstance * vec4((p0 + p1 + p2) / 3.0, 1.0))).xyz;
#else
  vec3 faceCentre = (modelMatrix * vec4((p0 + p1 + p2) / 3.0, 1.0)).xyz;
#endif
  vec3 faceNormal = cross(p1 - p0, p2 - p0);
  float m = max(max(abs(faceNormal.x), abs(faceNormal.y)), abs(faceNormal.z));
  faceNormal = m > 0.0 ? faceNormal / m : vec3(0.0); // rescaled so it neither overflows nor underflows
#ifdef SHADING_INSTANCE
  faceNormal = shadingRescale( shadingInstanceNormal * faceNormal );
#endif
#if defined( DOUBLE_SIDED ) || defined( FLIP_SIDED )
  // three's sides: a back face is lit with its flipped normal (both colours when both sides are drawn).
  vec3 backColor = shadeColor(faceCentre, -(shadingNormalMatrix * faceNormal));
#ifdef DOUBLE_SIDED
  vColor = shadeColor(faceCentre, shadingNormalMatrix * faceNormal);
  vColorBack = backColor;
#else
  vColor = backColor;
#endif
#else
  vColor = shadeColor(faceCentre, shadingNormalMatrix * faceNormal);
#endif
#else
#ifdef SPHERE_NORMALS
  vec3 objectNormal = position;
#else
  vec3 objectNormal = normal;
#endif
#ifdef SHADING_SCENE
  #include <morphnormal_vertex>
  #include <skinnormal_vertex>
  vec4 shadingLocal = vec4( transformed, 1.0 );
#ifdef SHADING_INSTANCE
  shadingLocal = shadingInstance * shadingLocal;
  objectNormal = shadingRescale( shadingInstanceNormal * objectNormal );
#endif
  vec3 worldPosition = ( modelMatrix * shadingLocal ).xyz;
#else
  vec3 worldPosition = (modelMatrix * vec4(position, 1.0)).xyz;
#endif
  vec3 worldNormal = shadingNormalMatrix * objectNormal;
#if defined(SHADING_GOURAUD) && ( defined( DOUBLE_SIDED ) || defined( FLIP_SIDED ) )
  vec3 backColor = shadeColor(worldPosition, -worldNormal);
#ifdef DOUBLE_SIDED
  vColor = shadeColor(worldPosition, worldNormal);
  vColorBack = backColor;
#else
  vColor = backColor;
#endif
#elif defined(SHADING_GOURAUD)
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
#include <fog_pars_fragment>
#include <clipping_planes_pars_fragment>
${sceneFeatures}
#if defined(SHADING_FLAT)
flat in vec3 vColor;
#ifdef DOUBLE_SIDED
flat in vec3 vColorBack;
#endif
#elif defined(SHADING_GOURAUD)
in vec3 vColor;
#ifdef DOUBLE_SIDED
in vec3 vColorBack;
#endif
#else
in vec3 vWorldPosition;
in vec3 vNormal;
#ifdef SHADING_TINT
in vec3 vShadingTint;
#endif
${lighting}
#endif

void main() {
  #include <logdepthbuf_fragment>
${clippingFragment}
#if defined(SHADING_PHONG)
#ifdef SHADING_TINT
  shadingTint = vShadingTint;
#endif
#if defined( DOUBLE_SIDED )
  vec3 color = shadeColor(vWorldPosition, gl_FrontFacing ? vNormal : -vNormal);
#elif defined( FLIP_SIDED )
  vec3 color = shadeColor(vWorldPosition, -vNormal);
#else
  vec3 color = shadeColor(vWorldPosition, vNormal);
#endif
#elif defined( DOUBLE_SIDED )
  vec3 color = gl_FrontFacing ? vColor : vColorBack;
#else
  vec3 color = vColor;
#endif
  gl_FragColor = vec4(color, 1.0);
${outputFragment}
}
`;

/** `source` with its light loop bound set to `count`, so that three unrolls the loop. */
export function withLightCount(source: string, count: number): string {
  return source.replace(/LIGHT_COUNT_LITERAL/g, String(count));
}
