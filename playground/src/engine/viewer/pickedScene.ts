/**
 * The scene picker's slot: the picked scene when it is not the lecture's sphere (built anew, and mounted under
 * the trackball by sceneRoot.tsx's JSX), the panel's material on its parts, and its drawing in the single or the
 * compare view.
 */
import type { PhongLight } from '@shadelab/material';
import type * as THREE from 'three';
import type { PlaygroundState, SceneName, Shading } from '../../state/schema';
import { createScene, type DemoScene } from '../scenes';
import { applyMaterial, applyOutline } from './applyState';
import { drawCells, type Layout } from './layout';
import type { Drawn } from './stats';

export class PickedScene {
  /** The picked scene; null for the lecture's sphere. */
  private demo: { name: SceneName; scene: DemoScene } | null = null;

  /**
   * @param mount - Mounts a scene under the trackball, or none (null), at once (sceneRoot.tsx).
   * @param scene - The three.js scene it is drawn in, with `renderer`.
   */
  constructor(
    private readonly mount: (scene: DemoScene | null) => void,
    private readonly scene: THREE.Scene,
    private readonly renderer: THREE.WebGLRenderer,
  ) {}

  /** Whether a scene other than the sphere is picked. */
  get active(): boolean {
    return this.demo !== null;
  }

  /** Swaps the picked scene in (built anew) and the previous one out (disposed); the sphere is none. */
  pick(name: SceneName): void {
    if (this.demo?.name === name) return;
    const previous = this.demo;
    this.demo = name === 'sphere' ? null : { name, scene: createScene(name) };
    this.mount(this.demo?.scene ?? null);
    previous?.scene.dispose();
  }

  /** Takes the picked scene out and frees it. */
  leave(): void {
    this.pick('sphere');
  }

  /** The panel's material options and lights on every part (and its outline). */
  applyMaterial(options: PlaygroundState['material'], lights: PhongLight[]): void {
    for (const part of this.demo?.scene.parts ?? []) {
      applyMaterial(part.material, options, lights);
      applyOutline(part.outline, options);
    }
  }

  /**
   * Draws the picked scene: in one view with the panel's shading, or in the compare view's cells with each
   * column's shading and cel bands set on its materials for that cell (and put back after). Adds each part's
   * draw to `drawn`.
   */
  draw(
    camera: THREE.Camera,
    material: PlaygroundState['material'],
    { layout, w, h }: { layout: Layout; w: number; h: number },
    drawn: Drawn[],
  ): void {
    const { renderer, scene } = this;
    const parts = this.demo?.scene.parts ?? [];
    const setShading = (shading: Shading, celBands: number, outline: boolean) => {
      for (const part of parts) {
        part.material.shading = shading;
        part.material.celBands = celBands;
        part.mesh.geometry = part.geometry(shading);
        part.outline.visible = outline;
      }
    };
    const drawnParts = () => {
      for (const part of parts) drawn.push({ geometry: part.mesh.geometry, outline: part.outline.visible });
    };
    const outline = material.outline && material.celBands > 0;
    if (layout.cols * layout.rows === 1) {
      setShading(material.shading, material.celBands, outline);
      drawnParts();
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      renderer.render(scene, camera);
      return;
    }
    try {
      drawCells(renderer, scene, camera, layout, w, h, (column) => {
        setShading(
          column.shading,
          column.cel ? Math.max(3, material.celBands) : 0,
          column.cel && material.outline,
        );
        drawnParts();
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
