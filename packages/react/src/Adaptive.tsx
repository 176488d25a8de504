import { type ThreeElements, useFrame, useThree } from '@react-three/fiber';
import { ShadingMaterial } from '@shadelab/material';
import {
  type AdaptiveAddOptions,
  AdaptiveShading,
  type AdaptiveShadingOptions,
} from '@shadelab/material/adaptive';
import { type ReactNode, type Ref, useImperativeHandle, useLayoutEffect, useMemo, useRef } from 'react';
import type { Group, InstancedMesh, Mesh, Object3D } from 'three';

/** Props of {@link Adaptive}: the budget and tuning of `AdaptiveShading`, and R3F's props of the group. */
export interface AdaptiveProps
  extends AdaptiveShadingOptions,
    Omit<ThreeElements['group'], 'args' | 'ref' | 'children'> {
  /** The scene part to manage: every Mesh and InstancedMesh under the group whose material is a ShadingMaterial. */
  children?: ReactNode;
  /** For every object added (a shipped `table`, the `shadings` allowed). @default {} */
  addOptions?: AdaptiveAddOptions;
  /** Receives the group. */
  ref?: Ref<Group>;
  /** Receives the `AdaptiveShading` (for `choiceOf`, `groupsOf`, `tableOf`, `stats`); a new one when an option changes. */
  adaptiveRef?: Ref<AdaptiveShading | null>;
}

/** The child InstancedMeshes an AdaptiveShading draws a managed InstancedMesh's instances with. */
const GROUP_NAME = 'AdaptiveShading group';

/**
 * Adaptive shading for a part of an R3F scene: every `Mesh` and `InstancedMesh` under this `<group>` whose
 * material is a `ShadingMaterial` gets, before every frame, the cheapest shading (flat, Gouraud or Phong) and, for
 * a `SubdivisionSphereGeometry`, the cheapest level, that keeps the picture within `maxError` 8-bit sRGB levels of
 * the same scene drawn with Phong shading at full detail (`AdaptiveShading` of `@shadelab/material/adaptive`, for
 * R3F's camera and the canvas's size in physical pixels: CSS size × dpr).
 *
 * - The objects are found by walking the group's subtree before each frame (the walk is the only per-frame cost
 *   of a still scene: `AdaptiveShading.update` is cached): one that appears is added (its error table measured
 *   then, on the CPU, once per geometry and material options; pass `addOptions.table` to ship it), one that
 *   leaves is removed (its material, geometry and instance count put back).
 * - A mesh that cannot be compared with Phong shading (a geometry without normals that is not a sphere) is left
 *   as it is, with one `console.error` naming it.
 * - Changing an option (`maxError`, `overFraction`, `hysteresis`, `levelsBelow`) makes a new `AdaptiveShading`;
 *   the objects move to it. Unmounting puts everything back.
 * - Edit the ShadingMaterial you gave (its props): the variants drawn follow it.
 *
 * @throws RangeError, at render, for a bad budget (not a finite number > 0) or tuning, as `AdaptiveShading`.
 * @example
 * <Adaptive maxError={8}>
 *   <instancedMesh args={[undefined, undefined, 1000]}>
 *     <subdivisionSphereGeometry args={[{ level: 4 }]} />
 *     <shadingMaterial />
 *   </instancedMesh>
 * </Adaptive>
 */
export function Adaptive({
  maxError,
  overFraction,
  hysteresis,
  levelsBelow,
  model,
  addOptions,
  adaptiveRef,
  ref,
  children,
  ...groupProps
}: AdaptiveProps) {
  // biome-ignore lint/correctness/useExhaustiveDependencies: made from the option values; `model` is read once.
  const adaptive = useMemo(
    () => new AdaptiveShading({ maxError, overFraction, hysteresis, levelsBelow, model }),
    [maxError, overFraction, hysteresis, levelsBelow],
  );
  useImperativeHandle(adaptiveRef, () => adaptive, [adaptive]);
  const group = useRef<Group>(null);
  useImperativeHandle(ref, () => group.current as Group, []);
  const managed = useRef(new Set<Mesh>());
  const refused = useRef(new WeakSet<Mesh>());
  const options = useRef(addOptions);
  options.current = addOptions;
  const invalidate = useThree((state) => state.invalidate);
  useLayoutEffect(() => {
    invalidate();
    const objects = managed.current;
    return () => {
      adaptive.dispose();
      objects.clear();
    };
  }, [adaptive, invalidate]);
  useFrame((state) => {
    const root = group.current;
    if (root === null) return;
    const found = meshesUnder(root, managed.current);
    for (const o of managed.current) {
      if (!found.has(o)) {
        adaptive.remove(o);
        managed.current.delete(o);
      }
    }
    for (const o of found) {
      if (managed.current.has(o) || refused.current.has(o)) continue;
      try {
        adaptive.add(o, options.current);
        managed.current.add(o);
      } catch (error) {
        refused.current.add(o);
        console.error(`<Adaptive>: left as it is: ${error instanceof Error ? error.message : String(error)}`);
      }
    }
    if (managed.current.size === 0) return;
    const dpr = state.viewport.dpr;
    adaptive.update(state.camera, { width: state.size.width * dpr, height: state.size.height * dpr });
  });
  return (
    <group ref={group} {...groupProps}>
      {children}
    </group>
  );
}

/** The Meshes and InstancedMeshes under `root` with a ShadingMaterial (managed ones wear its variants). */
function meshesUnder(root: Object3D, managed: ReadonlySet<Mesh>): Set<Mesh> {
  const found = new Set<Mesh>();
  const stack: Object3D[] = [...root.children];
  while (stack.length > 0) {
    const o = stack.pop() as Object3D;
    const mesh = o as Mesh;
    if (mesh.isMesh === true) {
      // The groups an AdaptiveShading adds under a managed InstancedMesh are its own, not the scene's.
      const parent = o.parent as InstancedMesh | null;
      if (o.name === GROUP_NAME && parent !== null && managed.has(parent)) continue;
      if (managed.has(mesh) || mesh.material instanceof ShadingMaterial) found.add(mesh);
    }
    for (const c of o.children) stack.push(c);
  }
  return found;
}
