import { describe, expect, it } from 'vitest';
import results from '../../../bench/results/adaptive.json';
import { ADAPTIVE_POINTS, adaptiveFront } from './adaptiveBenchData';

type Rows = Record<string, { vsAllPhong: { paired: number }; error: { p99: number } }>;
const views = (results as unknown as { results: Record<string, { rows: Rows }> }).results;

describe("adaptive shading's chart data", () => {
  it('has adaptive, fixed flat, fixed Gouraud and all-Phong in every view, with the JSON’s numbers', () => {
    for (const view of Object.keys(views)) {
      const points = ADAPTIVE_POINTS.filter((p) => p.view === view);
      expect(new Set(points.map((p) => p.kind))).toEqual(new Set(['adaptive', 'flat', 'gouraud', 'phong']));
      for (const p of points) {
        const row = views[view].rows[p.name];
        expect(p.frameRatio).toBe(row.vsAllPhong.paired);
        expect(p.p99).toBe(row.error.p99);
      }
      // all-Phong is the reference of both axes.
      const phong = points.find((p) => p.kind === 'phong');
      expect(phong?.frameRatio).toBe(1);
      expect(phong?.p99).toBe(0);
      expect(points.some((p) => p.name === 'MeshPhongMaterial')).toBe(false);
    }
  });

  it('the Pareto front: no point off it is both faster and more accurate than a point on it', () => {
    for (const view of Object.keys(views)) {
      const points = ADAPTIVE_POINTS.filter((p) => p.view === view);
      const front = adaptiveFront(points);
      expect(front.length).toBeGreaterThan(0);
      for (const f of front) {
        for (const p of points) {
          const dominates = p.frameRatio < f.frameRatio && p.p99 + p.over8 < f.p99 + f.over8;
          expect(dominates).toBe(false);
        }
      }
    }
  });
});
