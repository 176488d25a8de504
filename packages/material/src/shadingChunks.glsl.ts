// The lecture's equation and the shading stages as named GLSL chunks, included by ShadingMaterial, the
// impostor and the outline (as three's meshphong.glsl.js includes its chunks). three's own chunks
// (`#include <…>`) do the standard parts: instancing, batching, skinning, morph targets, clipping, fog, tone
// mapping and colour space, each compiled only when three's program parameters define its USE_* macro. Every
// chunk here compiles to nothing unless its feature is on, so a scene without them compiles the same code as
// before (tests/material-scene.spec.ts checks the active lines of every lecture program).

import { shadowTermsCopy } from './shadowChunks.glsl.js';

/**
 * Which of three's scene features this draw uses, from the USE_* macros three defines per program:
 * - `SHADING_SCENE` (vertex): the vertex goes through three's chunks (`transformed`, `mvPosition`);
 * - `SHADING_INSTANCE`: an InstancedMesh or BatchedMesh matrix moves the vertex (and its normal);
 * - `SHADING_DEFORM`: morph targets or skinning move the vertex;
 * - `SHADING_TINT`: an instance (or batch) colour, a vertex colour or a texel of `map` multiplies ka and kd.
 */
export const sceneFeatures = /* glsl */ `
#if defined( USE_INSTANCING ) || defined( USE_BATCHING ) || defined( USE_SKINNING ) || defined( USE_MORPHTARGETS ) || defined( USE_FOG ) || NUM_CLIPPING_PLANES > 0 || defined( USE_SHADOWMAP )
#define SHADING_SCENE
#endif
#if defined( USE_INSTANCING ) || defined( USE_BATCHING )
#define SHADING_INSTANCE
#endif
#if defined( USE_MORPHTARGETS ) || defined( USE_SKINNING )
#define SHADING_DEFORM
#endif
#if defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR ) || defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_MAP )
#define SHADING_TINT
#endif
`;

/**
 * The surface's textures and alpha, three's way (ShadingMaterial only), from three's USE_* macros:
 * - `SHADING_SPLIT` (both stages): a texture with vertex lighting (gouraud, exact flat) — the vertex stage passes
 *   the ka/kd part and the ks part of the colour separately, the fragment multiplies only the first by the texel;
 * - `SHADING_SURFACE` (fragment): `diffuseColor` = (texel, opacity × texel alpha × vertex alpha × alphaMap.g),
 *   alpha-tested and, unless opaque, written as the fragment's alpha;
 * - `SHADING_NORMALMAP` (fragment, phong shading only): three's normal map perturbs the normal, in world space,
 *   with three's derivative tangent frame (`getTangentFrame`; a `tangent` attribute is not used).
 */
export const surfaceVertexPars = /* glsl */ `
#if defined( USE_MAP ) && ! defined( SHADING_PHONG ) && ! defined( FLAT_DERIVATIVES ) && ! defined( SHADING_OUTPUT_DATA )
#define SHADING_SPLIT
#endif
#include <uv_pars_vertex>
#ifdef USE_COLOR_ALPHA
out float vShadingAlpha;
#endif
`;

/** Fragment declarations of the surface (see {@link surfaceVertexPars}). */
export const surfaceFragmentPars = /* glsl */ `
#if defined( USE_MAP ) && ! defined( SHADING_PHONG ) && ! defined( FLAT_DERIVATIVES ) && ! defined( SHADING_OUTPUT_DATA )
#define SHADING_SPLIT
#endif
#if defined( USE_MAP ) || defined( USE_ALPHAMAP ) || defined( USE_ALPHATEST ) || ! defined( OPAQUE )
#define SHADING_SURFACE
uniform float opacity;
#endif
#if defined( SHADING_EMISSIVE ) || defined( USE_EMISSIVEMAP )
uniform vec3 emissive;
#endif
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <emissivemap_pars_fragment>
#ifdef USE_COLOR_ALPHA
in float vShadingAlpha;
#endif
#if defined( USE_NORMALMAP ) && defined( SHADING_PHONG )
#define SHADING_NORMALMAP
#undef USE_TANGENT
#ifdef SHADING_VIEW_SPACE
#define normalMatrix ( mat3( viewMatrix ) * shadingNormalMatrix )
#else
#define normalMatrix shadingNormalMatrix
#endif
#endif
#include <normalmap_pars_fragment>
`;

