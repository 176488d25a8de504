import type { Object3D } from 'three';
import type { ShadingMaterial, ShadingMaterialOptions } from './ShadingMaterial.js';
import { type SwappedMaterials, swapWith } from './swapWith.js';
import { SHADING_MATERIAL, toShadingMaterial } from './toShadingMaterial.js';

/** Options of {@link swapMaterials}: the options every made material takes over what it carried over. */
export interface SwapMaterialsOptions extends ShadingMaterialOptions {}

const SWAP = { ...SHADING_MATERIAL, owner: 'swapMaterials', convert: toShadingMaterial };

/**
 * Swaps every mesh material under `root` (itself included) for a {@link ShadingMaterial} made by
 * {@link toShadingMaterial}, so that a loaded model or an existing scene is drawn with the lecture's shading.
 *
 * - Objects: `Mesh`, `SkinnedMesh`, `InstancedMesh` and `BatchedMesh` (three's `isMesh`), visible or not;
 *   material arrays (with groups) become new arrays, the original array kept for `restore()`.
 * - One ShadingMaterial per distinct original material: a material shared by several meshes becomes one shared
 *   ShadingMaterial, and a shared material array one shared array.
 * - Left in place and listed in `skipped` with the reason (and reported once, in one console.warn per call):
 *   ShaderMaterial and RawShaderMaterial, MeshNormal/Depth/Distance/Matcap and any other kind
 *   `toShadingMaterial` does not convert, materials already ShadingMaterials, `Points`, `Line` and `Sprite`
 *   objects, and a material whose conversion threw (its message is the reason). Nothing is thrown during the
 *   traversal, and nothing the user owns is disposed.
 *
 * @param root - The object whose subtree is swapped.
 * @param options - Options of every made material, over what each carried over (e.g. `{ shading: 'flat' }`).
 * @returns The made materials, what was skipped, `update(options)` and `restore()`.
 * @throws TypeError when `root` is not a THREE.Object3D; TypeError or RangeError naming the option when an
 *   option is bad (before anything is swapped).
 * @example
 * const swap = swapMaterials(gltf.scene, { shading: 'gouraud' });
 * swap.update({ celBands: 4 });
 * swap.restore(); // the model's own materials again
 */
export function swapMaterials(
  root: Object3D,
  options?: SwapMaterialsOptions,
): SwappedMaterials<ShadingMaterial> {
  return swapWith(SWAP, root, options);
}
