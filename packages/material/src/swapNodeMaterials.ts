import type { Object3D } from 'three';
import type { ShadingNodeMaterial, ShadingNodeMaterialOptions } from './ShadingNodeMaterial.js';
import { type SwappedMaterials, swapWith } from './swapWith.js';
import { SHADING_NODE_MATERIAL, toShadingNodeMaterial } from './toShadingNodeMaterial.js';

const SWAP = { ...SHADING_NODE_MATERIAL, owner: 'swapNodeMaterials', convert: toShadingNodeMaterial };

/**
 * `swapMaterials` for three's `WebGPURenderer`: swaps every mesh material under `root` for a
 * {@link ShadingNodeMaterial} made by {@link toShadingNodeMaterial} (the same traversal, sharing, `skipped`,
 * `update` and `restore` as `swapMaterials`; what the node material drops is listed on
 * `toShadingNodeMaterial`).
 *
 * @param root - The object whose subtree is swapped.
 * @param options - Options of every made material, over what each carried over.
 * @returns The made materials, what was skipped, `update(options)` and `restore()`.
 * @throws TypeError when `root` is not a THREE.Object3D; TypeError or RangeError naming the option when an
 *   option is bad (before anything is swapped).
 * @example
 * const swap = swapNodeMaterials(gltf.scene, { shading: 'flat' });
 * swap.restore();
 */
export function swapNodeMaterials(
  root: Object3D,
  options?: ShadingNodeMaterialOptions,
): SwappedMaterials<ShadingNodeMaterial, ShadingNodeMaterialOptions> {
  return swapWith(SWAP, root, options);
}