/**
 * Fragment stage, phong shading with a normal map: the normal (`vNormal`, turned to the drawn side) through
 * three's tangent frame and `normal_fragment_maps` (tangent space, or object space through the object's normal
 * matrix), in world space, then lit.
 */
export const normalMapFragment = /* glsl */ `
  float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#if defined( DOUBLE_SIDED )
  vec3 normal = normalize( vNormal ) * faceDirection;
#elif defined( FLIP_SIDED )
  vec3 normal = - normalize( vNormal );
#else
  vec3 normal = normalize( vNormal );
#endif
#ifdef USE_NORMALMAP_TANGENTSPACE
  mat3 tbn = getTangentFrame( vWorldPosition, normal, vNormalMapUv );
#ifdef DOUBLE_SIDED
  tbn[ 0 ] *= faceDirection;
  tbn[ 1 ] *= faceDirection;
#endif
#endif
  #include <normal_fragment_maps>
  vec3 color = shadeColor( vWorldPosition, normal );
`;

/**
 * Fragment stage, after clipping: three's map, vertex alpha, alpha map and alpha test on `diffuseColor`
 * (declared by {@link clippingFragment}).
 */
export const surfaceFragment = /* glsl */ `
#ifdef SHADING_SURFACE
  #include <map_fragment>
#ifdef USE_COLOR_ALPHA
  diffuseColor.a *= vShadingAlpha;
#endif
  #include <alphamap_fragment>
  #include <alphatest_fragment>
#endif
`;

/** Fragment stage: emissive (× emissiveMap, three's chunk) added to the lit colour, outside the lighting. */
export const emissiveFragment = /* glsl */ `
#if ( defined( SHADING_EMISSIVE ) || defined( USE_EMISSIVEMAP ) ) && ! defined( SHADING_OUTPUT_TERM )
  vec3 totalEmissiveRadiance = emissive;
  #include <emissivemap_fragment>
  color += totalEmissiveRadiance;
#endif
`;

/**
 * Vertex declarations for instancing and batching: the instance's normal matrix, made as `computeNormalMatrix`
 * makes the object's (sign(det A)·cof(A) of A / max|A|: finite for a singular or huge instance matrix, outward
 * under mirroring, right under shear), and the rescaling that keeps a product of normal matrices in range.
 * `shadingInstanceNormal(A, n)` is the instance's normal of n (a direction, normalised later): where every
 * instance matrix is a rotation times a scale (SHADING_INSTANCE_ORTHOGONAL, checked on the CPU by
 * `hasOrthogonalInstances`), A·(n / |aᵢ|²) = A⁻ᵀn, the direction of sign(det A)·cof(A)·n, for a fraction of the
 * cofactor's cost; else the cofactor, rescaled.
 */
export const instanceChunk = /* glsl */ `
#ifdef SHADING_INSTANCE
vec3 shadingRescale( vec3 v ) {
  float m = max( max( abs( v.x ), abs( v.y ) ), abs( v.z ) );
  return m > 0.0 ? v / m : vec3( 0.0 );
}
// cof(A / s) (its columns: the crosses of A's columns / s) with s = max|A|, and whether det A < 0.
mat3 shadingScaledCofactor( mat3 a, out float s, out bool mirrored ) {
  vec3 e = max( max( abs( a[ 0 ] ), abs( a[ 1 ] ) ), abs( a[ 2 ] ) );
  s = max( max( e.x, e.y ), e.z );
  float r = 1.0 / s; // one division, not nine (per vertex)
  vec3 a0 = a[ 0 ] * r;
  vec3 a1 = a[ 1 ] * r;
  vec3 a2 = a[ 2 ] * r;
  mat3 c = mat3( cross( a1, a2 ), cross( a2, a0 ), cross( a0, a1 ) );
  mirrored = dot( a0, c[ 0 ] ) < 0.0;
  return c;
}
// sign(det A)·cof(A / max|A|); the zero matrix for a zero or non-finite A (selects, not branches).
mat3 shadingCofactor( mat3 a ) {
  float s;
  bool mirrored;
  mat3 c = shadingScaledCofactor( a, s, mirrored );
  c = mirrored ? - c : c;
  return s > 0.0 ? c : mat3( 0.0 );
}
// shadingCofactor( a ) · n, the sign and the zero case applied to the vector (per vertex: cheaper, the same bits).
vec3 shadingCofactorTimes( mat3 a, vec3 n ) {
  float s;
  bool mirrored;
  vec3 m = shadingScaledCofactor( a, s, mirrored ) * n;
  m = mirrored ? - m : m;
  return s > 0.0 ? m : vec3( 0.0 );
}
vec3 shadingInstanceNormal( mat3 a, vec3 n ) {
#ifdef SHADING_INSTANCE_ORTHOGONAL
  return a * ( n / vec3( dot( a[ 0 ], a[ 0 ] ), dot( a[ 1 ], a[ 1 ] ), dot( a[ 2 ], a[ 2 ] ) ) );
#else
  return shadingRescale( shadingCofactorTimes( a, n ) );
#endif
}
#endif
`;

