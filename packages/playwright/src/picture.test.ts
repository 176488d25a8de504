import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { compareNeighbourhood } from './compareNeighbourhood.js';
import { GPU_TOLERANCE, GPU_TOLERANCE_HARD_EDGES } from './gpuTolerance.js';
import { summarisePicture } from './picture.js';
import type { RgbaImage } from './png.js';

/** A width × height picture of `fill`, with `paint(x, y)` returning another colour for some pixels. */
function picture(
  width: number,
  height: number,
  fill: [number, number, number],
  paint: (x: number, y: number) => [number, number, number] | undefined = () => undefined,
): RgbaImage {
  const data = new Uint8Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) data.set([...(paint(x, y) ?? fill), 255], 4 * (y * width + x));
  }
  return { width, height, data };
}

describe('summarisePicture', () => {
  it('a flat picture has no drawn pixel; its colour is the background', () => {
    const s = summarisePicture(picture(8, 6, [0, 0, 255]));
    expect(s).toEqual({ width: 8, height: 6, background: [0, 0, 255, 255], drawnPixels: 0 });
  });

  it('counts the pixels of another colour than the most frequent one, or than the background given', () => {
    const square = picture(8, 6, [10, 20, 30], (x, y) => (x < 3 && y < 2 ? [200, 0, 0] : undefined));
    expect(summarisePicture(square).drawnPixels).toBe(6);
    expect(summarisePicture(square, [200, 0, 0]).drawnPixels).toBe(42);
    expect(summarisePicture(square, [1, 2, 3]).drawnPixels).toBe(48);
  });

  it('refuses a background that is not three bytes, naming it', () => {
    expect(() => summarisePicture(picture(1, 1, [0, 0, 0]), [0, 0, 256])).toThrow(
      new RangeError('background must be three integers 0 … 255 (8-bit RGB), got [0, 0, 256]'),
    );
    expect(() => summarisePicture(picture(1, 1, [0, 0, 0]), [0, 0])).toThrow(RangeError);
  });
});

describe('compareNeighbourhood', () => {
  // A disc of orange on blue; `moved` moves its centre.
  const disc = (dx: number, colour: [number, number, number] = [220, 150, 100]) =>
    picture(40, 30, [0, 0, 255], (x, y) => ((x - 20 - dx) ** 2 + (y - 15) ** 2 < 64 ? colour : undefined));

  it('identical pictures: no excess, no pixel beyond', () => {
    const r = compareNeighbourhood(disc(0), disc(0));
    expect([r.maxExcess, r.failingPixels, r.worst]).toEqual([0, 0, null]);
  });

  it('an edge moved by one pixel passes a 3 × 3 neighbourhood and fails an exact (radius 0) comparison', () => {
    expect(compareNeighbourhood(disc(0), disc(1)).maxExcess).toBe(0);
    const exact = compareNeighbourhood(disc(0), disc(1), { radiusPx: 0 });
    expect(exact.maxExcess).toBe(220);
    expect(exact.failingPixels).toBeGreaterThan(0);
  });

  it('an edge moved by two pixels fails 3 × 3 and passes 5 × 5', () => {
    expect(compareNeighbourhood(disc(0), disc(2)).maxExcess).toBe(220);
    expect(compareNeighbourhood(disc(0), disc(2), { radiusPx: 2 }).maxExcess).toBe(0);
  });

  it('a colour off by 5 codes in the interior is an excess of 5, at the pixel where it is largest', () => {
    const r = compareNeighbourhood(disc(0), disc(0, [225, 150, 100]), { maxChannelDiff: 4 });
    expect(r.maxExcess).toBe(5);
    expect(r.failingPixels).toBeGreaterThan(100);
    expect(r.excess[15 * 40 + 20]).toBe(5);
    expect(compareNeighbourhood(disc(0), disc(0, [225, 150, 100]), { maxChannelDiff: 5 }).failingPixels).toBe(
      0,
    );
  });

  it('a blend of the two sides at an edge (antialiasing) lies within the range', () => {
    const blended = picture(40, 30, [0, 0, 255], (x, y) => {
      const d = Math.hypot(x - 20, y - 15) - 8;
      if (d < -0.5) return [220, 150, 100];
      if (d < 0.5) return [110, 75, 178]; // half and half
      return undefined;
    });
    expect(compareNeighbourhood(disc(0), blended).maxExcess).toBe(0);
  });

  it('refuses pictures of different sizes and bad parameters, naming them', () => {
    expect(() => compareNeighbourhood(disc(0), picture(4, 4, [0, 0, 0]))).toThrow(
      new RangeError('compareNeighbourhood: the pictures must have the same size, got 40×30 and 4×4'),
    );
    expect(() => compareNeighbourhood(disc(0), disc(0), { radiusPx: 9 })).toThrow(
      new RangeError('compareNeighbourhood: radiusPx must be an integer 0 … 8, got 9'),
    );
    expect(() => compareNeighbourhood(disc(0), disc(0), { maxChannelDiff: -1 })).toThrow(RangeError);
  });
});

describe('GPU_TOLERANCE', () => {
  it('is what bench/results/rasterisers.json derived from the measured pairs', () => {
    const results = JSON.parse(
      readFileSync(new URL('../../../bench/results/rasterisers.json', import.meta.url), 'utf8'),
    ) as {
      pairs: { edges: 'smooth' | 'hard'; sameSettings: boolean; maxExcess3x3: number }[];
      tolerance: { smooth: object; hardEdges: object };
    };
    expect(GPU_TOLERANCE).toEqual(results.tolerance.smooth);
    expect(GPU_TOLERANCE_HARD_EDGES).toEqual(results.tolerance.hardEdges);
    const largest = (pairs: typeof results.pairs) => Math.max(...pairs.map((p) => p.maxExcess3x3));
    const same = results.pairs.filter((p) => p.sameSettings);
    expect(GPU_TOLERANCE.maxChannelDiff).toBe(largest(same.filter((p) => p.edges === 'smooth')));
    expect(GPU_TOLERANCE_HARD_EDGES.maxChannelDiff).toBe(largest(same));
    // Both backends of three's WebGPURenderer were measured, and the pairs beyond the tolerance are recorded.
    expect(same.length).toBeGreaterThanOrEqual(6);
    expect(results.pairs.some((p) => !p.sameSettings && p.maxExcess3x3 > GPU_TOLERANCE.maxChannelDiff)).toBe(
      true,
    );
  });
});
