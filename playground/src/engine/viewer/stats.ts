/**
 * The stats panel's numbers: frames counted (and the first one reported), and what the last frame drew, summed
 * over every cell.
 */
import type { SphereDetail } from '@shadelab/sphere/detail';
import type * as THREE from 'three';
import type { DepthMode } from '../../state/schema';
import type { GpuFrame } from '../webgpu/status';

/** What the stats panel shows. */
export interface FrameStats {
  frames: number;
  /** CPU time of the last frame (submit + 1×1 readPixels), ms. */
  cpuMs: number;
  /**
   * GPU time of a recent frame, ms (WebGL mode: EXT_disjoint_timer_query_webgl2; WebGPU mode: three's timestamp
   * queries); null without them, and then `gpuNote` says why.
   */
  gpuMs: number | null;
  /** Why there is no GPU time (WebGPU mode), e.g. "n/a: the WebGPU adapter has no 'timestamp-query' feature". */
  gpuNote?: string | null;
  /** Triangles drawn in the frame (every cell of the compare view, outlines included; three's count). */
  triangles: number;
  /** Vertices drawn in the frame, summed like `triangles` over every draw of the sphere and its outline. */
  vertices: number;
  /** Bytes of the sphere's vertex and index buffers on the GPU (a buffer shared by several cells counts once). */
  bufferBytes: number;
  /** Cells drawn (4 in the compare view). */
  cells: number;
  programs: number;
  /** The depth mode the renderer runs. */
  depth: DepthMode;
  detail: SphereDetail | null;
  /** The drawn sphere's silhouette error on screen, px (an upper bound); null when unknown. */
  errorPx: number | null;
}

/** One draw of the sphere (or of a scene's part) in a cell, and whether its outline was drawn too. */
export interface Drawn {
  geometry: THREE.BufferGeometry;
  outline: boolean;
  /** The cell it was drawn in (0 in the single view): a scene of several parts draws several times in one. */
  cell: number;
}

/** What the viewer knows beside three's counters when it reports stats. */
export type FrameExtras = Pick<FrameStats, 'cpuMs' | 'gpuMs' | 'depth' | 'detail' | 'errorPx'>;

export class FrameCounter {
  /** Frames rendered so far. */
  frames = 0;
  /** The last frame's draws (one per cell and part). */
  drawn: Drawn[] = [];
  private firstFrameReported = false;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly onFirstFrame?: (ms: number) => void,
  ) {}

  /**
   * Whether a frame is asked for (the canvas's `data-render-pending`): a page at rest has neither it nor new
   * frames, which is what tests wait for (an animation asks for its next frame while it draws).
   */
  pending(on: boolean): void {
    this.canvas.toggleAttribute('data-render-pending', on);
  }

  /** Counts a frame (in the canvas's `data-frames` too); the first is reported with its time since navigation. */
  count(): void {
    this.frames += 1;
    this.canvas.dataset['frames'] = String(this.frames);
    if (!this.firstFrameReported) {
      this.firstFrameReported = true;
      const ms = performance.now();
      this.canvas.dataset['firstFrameMs'] = ms.toFixed(1);
      this.onFirstFrame?.(ms);
    }
  }

  /** The stats of the last frame, from three's counters and the geometries drawn. */
  stats(info: THREE.WebGLInfo, extras: FrameExtras): FrameStats {
    const buffers = new Set<ArrayBufferLike | THREE.TypedArray>();
    let bufferBytes = 0;
    let vertices = 0;
    for (const { geometry, outline } of this.drawn) {
      const arrays = Object.values(geometry.attributes).map((a) => (a as THREE.BufferAttribute).array);
      if (geometry.index) arrays.push(geometry.index.array);
      for (const array of arrays) {
        if (buffers.has(array)) continue;
        buffers.add(array);
        bufferBytes += array.byteLength;
      }
      // The outline draws the same geometry again.
      vertices += (geometry.attributes['position']?.count ?? 0) * (outline ? 2 : 1);
    }
    return {
      frames: this.frames,
      cpuMs: extras.cpuMs,
      gpuMs: extras.gpuMs,
      triangles: info.render.triangles,
      vertices,
      bufferBytes,
      cells: new Set(this.drawn.map((d) => d.cell)).size,
      programs: info.programs?.length ?? 0,
      depth: extras.depth,
      detail: extras.detail,
      errorPx: extras.errorPx,
    };
  }
}

/** WebGPU mode's stats: its frames counted, their stats from three's WebGPU counters, its GPU time when it comes. */
export class WebGPUStats {
  private last: FrameStats | null = null;

  constructor(
    private readonly counter: FrameCounter,
    private readonly onStats?: (stats: FrameStats) => void,
  ) {}

  /** A frame WebGPU mode drew (null: nothing drawn yet), with what the viewer knows beside it. */
  frame(frame: GpuFrame | null, extras: Omit<FrameExtras, 'cpuMs' | 'gpuMs' | 'depth'>): void {
    if (!frame) return;
    this.counter.count();
    const info = { render: { triangles: frame.triangles }, programs: { length: frame.programs } };
    this.last = this.counter.stats(info as unknown as THREE.WebGLInfo, {
      ...extras,
      cpuMs: frame.cpuMs,
      gpuMs: frame.gpuMs.ms,
      depth: 'standard',
    });
    this.last.gpuNote = frame.gpuMs.note;
    this.onStats?.(this.last);
  }

  /** A frame's GPU time arrived, ms. */
  readonly gpuTime = (ms: number): void => {
    if (this.last) this.onStats?.({ ...this.last, cpuMs: Number.NaN, gpuMs: ms, gpuNote: null });
  };

  /** WebGPU mode was left: a late GPU time is not reported. */
  reset(): void {
    this.last = null;
  }
}

/**
 * three keeps every program a material ever used until the material is disposed; a long session visiting many
 * variants would grow without bound. Past `cap` programs, `owners` free theirs: the next frame recompiles only
 * the variants on screen.
 */
export function capPrograms(
  renderer: THREE.WebGLRenderer,
  cap: number,
  owners: readonly { freePrograms(): void }[],
): void {
  if ((renderer.info.programs?.length ?? 0) <= cap) return;
  for (const owner of owners) owner.freePrograms();
}
