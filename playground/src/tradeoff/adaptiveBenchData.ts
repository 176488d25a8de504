// The measured trade of adaptive shading (bench/results/adaptive.json, written by `npm run bench -- adaptive`):
// in the realistic scene (1,000 instanced spheres, three's lights, fog, 1280×720), in the published and a deeper
// view, each variant's frame time (the median of the same-cycle ratios against all-Phong) and the measured error
// of its picture against all-Phong's, as chart points.
import results from '../../../bench/results/adaptive.json';

/** What a point is: adaptive at a budget, or one shading everywhere. */
export type AdaptiveKind = 'adaptive' | 'flat' | 'gouraud' | 'phong';

/** The bench's views. */
export type BenchView = 'published' | 'deep';

/** One measured variant in one view. */
export interface AdaptivePoint {
  /** The bench's row name (`adaptive, maxError 8`, `fixed Gouraud`, …). */
  name: string;
  kind: AdaptiveKind;
  view: BenchView;
  /** Frame time / all-Phong's, the median of the same-cycle ratios. */
  frameRatio: number;
  /** Median frame time, ms (under the run's load: compare within a view). */
  frameMs: number;
  /** 99th percentile of the per-pixel max |Δ| over RGB against all-Phong's picture, 8-bit sRGB levels. */
  p99: number;
  /** The largest per-pixel difference. */
  max: number;
  /** Fractions of the drawn pixels over 8 and 32 levels. */
  over8: number;
  over32: number;
  /** The budget (adaptive rows). */
  maxError: number | null;
}

interface Row {
  frameMs: { median: number };
  vsAllPhong: { paired: number };
  error: { p99: number; max: number; over8: number; over32: number };
  maxError?: number;
}

const KINDS: Record<string, AdaptiveKind> = {
  'all-Phong': 'phong',
  'fixed Gouraud': 'gouraud',
  'fixed flat': 'flat',
};

/** The rows the chart plots: adaptive, fixed flat, fixed Gouraud and all-Phong (not three's material). */
function kindOf(name: string): AdaptiveKind | null {
  return name.startsWith('adaptive') ? 'adaptive' : (KINDS[name] ?? null);
}

const views = (results as unknown as { results: Record<BenchView, { rows: Record<string, Row> }> }).results;

/** Every plotted variant of every view, in the bench's order. */
export const ADAPTIVE_POINTS: readonly AdaptivePoint[] = (Object.keys(views) as BenchView[]).flatMap((view) =>
  Object.entries(views[view].rows).flatMap(([name, r]) => {
    const kind = kindOf(name);
    if (kind === null) return [];
    return [
      {
        name,
        kind,
        view,
        frameRatio: r.vsAllPhong.paired,
        frameMs: r.frameMs.median,
        p99: r.error.p99,
        max: r.error.max,
        over8: r.error.over8,
        over32: r.error.over32,
        maxError: r.maxError ?? null,
      },
    ];
  }),
);

/** The run's conditions, for the caption. */
export const ADAPTIVE_CONDITIONS = {
  frames: (results as { frames: number }).frames,
  load: (results as { meta?: { loadavg?: number[] } }).meta?.loadavg ?? null,
};

/** The Pareto front of one view's points: no other point is both faster (ratio) and more accurate (p99, then > 8). */
export function adaptiveFront(points: readonly AdaptivePoint[]): AdaptivePoint[] {
  const sorted = [...points].sort(
    (a, b) => a.frameRatio - b.frameRatio || a.p99 - b.p99 || a.over8 - b.over8,
  );
  const out: AdaptivePoint[] = [];
  let best = Number.POSITIVE_INFINITY;
  for (const p of sorted) {
    const error = p.p99 + p.over8; // p99 first; > 8 breaks ties between equal p99s
    if (error < best) {
      out.push(p);
      best = error;
    }
  }
  return out;
}