/**
 * Vertex stage, first lines of `main`: three's chunks move the vertex (batching, instanced morph weights,
 * morph targets, skinning, instancing: `transformed`, `mvPosition`, `gl_Position`), then clipping and fog
 * read its view position; the lecture's scene (none of them) keeps its one-line projection.
 */
export const projectVertex = /* glsl */ `
#ifdef SHADING_SCENE
  #include <batching_vertex>
  #include <morphinstance_vertex>
  #include <skinbase_vertex>
  vec3 transformed = vec3( position );
  #include <morphtarget_vertex>
  #include <skinning_vertex>
  #include <project_vertex>
  #include <clipping_planes_vertex>
  #include <fog_vertex>
#else
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
#endif
`;

/**
 * Vertex stage: the instance (or batch) matrix (`shadingInstance`, whose normals `shadingCofactorTimes` turns),
 * and the tint: instance colour × vertex colour (`tint`).
 */
export const instanceVertex = /* glsl */ `
#ifdef SHADING_INSTANCE
  mat4 shadingInstance = mat4( 1.0 );
#ifdef USE_BATCHING
  shadingInstance = batchingMatrix;
#endif
#ifdef USE_INSTANCING
  shadingInstance = instanceMatrix;
#endif
#endif
#ifdef SHADING_TINT
  vec3 tint = vec3( 1.0 );
#ifdef USE_INSTANCING_COLOR
  tint *= instanceColor;
#endif
#ifdef USE_BATCHING_COLOR
  tint *= getBatchingColor( getIndirectIndex( gl_DrawID ) ).rgb;
#endif
#if defined( USE_COLOR_ALPHA )
  tint *= color.rgb;
#elif defined( USE_COLOR )
  tint *= color;
#endif
#endif
`;

/**
 * Flat shading's corners moved like their vertices (morph targets, then skinning, as three's chunks move a
 * vertex): `cornerIndex` holds their vertex indices, `faceSkin` their skin indices and weights.
 */
export const flatDeformVertex = /* glsl */ `
#ifdef SHADING_DEFORM
  vec3 corners[ 3 ] = vec3[ 3 ]( p0, p1, p2 );
  for ( int k = 0; k < 3; k ++ ) {
    vec3 c = corners[ k ];
#ifdef USE_MORPHTARGETS
    c *= morphTargetBaseInfluence;
    for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
      if ( morphTargetInfluences[ i ] != 0.0 ) c += getMorph( cornerIndex[ k ], i, 0 ).xyz * morphTargetInfluences[ i ];
    }
#endif
#ifdef USE_SKINNING
    int t = 2 * cornerIndex[ k ];
    int w = textureSize( faceSkin, 0 ).x;
    vec4 bones = texelFetch( faceSkin, ivec2( t % w, t / w ), 0 );
    vec4 weights = texelFetch( faceSkin, ivec2( t % w + 1, t / w ), 0 );
    vec4 bound = bindMatrix * vec4( c, 1.0 );
    vec4 skinned = getBoneMatrix( bones.x ) * bound * weights.x + getBoneMatrix( bones.y ) * bound * weights.y
      + getBoneMatrix( bones.z ) * bound * weights.z + getBoneMatrix( bones.w ) * bound * weights.w;
    c = ( bindMatrixInverse * skinned ).xyz;
#endif
    corners[ k ] = c;
  }
  p0 = corners[ 0 ];
  p1 = corners[ 1 ];
  p2 = corners[ 2 ];
#endif
`;

