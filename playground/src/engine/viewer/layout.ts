/**
 * The comparison layout: the compare view's columns, its cells on the canvas (one row on wide canvases, 2 × 2
 * otherwise), and the canvas size every cell is cut from.
 */
import * as THREE from 'three';

/** The compare view's columns, as in the lecture's slide. */
export const COMPARE_COLUMNS = [
  { label: 'flat', shading: 'flat', cel: false },
  { label: 'Gouraud', shading: 'gouraud', cel: false },
  { label: 'Phong', shading: 'phong', cel: false },
  { label: 'cel', shading: 'phong', cel: true },
] as const;

/** One of {@link COMPARE_COLUMNS}. */
export type CompareColumn = (typeof COMPARE_COLUMNS)[number];

/** Cells of the compare view. */
export interface Layout {
  cols: number;
  rows: number;
}

/** The single view's one cell. */
export const SINGLE: Layout = { cols: 1, rows: 1 };

/** The compare view in one row on wide canvases, 2 × 2 otherwise (cells as close to square as possible). */
export function compareLayout(width: number, height: number): Layout {
  return width / height >= 2 ? { cols: COMPARE_COLUMNS.length, rows: 1 } : { cols: 2, rows: 2 };
}

/** The canvas's size in CSS pixels (its drawing buffer's before it is laid out), at least 1 × 1. */
export function canvasSize(canvas: HTMLCanvasElement): { w: number; h: number } {
  return {
    w: Math.max(1, canvas.clientWidth || canvas.width),
    h: Math.max(1, canvas.clientHeight || canvas.height),
  };
}

const _size = /* @__PURE__ */ new THREE.Vector2();

/** Sizes the renderer's drawing buffer to its canvas's size (when it differs); returns that size. */
export function fitToCanvas(
  renderer: THREE.WebGLRenderer,
  canvas: HTMLCanvasElement,
): { w: number; h: number } {
  const size = canvasSize(canvas);
  renderer.getSize(_size);
  if (_size.x !== size.w || _size.y !== size.h) renderer.setSize(size.w, size.h, false);
  return size;
}

/** The cells drawn on `canvas` in `view`: the compare and parity views' four (compareLayout), or one. */
export function viewLayout(canvas: HTMLCanvasElement, view: string | undefined): Layout {
  const { w, h } = canvasSize(canvas);
  return view === 'compare' || view === 'parity' ? compareLayout(w, h) : SINGLE;
}

/** Width over height of one cell of `layout` on `canvas`. */
export function cellAspect(canvas: HTMLCanvasElement, { cols, rows }: Layout): number {
  const { w, h } = canvasSize(canvas);
  return w / cols / (h / rows);
}

/**
 * What the views draw with: three's WebGLRenderer, or an adapter with WebGL's conventions (viewport and scissor
 * from the bottom left) around WebGPURenderer (`webgpu/gpuCells.ts`) or around one cell of a canvas.
 */
export interface CellRenderer {
  setScissorTest(on: boolean): void;
  setViewport(x: number, y: number, width: number, height: number): void;
  setScissor(x: number, y: number, width: number, height: number): void;
  render(scene: THREE.Object3D, camera: THREE.Camera): void;
}

/** Cell `i` of `layout` on a `w` × `h` canvas, in pixels from the bottom left (row by row from the top). */
export function cellRect(
  { cols, rows }: Layout,
  w: number,
  h: number,
  i: number,
): { x: number; y: number; width: number; height: number } {
  const cw = w / cols;
  const ch = h / rows;
  const col = i % cols;
  const row = Math.floor(i / cols);
  const x = Math.round(col * cw);
  const y = Math.round(h - (row + 1) * ch);
  return { x, y, width: Math.round((col + 1) * cw) - x, height: Math.round(h - row * ch) - y };
}

/**
 * Draws `scene` once per compare column, each in its cell of a `w` × `h` canvas (row by row from the top),
 * after `setUp(column, i)` has set that column's shading. The scissor test is left on: the caller turns it off.
 */
export function drawCells(
  renderer: CellRenderer,
  scene: THREE.Scene,
  camera: THREE.Camera,
  layout: Layout,
  w: number,
  h: number,
  setUp: (column: CompareColumn, i: number) => void,
): void {
  renderer.setScissorTest(true);
  COMPARE_COLUMNS.forEach((column, i) => {
    setUp(column, i);
    const { x, y, width, height } = cellRect(layout, w, h, i);
    renderer.setViewport(x, y, width, height);
    renderer.setScissor(x, y, width, height);
    renderer.render(scene, camera);
  });
}
