import type { BufferGeometry, Material, Mesh } from 'three';
import { attachOutline, checkOutlined } from './createOutline.js';
import { OutlineNodeMaterial, type OutlineNodeMaterialOptions } from './OutlineNodeMaterial.js';

/**
 * `createOutline` for three's `WebGPURenderer` (`three/webgpu`): gives `mesh` an inverted-hull outline drawn with
 * an {@link OutlineNodeMaterial}, on the WebGPU and the WebGL2 backend. The same outline object as `createOutline`
 * makes (a child of the same kind as the mesh, sharing its geometry, reading its skeleton and bind matrices,
 * morph weights, instance matrices and count, and culling sphere at every use), with the same options, defaults
 * and checks. Being a child, it is clipped by the mesh's `ClippingGroup` (WebGPURenderer's clipping). Remove it
 * with `mesh.remove(outline)` and free it with `outline.material.dispose()`; do not call `dispose()` on an
 * instanced or skinned outline (it would free the mesh's shared resources).
 *
 * @example
 * const outline = createOutlineNode(mesh, { thickness: 0.05, color: '#000000' });
 * @throws TypeError for a `BatchedMesh` (its draws are not shared with a second object): outline each geometry
 *   with its own mesh.
 * @returns the outline mesh, already added to `mesh`.
 */
export function createOutlineNode(
  mesh: Mesh<BufferGeometry, Material | Material[]>,
  options: OutlineNodeMaterialOptions = {},
): Mesh<BufferGeometry, OutlineNodeMaterial> {
  checkOutlined('createOutlineNode', mesh);
  return attachOutline(mesh, new OutlineNodeMaterial(options));
}
