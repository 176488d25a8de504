import { readFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { decodePng, encodePng, flipRows, type RgbaImage } from './png.js';

/** A PNG of `channels` per pixel (colour type `colour`) whose rows use the given filters, built by the spec. */
function filteredPng(width: number, rows: number[][], channels: number, colour: number, filters: number[]) {
  const stride = width * channels;
  const raw: number[] = [];
  let prev = new Array(stride).fill(0);
  rows.forEach((row, y) => {
    const f = filters[y % filters.length];
    raw.push(f);
    for (let i = 0; i < stride; i++) {
      const a = i >= channels ? row[i - channels] : 0;
      const b = prev[i];
      const c = i >= channels ? prev[i - channels] : 0;
      const p = a + b - c;
      const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - c)];
      const paeth = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      const predicted = [0, a, b, (a + b) >> 1, paeth][f];
      raw.push((row[i] - predicted + 256) & 255);
    }
    prev = row;
  });
  // Take encodePng's chunks and replace its header and data.
  const template = encodePng({ width, height: rows.length, data: new Uint8Array(width * rows.length * 4) });
  const header = template.slice(8, 8 + 25);
  header[8 + 9] = colour;
  const chunk = (type: string, data: Uint8Array) => {
    const out = new Uint8Array(12 + data.length);
    new DataView(out.buffer).setUint32(0, data.length);
    out.set(Buffer.from(type), 4);
    out.set(data, 8);
    return out; // decodePng does not check CRCs
  };
  return Buffer.concat([
    template.subarray(0, 8),
    chunk('IHDR', header.subarray(8, 21)),
    chunk('IDAT', deflateSync(Buffer.from(raw))),
    chunk('IEND', new Uint8Array(0)),
  ]);
}

describe('PNG', () => {
  it('encodes and decodes RGBA exactly (rows top-down)', () => {
    const width = 7;
    const height = 5;
    const data = new Uint8Array(width * height * 4).map((_, i) => (i * 37 + 11) & 255);
    const back = decodePng(encodePng({ width, height, data }));
    expect(back.width).toBe(width);
    expect(back.height).toBe(height);
    expect(Array.from(back.data)).toEqual(Array.from(data));
  });

  it('undoes every row filter (none, sub, up, average, Paeth) of RGB, RGBA and grey images', () => {
    const width = 6;
    const rows = (channels: number) =>
      Array.from({ length: 10 }, (_, y) =>
        Array.from({ length: width * channels }, (_, i) => (y * 53 + i * 29 + ((i * y) % 7) * 40) & 255),
      );
    for (const [channels, colour] of [
      [3, 2],
      [4, 6],
      [1, 0],
      [2, 4],
    ]) {
      const r = rows(channels);
      const image = decodePng(filteredPng(width, r, channels, colour, [0, 1, 2, 3, 4]));
      r.forEach((row, y) => {
        for (let x = 0; x < width; x++) {
          const px = Array.from(image.data.subarray(4 * (y * width + x), 4 * (y * width + x) + 4));
          const s = row.slice(x * channels, (x + 1) * channels);
          const want =
            channels === 1
              ? [s[0], s[0], s[0], 255]
              : channels === 2
                ? [s[0], s[0], s[0], s[1]]
                : channels === 3
                  ? [...s, 255]
                  : s;
          expect(px, `channels ${channels}, pixel ${x}, ${y}`).toEqual(want);
        }
      });
    }
  });

  it("reads Chromium's screenshots: the kit's baseline has the blue background at its corners and the lit ellipsoid at its centre", () => {
    const png = readFileSync(
      new URL('../../../tests/__screenshots__/playwright-kit.spec.ts/kit-lecture.png', import.meta.url),
    );
    const image = decodePng(png);
    expect([image.width, image.height]).toEqual([320, 240]);
    const at = (x: number, y: number) =>
      Array.from(image.data.subarray(4 * (y * 320 + x), 4 * (y * 320 + x) + 4));
    expect(at(0, 0)).toEqual([0, 0, 255, 255]);
    expect(at(319, 239)).toEqual([0, 0, 255, 255]);
    const [r, g, b] = at(160, 120);
    expect(r).toBeGreaterThan(g);
    expect(g).toBeGreaterThan(b);
    expect(Array.from(decodePng(encodePng(image)).data)).toEqual(Array.from(image.data));
  });

  it('refuses what it cannot read, and bad sizes, naming them', () => {
    expect(() => decodePng(new Uint8Array([1, 2, 3]))).toThrow(
      new TypeError('decodePng: png is not a PNG file (no PNG signature)'),
    );
    const png = encodePng({ width: 1, height: 1, data: new Uint8Array(4) });
    png[8 + 8 + 8] = 16; // bit depth
    expect(() => decodePng(png)).toThrow(
      /only 8-bit grey, RGB and RGBA PNGs without interlacing are read, got bit depth 16/,
    );
    expect(() => encodePng({ width: 2, height: 2, data: new Uint8Array(15) })).toThrow(
      new RangeError('encodePng: data must hold 2×2 RGBA pixels (16 bytes), got 15'),
    );
    expect(() => encodePng({ width: 0, height: 2, data: new Uint8Array(0) })).toThrow(RangeError);
  });

  it('flipRows reverses the rows and is its own inverse', () => {
    const image: RgbaImage = { width: 2, height: 3, data: Uint8Array.from({ length: 24 }, (_, i) => i) };
    const flipped = flipRows(image);
    expect(Array.from(flipped.data.subarray(0, 8))).toEqual([16, 17, 18, 19, 20, 21, 22, 23]);
    expect(Array.from(flipRows(flipped).data)).toEqual(Array.from(image.data));
  });
});
