/**
 * What a scene of the picker is to the viewer: objects to put under the trackball's pivot, the meshes drawn with
 * a ShadingMaterial (which take the panel's material options and lights), and what the scene sets on the
 * renderer while it is shown (fog, background, clipping).
 */
import { flatShadingGeometry, type ShadingMaterial } from '@shadelab/material';
import type * as THREE from 'three';
import type { PlaygroundState, Shading } from '../../state/schema';
import { createOutlineMesh, type Outline } from '../meshes';

/** One mesh drawn with a ShadingMaterial, its geometry for each shading, and its cel outline. */
export interface ScenePart {
  readonly mesh: THREE.Mesh;
  readonly material: ShadingMaterial;
  /**
   * The inverted-hull outline (a child of the mesh, of the mesh's kind: instanced or skinned as it is), on the
   * shared geometry whatever the shading; hidden until the viewer shows it.
   */
  readonly outline: Outline;
  /** The geometry for `shading`: flat shading gets a prepared copy, made on first use and kept. */
  geometry(shading: Shading): THREE.BufferGeometry;
  dispose(): void;
}

/** A scene the picker shows instead of the lecture's sphere. */
export interface DemoScene {
  /** Added to the pivot, so the trackball turns it. */
  readonly root: THREE.Object3D;
  readonly parts: readonly ScenePart[];
  /** Sets what the scene needs on the renderer and the three.js scene (undone by `leave`). */
  enter?(scene: THREE.Scene, renderer: THREE.WebGLRenderer): void;
  leave?(scene: THREE.Scene, renderer: THREE.WebGLRenderer): void;
  /** Frees the geometries, materials and textures. */
  dispose(): void;
  /**
   * Sets the panel's material options on the scene, instead of the default (every option and the panel's lights
   * on each part's material): a loaded model keeps its own colours and lights.
   */
  applyMaterial?(options: PlaygroundState['material']): void;
  /** Sets one shading and cel bands on every material of the scene, instead of on each part's material. */
  setShading?(shading: Shading, celBands: number): void;
  /** Advances the scene's animation by `seconds` (each frame's time, from R3F's clock). */
  step?(seconds: number): void;
  /** Whether the scene is animating: the viewer asks for the next frame after each frame it draws. */
  readonly animating?: boolean;
}

/**
 * A part (its material already set on `mesh`, so that the outline shares its clipping planes) whose flat geometry is `makeFlat(shared)` (default: the material's flatShadingGeometry), built on first
 * use.
 */
export function scenePart(
  mesh: THREE.Mesh,
  material: ShadingMaterial,
  makeFlat: (shared: THREE.BufferGeometry) => THREE.BufferGeometry = flatShadingGeometry,
): ScenePart {
  const shared = mesh.geometry;
  let flat: THREE.BufferGeometry | null = null;
  const outline = createOutlineMesh(mesh);
  outline.visible = false;
  return {
    mesh,
    material,
    outline,
    geometry(shading) {
      if (shading !== 'flat') return shared;
      flat ??= makeFlat(shared);
      return flat;
    },
    dispose() {
      mesh.remove(outline);
      outline.material.dispose();
      shared.dispose();
      flat?.dispose();
    },
  };
}

/** Disposes every part's geometries and every distinct material of the parts. */
export function disposeParts(parts: readonly ScenePart[]): void {
  for (const part of parts) part.dispose();
  for (const material of new Set(parts.map((p) => p.material))) material.dispose();
}
