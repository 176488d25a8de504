import {
  type BufferGeometry,
  type InstancedMesh,
  InstancedMesh as InstancedMeshClass,
  type Material,
  Mesh,
  type SkinnedMesh,
  SkinnedMesh as SkinnedMeshClass,
} from 'three';
import { OutlineMaterial, type OutlineMaterialOptions } from './OutlineMaterial.js';

/** The mesh's properties the outline reads through (instances, bones, morph weights, culling sphere). */
const SHARED = {
  morph: ['morphTargetInfluences', 'morphTargetDictionary'],
  instanced: ['instanceMatrix', 'count', 'morphTexture', 'boundingSphere', 'boundingBox'],
  skinned: ['skeleton', 'bindMode', 'bindMatrix', 'bindMatrixInverse', 'boundingSphere', 'boundingBox'],
} as const;

/**
 * Give `mesh` an inverted-hull outline (the classic toon look): a child mesh sharing its geometry, drawn
 * with an {@link OutlineMaterial}. Being a child, it follows the mesh's transform. It shares the mesh
 * material's `clippingPlanes` array (and takes its `clipIntersection`), so a clipped mesh has a clipped
 * outline; assign the outline material's `clippingPlanes` too if you later replace the mesh's array. Remove it
 * with `mesh.remove(outline)` and free it with `outline.material.dispose()` (the geometry stays the mesh's).
 *
 * The outline is the same kind of object as the mesh, so three deforms and instances it the same way: for a
 * `SkinnedMesh`, a `SkinnedMesh` reading the mesh's `skeleton`, `bindMode` and bind matrices; for an
 * `InstancedMesh`, an `InstancedMesh` reading its `instanceMatrix`, `count` and per-instance morph weights
 * (`morphTexture`); for morph targets, the mesh's `morphTargetInfluences`. It reads them from the mesh at every
 * use (a getter each: assigning them on the outline does nothing), culls with the mesh's bounding sphere
 * where the mesh has its own (skinned, instanced) and is culled only when the mesh is (`frustumCulled`). So
 * the hull is pushed out around the deformed surface of each instance, as the mesh draws it. Do not call
 * `dispose()` on an instanced or skinned outline: it would free the mesh's shared resources; dispose of its
 * material.
 *
 * For three's `WebGPURenderer` (which draws node materials only), `createOutlineNode` of
 * `@shadelab/material/webgpu` makes the same outline with an `OutlineNodeMaterial`.
 *
 * @example
 * const outline = createOutline(mesh, { thickness: 0.05, color: '#000000' });
 * @throws TypeError for a `BatchedMesh` (its draws are not shared with a second object): outline each geometry
 *   with its own mesh.
 * @returns the outline mesh, already added to `mesh`.
 */
export function createOutline(
  mesh: Mesh<BufferGeometry, Material | Material[]>,
  options: OutlineMaterialOptions = {},
): Mesh<BufferGeometry, OutlineMaterial> {
  checkOutlined('createOutline', mesh);
  return attachOutline(mesh, new OutlineMaterial(options));
}

/** Throws the TypeError of `createOutline` and `createOutlineNode` (named by `caller`) for a BatchedMesh. */
export function checkOutlined(caller: string, mesh: Mesh<BufferGeometry, Material | Material[]>): void {
  if ((mesh as { isBatchedMesh?: boolean }).isBatchedMesh === true) {
    throw new TypeError(
      `${caller}(mesh): mesh must be a Mesh, SkinnedMesh or InstancedMesh, got a BatchedMesh (not supported: outline each geometry with its own mesh)`,
    );
  }
}

/**
 * The outline object of `createOutline` and `createOutlineNode`: a child of `mesh` of the same kind, sharing its
 * geometry, drawn with `material` (see {@link createOutline}).
 */
export function attachOutline<M extends Material>(
  mesh: Mesh<BufferGeometry, Material | Material[]>,
  material: M,
): Mesh<BufferGeometry, M> {
  const skinned = (mesh as SkinnedMesh).isSkinnedMesh === true;
  const instanced = (mesh as InstancedMesh).isInstancedMesh === true;
  const outline: Mesh<BufferGeometry, M> = skinned
    ? (new SkinnedMeshClass(mesh.geometry, material) as unknown as Mesh<BufferGeometry, M>)
    : instanced
      ? (new InstancedMeshClass(mesh.geometry, material, 0) as unknown as Mesh<BufferGeometry, M>)
      : new Mesh(mesh.geometry, material);
  const keys = new Set<string>(SHARED.morph);
  if (instanced) {
    for (const key of SHARED.instanced) keys.add(key);
    // An object that is both (a SkinnedMesh with an instance matrix): instanced for three's program too.
    Object.assign(outline, { isInstancedMesh: true, instanceColor: null });
  }
  if (skinned) for (const key of SHARED.skinned) keys.add(key);
  const source = mesh as unknown as Record<string, unknown>;
  for (const key of keys) {
    Object.defineProperty(outline, key, {
      configurable: true,
      enumerable: true,
      get: () => {
        // three culls with the object's own sphere, computing it when null: the mesh's, computed by the mesh.
        if (source[key] === null && key === 'boundingSphere') (mesh as InstancedMesh).computeBoundingSphere();
        if (source[key] === null && key === 'boundingBox') (mesh as InstancedMesh).computeBoundingBox();
        return source[key];
      },
      set: () => {},
    });
  }
  let culled = true;
  Object.defineProperty(outline, 'frustumCulled', {
    configurable: true,
    enumerable: true,
    get: () => culled && mesh.frustumCulled,
    set: (value: boolean) => {
      culled = value;
    },
  });
  const clipSource = Array.isArray(mesh.material) ? mesh.material[0] : mesh.material;
  if (clipSource?.clippingPlanes) {
    outline.material.clippingPlanes = clipSource.clippingPlanes;
    outline.material.clipIntersection = clipSource.clipIntersection;
  }
  outline.name = 'outline';
  mesh.add(outline);
  return outline;
}
