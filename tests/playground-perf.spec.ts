import { expect } from '@playwright/test';
import { recordBrowser, writeJson } from '../bench/lib/meta.mjs';
import { test } from './harness-helpers';
import { settle } from './playground-helpers';

// Time from navigation to the first rendered frame: performance.now() when the first frame was drawn (the page
// writes it to the canvas's data-first-frame-ms and to the console). Logged, never asserted (speed is measured,
// not tested); run this file alone for quiet numbers. With SHADELAB_FIRST_FRAME_JSON=bench/results/playground-first-frame.json
// it also writes them, with the run's meta block, for BENCHMARKS.md (npm run benchmarks).
test('time from navigation to the first rendered frame', async ({ page, browser }) => {
  test.setTimeout(120_000);
  const samples: number[] = [];
  for (let i = 0; i < 5; i++) {
    await page.goto('about:blank');
    await page.goto('/');
    await settle(page);
    const ms = Number(await page.getByTestId('viewport').getAttribute('data-first-frame-ms'));
    expect(ms).toBeGreaterThan(0);
    samples.push(ms);
  }
  const sorted = [...samples].sort((a, b) => a - b);
  const median = sorted[Math.floor(sorted.length / 2)]!;
  const line = `first frame after navigation: median ${median.toFixed(0)} ms, min ${sorted[0]!.toFixed(0)}, max ${sorted.at(-1)!.toFixed(0)} (${samples.map((s) => s.toFixed(0)).join(', ')})`;
  console.log(line);
  const json = process.env.SHADELAB_FIRST_FRAME_JSON;
  if (json) {
    recordBrowser(`Chromium ${browser.version()}`);
    const viewport = page.viewportSize();
    writeJson(json, {
      test: 'tests/playground-perf.spec.ts',
      viewport,
      loads: samples.length,
      samplesMs: samples,
    });
  }
  test.info().annotations.push({ type: 'first frame', description: line });
});
