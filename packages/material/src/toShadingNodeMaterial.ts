import type { Material } from 'three';
import { ShadingNodeMaterial, type ShadingNodeMaterialOptions } from './ShadingNodeMaterial.js';
import { convertWith, SHADING_MATERIAL_OPTION_KEYS, type ShadingMaterialKind } from './shadingOptionsOf.js';

/** A ShadingNodeMaterial made once, to see which of ShadingMaterial's options the node material has. */
let probe: ShadingNodeMaterial | undefined;
/** The options of ShadingMaterial's that ShadingNodeMaterial takes too (a property of that name). */
let keys: readonly string[] | undefined;
const nodeOptionKeys = (): readonly string[] => {
  if (keys === undefined) {
    probe ??= new ShadingNodeMaterial();
    const made = probe;
    keys = SHADING_MATERIAL_OPTION_KEYS.filter((key) => key === 'lights' || key in made);
  }
  return keys;
};

/** ShadingNodeMaterial as the shared conversion and swap see it. @internal */
export const SHADING_NODE_MATERIAL: ShadingMaterialKind<ShadingNodeMaterial, ShadingNodeMaterialOptions> = {
  owner: 'toShadingNodeMaterial',
  make: (options) => new ShadingNodeMaterial(options),
  get optionKeys() {
    return nodeOptionKeys();
  },
  refused: (kind) =>
    kind === 'basic' && !nodeOptionKeys().includes('emissive')
      ? 'an unlit material is drawn through emissive, which this ShadingNodeMaterial does not take'
      : undefined,
};

/**
 * `toShadingMaterial` for three's `WebGPURenderer`: a {@link ShadingNodeMaterial} carrying over what
 * `toShadingMaterial` carries over, by the same rules (one mapping, stated on `toShadingMaterial`): the
 * lecture's options (shading from `flatShading`, lighting, celBands from a toon gradient map, ka, kd, ks and
 * shininess from the colour, Phong's specular or the Standard/Physical roughness and metalness), three's surface
 * options (`map`, `vertexColors`, `emissive` × `emissiveIntensity`, `emissiveMap`, `opacity`, `transparent`,
 * `alphaTest`, `alphaMap`, `normalMap`, `normalScale`) and the Material properties (`name`, `side`, `fog`,
 * `toneMapped`, the clipping planes, depth, blending and the rest listed there).
 *
 * An option this ShadingNodeMaterial has no property for is dropped; without `emissive`, a MeshBasicMaterial
 * (drawn through emissive) is refused with a TypeError instead of becoming black.
 *
 * @param material - The material to convert (MeshBasic, MeshLambert, MeshPhong, MeshStandard, MeshPhysical,
 *   MeshToon, or their node versions).
 * @param options - Options of the new material, over the carried-over ones.
 * @throws TypeError when `material` is not a THREE.Material or is of a kind that does not convert, naming its
 *   type; TypeError or RangeError naming the option when an option is bad.
 * @example
 * mesh.material = toShadingNodeMaterial(mesh.material as THREE.Material, { shading: 'gouraud' });
 */
export function toShadingNodeMaterial(
  material: Material,
  options?: ShadingNodeMaterialOptions,
): ShadingNodeMaterial {
  return convertWith(SHADING_NODE_MATERIAL, material, options);
}
