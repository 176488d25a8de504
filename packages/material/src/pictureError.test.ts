import { pictureError } from '@shadelab/material/adaptive';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';

/** An RGBA picture from [r, g, b, a] pixels. */
const rgba = (pixels: number[][]) => Uint8Array.from(pixels.flat());

describe('pictureError', () => {
  it('per pixel the largest |Δ| over R, G, B of the drawn pixels: p99, max, and the share over the budget', () => {
    const reference = rgba([
      [10, 10, 10, 255],
      [10, 10, 10, 255],
      [0, 0, 0, 0],
      [50, 60, 70, 255],
    ]);
    const picture = rgba([
      [10, 10, 10, 255],
      [13, 5, 10, 255], // |Δ| = 5
      [200, 0, 0, 0], // not drawn in either: not compared
      [50, 60, 90, 255], // |Δ| = 20
    ]);
    // Sorted [0, 5, 20]: the 99th percentile is the element at ⌊0.99·3⌋ = 2.
    expect(pictureError(reference, picture, 8)).toEqual({ drawn: 3, p99: 20, max: 20, over: 1 / 3 });
    expect(pictureError(reference, picture, 20).over).toBe(0);
    // A pixel drawn in one picture only is compared.
    const only = rgba([[0, 0, 0, 0]]);
    expect(pictureError(only, rgba([[9, 0, 0, 255]]), 8)).toEqual({ drawn: 1, p99: 9, max: 9, over: 1 });
    // Another notion of drawn: not black in either.
    const notBlack = (i: number) => reference[4 * i] + picture[4 * i] > 0;
    expect(pictureError(reference, picture, 8, notBlack).drawn).toBe(4);
  });

  it('nothing drawn: zero errors; pictures of different sizes: a RangeError naming both', () => {
    expect(pictureError(rgba([[1, 2, 3, 0]]), rgba([[9, 9, 9, 0]]), 2)).toEqual({
      drawn: 0,
      p99: 0,
      max: 0,
      over: 0,
    });
    expect(() => pictureError(new Uint8Array(8), new Uint8Array(4), 2)).toThrow(RangeError);
    expect(() => pictureError(new Uint8Array(6), new Uint8Array(6), 2)).toThrow(/8|6 bytes/);
  });

  it('property: p99 ≤ max ≤ 255, over falls as the budget rises, a picture against itself has no error', () => {
    const pictures = fc
      .integer({ min: 1, max: 200 })
      .chain((n) =>
        fc.tuple(
          fc.uint8Array({ minLength: 4 * n, maxLength: 4 * n }),
          fc.uint8Array({ minLength: 4 * n, maxLength: 4 * n }),
        ),
      );
    fc.assert(
      fc.property(pictures, fc.integer({ min: 0, max: 254 }), ([a, b], budget) => {
        const e = pictureError(a, b, budget);
        expect(e.p99).toBeLessThanOrEqual(e.max);
        expect(e.max).toBeLessThanOrEqual(255);
        expect(pictureError(a, b, budget + 1).over).toBeLessThanOrEqual(e.over);
        const self = pictureError(a, a, budget);
        expect([self.max, self.over]).toEqual([0, 0]);
      }),
    );
  });
});
