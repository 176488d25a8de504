/**
 * The lecture's sphere: its mesh (with the panel's material, and one material per compare column), the cel
 * outline, the ray-cast impostor, and the subdivision geometries of the current base and level (chosen from the
 * silhouette error on screen with automatic detail).
 */
import { type PhongLight, ShadingMaterial } from '@shadelab/material';
import type { SphereImpostor } from '@shadelab/material/impostor';
import {
  chooseSphereDetail,
  type SphereDetail,
  silhouetteErrorScalePx,
  sphereError,
} from '@shadelab/sphere/detail';
import type * as THREE from 'three';
import type { PlaygroundState, Shading, SphereBase } from '../../state/schema';
import { createOutlineMesh, createSphere, type Outline, sphereKey } from '../meshes';
import { applyLighting, applyMaterial, applyOutline, columnOptions } from './applyState';
import { COMPARE_COLUMNS, drawCells, type Layout } from './layout';
import type { LectureSphereObjects } from './sceneRoot';
import type { Drawn } from './stats';

export class LectureSphere {
  /** The panel's material (its program is the one the shader editor shows). */
  readonly material: ShadingMaterial;
  /** One material per compare column. */
  readonly compareMaterials = COMPARE_COLUMNS.map(() => new ShadingMaterial());
  readonly mesh: THREE.Mesh;
  readonly outline: Outline;
  /** The ray-cast sphere, drawn instead of the mesh when `sphere.render` is 'impostor' (single view). */
  readonly impostor: SphereImpostor;
  /** The level of detail automatic detail chose last; null when it is off. */
  detail: SphereDetail | null = null;
  /** Geometries of the current base, level and radius, by {@link sphereKey}. */
  private geometries = new Map<string, THREE.BufferGeometry>();
  private current: { base: SphereBase; level: number; radius: number } | null = null;

  /** Takes the mesh, its material and the impostor that sceneRoot.tsx mounted, and gives the mesh its outline. */
  constructor({ mesh, material, impostor }: Pick<LectureSphereObjects, 'mesh' | 'material' | 'impostor'>) {
    this.mesh = mesh;
    this.material = material;
    this.impostor = impostor;
    this.outline = createOutlineMesh(this.mesh);
    this.outline.visible = false;
  }

  /** The panel's material options on the mesh's material, each column's and the impostor's, and the outline. */
  applyMaterial(options: PlaygroundState['material'], lights: PhongLight[]): void {
    applyMaterial(this.material, options, lights);
    COMPARE_COLUMNS.forEach((column, i) => {
      applyMaterial(this.compareMaterials[i]!, columnOptions(options, column), lights);
    });
    applyLighting(this.impostor.material, options, lights);
    applyOutline(this.outline, options);
  }

  /**
   * Builds the geometries the view draws (each compare column's shading, or the panel's), at the state's base
   * and level or, with automatic detail, the cheapest within `sphere.maxErrorPx` at `errorScalePx` pixels per
   * unit of relative error. A refused level throws before anything is swapped: the previous sphere stays.
   */
  applySphere(state: PlaygroundState, errorScalePx: () => number): void {
    let { base, level } = state.sphere;
    const { radius } = state.sphere;
    this.detail = null;
    if (state.sphere.auto) {
      this.detail = chooseSphereDetail({ radiusPx: errorScalePx(), maxErrorPx: state.sphere.maxErrorPx });
      ({ base, level } = this.detail);
    }
    const shadings =
      state.view === 'compare' ? COMPARE_COLUMNS.map((c) => c.shading) : [state.material.shading];
    const wanted = new Map<string, THREE.BufferGeometry>();
    for (const shading of shadings) {
      const key = sphereKey(base, level, shading, radius);
      if (wanted.has(key)) continue;
      wanted.set(key, this.geometries.get(key) ?? createSphere(base, level, shading, radius));
    }
    for (const [key, geometry] of this.geometries) if (!wanted.has(key)) geometry.dispose();
    this.geometries = wanted;
    this.current = { base, level, radius };
    this.showGeometry(state.material.shading);
  }

