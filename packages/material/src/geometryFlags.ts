// The names by which a geometry tells the shading materials what it is (shared by the WebGL and node materials,
// the outline and the impostor, without importing any of them).

/** The `userData` flag that marks a geometry as a sphere centred at its origin (see `ShadingMaterial`). */
export const SPHERE_FLAG = 'isSphere';

/** The attributes flat shading reads from a geometry made by `flatShadingGeometry`: a face's other two corners. */
export const FLAT_CORNERS = ['flatCornerA', 'flatCornerB'] as const;

/**
 * The attribute of a `flatShadingGeometry` made from a skinned or morphed geometry: the vertex indices of a
 * face's other two corners, so that flat shading moves them as three moves their vertices.
 */
export const FLAT_CORNER_INDEX = 'flatCornerIndex';

/**
 * The `userData` key of a `flatShadingGeometry`: which vertex of each triangle carries the face, `'last'`
 * (WebGL's provoking vertex) or `'first'` (WebGPU's).
 */
export const FLAT_PROVOKING_VERTEX = 'flatProvokingVertex';
