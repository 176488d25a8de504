// The measured trade (bench/results/tradeoff.json, written by `npm run bench`) as chart points.
import results from '../../../bench/results/tradeoff.json';
import type { TradeOption } from './tradeoffScene';

/** One measured option. */
export interface TradePoint {
  name: string;
  option: TradeOption;
  shading: TradeOption['shading'];
  /** Median frame time at 1280×720, ms. */
  frameMs: number;
  rmse: number;
  max: number;
  silhouettePx: number;
  triangles: number;
  bytes: number;
}

interface Row {
  option: TradeOption;
  triangles: number;
  bytes: number;
  error: { rmse: number; max: number; silhouettePx: number };
  frameMs: { median: number };
}

/** Every measured option, in the bench's order. */
export const TRADE_POINTS: readonly TradePoint[] = Object.entries(results.rows as Record<string, Row>).map(
  ([name, r]) => ({
    name,
    option: r.option,
    shading: r.option.shading,
    frameMs: r.frameMs.median,
    rmse: r.error.rmse,
    max: r.error.max,
    silhouettePx: r.error.silhouettePx,
    triangles: r.triangles,
    bytes: r.bytes,
  }),
);

/** The measurement conditions, for the caption. */
export const TRADE_CONDITIONS = {
  width: results.width,
  height: results.height,
  frames: results.frames,
  load: results.load.before,
  note: results.note,
};

/** Which error the chart plots. */
export type ErrorMetric = 'rmse' | 'silhouettePx';

/** The Pareto front for `metric`: no other option is both faster and more accurate. */
export function paretoFront(points: readonly TradePoint[], metric: ErrorMetric): TradePoint[] {
  const sorted = [...points].sort((a, b) => a.frameMs - b.frameMs || a[metric] - b[metric]);
  const out: TradePoint[] = [];
  let best = Number.POSITIVE_INFINITY;
  for (const p of sorted) {
    if (p[metric] < best) {
      out.push(p);
      best = p[metric];
    }
  }
  return out;
}

/** The fastest measured option with RMSE ≤ `rmse` and silhouette error ≤ `silhouettePx`, if any. */
export function cheapestMeeting(rmse: number, silhouettePx: number): TradePoint | undefined {
  return [...TRADE_POINTS]
    .filter((p) => p.rmse <= rmse && p.silhouettePx <= silhouettePx)
    .sort((a, b) => a.frameMs - b.frameMs || a.bytes - b.bytes)[0];
}
