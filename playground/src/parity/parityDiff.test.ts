import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { HEAT_BACKGROUND, HEAT_EXACT, heatColor, silhouetteColor } from '../tradeoff/errorHeatmap';
import { parityDiff, topDown } from './parityDiff';

/** A w × h RGBA picture from a list of [r, g, b] per pixel (rows bottom-up). */
const picture = (pixels: number[][]) => new Uint8Array(pixels.flatMap(([r, g, b]) => [r!, g!, b!, 255]));

describe('parityDiff', () => {
  it('gives the largest channel difference per pixel: max, mean over every pixel, counts over 1 and 3', () => {
    const a = picture([
      [0, 0, 0],
      [100, 100, 100],
      [100, 100, 100],
      [50, 60, 70],
    ]);
    const b = picture([
      [0, 0, 0],
      [101, 100, 99],
      [100, 104, 100],
      [50, 58, 70],
    ]);
    const { numbers, heatmap } = parityDiff(a, b, 2, 2);
    expect(numbers).toEqual({
      pixels: 4,
      max: 4,
      mean: (0 + 1 + 4 + 2) / 4,
      over1: 2,
      over3: 1,
      coverage: 0,
    });
    // Rows top-down in the heat map: the bottom row (pixels 0 and 1) comes last.
    expect([...heatmap.subarray(8, 11)]).toEqual([...HEAT_BACKGROUND]);
    expect([...heatmap.subarray(12, 15)]).toEqual([...heatColor(1)]);
    expect([...heatmap.subarray(0, 3)]).toEqual([...heatColor(4)]);
    expect([...heatmap.subarray(4, 7)]).toEqual([...heatColor(2)]);
  });

  it('marks a pixel lit in one picture only as a silhouette mismatch, and equal lit pixels as exact', () => {
    const a = picture([
      [200, 10, 10],
      [30, 30, 30],
    ]);
    const b = picture([
      [0, 0, 0],
      [30, 30, 30],
    ]);
    const { numbers, heatmap } = parityDiff(a, b, 2, 1);
    expect(numbers.coverage).toBe(1);
    expect(numbers.max).toBe(200);
    expect([...heatmap.subarray(0, 3)]).toEqual([...silhouetteColor(1)]);
    expect([...heatmap.subarray(4, 7)]).toEqual([...HEAT_EXACT]);
  });

  it('equals a plain recomputation on random pictures', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 6 }),
        fc.integer({ min: 1, max: 6 }),
        fc.infiniteStream(fc.integer({ min: 0, max: 255 })),
        (w, h, values) => {
          const it = values[Symbol.iterator]();
          const next = () => it.next().value as number;
          const a = new Uint8Array(4 * w * h).map(next);
          const b = new Uint8Array(4 * w * h).map(next);
          const d: number[] = [];
          for (let k = 0; k < w * h; k++)
            d.push(Math.max(...[0, 1, 2].map((c) => Math.abs(a[4 * k + c]! - b[4 * k + c]!))));
          const { numbers } = parityDiff(a, b, w, h);
          expect(numbers.max).toBe(Math.max(...d));
          expect(numbers.mean).toBeCloseTo(d.reduce((s, x) => s + x, 0) / d.length, 12);
          expect(numbers.over1).toBe(d.filter((x) => x > 1).length);
          expect(numbers.over3).toBe(d.filter((x) => x > 3).length);
        },
      ),
    );
  });

  it('refuses pictures smaller than w × h', () => {
    expect(() => parityDiff(new Uint8Array(4), new Uint8Array(16), 2, 2)).toThrow(RangeError);
  });

  it('turns read-back rows (bottom-up) into ImageData rows (top-down)', () => {
    const rows = new Uint8Array([1, 1, 1, 1, 2, 2, 2, 2]);
    expect([...topDown(rows, 1, 2)]).toEqual([2, 2, 2, 2, 1, 1, 1, 1]);
  });
});
