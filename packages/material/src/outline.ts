/**
 * The outline toon users expect around cel shading: an inverted hull (the back faces of the mesh pushed out
 * along their normals by a width in pixels or world units), drawn before the shaded mesh.
 * @module @shadelab/material/outline
 */
export { createOutline } from './createOutline.js';
export { OutlineMaterial, type OutlineMaterialOptions } from './OutlineMaterial.js';
