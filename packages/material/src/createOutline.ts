import { type BufferGeometry, type Material, Mesh } from 'three';
import { OutlineMaterial, type OutlineMaterialOptions } from './OutlineMaterial.js';

/**
 * Give `mesh` an inverted-hull outline (the classic toon look): a child mesh sharing its geometry, drawn
 * with an {@link OutlineMaterial}. Being a child, it follows the mesh's transform. It shares the mesh
 * material's `clippingPlanes` array (and takes its `clipIntersection`), so a clipped mesh has a clipped
 * outline; assign the outline material's `clippingPlanes` too if you later replace the mesh's array. Remove it
 * with `mesh.remove(outline)` and free it with `outline.material.dispose()` (the geometry stays the mesh's).
 *
 * @example
 * const outline = createOutline(mesh, { thickness: 0.05, color: '#000000' });
 * @returns the outline mesh, already added to `mesh`.
 */
export function createOutline(
  mesh: Mesh<BufferGeometry, Material | Material[]>,
  options: OutlineMaterialOptions = {},
): Mesh<BufferGeometry, OutlineMaterial> {
  const outline = new Mesh(mesh.geometry, new OutlineMaterial(options));
  const source = Array.isArray(mesh.material) ? mesh.material[0] : mesh.material;
  if (source?.clippingPlanes) {
    outline.material.clippingPlanes = source.clippingPlanes;
    outline.material.clipIntersection = source.clipIntersection;
  }
  outline.name = 'outline';
  mesh.add(outline);
  return outline;
}
