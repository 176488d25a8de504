/**
 * The parity view's frame: WebGL mode's picture drawn in the first cell of the viewer's canvas and read back,
 * WebGPU mode's picture of the same state drawn offscreen at that cell's size (webgpu/WebGPUView.ts, output
 * 'offscreen': never presented, so the WebGPU backend runs headless too) and read back, and the two compared
 * (`parity/parityDiff.ts`). The app shows WebGPU's picture, the heat map and the numbers in the other cells.
 */
import type * as THREE from 'three';
import { type ParityNumbers, parityDiff } from '../../parity/parityDiff';
import type { WebGPUSwitch } from '../webgpu/switch';
import { type CellRenderer, cellRect, type Layout, SINGLE } from './layout';

/** One comparison: both read-backs (RGBA8 sRGB, rows bottom-up), the heat map (rows top-down) and the numbers. */
export interface ParityResult {
  /** The comparison's number (1, 2, …): a newer frame's is larger. */
  readonly seq: number;
  readonly w: number;
  readonly h: number;
  /** WebGL's cell on the viewer's canvas, in GL pixels from the bottom left. */
  readonly cell: { x: number; y: number; width: number; height: number };
  readonly webgl: Uint8Array;
  readonly webgpu: Uint8Array;
  readonly heatmap: Uint8ClampedArray<ArrayBuffer>;
  readonly numbers: ParityNumbers;
}

/** Draws one view with `renderer` on a `w` × `h` target in `layout` (the viewer's draw code). */
export type DrawViews = (renderer: CellRenderer, w: number, h: number, layout: Layout) => void;

export class ParityFrames {
  /** The frame whose comparison is awaited (a newer frame drops an older read-back). */
  private generation = 0;

  constructor(
    private readonly renderer: THREE.WebGLRenderer,
    private readonly webgpu: WebGPUSwitch,
    private readonly draw: DrawViews,
    private readonly onResult: (result: ParityResult) => void,
  ) {}

  /** Draws WebGL's cell of a `w` × `h` canvas in `layout` now, and WebGPU's picture offscreen; compares both. */
  frame(w: number, h: number, layout: Layout): void {
    const { renderer } = this;
    const cell = cellRect(layout, w, h, 0);
    const { width: cw, height: ch } = cell;
    renderer.setScissorTest(false);
    renderer.clear();
    renderer.setScissorTest(true);
    renderer.setScissor(cell.x, cell.y, cw, ch);
    const inCell: CellRenderer = {
      setScissorTest: () => {},
      setViewport: (x, y, width, height) => renderer.setViewport(cell.x + x, cell.y + y, width, height),
      setScissor: (x, y, width, height) => renderer.setScissor(cell.x + x, cell.y + y, width, height),
      render: (scene, camera) => renderer.render(scene, camera),
    };
    try {
      this.draw(inCell, cw, ch, SINGLE);
    } finally {
      renderer.setScissorTest(false);
    }
    const gl = renderer.getContext();
    const webgl = new Uint8Array(4 * cw * ch);
    gl.readPixels(cell.x, cell.y, cw, ch, gl.RGBA, gl.UNSIGNED_BYTE, webgl);
    const drawn = this.webgpu.render((gpu, gw, gh) => this.draw(gpu, gw, gh, SINGLE), { w: cw, h: ch });
    if (!drawn) return;
    const generation = ++this.generation;
    void this.webgpu.read().then(
      (read) => {
        if (generation !== this.generation || !read || read.w !== cw || read.h !== ch) return;
        const { numbers, heatmap } = parityDiff(webgl, read.pixels, cw, ch);
        this.onResult({ seq: generation, w: cw, h: ch, cell, webgl, webgpu: read.pixels, heatmap, numbers });
      },
      () => {},
    );
  }
}
