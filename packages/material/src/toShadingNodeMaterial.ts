import type { Material } from 'three';
import { ShadingNodeMaterial, type ShadingNodeMaterialOptions } from './ShadingNodeMaterial.js';
import { convertWith, type ShadingMaterialKind } from './shadingOptionsOf.js';

/** Every option `ShadingNodeMaterial` takes (what the conversion may set; the rest is dropped). */
const OPTION_KEYS = [
  'shading',
  'lighting',
  'celBands',
  'ka',
  'kd',
  'ks',
  'shininess',
  'lights',
] as const satisfies readonly (keyof ShadingNodeMaterialOptions)[];

/** ShadingNodeMaterial as the shared conversion and swap see it. @internal */
export const SHADING_NODE_MATERIAL: ShadingMaterialKind<ShadingNodeMaterial, ShadingNodeMaterialOptions> = {
  owner: 'toShadingNodeMaterial',
  make: (options) => new ShadingNodeMaterial(options),
  optionKeys: OPTION_KEYS,
  refused: {
    basic: 'an unlit material is drawn through emissive, which ShadingNodeMaterial does not take yet',
  },
};

/**
 * `toShadingMaterial` for three's `WebGPURenderer`: a {@link ShadingNodeMaterial} carrying over what
 * `toShadingMaterial` carries over (the same mapping, defined once), as far as ShadingNodeMaterial takes it:
 * shading (`flatShading`), lighting, celBands, ka, kd, ks and shininess, and three's Material properties
 * `opacity`, `transparent`, `alphaTest`, `vertexColors` (their alpha), `name`, `side`, `fog`, `toneMapped`, the
 * clipping planes, depth, blending and the rest listed on `toShadingMaterial`.
 *
 * Dropped, because ShadingNodeMaterial does not take them yet: `map`, `normalMap`/`normalScale`, `emissive`
 * (× `emissiveIntensity`) and `emissiveMap`, `alphaMap`, and the RGB of vertex colours. So a MeshBasicMaterial,
 * which is drawn through `emissive`, is refused (a TypeError) instead of becoming black, and a textured
 * material loses its texture.
 *
 * @param material - The material to convert (MeshLambert, MeshPhong, MeshStandard, MeshPhysical, MeshToon, or
 *   their node versions).
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
