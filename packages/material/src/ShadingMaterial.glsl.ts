// GLSL of ShadingMaterial. Variants are chosen with defines (see ShadingMaterial.defines):
//   SHADING_FLAT | SHADING_GOURAUD | SHADING_PHONG  where the lighting is evaluated
//   LIGHTING_BLINN                                 Blinn-Phong specular (else Phong)
//   CEL_BANDS n                                    0 = off, n ≥ 2 = cel shading with n diffuse shades
//   NUM_LIGHTS n                                   number of PhongLights
//   USE_ATTENUATION                                some light has b or c ≠ 0 or a ≠ 1
//   SPHERE_NORMALS                                 object normal = position (no normal attribute)
//   FLAT_CORNERS                                   flat shading of a flatShadingGeometry (indexed, per-vertex face)
//   FLAT_DERIVATIVES                               flat shading of a plain indexed geometry: per-fragment lighting
//                                                  with the face normal from screen-space derivatives
//   SHADING_EMISSIVE                               emissive ≠ black (added after the lighting)
// three's DOUBLE_SIDED / FLIP_SIDED (side): a back face is lit with its flipped normal (gl_FrontFacing).
// and by three's program parameters (USE_INSTANCING, USE_SKINNING, USE_FOG, NUM_CLIPPING_PLANES, …: see
// shadingChunks.glsl.ts). Everything is in world space. The rules for degenerate inputs match `shade()` in
// shade.ts exactly. The shaders are lists of chunks: the lecture's equation and stages from shadingChunks,
// the standard parts from three's.
import {
  clippingFragment,
  emissiveFragment,
  flatDeformVertex,
  instanceChunk,
  instanceVertex,
  lightingChunk as lighting,
  normalMapFragment,
  outputFragment,
  projectVertex,
  sceneFeatures,
  surfaceFragment,
  surfaceFragmentPars,
  surfaceVertexPars,
} from './shadingChunks.glsl.js';
import {
  shadowFeatures,
  shadowFragmentPars,
  shadowTermsCopy,
  shadowTermsFragment,
  shadowVertex,
  shadowVertexPars,
} from './shadowChunks.glsl.js';

