// What ShadingMaterial draws (its `output` option, a debugging aid). The material defines, for an output other
// than the colour (none for the colour, so its program is unchanged):
// - SHADING_OUTPUT_<NAME> (AMBIENT, DIFFUSE, SPECULAR, ATTENUATION or NORMAL), and SHADING_OUTPUT_TERM;
// - SHADING_OUTPUT_DATA: attenuation or normal (written as is: no texel, tone mapping or colour space);
// - SHADING_NO_AMBIENT, SHADING_NO_DIFFUSE, SHADING_NO_SPECULAR: the terms the lighting leaves out.
// Emissive and fog are left out of every output but the colour.

/**
 * In the lighting chunk: how many direct lights the attenuation output averages over (the PhongLights and
 * three's directional, point and spot lights).
 */
export const directLightCount = /* glsl */ `
#ifdef SHADING_OUTPUT_ATTENUATION
#ifdef SHADING_THREE_LIGHTS
#define SHADING_DIRECT_LIGHTS ( NUM_LIGHTS + NUM_DIR_LIGHTS + NUM_POINT_LIGHTS + NUM_SPOT_LIGHTS )
#else
#define SHADING_DIRECT_LIGHTS NUM_LIGHTS
#endif
#endif
`;

/** In `lightFactors`: the diffuse or specular factor zeroed when the output leaves its term out. */
export const outputFactors = /* glsl */ `
#ifdef SHADING_NO_DIFFUSE
  diffuse = 0.0;
#endif
#ifdef SHADING_NO_SPECULAR
  spec = 0.0;
#endif
`;

/**
 * In `shadeColor`, once `n` (unit, world space, or view space with SHADING_VIEW_SPACE) is known: the normal
 * output returns it in view space as three's MeshNormalMaterial packs it (n·0.5 + 0.5).
 */
export const outputNormal = /* glsl */ `
#ifdef SHADING_OUTPUT_NORMAL
#ifdef SHADING_VIEW_SPACE
  return n * 0.5 + 0.5;
#else
  return normalize( mat3( viewMatrix ) * n ) * 0.5 + 0.5;
#endif
#endif
`;

/**
 * The vertex stage's object normal matrix with `normalMatrix: 'model'` (SHADING_MODEL_NORMALS): the model matrix
 * itself, the lecture's wrong way (after the `shadingNormalMatrix` uniform's declaration).
 */
export const modelNormalsVertex = /* glsl */ `
#ifdef SHADING_MODEL_NORMALS
#define shadingNormalMatrix mat3( modelMatrix )
#endif
`;
