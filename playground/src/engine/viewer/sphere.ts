/**
 * The lecture's sphere: its mesh (with the panel's material), the compare view's meshes (one per column, with
 * that column's material), the cel outlines, the ray-cast impostor, and the subdivision geometries of the
 * current base and level (chosen from the silhouette error on screen with automatic detail).
 */
import type { PhongLight, ShadingMaterial } from '@shadelab/material';
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
import { type CellRenderer, COMPARE_COLUMNS, drawCells, type Layout } from './layout';
import type { LectureSphereObjects } from './sceneRoot';
import type { Drawn } from './stats';

export class LectureSphere {
  /** The panel's material (its program is the one the shader editor shows). */
  readonly material: ShadingMaterial;
  readonly mesh: THREE.Mesh;
  readonly outline: Outline;
  /** The compare view's meshes, one per column, each drawn in its own cell. */
  readonly columns: LectureSphereObjects['columns'];
  /** The outline of each cel column's mesh (null for the others). */
  private readonly columnOutlines: (Outline | null)[];
  /** The ray-cast sphere, drawn instead of the mesh when `sphere.render` is 'impostor' (single view). */
  readonly impostor: SphereImpostor;
  /** The level of detail automatic detail chose last; null when it is off. */
  detail: SphereDetail | null = null;
  /** Geometries of the current base, level and radius, by {@link sphereKey}. */
  private geometries = new Map<string, THREE.BufferGeometry>();
  private current: { base: SphereBase; level: number; radius: number } | null = null;
  /** Whether the last frame drew the impostor (the single view's; the compare view draws the meshes). */
  private drewImpostor = false;

  /** Takes the meshes, the material and the impostor that sceneRoot.tsx mounted, and gives the meshes outlines. */
  constructor({
    mesh,
    material,
    impostor,
    columns,
  }: Pick<LectureSphereObjects, 'mesh' | 'material' | 'impostor' | 'columns'>) {
    this.mesh = mesh;
    this.material = material;
    this.impostor = impostor;
    this.columns = columns;
    this.outline = createOutlineMesh(this.mesh);
    this.outline.visible = false;
    this.columnOutlines = COMPARE_COLUMNS.map((column, i) =>
      column.cel ? createOutlineMesh(columns[i]!) : null,
    );
  }

  /** The panel's material options on the mesh's material, each column's and the impostor's, and the outline. */
  applyMaterial(options: PlaygroundState['material'], lights: PhongLight[]): void {
    applyMaterial(this.material, options, lights);
    COMPARE_COLUMNS.forEach((column, i) => {
      applyMaterial(this.columns[i]!.material, columnOptions(options, column), lights);
    });
    applyLighting(this.impostor.material, options, lights);
    for (const outline of [this.outline, ...this.columnOutlines]) if (outline) applyOutline(outline, options);
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

  /** Puts the sphere geometry for `shading` on the single view's mesh (and its outline). */
  showGeometry(shading: Shading): void {
    this.setGeometry(this.mesh, this.outline, shading);
  }

  /** Puts the sphere geometry for `shading` on `mesh` and its outline. */
  private setGeometry(mesh: THREE.Mesh, outline: Outline | null, shading: Shading): void {
    if (!this.current) return;
    const { base, level, radius } = this.current;
    const geometry = this.geometries.get(sphereKey(base, level, shading, radius));
    if (!geometry) return;
    mesh.geometry = geometry;
    if (outline) outline.geometry = geometry;
  }

  /**
   * The silhouette error on screen in pixels (at most) of the sphere drawn last: 0 for the impostor (the exact
   * sphere); null before a sphere is built or when unknown.
   */
  errorPx(errorScalePx: () => number): number | null {
    if (!this.current) return null;
    if (this.drewImpostor) return 0;
    try {
      const scale = errorScalePx();
      return sphereError(this.current.base, this.current.level) * scale;
    } catch {
      return null;
    }
  }

  /**
   * Draws the sphere in the single view (the mesh or the impostor), or in the compare view each column's mesh in
   * its cell (only that one shown); adds each draw to `drawn`.
   */
  draw(
    renderer: CellRenderer,
    scene: THREE.Scene,
    camera: THREE.Camera,
    state: PlaygroundState,
    { layout, w, h }: { layout: Layout; w: number; h: number },
    drawn: Drawn[],
  ): void {
    const impostor = state.sphere.render === 'impostor';
    this.drewImpostor = impostor && layout.cols * layout.rows === 1;
    if (layout.cols * layout.rows === 1) {
      this.outline.visible = state.material.outline && state.material.celBands > 0;
      this.mesh.visible = !impostor;
      this.impostor.visible = impostor;
      this.showGeometry(state.material.shading);
      drawn.push(
        impostor
          ? { geometry: this.impostor.geometry, outline: false, cell: 0 }
          : { geometry: this.mesh.geometry, outline: this.outline.visible, cell: 0 },
      );
      renderer.setScissorTest(false);
      renderer.setViewport(0, 0, w, h);
      renderer.render(scene, camera);
      return;
    }
    this.hide();
    try {
      drawCells(renderer, scene, camera, layout, w, h, (column, i) => {
        const outline = this.columnOutlines[i] ?? null;
        this.columns.forEach((mesh, j) => {
          mesh.visible = j === i;
        });
        this.setGeometry(this.columns[i]!, outline, column.shading);
        if (outline) outline.visible = state.material.outline;
        drawn.push({ geometry: this.columns[i]!.geometry, outline: outline?.visible ?? false, cell: i });
      });
    } finally {
      renderer.setScissorTest(false);
      for (const mesh of this.columns) mesh.visible = false;
    }
  }

  /** Hides the meshes, their outlines and the impostor (a picked scene, or the compare view, is drawn instead). */
  hide(): void {
    for (const object of [this.mesh, this.impostor, this.outline, ...this.columns]) object.visible = false;
  }

  /** Frees the materials' programs (the next frame compiles only the variants on screen). */
  freePrograms(): void {
    this.material.dispose();
    for (const mesh of this.columns) mesh.material.dispose();
  }

  dispose(): void {
    for (const geometry of this.geometries.values()) geometry.dispose();
    this.freePrograms();
    for (const outline of [this.outline, ...this.columnOutlines]) outline?.material.dispose();
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
