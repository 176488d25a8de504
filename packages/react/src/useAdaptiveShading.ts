import { useFrame, useThree } from '@react-three/fiber';
import {
  type AdaptiveAddOptions,
  AdaptiveShading,
  type AdaptiveShadingOptions,
} from '@shadelab/material/adaptive';
import { useLayoutEffect, useMemo } from 'react';
import type { Mesh } from 'three';

/**
 * `AdaptiveShading` (`@shadelab/material/adaptive`) driven by R3F: the objects (Meshes or InstancedMeshes with a
 * `ShadingMaterial`) get, before every frame, the cheapest shading and detail that keeps `maxError` (8-bit sRGB
 * levels against Phong shading at full detail) for R3F's camera and canvas (in physical pixels).
 *
 * - The `AdaptiveShading` is made once per set of options (`maxError`, `overFraction`, `hysteresis`,
 *   `levelsBelow`); changing one makes a new one, and the objects move to it.
 * - The objects are added in a layout effect (their error tables measured there, on the CPU; pass `table` in
 *   `addOptions` to skip it) and removed, with their materials, geometries and instance counts put back, when
 *   they leave the list or the component unmounts.
 * - It runs in `useFrame` at priority 0, before R3F draws; with `frameloop="demand"`, a frame drawn for another
 *   reason updates the choice.
 *
 * @param objects - the objects to manage (`null` entries, say refs not yet set, are skipped).
 * @param options - the budget and the tuning (see `AdaptiveShadingOptions`).
 * @param addOptions - for every object (see `AdaptiveAddOptions`).
 * @returns the `AdaptiveShading` (for `choiceOf`, `groupsOf`, `tableOf`).
 * @throws the RangeError of `AdaptiveShading` for a bad budget, the TypeError of `add` for an object without a
 *   ShadingMaterial.
 */
export function useAdaptiveShading(
  objects: readonly (Mesh | null | undefined)[],
  options: AdaptiveShadingOptions,
  addOptions?: AdaptiveAddOptions,
): AdaptiveShading {
  const { maxError, overFraction, hysteresis, levelsBelow } = options;
  // biome-ignore lint/correctness/useExhaustiveDependencies: made from the option values; `model` is read once.
  const adaptive = useMemo(
    () => new AdaptiveShading({ maxError, overFraction, hysteresis, levelsBelow, model: options.model }),
    [maxError, overFraction, hysteresis, levelsBelow],
  );
  const invalidate = useThree((state) => state.invalidate);
  const present = objects.filter((o): o is Mesh => o !== null && o !== undefined);
  const key = present.map((o) => o.uuid).join();
  // biome-ignore lint/correctness/useExhaustiveDependencies: the objects are keyed by their uuids.
  useLayoutEffect(() => {
    for (const o of present) adaptive.add(o, addOptions);
    invalidate();
    return () => {
      for (const o of present) adaptive.remove(o);
    };
  }, [adaptive, key]);
  useLayoutEffect(() => () => adaptive.dispose(), [adaptive]);
  useFrame((state) => {
    if (adaptive.objects.length === 0) return;
    const dpr = state.viewport.dpr;
    adaptive.update(state.camera, { width: state.size.width * dpr, height: state.size.height * dpr });
  });
  return adaptive;
}
