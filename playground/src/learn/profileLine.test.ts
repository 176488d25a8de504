import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { linePixels, luma, slopeBreaks } from './profileLine';

describe('linePixels', () => {
  it('a zero-length line (both ends in one pixel) gives null', () => {
    expect(linePixels([10.2, 5.9], [10.2, 5.9], 100, 100)).toBeNull();
    expect(linePixels([10.1, 5.1], [10.9, 5.8], 100, 100)).toBeNull();
  });

  it('a horizontal, a vertical and a diagonal line, end to end', () => {
    expect(linePixels([1.5, 2.5], [4.5, 2.5], 10, 10)).toEqual([
      [1, 2],
      [2, 2],
      [3, 2],
      [4, 2],
    ]);
    expect(linePixels([3, 4], [3, 1], 10, 10)).toEqual([
      [3, 4],
      [3, 3],
      [3, 2],
      [3, 1],
    ]);
    expect(linePixels([0, 0], [2.9, 2.9], 10, 10)).toEqual([
      [0, 0],
      [1, 1],
      [2, 2],
    ]);
  });

  it('drops the pixels outside the canvas', () => {
    expect(linePixels([-2, 1], [2, 1], 2, 2)).toEqual([
      [0, 1],
      [1, 1],
    ]);
  });

  it('one 8-connected pixel per step, from the start pixel to the end pixel, within half a pixel of the segment', () => {
    const point = fc.tuple(
      fc.double({ min: 0, max: 63.99, noNaN: true }),
      fc.double({ min: 0, max: 47.99, noNaN: true }),
    );
    fc.assert(
      fc.property(point, point, (from, to) => {
        const pixels = linePixels(from, to, 64, 48);
        const [a, b] = [from.map(Math.floor), to.map(Math.floor)];
        if (a[0] === b[0] && a[1] === b[1]) {
          expect(pixels).toBeNull();
          return;
        }
        expect(pixels![0]).toEqual(a);
        expect(pixels!.at(-1)).toEqual(b);
        expect(pixels!.length).toBe(Math.max(Math.abs(b[0]! - a[0]!), Math.abs(b[1]! - a[1]!)) + 1);
        const [dx, dy] = [b[0]! - a[0]!, b[1]! - a[1]!];
        for (let i = 1; i < pixels!.length; i++) {
          const [p, q] = [pixels![i - 1]!, pixels![i]!];
          expect(Math.max(Math.abs(q[0] - p[0]), Math.abs(q[1] - p[1]))).toBe(1);
        }
        for (const [x, y] of pixels!) {
          // Distance from the pixel to the line through the end pixels, in pixels along the minor axis.
          const cross = Math.abs((x - a[0]!) * dy - (y - a[1]!) * dx) / Math.max(Math.abs(dx), Math.abs(dy));
          expect(cross).toBeLessThanOrEqual(0.5 + 1e-9);
        }
      }),
    );
  });

  it('refuses a bad size or point, naming it', () => {
    expect(() => linePixels([0, 0], [1, 1], 0, 10)).toThrow(
      new RangeError('linePixels: width 0 is not an integer ≥ 1'),
    );
    expect(() => linePixels([0, 0], [1, 1], 10, 2.5)).toThrow(RangeError);
    expect(() => linePixels([0, Number.NaN], [1, 1], 10, 10)).toThrow(
      new TypeError('linePixels: from (0, NaN) is not a finite point'),
    );
  });
});

describe('luma', () => {
  it('is Rec. 709 on the codes: white 255, black 0, each primary its weight', () => {
    expect(luma([255, 255, 255])).toBeCloseTo(255, 10);
    expect(luma([0, 0, 0])).toBe(0);
    expect(luma([100, 0, 0])).toBeCloseTo(21.26, 10);
    expect(luma([0, 100, 0])).toBeCloseTo(71.52, 10);
    expect(luma([0, 0, 100])).toBeCloseTo(7.22, 10);
  });
});

describe('slopeBreaks', () => {
  it('finds a staircase step (flat facets) once, at the first pixel after it', () => {
    expect(slopeBreaks([10, 10, 10, 20, 20, 20])).toEqual([3]);
  });

  it('finds the kink of a continuous profile whose slope jumps (Gouraud), and nothing on a straight ramp', () => {
    expect(slopeBreaks([0, 1, 2, 3, 7, 11, 15], 2)).toEqual([3]);
    expect(slopeBreaks([0, 3, 6, 9, 12], 2)).toEqual([]);
  });

  it('ignores jumps of the slope below the threshold (8-bit rounding), and refuses a threshold ≤ 0', () => {
    expect(slopeBreaks([10, 11, 11, 12, 12, 13], 2)).toEqual([]);
    expect(() => slopeBreaks([1, 2, 3], 0)).toThrow(new RangeError('slopeBreaks: threshold 0 is not > 0'));
  });
});
