// The parity view's overlay (view: 'parity'), over the viewer's canvas in its compare layout: cell 1 is WebGL
// mode's picture (drawn by the viewer on its own canvas), cell 2 WebGPU mode's (its read-back), cell 3 the heat
// map of their difference (the trade-off page's colours and legend) and cell 4 the numbers.
import { useEffect, useRef } from 'react';
import type { Layout } from '../engine/viewer/layout';
import type { ParityResult } from '../engine/viewer/parity';
import { backendLabel, type WebGPUStatus } from '../engine/webgpu/status';
import { HeatmapLegend } from '../tradeoff/HeatmapLegend';
import { topDown } from './parityDiff';

/** Puts RGBA rows (top-down) of a `w` × `h` picture on `canvas`. */
function paint(canvas: HTMLCanvasElement | null, rgba: Uint8ClampedArray<ArrayBuffer>, w: number, h: number) {
  if (!canvas) return;
  canvas.width = w;
  canvas.height = h;
  canvas.getContext('2d')?.putImageData(new ImageData(rgba, w, h), 0, 0);
}

const percent = (n: number, of: number) => `${((100 * n) / Math.max(1, of)).toFixed(2)} %`;

export function ParityPanel({
  result,
  layout,
  status,
}: {
  result: ParityResult | null;
  layout: Layout;
  status: WebGPUStatus | null;
}) {
  const gpu = useRef<HTMLCanvasElement>(null);
  const heat = useRef<HTMLCanvasElement>(null);
  useEffect(() => {
    if (!result) return;
    paint(gpu.current, topDown(result.webgpu, result.w, result.h), result.w, result.h);
    paint(heat.current, result.heatmap, result.w, result.h);
  }, [result]);
  const n = result?.numbers;
  const cell = result?.cell;
  return (
    <div
      className="parity"
      data-testid="parity"
      data-cell={cell ? [cell.x, cell.y, cell.width, cell.height].join(',') : undefined}
      data-seq={result?.seq ?? 0}
      style={{
        gridTemplateColumns: `repeat(${layout.cols}, 1fr)`,
        gridTemplateRows: `repeat(${layout.rows}, 1fr)`,
      }}
    >
      <div>
        <span className="parity-label">WebGL: WebGLRenderer + ShadingMaterial</span>
      </div>
      <div>
        <canvas ref={gpu} data-testid="parity-webgpu" aria-label="WebGPU mode's picture" />
        <span className="parity-label" data-testid="parity-backend">
          WebGPU: WebGPURenderer + ShadingNodeMaterial ({status ? backendLabel(status) : 'starting…'})
        </span>
      </div>
      <div>
        <canvas ref={heat} data-testid="parity-heatmap" aria-label="heat map of the difference" />
        <span className="parity-label">difference (largest channel, 8-bit codes)</span>
      </div>
      <div className="parity-numbers">
        {n ? (
          <dl
            data-testid="parity-numbers"
            data-pixels={n.pixels}
            data-max={n.max}
            data-mean={n.mean}
            data-over1={n.over1}
            data-over3={n.over3}
            data-coverage={n.coverage}
          >
            <dt>pixels</dt>
            <dd>
              {n.pixels.toLocaleString('en-US')} ({result.w} × {result.h})
            </dd>
            <dt>max</dt>
            <dd>{n.max}/255</dd>
            <dt>mean</dt>
            <dd>{n.mean.toFixed(3)}/255</dd>
            <dt>&gt; 1/255</dt>
            <dd>
              {n.over1.toLocaleString('en-US')} ({percent(n.over1, n.pixels)})
            </dd>
            <dt>&gt; 3/255</dt>
            <dd>
              {n.over3.toLocaleString('en-US')} ({percent(n.over3, n.pixels)})
            </dd>
            <dt>lit in one only</dt>
            <dd>{n.coverage.toLocaleString('en-US')}</dd>
          </dl>
        ) : (
          <p>Waiting for both pictures…</p>
        )}
        <HeatmapLegend />
      </div>
    </div>
  );
}
