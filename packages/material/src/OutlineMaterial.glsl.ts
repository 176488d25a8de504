// GLSL of OutlineMaterial: the inverted hull. Back faces of the mesh, pushed out along the world normal;
// moved by three's instancing, morph target and skinning chunks (compiled only when the outlined object uses
// them), clipped, tone-mapped and fogged by three's chunks like the mesh it outlines (shadingChunks.glsl.ts).
import { clippingFragment, instanceChunk, outputFragment, sceneFeatures } from './shadingChunks.glsl.js';

/**
 * Vertex stage: world position + thickness · unit world normal, both of the deformed (morph targets, then
 * skinning, as three's chunks move a vertex) and instanced vertex: the instance's normal matrix is made as
 * ShadingMaterial makes it (`shadingCofactor`), so the hull is pushed out along the normal ShadingMaterial lights.
 */
export const vertexShader = /* glsl */ `
#include <common>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
${sceneFeatures}
#if defined( USE_INSTANCING ) || defined( USE_SKINNING ) || defined( USE_MORPHTARGETS )
#define OUTLINE_MOVED
#endif
uniform mat3 shadingNormalMatrix;
uniform float thickness;
${instanceChunk}

void main() {
#ifdef SPHERE_NORMALS
  vec3 objectNormal = position;
#else
  vec3 objectNormal = normal;
#endif
#ifdef OUTLINE_MOVED
  #include <morphinstance_vertex>
  #include <skinbase_vertex>
  vec3 transformed = vec3( position );
  #include <morphtarget_vertex>
  #include <skinning_vertex>
  #include <morphnormal_vertex>
  #include <skinnormal_vertex>
  vec4 outlineLocal = vec4( transformed, 1.0 );
#ifdef USE_INSTANCING
  outlineLocal = instanceMatrix * outlineLocal;
  objectNormal = shadingRescale( shadingCofactor( mat3( instanceMatrix ) ) * objectNormal );
#endif
#endif
  vec3 n = shadingNormalMatrix * objectNormal;
  float len = length(n);
  n = len > 0.0 ? n / len : vec3(0.0);
#ifdef OUTLINE_MOVED
  vec4 worldPosition = modelMatrix * outlineLocal;
#else
  vec4 worldPosition = modelMatrix * vec4(position, 1.0);
#endif
  worldPosition.xyz += thickness * n;
  gl_Position = projectionMatrix * viewMatrix * worldPosition;
  #include <logdepthbuf_vertex>
#if defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0
  vec4 mvPosition = viewMatrix * worldPosition;
  #include <clipping_planes_vertex>
  #include <fog_vertex>
#endif
}
`;

/** Fragment stage: one colour. */
export const fragmentShader = /* glsl */ `
#include <logdepthbuf_pars_fragment>
#include <fog_pars_fragment>
#include <clipping_planes_pars_fragment>
uniform vec3 outlineColor;

void main() {
  #include <logdepthbuf_fragment>
${clippingFragment}
  gl_FragColor = vec4(outlineColor, 1.0);
${outputFragment}
}
`;
