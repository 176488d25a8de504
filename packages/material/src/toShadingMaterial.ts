import type { Material } from 'three';
import { ShadingMaterial, type ShadingMaterialOptions } from './ShadingMaterial.js';
import { convertWith, SHADING_MATERIAL_OPTION_KEYS, type ShadingMaterialKind } from './shadingOptionsOf.js';

/** ShadingMaterial as the shared conversion and swap see it. @internal */
export const SHADING_MATERIAL: ShadingMaterialKind<ShadingMaterial, ShadingMaterialOptions> = {
  owner: 'toShadingMaterial',
  make: (options) => new ShadingMaterial(options),
  optionKeys: SHADING_MATERIAL_OPTION_KEYS,
};

/**
 * A {@link ShadingMaterial} that draws like `material` under three's lights: three's `MeshBasicMaterial`,
 * `MeshLambertMaterial`, `MeshPhongMaterial`, `MeshStandardMaterial`, `MeshPhysicalMaterial` and
 * `MeshToonMaterial` (and their node versions, by the same flags), told apart by three's `is…Material` flags.
 * `material` itself is neither changed nor disposed; its textures are shared, not cloned.
 *
 * What is carried over (colours are three's linear working colours):
 * - **every kind**: `map`, `normalMap`, `normalScale`, `emissive` × `emissiveIntensity`, `emissiveMap`,
 *   `vertexColors`, `opacity`, `transparent`, `alphaTest`, `alphaMap`, `flatShading` (→ `shading: 'flat'`, else
 *   `'phong'`), and the Material properties `name`, `side`, `shadowSide`, `fog`, `toneMapped`,
 *   `clippingPlanes` (the same array), `clipIntersection`, `clipShadows`, `depthTest`, `depthWrite`,
 *   `depthFunc`, the blending (`blending`, `blendSrc` … `premultipliedAlpha`), `colorWrite`, `visible`, the
 *   polygon offset, `alphaToCoverage` and `dithering`. `lighting` is `'blinn-phong'` (three's specular is
 *   Blinn-Phong's n·h) with three's exponent s as the shininess. Given `options.lighting: 'phong'`, the shininess
 *   is s/4, whose (v·r)^(s/4) has the same peak and width as (n·h)^s (in the plane of l and v, the angle of v to r
 *   is twice that of n to h): cheaper, and brighter than three's towards grazing views.
 * - **MeshBasic** (unlit): ka = kd = ks = 0; `emissive` = colour and `emissiveMap` = `map`, so the picture is
 *   colour × texel, before fog and tone mapping, as three draws it; `map` stays for its alpha. Vertex and
 *   instance colours multiply ka and kd only, so a MeshBasic's vertex colours are lost (their alpha is kept).
 * - **MeshLambert**: ka = kd = colour, ks = 0.
 * - **MeshPhong**: ka = kd = colour, three's shininess s carried over as above, ks = specular × (s + 2)/8: three's
 *   `BRDF_BlinnPhong` (F·(s/2 + 1)/(4π)·(n·h)^s times n·l) and the lecture's ks·Is·(n·h)^s (or ks·Is·(v·r)^(s/4))
 *   with Is = colour/π are then equal where l = v = n; elsewhere three's term also has n·l and Schlick's Fresnel.
 * - **MeshStandard / MeshPhysical**: α = max(roughness, 0.045)² (three's), shininess = 2/α² − 2 (the
 *   Blinn-Phong lobe of GGX's width and peak; carried over as above), ks = F0 × (shininess + 2)/8 with three's
 *   F0 = mix(dielectric, colour, metalness), dielectric = 0.04 (Physical: min(((ior − 1)/(ior + 1))² ×
 *   specularColor, 1) × specularIntensity); ka = kd = colour × (1 − metalness) × (1 − dielectric) (three's
 *   diffuse contribution after its Fresnel mix at normal incidence). The highlight equals three's `BRDF_GGX`
 *   where l = v = n (within 0.5 %); measured against `BRDF_GGX` over every light direction
 *   (`shadingOptionsOf.test.ts`): for roughness ≤ 0.5 and views within 30° of the normal, within 17 % of three's
 *   peak everywhere and 0.85 … 1.10 of its energy; more at grazing views and for rougher surfaces (the lecture's
 *   highlight has no n·l and no Fresnel: the package README, "Swap into an existing scene", has the table). Not carried: the environment map,
 *   roughness and metalness maps, clearcoat, sheen, transmission, iridescence, anisotropy.
 * - **MeshToon**: ka = kd = colour, ks = 0, `celBands` = the `gradientMap`'s width in texels (2 … 255), 2
 *   without one (three's two tones).
 *
 * `options` override what was carried over (undefined entries are ignored), e.g. `{ shading: 'gouraud' }`.
 *
 * @param material - The material to convert.
 * @param options - Options of the new material, over the carried-over ones.
 * @throws TypeError when `material` is not a THREE.Material or is of another kind (ShaderMaterial,
 *   MeshNormal/Depth/Distance/Matcap, points and line materials, a ShadingMaterial...), naming its type;
 *   TypeError or RangeError naming the option when an option (or a carried-over value, e.g. a negative colour)
 *   is out of range.
 * @example
 * const shading = toShadingMaterial(mesh.material as THREE.Material, { shading: 'gouraud' });
 * mesh.material = shading;
 */
export function toShadingMaterial(material: Material, options?: ShadingMaterialOptions): ShadingMaterial {
  return convertWith(SHADING_MATERIAL, material, options);
}
