// GLSL of ShadingMaterial, as three's meshphong.glsl.js: a list of chunks, three's (`#include <…>`) and the
// lecture's (`${include.…}`: shadingChunks, lightingChunks and shadowChunks, composed here as strings; see
// `include` below). Variants are chosen with defines (see ShadingMaterial.defines):
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
//   SHADING_OUTPUT_<NAME>, SHADING_OUTPUT_TERM, …  output ≠ 'color': one term, the attenuation or the normal
//                                                  (see outputChunks.glsl.ts)
//   SHADING_MODEL_NORMALS                          normalMatrix 'model': normals × M, the lecture's wrong way
//   SHADING_INSTANCE_ORTHOGONAL                    every instance matrix is a rotation × a scale (orthogonalInstances.ts)
//   SHADING_THREE_LIGHTS (SHADING_LIGHT_CUTOFF, SHADING_INVERSE_SQUARE, SHADING_VIEW_SPACE)  three's lights
// three's DOUBLE_SIDED / FLIP_SIDED (side): a back face is lit with its flipped normal (gl_FrontFacing).
// and by three's program parameters (USE_INSTANCING, USE_SKINNING, USE_FOG, NUM_CLIPPING_PLANES, …: see
// shadingChunks.glsl.ts). Everything is in world space. The rules for degenerate inputs match `shade()` in
// shade.ts exactly.
//
// The chunks are strings composed in JavaScript, not registered in three's global THREE.ShaderChunk: the package
// has no side effects on import (it tree-shakes, and nothing is written into three's globals), and two copies of
// it in one app (two versions, one three) never compile one another's chunks under a shared `shadelab_` name.
import * as lighting from './lightingChunks.glsl.js';
import * as output from './outputChunks.glsl.js';
import * as shading from './shadingChunks.glsl.js';
import * as shadows from './shadowChunks.glsl.js';

/** The chunks by name (what `#include <name>` is to three's ShaderChunk). */
const include = { ...lighting, ...output, ...shading, ...shadows };

/** Vertex stage. */
export const vertexShader = /* glsl */ `
#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
${include.sceneFeatures}
${include.surfaceVertexPars}
uniform mat3 shadingNormalMatrix; // sign(det)·cof(modelMatrix), see computeNormalMatrix
${include.modelNormalsVertex}
${include.instanceChunk}
${include.shadowFeatures}
${include.shadowVertexPars}
${include.shadingVaryings('out')}
${include.flatParsVertex}
#if !defined(SHADING_PHONG) && !defined(FLAT_DERIVATIVES)
${include.lightingChunk}
#endif

void main() {
${include.projectVertex}
  // three's logarithmic depth buffer (when the renderer has one), like its own materials.
  #include <logdepthbuf_vertex>
${include.instanceVertex}
  #include <uv_vertex>
${include.surfaceVertex}
#if defined(SHADING_FLAT) && !defined(FLAT_DERIVATIVES)
  // Once per face: at the centroid of the triangle this vertex belongs to (or provokes), with the face normal.
${include.flatFaceVertex}
${include.litSidesVertex('faceCentre', 'shadingNormalMatrix * faceNormal')}
#else
${include.worldVertex}
#if defined(SHADING_GOURAUD)
${include.litSidesVertex('worldPosition', 'worldNormal')}
#else
${include.phongVertex}
#endif
#endif
${include.shadowVertex}
}
`;

/** Fragment stage. */
export const fragmentShader = /* glsl */ `
#include <logdepthbuf_pars_fragment>
${include.fogParsFragment}
#include <clipping_planes_pars_fragment>
${include.sceneFeatures}
${include.surfaceFragmentPars}
${include.shadowFeatures}
${include.shadowFragmentPars}
${include.shadingVaryings('in')}
#ifdef FLAT_DERIVATIVES
vec3 vNormal; // the face's outward normal, from the derivatives (set in main; not a varying here)
#endif
#if defined(SHADING_PHONG) || defined(FLAT_DERIVATIVES)
${include.lightingChunk}
#endif

void main() {
  #include <logdepthbuf_fragment>
${include.clippingFragment}
${include.surfaceFragment}
#if defined(SHADING_PHONG) || defined(FLAT_DERIVATIVES)
${include.litFragment}
#else
${include.vertexLitFragment}
#endif
${include.shadowTermsFragment}
${include.emissiveFragment}
#if defined( SHADING_SURFACE ) && ! defined( OPAQUE )
  gl_FragColor = vec4(color, diffuseColor.a);
#else
  gl_FragColor = vec4(color, 1.0);
#endif
${include.outputFragment}
  #include <premultiplied_alpha_fragment>
}
`;
