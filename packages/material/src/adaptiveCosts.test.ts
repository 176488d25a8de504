// The cost table in adaptiveCosts.ts is the committed bench JSON, recomputed here: a rerun of the benches that
// moves a number fails this test until the table is updated from it.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { chooseFlatPath, SHADING_COST_TABLE, shadingCost } from './adaptiveCosts.js';

const read = (name: string) =>
  JSON.parse(readFileSync(fileURLToPath(new URL(`../../../bench/results/${name}`, import.meta.url)), 'utf8'));
const median = (a: number[]) => {
  const s = [...a].sort((x, y) => x - y);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};

interface Row {
  option: { shading: string; base: string; level: number };
  triangles: number;
  error: { interiorPixels: number };
  gpuMs: { median: number };
}

describe('SHADING_COST_TABLE', () => {
  const trade = read('tradeoff.json');
  const rows = trade.rows as Record<string, Row>;
  const points = Object.values(rows)
    .filter((r) => r.option.shading === 'phong' && r.option.level <= 8)
    .map((p) => {
      const { base, level } = p.option;
      return {
        tau: p.triangles / p.error.interiorPixels,
        flat: rows[`flat ${base} ${level}`].gpuMs.median / p.gpuMs.median,
        gouraud: rows[`gouraud ${base} ${level}`].gpuMs.median / p.gpuMs.median,
        phong: p.gpuMs.median,
        triangles: p.triangles,
        pixels: p.error.interiorPixels,
      };
    });

  it('is the median ratio per half-decade of triangles per pixel in bench/results/tradeoff.json', () => {
    const xs: number[] = [];
    const flat: number[] = [];
    const gouraud: number[] = [];
    for (let e = -6; e <= 2; e += 0.5) {
      const sel = points.filter((p) => Math.abs(Math.log10(p.tau) - e) <= 0.25);
      if (sel.length === 0) continue;
      xs.push(e);
      flat.push(Number(median(sel.map((p) => p.flat)).toFixed(2)));
      gouraud.push(Number(median(sel.map((p) => p.gouraud)).toFixed(2)));
    }
    expect(SHADING_COST_TABLE.log10TrianglesPerPixel).toEqual(xs);
    expect(SHADING_COST_TABLE.flat).toEqual(flat);
    expect(SHADING_COST_TABLE.gouraud).toEqual(gouraud);
  });

  it("has a triangle's cost in pixels from the same runs", () => {
    const big = points.filter((p) => p.tau >= 0.1);
    const mx = big.reduce((s, p) => s + p.triangles, 0) / big.length;
    const my = big.reduce((s, p) => s + p.phong, 0) / big.length;
    const slope =
      big.reduce((s, p) => s + (p.triangles - mx) * (p.phong - my), 0) /
      big.reduce((s, p) => s + (p.triangles - mx) ** 2, 0);
    const perPixel = median(points.filter((p) => p.tau <= 0.01).map((p) => p.phong / p.pixels));
    expect(SHADING_COST_TABLE.pixelsPerTriangle).toBeCloseTo(slope / perPixel, 1);
  });

  it("has flat shading's derivatives/prepared ratios from bench/results/scene.json", () => {
    const scene = read('scene.json');
    const measured = Object.values(
      scene.flat.meshes as Record<
        string,
        {
          triangles: number;
          modes: { indexed: { error: { pixels: number }; vsPrepared: { paired: number } } };
        }
      >,
    )
      .map((m) => [
        Number(Math.log10(m.triangles / m.modes.indexed.error.pixels).toFixed(4)),
        Number(m.modes.indexed.vsPrepared.paired.toFixed(2)),
      ])
      .sort((a, b) => a[0] - b[0]);
    expect(SHADING_COST_TABLE.derivativesOverPrepared).toEqual(measured);
  });
});

describe('shadingCost and chooseFlatPath', () => {
  it('do not assume flat < Gouraud < Phong: flat costs more than Phong in a vertex-heavy mesh', () => {
    // 100 pixels, 10,000 triangles: τ = 100.
    expect(shadingCost('flat-prepared', 10_000, 100)).toBeGreaterThan(shadingCost('phong', 10_000, 100));
    expect(shadingCost('gouraud', 10_000, 100)).toBeGreaterThan(shadingCost('phong', 10_000, 100));
    // A large, coarse mesh: both cheaper than Phong.
    expect(shadingCost('flat-prepared', 256, 160_000)).toBeLessThan(shadingCost('phong', 256, 160_000));
    expect(shadingCost('gouraud', 256, 160_000)).toBeLessThan(shadingCost('phong', 256, 160_000));
  });

  it('picks the prepared geometry for few triangles per pixel and derivatives for many', () => {
    expect(chooseFlatPath(1024, 300_000)).toBe('prepared');
    expect(chooseFlatPath(16_384, 180_000)).toBe('prepared');
    expect(chooseFlatPath(100_000, 50_000)).toBe('derivatives');
    // The crossover lies where the measured ratio, carried past 0.09 triangles per pixel, reaches 1.
    expect(chooseFlatPath(5, 10)).toBe('prepared');
    expect(chooseFlatPath(8, 10)).toBe('derivatives');
  });

  it('stays finite at 0 pixels and 0 triangles', () => {
    for (const s of ['phong', 'gouraud', 'flat-prepared', 'flat-derivatives'] as const) {
      expect(Number.isFinite(shadingCost(s, 100, 0))).toBe(true);
      expect(Number.isFinite(shadingCost(s, 0, 100))).toBe(true);
      expect(Number.isFinite(shadingCost(s, 0, 0))).toBe(true);
    }
  });
});