// Shadows of three's lights (shadowChunks.glsl.ts): applied in the light loop where the lighting is per fragment,
// recorded per light where it is per vertex or face, and then shadowed per fragment.
const shadowStages = /* glsl */ `
${shadowFeatures}
#ifdef SHADING_SHADOWS
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
${surfaceVertexPars}
uniform mat3 shadingNormalMatrix; // sign(det)·cof(modelMatrix), see computeNormalMatrix
${instanceChunk}
${shadowStages}
${shadowVertexPars}

#if defined(SHADING_FLAT) && !defined(FLAT_DERIVATIVES)
flat out vec3 vColor;
#ifdef DOUBLE_SIDED
flat out vec3 vColorBack; // the back face's colour, lit with the flipped normal
#endif
#ifdef SHADING_SPLIT
flat out vec3 vSpecular; // the ks part (vColor is then the ka/kd part, multiplied by the texel per fragment)
#ifdef DOUBLE_SIDED
flat out vec3 vSpecularBack;
#endif
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
#ifdef SHADING_SPLIT
out vec3 vSpecular;
#ifdef DOUBLE_SIDED
out vec3 vSpecularBack;
#endif
#endif
#else
out vec3 vWorldPosition;
#ifndef FLAT_DERIVATIVES
out vec3 vNormal;
#endif
#ifdef SHADING_TINT
out vec3 vShadingTint;
#endif
#endif

#if !defined(SHADING_PHONG) && !defined(FLAT_DERIVATIVES)
${lighting}
#endif

void main() {
${projectVertex}
  // three's logarithmic depth buffer (when the renderer has one), like its own materials.
  #include <logdepthbuf_vertex>
${instanceVertex}
  #include <uv_vertex>
#ifdef USE_COLOR_ALPHA
  vShadingAlpha = color.a;
#endif
#if defined(SHADING_TINT) && ( defined(SHADING_PHONG) || defined(FLAT_DERIVATIVES) )
  vShadingTint = tint;
#elif defined(SHADING_TINT)
  shadingTint = tint;
#endif
#if defined(SHADING_FLAT) && !defined(FLAT_DERIVATIVES)
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
#ifdef SHADING_SPLIT
  vec3 backSpecular = shadingSpecular;
#endif
#ifdef DOUBLE_SIDED
${shadowTermsCopy('Back')}
  vColor = shadeColor(faceCentre, shadingNormalMatrix * faceNormal);
${shadowTermsCopy('')}
  vColorBack = backColor;
#ifdef SHADING_SPLIT
  vSpecular = shadingSpecular;
  vSpecularBack = backSpecular;
#endif
#else
  vColor = backColor;
${shadowTermsCopy('')}
#ifdef SHADING_SPLIT
  vSpecular = backSpecular;
#endif
#endif
#else
  vColor = shadeColor(faceCentre, shadingNormalMatrix * faceNormal);
${shadowTermsCopy('')}
#ifdef SHADING_SPLIT
  vSpecular = shadingSpecular;
#endif
#endif
#else
#ifndef FLAT_DERIVATIVES
#ifdef SPHERE_NORMALS
  vec3 objectNormal = position;
#else
  vec3 objectNormal = normal;
#endif
#endif
#ifdef SHADING_SCENE
#ifndef FLAT_DERIVATIVES
  #include <morphnormal_vertex>
  #include <skinnormal_vertex>
#endif
  vec4 shadingLocal = vec4( transformed, 1.0 );
#ifdef SHADING_INSTANCE
  shadingLocal = shadingInstance * shadingLocal;
#ifndef FLAT_DERIVATIVES
  objectNormal = shadingRescale( shadingInstanceNormal * objectNormal );
#endif
#endif
  vec3 worldPosition = ( modelMatrix * shadingLocal ).xyz;
#else
  vec3 worldPosition = (modelMatrix * vec4(position, 1.0)).xyz;
#endif
#ifndef FLAT_DERIVATIVES
  vec3 worldNormal = shadingNormalMatrix * objectNormal;
#endif
#if defined(SHADING_GOURAUD) && ( defined( DOUBLE_SIDED ) || defined( FLIP_SIDED ) )
  vec3 backColor = shadeColor(worldPosition, -worldNormal);
#ifdef SHADING_SPLIT
  vec3 backSpecular = shadingSpecular;
#endif
#ifdef DOUBLE_SIDED
${shadowTermsCopy('Back')}
  vColor = shadeColor(worldPosition, worldNormal);
${shadowTermsCopy('')}
  vColorBack = backColor;
#ifdef SHADING_SPLIT
  vSpecular = shadingSpecular;
  vSpecularBack = backSpecular;
#endif
#else
  vColor = backColor;
${shadowTermsCopy('')}
#ifdef SHADING_SPLIT
  vSpecular = backSpecular;
#endif
#endif
#elif defined(SHADING_GOURAUD)
  vColor = shadeColor(worldPosition, worldNormal);
${shadowTermsCopy('')}
#ifdef SHADING_SPLIT
  vSpecular = shadingSpecular;
#endif
#elif defined( SHADING_VIEW_SPACE )
  // Lit in view space, where three's light uniforms are (the view matrix is rigid: see ShadingMaterial).
#ifndef FLAT_DERIVATIVES
  vec3 viewNormal = mat3( viewMatrix ) * worldNormal;
  float normalLength = length(viewNormal);
  vNormal = normalLength > 0.0 ? viewNormal / normalLength : vec3(0.0);
#endif
  vWorldPosition = ( viewMatrix * vec4( worldPosition, 1.0 ) ).xyz;
#else
#ifndef FLAT_DERIVATIVES
  float normalLength = length(worldNormal);
  vNormal = normalLength > 0.0 ? worldNormal / normalLength : vec3(0.0);
#endif
  vWorldPosition = worldPosition;
#endif
#endif
#ifdef SHADING_SHADOWS
#if defined( SHADING_FLAT ) && ! defined( FLAT_DERIVATIVES )
#define SHADING_SHADOW_NORMAL ( shadingNormalMatrix * faceNormal )
#elif defined( FLAT_DERIVATIVES )
#undef HAS_NORMAL // no vertex normal: three's normalBias is not applied
#define SHADING_SHADOW_NORMAL vec3( 0.0 )
#else
#define SHADING_SHADOW_NORMAL worldNormal
#endif
#endif
${shadowVertex}
}
`;

