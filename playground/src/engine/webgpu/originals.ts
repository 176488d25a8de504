/**
 * The user's model's own materials, remembered before `swapMaterials` replaces them with ShadingMaterials, so
 * that WebGPU mode can swap the same originals with `swapNodeMaterials` (which takes three's materials, not
 * ShadingMaterials). In the WebGL bundle: no three/webgpu here.
 */
import type * as THREE from 'three';

/** The model root of each mesh, and each root's meshes with the material(s) they had when loaded. */
const _rootOf = new WeakMap<THREE.Object3D, THREE.Object3D>();
const _originals = new WeakMap<THREE.Object3D, Map<THREE.Mesh, THREE.Material | THREE.Material[]>>();

/** Remembers the materials of every mesh under `root` (call it before swapping them). */
export function rememberOriginals(root: THREE.Object3D): void {
  const meshes = new Map<THREE.Mesh, THREE.Material | THREE.Material[]>();
  root.traverse((object) => {
    const mesh = object as THREE.Mesh;
    if (mesh.isMesh) {
      meshes.set(mesh, mesh.material);
      _rootOf.set(mesh, root);
    }
  });
  _originals.set(root, meshes);
}

/** The model root `mesh` was loaded under and the original materials of that root's meshes; null when none. */
export function originalsOf(
  mesh: THREE.Object3D,
): { root: THREE.Object3D; meshes: Map<THREE.Mesh, THREE.Material | THREE.Material[]> } | null {
  const root = _rootOf.get(mesh);
  const meshes = root && _originals.get(root);
  return root && meshes ? { root, meshes } : null;
}
