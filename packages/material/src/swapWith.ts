// The traversal both swaps run (swapMaterials for ShadingMaterial, swapNodeMaterials for ShadingNodeMaterial):
// which objects and materials are swapped, what is skipped and why, restore() and update().
import type { Material, Object3D } from 'three';
import type { ShadingMaterial, ShadingMaterialOptions } from './ShadingMaterial.js';
import type { Lighting } from './shade.js';
import {
  definedOptions,
  kindOf,
  type ShadingMaterialKind,
  setOptions,
  shadingOptionsOf,
  unsupportedReason,
} from './shadingOptionsOf.js';

/** A material `swapMaterials` left in place, on the object that holds it, with the reason. */
export interface SkippedMaterial {
  /** The object whose material (or one of whose materials) was left in place. */
  readonly object: Object3D;
  /** The material left in place; null when the object's `material` is not a three.js Material. */
  readonly material: Material | null;
  /** Why: what the material or the object is, or the message of the error its conversion threw. */
  readonly reason: string;
}

/**
 * What `swapMaterials` (or `swapNodeMaterials`) did, and how to undo it.
 * @typeParam M - The material class the swap made.
 * @typeParam O - The options `update` takes.
 */
export interface SwappedMaterials<M extends Material = ShadingMaterial, O = ShadingMaterialOptions> {
  /** The materials the swap made (one per distinct original material), in traversal order. */
  readonly materials: readonly M[];
  /** What was left in place, with the reason (also reported once, in one console.warn, when not empty). */
  readonly skipped: readonly SkippedMaterial[];
  /**
   * Sets these options on every material the swap made (live editing: shading, lighting, celBands, ...). The
   * options are checked first: a bad value throws (a TypeError or RangeError naming the parameter) before any
   * material is changed. After `restore()` it still checks, and changes nothing. A new `lighting` without a
   * `shininess` also carries each original's highlight over for that lighting (`'phong'`: three's exponent / 4;
   * `'blinn-phong'`: three's exponent), as the swap did.
   */
  update(options: O): void;
  /**
   * Puts every original material back on its object (the same objects, material arrays included) where the
   * object still holds what the swap gave it, and disposes the materials the swap made (never the originals or
   * their textures); idempotent.
   */
  restore(): void;
}

interface MeshLike extends Object3D {
  material?: unknown;
  isMesh?: boolean;
  isPoints?: boolean;
  isLine?: boolean;
  isSprite?: boolean;
}

/** A swapped object: what it held and what the swap gave it. */
interface Swapped {
  readonly object: MeshLike;
  readonly original: Material | Material[];
  readonly given: Material | Material[];
}

const isMaterial = (value: unknown): value is Material =>
  typeof value === 'object' && value !== null && (value as Material).isMaterial === true;

/**
 * Swaps the materials of every mesh under `root` for materials made by `kind` (one per distinct material,
 * shared where the original is shared; a shared material array stays shared). Never throws during the
 * traversal: what does not convert goes into `skipped`.
 */
export function swapWith<M extends Material, O extends object>(
  kind: ShadingMaterialKind<M, O> & { convert(material: Material, options: O): M },
  root: unknown,
  options: O | undefined,
): SwappedMaterials<M, O> {
  const owner = kind.owner;
  if (typeof root !== 'object' || root === null || (root as Object3D).isObject3D !== true) {
    throw new TypeError(`${owner}: root must be a THREE.Object3D, got ${String(root)}`);
  }
  const overrides = definedOptions(`${owner}: options`, options) as O;
  // A bad option throws here, naming the parameter, before anything is swapped.
  kind.make(overrides).dispose();

  const made = new Map<Material, M>();
  const madeArrays = new Map<Material[], Material[]>();
  const failed = new Map<Material, string>();
  const swapped: Swapped[] = [];
  const skipped: SkippedMaterial[] = [];

  /** The material to put in place of `material` on `object`, or null (then recorded in `skipped`). */
  const convert = (object: Object3D, material: unknown): Material | null => {
    if (!isMaterial(material)) {
      skipped.push({
        object,
        material: null,
        reason: `its material is not a THREE.Material (${String(material)})`,
      });
      return null;
    }
    const done = made.get(material);
    if (done !== undefined) return done;
    let reason = failed.get(material);
    if (reason === undefined && kindOf(material) === null) {
      reason = unsupportedReason(material);
      failed.set(material, reason);
    }
    if (reason === undefined) {
      try {
        const result = kind.convert(material, overrides);
        made.set(material, result);
        return result;
      } catch (error) {
        reason = error instanceof Error ? error.message : String(error);
        failed.set(material, reason);
      }
    }
    skipped.push({ object, material, reason });
    return null;
  };

  (root as Object3D).traverse((object: MeshLike) => {
    const held = object.material;
    if (object.isMesh !== true) {
      const drawn = object.isPoints === true || object.isLine === true || object.isSprite === true;
      if (!drawn || held === undefined) return;
      const reason = `${object.type} draws points, lines or sprites: shading materials light mesh triangles only`;
      for (const material of Array.isArray(held) ? held : [held]) {
        skipped.push({ object, material: isMaterial(material) ? material : null, reason });
      }
      return;
    }
    if (Array.isArray(held)) {
      let given = madeArrays.get(held);
      if (given === undefined) {
        let changed = false;
        given = held.map((material: unknown) => {
          const result = convert(object, material);
          if (result !== null) changed = true;
          return result ?? (material as Material);
        });
        if (!changed) return;
        madeArrays.set(held, given);
      } else {
        // A shared array: its skipped entries are listed for this object too.
        for (const material of held) if (!made.has(material)) convert(object, material);
      }
      object.material = given;
      swapped.push({ object, original: held, given });
      return;
    }
    const given = convert(object, held);
    if (given === null) return;
    object.material = given;
    swapped.push({ object, original: held as Material, given });
  });

  if (skipped.length > 0) {
    const counts = new Map<string, number>();
    for (const { reason } of skipped) counts.set(reason, (counts.get(reason) ?? 0) + 1);
    const lines = [...counts].map(([reason, count]) => `${count} × ${reason}`);
    console.warn(`${owner}: left ${skipped.length} material(s) in place:\n${lines.join('\n')}`);
  }

  const materials = Object.freeze([...made.values()]);
  let restored = false;
  return {
    materials,
    skipped: Object.freeze(skipped),
    update(next: O): void {
      const checked = definedOptions(`${owner}: update options`, next);
      kind.make(checked as O).dispose();
      if (restored) return;
      const lighting = (checked as { lighting?: Lighting }).lighting;
      for (const [original, material] of made) {
        setOptions(material, checked, kind.optionKeys);
        // A new lighting without a shininess: the original's highlight, carried over for that lighting.
        if (lighting !== undefined && !('shininess' in checked)) {
          const shininess = shadingOptionsOf(original, lighting)?.options.shininess;
          if (shininess !== undefined) (material as unknown as { shininess: number }).shininess = shininess;
        }
      }
    },
    restore(): void {
      if (restored) return;
      restored = true;
      for (const { object, original, given } of swapped) {
        if (object.material === given) object.material = original;
      }
      for (const material of materials) material.dispose();
    },
  };
}
