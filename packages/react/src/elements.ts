// Registers shadelab's classes as R3F JSX elements (the package's one side effect, declared in package.json's
// `sideEffects`) and types them: importing anything from @shadelab/react makes `<shadingMaterial>` & co. exist
// at run time and type-check, with no `extend` or `declare module` in the app.
import { type ConstructorRepresentation, extend, type ThreeElement } from '@react-three/fiber';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { OutlineMaterial } from '@shadelab/material/outline';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { AutoDetailSphere } from '@shadelab/sphere/detail';
import type { Color } from 'three';

/**
 * A colour prop of a shadelab JSX element: a CSS colour string (sRGB, `'#ff8000'`), a `THREE.Color`, or linear
 * `[r, g, b]`. R3F writes it into the object's `Color` in place (`Color.set`, `fromArray`), so a bare number
 * would be read as a hex colour (`0.2` → black), not as the grey level the constructors take: write a grey
 * level as `[0.2, 0.2, 0.2]`, or pass it in `args`.
 */
export type ColorProp = string | Color | readonly [r: number, g: number, b: number];

/** The JSX props of a shadelab class: R3F's, with its colour properties typed as {@link ColorProp}. */
export type ShadelabElement<T extends ConstructorRepresentation, Colors extends string = never> = Omit<
  ThreeElement<T>,
  Colors
> & {
  [K in Colors]?: ColorProp;
};

/**
 * The JSX elements `@shadelab/react` registers, by element name: each takes the class's documented properties
 * as props (validated by their setters as the class validates them) and its constructor's options in `args`.
 * `<shadingMaterial>`'s list of PhongLights is `phongLights` (three's `lights` is the boolean flag of
 * ShaderMaterial, not the list).
 */
export interface ShadelabElements {
  /** `ShadingMaterial`: flat, Gouraud or Phong shading with Phong, Blinn-Phong or cel lighting. */
  shadingMaterial: ShadelabElement<typeof ShadingMaterial, 'ka' | 'kd' | 'ks'>;
  /** `PhongLight`: the lecture's light source (Ia, Id, Is and attenuation). */
  phongLight: ShadelabElement<typeof PhongLight, 'ambient' | 'diffuse' | 'specular'>;
  /** `SubdivisionSphereGeometry`: the sphere by recursive subdivision; its options go in `args`. */
  subdivisionSphereGeometry: ShadelabElement<typeof SubdivisionSphereGeometry>;
  /** `OutlineMaterial` (`@shadelab/material/outline`): the inverted-hull outline of cel shading. */
  outlineMaterial: ShadelabElement<typeof OutlineMaterial, 'color'>;
  /** `SphereImpostorMaterial` (`@shadelab/material/impostor`): the exact sphere, ray-cast per fragment. */
  sphereImpostorMaterial: ShadelabElement<typeof SphereImpostorMaterial, 'ka' | 'kd' | 'ks'>;
  /** `SphereImpostor` (`@shadelab/material/impostor`): the impostor's quad mesh; `args={[material]}`. */
  sphereImpostor: ShadelabElement<typeof SphereImpostor>;
  /**
   * `AutoDetailSphere` (`@shadelab/sphere/detail`) as a bare element: its detail follows the camera only when
   * something calls `update`; the `<AutoDetailSphere>` component does.
   */
  autoDetailSphere: ShadelabElement<typeof AutoDetailSphere>;
}

declare module '@react-three/fiber' {
  interface ThreeElements extends ShadelabElements {}
}

extend({
  ShadingMaterial,
  PhongLight,
  SubdivisionSphereGeometry,
  OutlineMaterial,
  SphereImpostorMaterial,
  SphereImpostor,
  AutoDetailSphere,
});
