// The measured trade (bench/results/tradeoff.json, written by `npm run bench`) as chart points.
import results from '../../../bench/results/tradeoff.json';
import { optionCost, optionKey, type TradeOption } from './tradeOption';

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
  error: { rmse: number; max: number; silhouettePx: number };
  /** null in a `--no-timing` run. */
  frameMs: { median: number } | null;
}

/**
 * Every measured option, in the bench's order. Triangles and bytes are those of what the scene draws now
 * (`optionCost`: exact, and current even when the timed results predate a geometry change such as flat
 * shading's move to flatShadingGeometry); frame time and errors are the bench's.
 */
export const TRADE_POINTS: readonly TradePoint[] = Object.entries(
  results.rows as Record<string, Row>,
).flatMap(([name, r]) => {
  if (r.frameMs === null) return [];
  const cost = optionCost(r.option);
  return [
    {
      name,
      option: r.option,
      shading: r.option.shading,
      frameMs: r.frameMs.median,
      rmse: r.error.rmse,
      max: r.error.max,
      silhouettePx: r.error.silhouettePx,
      triangles: cost.triangles,
      bytes: cost.bytes,
    },
  ];
});

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

/** Log axes cannot show 0: errors below this are drawn at it. */
export const CHART_FLOOR = 0.01;

/** One point as the chart draws it: x = bench frame time (ms), y = the error (floored for the log axis). */
export interface ChartPoint {
  name: string;
  x: number;
  y: number;
  triangles: number;
  bytes: number;
  /** The error itself (not floored). */
  error: number;
}

/** Chart points of `points` for `metric`. */
export function chartPoints(points: readonly TradePoint[], metric: ErrorMetric): ChartPoint[] {
  return points.map((p) => ({
    name: p.name,
    x: p.frameMs,
    y: Math.max(p[metric], CHART_FLOOR),
    triangles: p.triangles,
    bytes: p.bytes,
    error: p[metric],
  }));
}

/**
 * The marker of the current option: its own bench point (the same x and y as its dot in the chart), or none
 * when the bench did not measure it. It shows the bench's frame time and error for the lecture scene at
 * 1280×720, not the live view's.
 */
export function currentMarker(option: TradeOption, metric: ErrorMetric): ChartPoint[] {
  const name = optionKey(option);
  return chartPoints(
    TRADE_POINTS.filter((p) => p.name === name),
    metric,
  );
}

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

/**
 * Ticks of a log axis over the whole range of `values`: 1, 2 and 5 times the powers of ten, from the largest at or
 * below the smallest value to the smallest at or above the largest, so the axis' domain is its first and last tick
 * and every value lies between two labelled ticks.
 */
export function logTicks(values: readonly number[]): number[] {
  const positive = values.filter((v) => v > 0 && Number.isFinite(v));
  if (positive.length === 0) return [1];
  const lo = Math.min(...positive);
  const hi = Math.max(...positive);
  const candidates: number[] = [];
  for (let power = Math.floor(Math.log10(lo)); power <= Math.ceil(Math.log10(hi)); power++) {
    // toPrecision: 2 · 0.1 is 0.2, not 0.20000000000000004.
    for (const step of [1, 2, 5]) candidates.push(Number((step * 10 ** power).toPrecision(12)));
  }
  let first = 0;
  while (candidates[first + 1] <= lo) first++;
  const last = candidates.findIndex((t) => t >= hi);
  return candidates.slice(first, last + 1);
}