  /** Puts the sphere geometry for `shading` on the mesh (and its outline). */
  showGeometry(shading: Shading): void {
    if (!this.current) return;
    const { base, level, radius } = this.current;
    const geometry = this.geometries.get(sphereKey(base, level, shading, radius));
    if (!geometry) return;
    this.mesh.geometry = geometry;
    this.outline.geometry = geometry;
  }

  /** The silhouette error on screen in pixels (at most); null before a sphere is built or when unknown. */
  errorPx(errorScalePx: () => number): number | null {
    if (!this.current) return null;
    try {
      const scale = errorScalePx();
      return sphereError(this.current.base, this.current.level) * scale;
    } catch {
      return null;
    }
  }

  /**
   * Draws the sphere in the single view, or each compare column's in its cell; adds each draw to `drawn`.
   *
   * Imperative: the compare view draws the one mesh four times in a frame, its material and geometry swapped
   * between `renderer.render` calls under a scissor per cell, which no single set of JSX props can say. In R3F
   * this is a `useFrame` that takes the render over (priority 1); it moves there once R3F drives the frame, which
   * it does not yet (`frameloop: 'never'`, the viewer renders on demand): `advance` would also run
   * `useTrackball`'s damping `useFrame` beside input.ts's own spin, turning a damped sphere twice per frame.
   */
  draw(
    renderer: THREE.WebGLRenderer,
    scene: THREE.Scene,
    camera: THREE.Camera,
    state: PlaygroundState,
    { layout, w, h }: { layout: Layout; w: number; h: number },
    drawn: Drawn[],
  ): void {
    const cells = layout.cols * layout.rows;
    const impostor = state.sphere.render === 'impostor';
    this.outline.visible = state.material.outline && state.material.celBands > 0;
    this.mesh.visible = !impostor || cells > 1;
    this.impostor.visible = impostor && cells === 1;
    if (cells === 1) {
      this.mesh.material = this.material;
      this.showGeometry(state.material.shading);
      drawn.push(
        impostor
          ? { geometry: this.impostor.geometry, outline: false }
          : { geometry: this.mesh.geometry, outline: this.outline.visible },
      );
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      renderer.render(scene, camera);
      return;
    }
    drawCells(renderer, scene, camera, layout, w, h, (column, i) => {
      this.mesh.material = this.compareMaterials[i]!;
      this.showGeometry(column.shading);
      this.outline.visible = column.cel && state.material.outline;
      drawn.push({ geometry: this.mesh.geometry, outline: this.outline.visible });
    });
    renderer.setScissorTest(false);
    this.mesh.material = this.material;
    this.showGeometry(state.material.shading);
  }

  /** Hides the mesh, its outline and the impostor (a picked scene is drawn instead). */
  hide(): void {
    this.mesh.visible = false;
    this.impostor.visible = false;
    this.outline.visible = false;
  }

  /** Frees the materials' programs (the next frame compiles only the variants on screen). */
  freePrograms(): void {
    this.material.dispose();
    for (const material of this.compareMaterials) material.dispose();
  }

  dispose(): void {
    for (const geometry of this.geometries.values()) geometry.dispose();
    this.freePrograms();
    this.outline.material.dispose();
    this.impostor.geometry.dispose();
    this.impostor.material.dispose();
  }
}

/**
 * Pixels of silhouette error on screen per unit of the sphere's relative radial error: an upper bound for this
 * camera and model matrix, near the camera and off axis too (@shadelab/sphere's `silhouetteErrorScalePx`). Capped
 * at sixteen viewport heights: with the eye inside the sphere, or its outline reaching behind the eye, it is
 * Infinity, and no detail is needed beyond the finest level there.
 */
export function cappedErrorScalePx(
  camera: THREE.Camera,
  matrixWorld: THREE.Matrix4,
  viewportHeightPx: number,
  radius: number,
): number {
  const px = silhouetteErrorScalePx({ camera, matrixWorld, viewportHeightPx, radius });
  return Math.min(px, 16 * viewportHeightPx);
}
