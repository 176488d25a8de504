// The WebGPU benchmark page (bench/harness/webgpu-bench.ts) driven from Node, shared by bench/webgpu.bench.mjs
// and bench/lecture-refactor.bench.mjs: open it in a Chromium with WebGPU, time specs interleaved frame by frame
// in rounds, and compare rows by the median of the ratios of frames timed in the same cycle.
import { chromium } from '@playwright/test';
import { chromiumArgs, chromiumExecutable, webgpuArgs } from '../../scripts/browser.mjs';
import { summarize } from './bench.mjs';
import { openPlayground } from './browser.mjs';

/** @typedef {import('../harness/webgpu-bench').BenchSpec} BenchSpec */
/** @typedef {{ frameMs: ReturnType<typeof summarize>, gpuMs: ReturnType<typeof summarize> | null } | { error: string }} Row */
/** @typedef {{ paired: number, median: number, min: number, gpu: number | null }} Ratio */

/**
 * Build and serve the harness pages, launch Chromium with WebGPU and open the page at `width`×`height`; logs the
 * page's errors and warnings. Call `close()` when done.
 * @param {{ width: number, height: number }} size
 */
export async function openWebgpuBench({ width, height }) {
  const playground = await openPlayground();
  const browser = await chromium.launch({
    executablePath: chromiumExecutable() ?? undefined,
    args: [...chromiumArgs, ...webgpuArgs],
  });
  const close = async () => {
    await browser.close();
    await playground.close();
  };
  try {
    const page = await browser.newPage();
    page.on('console', (m) => {
      if ((m.type() === 'error' || m.type() === 'warning') && !m.text().includes('404'))
        console.log(`page ${m.type()}: ${m.text()}`);
    });
    await page.goto(playground.url(`harness/webgpu-bench.html?width=${width}&height=${height}`));
    await page.waitForFunction(() => document.body.dataset.ready === '1', undefined, { timeout: 120_000 });
    const info = await page.evaluate(() => window.webgpuBench.info());
    return { page, info, close };
  } catch (error) {
    await close();
    throw error;
  }
}

/**
 * Timed rows: `rows` by name, and every timed frame of each in the order of the cycles (`frames`, for the
 * paired ratios).
 */
export class Timings {
  /** @type {Record<string, Row>} */
  rows = {};
  /** @type {Map<string, number[]>} */
  frames = new Map();

  /**
   * Time `specs` on `page` interleaved frame by frame (the page's cycle) in `rounds` rounds of
   * ceil(frames / rounds) cycles each, and add their rows: frame time (and GPU time) median, min, max. Frame k of
   * every spec comes from the same cycle. A spec that throws gets `{ error }`.
   * @param {import('@playwright/test').Page} page
   * @param {Array<[string, BenchSpec]>} specs named specs (names unique across every call)
   * @param {{ frames: number, rounds: number, label?: string }} count
   */
  async time(page, specs, { frames, rounds, label = '' }) {
    /** @type {Record<string, { frames: number[], gpu: number[], error?: string }>} */
    const pooled = Object.fromEntries(specs.map(([name]) => [name, { frames: [], gpu: [] }]));
    for (let round = 0; round < rounds; round++) {
      const live = specs.filter(([name]) => !pooled[name].error);
      const t0 = Date.now();
      const results = await page.evaluate((a) => window.webgpuBench.cycle(a.specs, a.frames, a.warmup), {
        specs: live.map(([, spec]) => spec),
        frames: Math.ceil(frames / rounds),
        warmup: round === 0 ? 3 : 1,
      });
      live.forEach(([name], k) => {
        const r = results[k];
        if (r.error) pooled[name].error = r.error;
        pooled[name].frames.push(...r.frames);
        pooled[name].gpu.push(...r.gpu);
      });
      console.log(`${label}round ${round + 1}/${rounds}: ${((Date.now() - t0) / 1000).toFixed(1)} s`);
    }
    for (const [name, p] of Object.entries(pooled)) {
      this.frames.set(name, p.frames);
      this.rows[name] = p.error
        ? { error: p.error }
        : { frameMs: summarize(p.frames), gpuMs: p.gpu.length ? summarize(p.gpu) : null };
    }
  }

  /**
   * Row `a` against row `b`: `paired`, the median of the ratios of frames timed in the same cycle (what a change
   * of load during the run moves least); `median` and `min`, the ratios of the medians and of the minima; `gpu`,
   * the ratio of the GPU-time medians when both have them. Null when either did not render.
   * @param {string} a @param {string} b @returns {Ratio | null}
   */
  ratio(a, b) {
    const ra = this.rows[a];
    const rb = this.rows[b];
    if (!ra || !rb || 'error' in ra || 'error' in rb) return null;
    const fa = this.frames.get(a) ?? [];
    const fb = this.frames.get(b) ?? [];
    const pairs = fa.slice(0, Math.min(fa.length, fb.length)).map((t, i) => t / fb[i]);
    return {
      paired: summarize(pairs).median,
      median: ra.frameMs.median / rb.frameMs.median,
      min: ra.frameMs.min / rb.frameMs.min,
      gpu: ra.gpuMs && rb.gpuMs ? ra.gpuMs.median / rb.gpuMs.median : null,
    };
  }
}
