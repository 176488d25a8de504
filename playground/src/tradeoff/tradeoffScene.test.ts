import { createImpostorQuad } from '@shadelab/material/impostor';
import { SPHERE_BASES, SubdivisionSphereGeometry } from '@shadelab/sphere';
import { describe, expect, it } from 'vitest';
import { cheapestMeeting, paretoFront, TRADE_POINTS } from './benchData';
import { optionCost } from './tradeoffScene';

describe('optionCost', () => {
  it("matches the geometries' real arrays (and the flat texture's 2048-texel rows)", () => {
    for (const base of SPHERE_BASES) {
      for (let level = 0; level <= 5; level++) {
        const indexed = new SubdivisionSphereGeometry({ base, level, normals: 'none', indexed: true });
        const smooth = optionCost({ shading: 'phong', base, level });
        const index = indexed.index?.array as Uint16Array | Uint32Array;
        expect(smooth.bytes).toBe(indexed.getAttribute('position').array.byteLength + index.byteLength);
        expect(smooth.triangles).toBe(index.length / 3);
        expect(smooth.vertices).toBe(indexed.getAttribute('position').count);
        const soup = new SubdivisionSphereGeometry({ base, level, normals: 'none', indexed: false });
        const flat = optionCost({ shading: 'flat', base, level });
        const count = soup.getAttribute('position').count;
        expect(flat.vertices).toBe(count);
        expect(flat.bytes).toBe(count * 12 + 2048 * Math.ceil(count / 2048) * 12);
      }
    }
    const quad = createImpostorQuad();
    expect(optionCost({ shading: 'impostor' }).bytes).toBe(
      quad.getAttribute('position').array.byteLength + (quad.index?.array.byteLength ?? 0),
    );
  });
});

describe('measured trade', () => {
  it('the Pareto front: nothing measured is both faster and more accurate than a front point', () => {
    for (const metric of ['rmse', 'silhouettePx'] as const) {
      const front = paretoFront(TRADE_POINTS, metric);
      expect(front.length).toBeGreaterThan(3);
      for (const f of front) {
        expect(TRADE_POINTS.some((p) => p.frameMs < f.frameMs && p[metric] < f[metric])).toBe(false);
      }
    }
  });
  it('cheapestMeeting is the fastest option meeting both targets', () => {
    for (const [rmse, sil] of [
      [1, 0.5],
      [4, 2],
      [100, 1000],
    ]) {
      const c = cheapestMeeting(rmse, sil);
      expect(c).toBeDefined();
      if (!c) continue;
      expect(c.rmse).toBeLessThanOrEqual(rmse);
      expect(c.silhouettePx).toBeLessThanOrEqual(sil);
      expect(TRADE_POINTS.some((p) => p.rmse <= rmse && p.silhouettePx <= sil && p.frameMs < c.frameMs)).toBe(
        false,
      );
    }
    expect(cheapestMeeting(0, 0)).toBeUndefined();
  });
});
