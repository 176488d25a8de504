import { flatShadingGeometry } from '@shadelab/material';
import { createImpostorQuad } from '@shadelab/material/impostor';
import { SPHERE_BASES, SubdivisionSphereGeometry } from '@shadelab/sphere';
import type { BufferGeometry } from 'three';
import { describe, expect, it } from 'vitest';
import { cheapestMeeting, paretoFront, TRADE_POINTS } from './benchData';
import { optionCost } from './tradeoffScene';

describe('optionCost', () => {
  /** Every buffer byte a geometry uploads: its attributes and its index. */
  const bufferBytes = (g: BufferGeometry): number =>
    Object.values(g.attributes).reduce((sum, a) => sum + a.array.byteLength, 0) +
    (g.index?.array.byteLength ?? 0);

  it('matches the real arrays of what setOption draws: flatShadingGeometry (V′ = T, 36 B/vertex) for flat, the indexed sphere (12 B/vertex) for gouraud and phong', () => {
    for (const base of SPHERE_BASES) {
      // Level 6 of the icosahedron has 81,920 flat vertices: the Uint32 index.
      for (let level = 0; level <= (base === 'icosahedron' ? 6 : 5); level++) {
        const indexed = new SubdivisionSphereGeometry({ base, level, normals: 'none', indexed: true });
        const index = indexed.index?.array as Uint16Array | Uint32Array;
        for (const shading of ['gouraud', 'phong'] as const) {
          const smooth = optionCost({ shading, base, level });
          expect(Object.keys(indexed.attributes)).toEqual(['position']);
          expect(smooth.bytes).toBe(bufferBytes(indexed));
          expect(smooth.triangles).toBe(index.length / 3);
          expect(smooth.vertices).toBe(indexed.getAttribute('position').count);
          expect(smooth.bytesPerVertex).toBe(12);
        }
        const faces = flatShadingGeometry(indexed);
        const flat = optionCost({ shading: 'flat', base, level });
        const count = faces.getAttribute('position').count;
        // V′ = T on a subdivision sphere, but for one duplicate on the bare octahedron and icosahedron.
        expect(count).toBe(flat.triangles + (level === 0 && base !== 'tetrahedron' ? 1 : 0));
        expect(flat.vertices).toBe(count);
        expect(flat.bytes).toBe(bufferBytes(faces));
        expect(flat.bytesPerVertex).toBe(
          Object.values(faces.attributes).reduce((sum, a) => sum + a.array.BYTES_PER_ELEMENT * a.itemSize, 0),
        );
        expect(flat.bytesPerVertex).toBe(36);
        expect(faces.index?.array.BYTES_PER_ELEMENT).toBe(count <= 65536 ? 2 : 4);
        if (level > 0) expect(flat.bytesPerTriangle).toBe(count <= 65536 ? 42 : 48);
        expect(flat.bytesPerTriangle).toBe(flat.bytes / flat.triangles);
        faces.dispose();
        indexed.dispose();
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
