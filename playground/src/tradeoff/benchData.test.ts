import { describe, expect, it } from 'vitest';
import { CHART_FLOOR, chartPoints, currentMarker, logTicks, TRADE_POINTS } from './benchData';
import { optionCost, optionKey } from './tradeoffScene';

describe('the chart data', () => {
  it('the current-option marker sits exactly on that option’s own bench point, for every measured option', () => {
    expect(TRADE_POINTS.length).toBeGreaterThan(10);
    for (const metric of ['rmse', 'silhouettePx'] as const) {
      for (const shading of ['flat', 'gouraud', 'phong', 'impostor'] as const) {
        // The dots the chart draws for this shading (one Scatter per shading).
        const dots = chartPoints(
          TRADE_POINTS.filter((p) => p.shading === shading),
          metric,
        );
        for (const p of TRADE_POINTS.filter((q) => q.shading === shading)) {
          const marker = currentMarker(p.option, metric);
          expect(marker).toHaveLength(1);
          const dot = dots.find((d) => d.name === optionKey(p.option));
          expect(dot).toBeDefined();
          expect(marker[0]).toEqual(dot);
          expect(marker[0].x).toBe(p.frameMs);
          expect(marker[0].y).toBe(Math.max(p[metric], CHART_FLOOR));
          expect(marker[0].error).toBe(p[metric]);
        }
      }
    }
  });

  it('no marker for an option the bench did not measure', () => {
    expect(currentMarker({ shading: 'phong', base: 'tetrahedron', level: 12 }, 'rmse')).toEqual([]);
  });

  it("points carry the current geometry's triangles and bytes (optionCost), whatever run the timings came from", () => {
    for (const p of TRADE_POINTS) {
      const cost = optionCost(p.option);
      expect(p.triangles).toBe(cost.triangles);
      expect(p.bytes).toBe(cost.bytes);
    }
  });

  it('log ticks span every value: 1, 2, 5 × 10^k from at or below the least to at or above the greatest', () => {
    expect(logTicks([3.1, 23.4, 180])).toEqual([2, 5, 10, 20, 50, 100, 200]);
    expect(logTicks([0.01, 0.5])).toEqual([0.01, 0.02, 0.05, 0.1, 0.2, 0.5]);
    expect(logTicks([7])).toEqual([5, 10]);
    expect(logTicks([])).toEqual([1]);
    for (const metric of ['rmse', 'silhouettePx'] as const) {
      const points = chartPoints(TRADE_POINTS, metric);
      for (const axis of ['x', 'y'] as const) {
        const values = points.map((p) => p[axis]);
        const ticks = logTicks(values);
        expect(ticks[0]).toBeLessThanOrEqual(Math.min(...values));
        expect(ticks.at(-1)).toBeGreaterThanOrEqual(Math.max(...values));
      }
    }
  });
});
