import { useThree } from '@react-three/fiber';
import {
  type ShadingMaterial,
  type ShadingMaterialOptions,
  type SwappedMaterials,
  swapMaterials,
} from '@shadelab/material';
import { useLayoutEffect, useRef, useState } from 'react';
import type { Object3D } from 'three';

/** A swap the hook made, and what it has applied to it since. */
interface Swap {
  readonly root: Object3D;
  readonly swapped: SwappedMaterials;
  /** The option values applied, by key (a copy of each array, Color and Vector2, to compare by value). */
  readonly applied: Map<string, unknown>;
  /** Each material's own value of a key before an option first set it: put back when the option goes away. */
  readonly own: Map<string, unknown[]>;
}

/** `isColor`/`isVector2` values (three's `Color`, `Vector2`): copied and compared by value. */
interface ValueObject {
  clone(): ValueObject;
  equals(other: never): boolean;
}
const isValueObject = (v: unknown): v is ValueObject =>
  typeof v === 'object' && v !== null && ('isColor' in v || 'isVector2' in v);

/** A copy of an option value that later edits of the caller's object do not change. */
const snapshot = (v: unknown): unknown => (Array.isArray(v) ? [...v] : isValueObject(v) ? v.clone() : v);

/** Whether `next` is the value `applied` recorded: arrays element by element, Colors and Vector2s by value. */
function sameValue(applied: unknown, next: unknown): boolean {
  if (Object.is(applied, next)) return true;
  if (Array.isArray(applied) && Array.isArray(next)) {
    return applied.length === next.length && applied.every((x, i) => Object.is(x, next[i]));
  }
  if (isValueObject(applied) && isValueObject(next) && applied.constructor === next.constructor) {
    return applied.equals(next as never);
  }
  return false;
}

/** The material's property for an option (`lights` is `phongLights`: `lights` is three's own flag). */
const propertyOf = (key: string) => (key === 'lights' ? 'phongLights' : key);

/** A material's current value of an option, copied (its Colors and Vector2 are its own, changed in place). */
function readOption(material: ShadingMaterial, key: string): unknown {
  return snapshot((material as unknown as Record<string, unknown>)[propertyOf(key)]);
}

/** Set one material's option as its constructor does (through the validating setters; `normalScale` copied). */
function writeOption(material: ShadingMaterial, key: string, value: unknown): void {
  if (key === 'normalScale') material.normalScale.copy(value as ShadingMaterial['normalScale']);
  else (material as unknown as Record<string, unknown>)[propertyOf(key)] = value;
}

/**
 * Swaps the materials of a loaded model (a `useGLTF` scene, a `<primitive>`'s object, any Object3D) for
 * `ShadingMaterial`s with `swapMaterials` from `@shadelab/material`, applies `options` to them live, and puts the
 * original materials back when the component unmounts or `root` changes.
 *
 * - The swap happens once per `root`, in a layout effect (so the first frame draws the swapped materials); an
 *   option change never swaps again: the changed options go to `update()`, so the materials stay the same
 *   objects and only a changed variant (shading, lighting, cel bands, …) compiles a program.
 * - Options are compared by value, key by key (arrays such as `ka={[1, 0.5, 0]}` element by element, a `Color`
 *   or `Vector2` with `equals`), so a new object literal each render applies nothing. An option that goes
 *   away (or becomes `undefined`) puts back each material's own value, carried over from its original material.
 * - Restoring puts every original material back and disposes the ShadingMaterials the swap made (nothing the
 *   model owns is disposed); under React's StrictMode the swap, restore and swap of a double mount leave the
 *   model as it was after unmount.
 * - Each change invalidates R3F's frame (`frameloop="demand"` redraws).
 *
 * A bad option value throws the material's `RangeError`/`TypeError` naming it, as the option would in
 * `new ShadingMaterial(…)`. What the swap left in place (`skipped`, with the reason) is also reported once in a
 * console warning.
 *
 * @param root - the object whose meshes get ShadingMaterials; `null`/`undefined` swaps nothing (while a model
 *   loads, say).
 * @param options - the ShadingMaterial options set on every swapped material (shading, lighting, celBands, ka,
 *   …); what is left out keeps what was carried over from each original material.
 * @returns the swap (its `materials`, `skipped`, `update` and `restore`), or `null` before the first swap and
 *   while `root` is `null`. Do not call its `restore()` yourself while the component is mounted.
 *
 * @example
 * function Model() {
 *   const { scene } = useGLTF('/model.glb');
 *   useSwapMaterials(scene, { shading: 'gouraud', lighting: 'blinn-phong' });
 *   return <primitive object={scene} />;
 * }
 */
export function useSwapMaterials(
  root: Object3D | null | undefined,
  options: ShadingMaterialOptions = {},
): SwappedMaterials | null {
  const invalidate = useThree((state) => state.invalidate);
  const [result, setResult] = useState<SwappedMaterials | null>(null);
  const current = useRef<Swap | null>(null);

  // Swap once per root; restore on unmount and before another root is swapped.
  useLayoutEffect(() => {
    if (!root) {
      setResult(null);
      return;
    }
    // Swapped with what each original material carries; the options effect below (run after this one in the
    // same commit) sets the options, so that it knows each material's own value of every option it sets.
    const swap: Swap = { root, swapped: swapMaterials(root), applied: new Map(), own: new Map() };
    current.current = swap;
    setResult(swap.swapped);
    invalidate();
    return () => {
      if (current.current === swap) current.current = null;
      swap.swapped.restore();
      invalidate();
    };
  }, [root, invalidate]);

  // Every commit: apply what changed, put back what went away.
  useLayoutEffect(() => {
    const swap = current.current;
    if (!swap) return;
    const values = options as Record<string, unknown>;
    const changed: Record<string, unknown> = {};
    let count = 0;
    for (const key of Object.keys(values)) {
      const value = values[key];
      if (value === undefined) continue;
      if (swap.applied.has(key) && sameValue(swap.applied.get(key), value)) continue;
      if (!swap.own.has(key)) {
        swap.own.set(
          key,
          swap.swapped.materials.map((m) => readOption(m, key)),
        );
      }
      changed[key] = value;
      count++;
    }
    const removed = [...swap.applied.keys()].filter((key) => values[key] === undefined);
    if (count > 0) {
      swap.swapped.update(changed as ShadingMaterialOptions);
      for (const key of Object.keys(changed)) swap.applied.set(key, snapshot(changed[key]));
    }
    for (const key of removed) {
      const own = swap.own.get(key) ?? [];
      swap.swapped.materials.forEach((m, i) => {
        writeOption(m, key, own[i]);
      });
      swap.applied.delete(key);
    }
    if (count > 0 || removed.length > 0) invalidate();
  });

  return result;
}