/**
 * Fragment: `diffuseColor` (the surface's, see {@link surfaceFragmentPars}, or for three's clipping chunk, which
 * scales its alpha with alpha to coverage), then three's clipping.
 */
export const clippingFragment = /* glsl */ `
#if defined( SHADING_SURFACE )
  vec4 diffuseColor = vec4( vec3( 1.0 ), opacity );
#elif NUM_CLIPPING_PLANES > 0 && defined( ALPHA_TO_COVERAGE )
  vec4 diffuseColor = vec4( 1.0 );
#endif
  #include <clipping_planes_fragment>
`;

/** three's fog uniforms (as its `fog_pars_fragment` declares them, without the depth varying). */
export const fogUniforms = /* glsl */ `uniform vec3 fogColor;
#ifdef FOG_EXP2
uniform float fogDensity;
#else
uniform float fogNear;
uniform float fogFar;
#endif`;

/**
 * Fragment declarations of fog: three's `fog_pars_fragment`, except where the fragment's position is in view
 * space already (phong shading and flat from derivatives, lit in view space: SHADING_VIEW_SPACE), whose depth is
 * the fog depth three's `fog_vertex` passes (−mvPosition.z): one varying less to interpolate. (No blank line
 * before or after: the learning view's active lines of the lecture's programs stay as they were.)
 */
export const fogParsFragment = /* glsl */ `#if defined( USE_FOG ) && defined( SHADING_VIEW_SPACE ) && ( defined( SHADING_PHONG ) || defined( FLAT_DERIVATIVES ) )
#define vFogDepth ( - vWorldPosition.z )
${fogUniforms}
#else
#include <fog_pars_fragment>
#endif`;

/**
 * Fragment stage, last lines: three's tone mapping and output colour space, then fog as three's
 * `fog_fragment` blends it (in the output colour space), except that fog near = far (where `smoothstep` is
 * undefined) is a step at that depth: no fog before it, all fog beyond.
 */
export const outputFragment = /* glsl */ `
#ifndef SHADING_OUTPUT_DATA
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
#endif
#if defined( USE_FOG ) && ! defined( SHADING_OUTPUT_TERM )
#ifdef FOG_EXP2
  float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
#else
  float fogFactor = fogFar > fogNear ? smoothstep( fogNear, fogFar, vFogDepth ) : step( fogNear, vFogDepth );
#endif
  gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif
`;

/**
 * The varyings from the vertex to the fragment stage (`qualifier` 'out' in the vertex stage, 'in' in the
 * fragment): the colours lit per face (flat, interpolated `flat`) or per vertex (gouraud), or the position,
 * normal and tint lit per fragment (phong, and flat from derivatives, which has no normal varying).
 */
export function shadingVaryings(qualifier: 'out' | 'in'): string {
  return /* glsl */ `
#if defined( SHADING_FLAT ) && ! defined( FLAT_DERIVATIVES )
${litVaryings(`flat ${qualifier}`)}
#elif defined( SHADING_GOURAUD )
${litVaryings(qualifier)}
#else
${qualifier} vec3 vWorldPosition;
#ifndef FLAT_DERIVATIVES
${qualifier} vec3 vNormal;
#endif
#ifdef SHADING_TINT
${qualifier} vec3 vShadingTint;
#endif
#endif
`;
}

/**
 * The colours lit in the vertex stage: the front face's (`vColor`) and, when both sides are drawn, the back
 * face's, lit with the flipped normal; with a texture (SHADING_SPLIT) their ks parts apart (`vSpecular…`).
 */
function litVaryings(qualifier: string): string {
  return /* glsl */ `${qualifier} vec3 vColor;
#ifdef DOUBLE_SIDED
${qualifier} vec3 vColorBack;
#endif
#ifdef SHADING_SPLIT
${qualifier} vec3 vSpecular;
#ifdef DOUBLE_SIDED
${qualifier} vec3 vSpecularBack;
#endif
#endif`;
}

/**
 * Vertex declarations of flat shading (lit once per face, in the vertex stage): a flatShadingGeometry's
 * corner attributes, or the soup's positions (and skin) fetched from textures.
 */
export const flatParsVertex = /* glsl */ `
#if defined( SHADING_FLAT ) && ! defined( FLAT_DERIVATIVES )
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
#endif
`;

/**
 * Vertex stage: the vertex alpha and the tint for the fragment stage (lit per fragment) or for `shadeColor`
 * here (lit per face or vertex).
 */
