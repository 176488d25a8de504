/**
 * The stats panel's numbers: frames counted (and the first one reported), and what the last frame drew, summed
 * over every cell.
 */
import type { SphereDetail } from '@shadelab/sphere/detail';
import type * as THREE from 'three';
import type { DepthMode } from '../../state/schema';

/** What the stats panel shows. */
export interface FrameStats {
  frames: number;
  /** CPU time of the last frame (submit + 1×1 readPixels), ms. */
  cpuMs: number;
  /** GPU time of a recent frame (EXT_disjoint_timer_query_webgl2), ms; null without the extension. */
  gpuMs: number | null;
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
      cells: this.drawn.length,
      programs: info.programs?.length ?? 0,
      depth: extras.depth,
      detail: extras.detail,
      errorPx: extras.errorPx,
    };
  }
}
