import type { ThreeElements } from '@react-three/fiber';
import { SHADING_MATERIAL_OPTION_KEYS, type ShadingMaterialOptions } from '@shadelab/material';
import type { ReactNode, Ref } from 'react';
import type { Object3D } from 'three';
import { useSwapMaterials } from './useSwapMaterials.js';

/** Every ShadingMaterial option, to tell them from the object's props (`@shadelab/material`'s complete list). */
const OPTION_KEYS = SHADING_MATERIAL_OPTION_KEYS;

/**
 * Props of {@link ShadedModel}: the object, the ShadingMaterial options, and R3F's props of the object (but its
 * `normalMatrix`, which three computes: the prop is the material option).
 */
export interface ShadedModelProps
  extends ShadingMaterialOptions,
    Omit<ThreeElements['group'], 'args' | 'ref' | 'children' | 'object' | 'normalMatrix'> {
  /** The model (a `useGLTF` scene, any Object3D): rendered as a `<primitive>`, its materials swapped. */
  object: Object3D;
  /** Placed inside the object, as `<primitive>` children are. */
  children?: ReactNode;
  /** Receives the object. */
  ref?: Ref<Object3D>;
}

/**
 * A loaded model drawn with `ShadingMaterial`s: renders `object` as a `<primitive>` (position, rotation, scale and
 * the other props go to it, as with drei's `<Clone>`) and swaps its materials with {@link useSwapMaterials}:
 * every three.js material that `toShadingMaterial` converts becomes a ShadingMaterial that keeps its colour, maps
 * and alpha, the option props (`shading`, `lighting`, `celBands`, `ka`, …) are applied live, and the original
 * materials are put back on unmount. Use the hook when you need the swap itself (its `skipped` list, say).
 *
 * @example
 * function Model() {
 *   const { scene } = useGLTF('/model.glb');
 *   return <ShadedModel object={scene} shading="gouraud" lighting="blinn-phong" position={[0, -1, 0]} />;
 * }
 */
export function ShadedModel(props: ShadedModelProps) {
  const options: Record<string, unknown> = {};
  const rest: Record<string, unknown> = {};
  for (const [key, value] of Object.entries(props)) {
    if ((OPTION_KEYS as readonly string[]).includes(key)) options[key] = value;
    else rest[key] = value;
  }
  const { object, children, ref, ...objectProps } = rest as Omit<
    ShadedModelProps,
    (typeof OPTION_KEYS)[number]
  >;
  useSwapMaterials(object, options as ShadingMaterialOptions);
  return (
    <primitive object={object} ref={ref} {...objectProps}>
      {children}
    </primitive>
  );
}