/** Fragment stage; `LIGHT_COUNT_LITERAL` is replaced by the number of lights. */
export const fragmentShader = /* glsl */ `
#include <logdepthbuf_pars_fragment>
#include <fog_pars_fragment>
#include <clipping_planes_pars_fragment>
${sceneFeatures}
${surfaceFragmentPars}
${shadowStages}
${shadowFragmentPars}
#if defined(SHADING_FLAT) && !defined(FLAT_DERIVATIVES)
flat in vec3 vColor;
#ifdef DOUBLE_SIDED
flat in vec3 vColorBack;
#endif
#ifdef SHADING_SPLIT
flat in vec3 vSpecular;
#ifdef DOUBLE_SIDED
flat in vec3 vSpecularBack;
#endif
#endif
#elif defined(SHADING_GOURAUD)
in vec3 vColor;
#ifdef DOUBLE_SIDED
in vec3 vColorBack;
#endif
#ifdef SHADING_SPLIT
in vec3 vSpecular;
#ifdef DOUBLE_SIDED
in vec3 vSpecularBack;
#endif
#endif
#else
in vec3 vWorldPosition;
#ifdef FLAT_DERIVATIVES
vec3 vNormal; // the face's outward normal, from the derivatives (set in main; not a varying here)
#else
in vec3 vNormal;
#endif
#ifdef SHADING_TINT
in vec3 vShadingTint;
#endif
${lighting}
#endif

void main() {
  #include <logdepthbuf_fragment>
${clippingFragment}
${surfaceFragment}
#if defined(SHADING_PHONG) || defined(FLAT_DERIVATIVES)
#ifdef SHADING_TINT
  shadingTint = vShadingTint;
#endif
#ifdef USE_MAP
  shadingTint *= diffuseColor.rgb; // the texel multiplies ka and kd, not ks
#endif
#ifdef FLAT_DERIVATIVES
  // The plane of the fragment's triangle: cross(dFdx p, dFdy p) faces the viewer (each rescaled so the cross
  // product neither overflows nor underflows); outward is that for a front face of the geometry, its opposite
  // for a back face.
  vec3 fdx = dFdx( vWorldPosition );
  vec3 fdy = dFdy( vWorldPosition );
  fdx /= max( max( max( abs( fdx.x ), abs( fdx.y ) ), abs( fdx.z ) ), 1e-30 );
  fdy /= max( max( max( abs( fdy.x ), abs( fdy.y ) ), abs( fdy.z ) ), 1e-30 );
  vNormal = cross( fdx, fdy );
#ifdef FLIP_SIDED
  vNormal = gl_FrontFacing ? - vNormal : vNormal; // BackSide: three turns the front face round
#else
  vNormal = gl_FrontFacing ? vNormal : - vNormal;
#endif
#endif
#if defined( SHADING_NORMALMAP )
${normalMapFragment}
#elif defined( DOUBLE_SIDED )
  vec3 color = shadeColor(vWorldPosition, gl_FrontFacing ? vNormal : -vNormal);
#elif defined( FLIP_SIDED )
  vec3 color = shadeColor(vWorldPosition, -vNormal);
#else
  vec3 color = shadeColor(vWorldPosition, vNormal);
#endif
#elif defined( DOUBLE_SIDED )
  vec3 color = gl_FrontFacing ? vColor : vColorBack;
#ifdef SHADING_SPLIT
  color = color * diffuseColor.rgb + ( gl_FrontFacing ? vSpecular : vSpecularBack );
#endif
#else
  vec3 color = vColor;
#ifdef SHADING_SPLIT
  color = color * diffuseColor.rgb + vSpecular;
#endif
#endif
${shadowTermsFragment}
${emissiveFragment}
#if defined( SHADING_SURFACE ) && ! defined( OPAQUE )
  gl_FragColor = vec4(color, diffuseColor.a);
#else
  gl_FragColor = vec4(color, 1.0);
#endif
${outputFragment}
  #include <premultiplied_alpha_fragment>
}
`;

/** `source` with its light loop bound set to `count`, so that three unrolls the loop. */
export function withLightCount(source: string, count: number): string {
  return source.replace(/LIGHT_COUNT_LITERAL/g, String(count));
}
