/**
 * The scene picker's slot: the picked scene when it is not the lecture's sphere (built anew, and mounted under
 * the trackball by sceneRoot.tsx's JSX), the panel's material on its parts, and its drawing in the single or the
 * compare view. The user's model (`scene: 'model'`) is built by the app from the file and handed in with
 * {@link PickedScene.setModel}; until it arrives the slot is empty.
 */
import type { PhongLight } from '@shadelab/material';
import type * as THREE from 'three';
import type { PlaygroundState, SceneName, Shading } from '../../state/schema';
import { createScene, type DemoScene } from '../scenes';
import { applyMaterial, applyOutline } from './applyState';
import { type CellRenderer, drawCells, type Layout } from './layout';
import type { Drawn } from './stats';

export class PickedScene {
  /** The picked scene; null for the lecture's sphere (and for the model until it is handed in). */
  private demo: { name: SceneName; scene: DemoScene } | null = null;
  private picked: SceneName = 'sphere';
  /** The model handed in before its scene was picked (taken by the next `pick('model')`). */
  private model: DemoScene | null = null;
  /** The panel's options and lights applied last (a model handed in later gets them). */
  private material: { options: PlaygroundState['material']; lights: PhongLight[] } | null = null;

  /**
   * @param mount - Mounts a scene under the trackball, or none (null), at once (sceneRoot.tsx).
   * @param scene - The three.js scene it is drawn in, with `renderer`.
   * @param requestRender - Asks for the next frame (after each frame of an animating scene).
   */
  constructor(
    private readonly mount: (scene: DemoScene | null) => void,
    private readonly scene: THREE.Scene,
    private readonly renderer: THREE.WebGLRenderer,
    private readonly requestRender: () => void = () => {},
  ) {}

  /** Whether a scene other than the sphere is picked (the model's slot counts, even while it is empty). */
  get active(): boolean {
    return this.picked !== 'sphere';
  }

  /** The model's scene shown or waiting to be shown; null when none was handed in (or it was freed). */
  get modelScene(): DemoScene | null {
    return this.picked === 'model' ? (this.demo?.scene ?? null) : this.model;
  }

  /**
   * Swaps the picked scene in (built anew; the model: the one handed in) and the previous one out (disposed,
   * the model included: picking it again needs a new one).
   */
  pick(name: SceneName): void {
    if (this.picked === name) return;
    const previous = this.demo;
    this.picked = name;
    if (name === 'model') {
      this.demo = this.model ? { name, scene: this.model } : null;
      this.model = null;
    } else {
      this.demo = name === 'sphere' ? null : { name, scene: createScene(name) };
    }
    this.mount(this.demo?.scene ?? null);
    previous?.scene.dispose();
    if (this.demo && this.material) this.applyMaterial(this.material.options, this.material.lights);
  }

  /**
   * Hands in the user's model (built by the app from the file): shown at once when the model is picked (the
   * previous one disposed), else kept for the next `pick('model')`. null frees the model.
   */
  setModel(model: DemoScene | null): void {
    if (this.picked !== 'model') {
      if (this.model !== model) this.model?.dispose();
      this.model = model;
      return;
    }
    const previous = this.demo;
    this.demo = model ? { name: 'model', scene: model } : null;
    this.mount(model);
    if (previous?.scene !== model) previous?.scene.dispose();
    if (model && this.material) this.applyMaterial(this.material.options, this.material.lights);
    this.requestRender();
  }

  /** Takes the picked scene out and frees it (and a model waiting to be shown). */
  leave(): void {
    this.pick('sphere');
    this.setModel(null);
  }

  /** The panel's material options and lights on every part (and its outline). */
  applyMaterial(options: PlaygroundState['material'], lights: PhongLight[]): void {
    this.material = { options, lights };
    const scene = this.demo?.scene;
    if (scene?.applyMaterial) {
      scene.applyMaterial(options);
      return;
    }
    for (const part of scene?.parts ?? []) {
      applyMaterial(part.material, options, lights);
      applyOutline(part.outline, options);
    }
  }

  /**
   * Draws the picked scene: in one view with the panel's shading, or in the compare view's cells with each
   * column's shading and cel bands set on its materials for that cell (and put back after). Adds each part's
   * draw to `drawn`. Drawn with `renderer` (WebGPU mode's, a parity cell's), by default the viewer's.
   */
  draw(
    camera: THREE.Camera,
    material: PlaygroundState['material'],
    { layout, w, h }: { layout: Layout; w: number; h: number },
    drawn: Drawn[],
    renderer: CellRenderer = this.renderer,
  ): void {
    const { scene } = this;
    const picked = this.demo?.scene;
    const parts = picked?.parts ?? [];
    if (picked?.animating) this.requestRender();
    const setShading = (shading: Shading, celBands: number, outline: boolean) => {
      picked?.setShading?.(shading, celBands);
      for (const part of parts) {
        if (!picked?.setShading) {
          part.material.shading = shading;
          part.material.celBands = celBands;
        }
        part.mesh.geometry = part.geometry(shading);
        part.outline.visible = outline;
      }
    };
    const drawnParts = (cell: number) => {
      for (const part of parts)
        drawn.push({ geometry: part.mesh.geometry, outline: part.outline.visible, cell });
    };
    const outline = material.outline && material.celBands > 0;
    if (layout.cols * layout.rows === 1) {
      setShading(material.shading, material.celBands, outline);
      drawnParts(0);
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      renderer.render(scene, camera);
      return;
    }
    try {
      drawCells(renderer, scene, camera, layout, w, h, (column, cell) => {
        setShading(
          column.shading,
          column.cel ? Math.max(3, material.celBands) : 0,
          column.cel && material.outline,
        );
        drawnParts(cell);
      });
    } finally {
      renderer.setScissorTest(false);
      setShading(material.shading, material.celBands, outline);
    }
  }

  /** Frees the parts' programs (the next frame compiles only the variants on screen). */
  freePrograms(): void {
    for (const part of this.demo?.scene.parts ?? []) {
      part.material.dispose();
      part.outline.material.dispose();
    }
  }
}
