/**
 * Vertex normals of any indexed triangle mesh, averaged over the faces around each vertex (the lecture's
 * rule), or weighted by face area or by corner angle.
 * @module @shadelab/sphere/normals
 */
export { computeVertexNormals, type NormalWeighting } from './computeVertexNormals.js';