export const surfaceVertex = /* glsl */ `
#ifdef USE_COLOR_ALPHA
  vShadingAlpha = color.a;
#endif
#if defined(SHADING_TINT) && ( defined(SHADING_PHONG) || defined(FLAT_DERIVATIVES) )
  vShadingTint = tint;
#elif defined(SHADING_TINT)
  shadingTint = tint;
#endif
`;

/**
 * Vertex stage, flat shading: the face this vertex belongs to (or provokes), moved as its vertices are, at its
 * world centroid (`faceCentre`) with its face normal (`faceNormal`, object space, rescaled; × the instance's
 * normal matrix).
 */
export const flatFaceVertex = /* glsl */ `
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
  faceNormal = shadingInstanceNormal( mat3( shadingInstance ), faceNormal );
#endif
`;

/**
 * Vertex stage, gouraud and phong shading (and flat from derivatives, without a normal): the vertex's world
 * position (`worldPosition`) and normal (`worldNormal`), moved by morph targets, skinning and the instance.
 */
export const worldVertex = /* glsl */ `
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
  objectNormal = shadingInstanceNormal( mat3( shadingInstance ), objectNormal );
#endif
#endif
  vec3 worldPosition = ( modelMatrix * shadingLocal ).xyz;
#else
  vec3 worldPosition = (modelMatrix * vec4(position, 1.0)).xyz;
#endif
#ifndef FLAT_DERIVATIVES
  vec3 worldNormal = shadingNormalMatrix * objectNormal;
#endif
`;

/** One side lit in the vertex stage: its colour (`suffix` '' the front face, 'Back' the back face). */
function litSide(suffix: '' | 'Back', point: string, normal: string): string {
  return /* glsl */ `
  vColor${suffix} = shadeColor(${point}, ${normal});
${shadowTermsCopy(suffix)}
#ifdef SHADING_SPLIT
  vSpecular${suffix} = shadingSpecular;
#endif`;
}

/**
 * Vertex stage, flat and gouraud shading: the colours at `point` with `normal` (world space, GLSL
 * expressions), one side at a time with {@link litSide}: three's sides light a back face with its flipped normal,
 * both colours when both sides are drawn (the fragment picks by `gl_FrontFacing`).
 */
export function litSidesVertex(point: string, normal: string): string {
  return /* glsl */ `
#if defined( DOUBLE_SIDED )
${litSide('Back', point, `-(${normal})`)}
${litSide('', point, normal)}
#elif defined( FLIP_SIDED )
${litSide('', point, `-(${normal})`)}
#else
${litSide('', point, normal)}
#endif
`;
}

/**
 * Vertex stage, phong shading (and flat from derivatives): the position and unit normal for the fragment stage,
 * in world space, or in view space where three's light uniforms are (SHADING_VIEW_SPACE: the view matrix is
 * rigid, see ShadingMaterial).
 */
export const phongVertex = /* glsl */ `
#ifdef SHADING_VIEW_SPACE
#ifndef FLAT_DERIVATIVES
  vec3 viewNormal = mat3( viewMatrix ) * worldNormal;
  float normalLength = length(viewNormal);
  vNormal = normalLength > 0.0 ? viewNormal / normalLength : vec3(0.0);
#endif
#if defined( SHADING_SCENE )
  vWorldPosition = mvPosition.xyz; // three's project_vertex: modelViewMatrix × the moved vertex
#else
  vWorldPosition = ( viewMatrix * vec4( worldPosition, 1.0 ) ).xyz;
#endif
#else
#ifndef FLAT_DERIVATIVES
  float normalLength = length(worldNormal);
  vNormal = normalLength > 0.0 ? worldNormal / normalLength : vec3(0.0);
#endif
  vWorldPosition = worldPosition;
#endif
`;

/**
 * Fragment stage, phong shading (and flat from derivatives): the tint (× the texel), the face normal from
 * screen-space derivatives for flat shading, then `color` lit at the fragment on the drawn side (or through the
 * normal map).
 */
export const litFragment = /* glsl */ `
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
`;

/**
 * Fragment stage, flat and gouraud shading: `color` is the drawn side's colour lit in the vertex stage (with a
 * texture, its ka/kd part × the texel plus its ks part).
 */
export const vertexLitFragment = /* glsl */ `
#if defined( DOUBLE_SIDED )
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
`;
