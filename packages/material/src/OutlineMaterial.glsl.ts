// GLSL of OutlineMaterial: the inverted hull. Back faces of the mesh, pushed out along the world normal;
// clipped, tone-mapped and fogged by three's chunks like the mesh it outlines (shadingChunks.glsl.ts).
import { clippingFragment, outputFragment } from './shadingChunks.glsl.js';

/** Vertex stage: world position + thickness · unit world normal. */
export const vertexShader = /* glsl */ `
#include <common>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
uniform mat3 shadingNormalMatrix;
uniform float thickness;

void main() {
#ifdef SPHERE_NORMALS
  vec3 objectNormal = position;
#else
  vec3 objectNormal = normal;
#endif
  vec3 n = shadingNormalMatrix * objectNormal;
  float len = length(n);
  n = len > 0.0 ? n / len : vec3(0.0);
  vec4 worldPosition = modelMatrix * vec4(position, 1.0);
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
