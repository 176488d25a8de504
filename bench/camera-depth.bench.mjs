// Depth precision of @shadelab/camera's depth modes, measured by rendering in headless Chromium (SwiftShader):
// for each mode, far/near from 1e2 to 1e9 (near = 0.01, far = near · ratio) and surface distance z = 1, 100, 1e4,
// the smallest relative separation Δz/z at which a red quad at z still hides a green one at z·(1 + Δz/z) drawn
// after it (a log grid of 20 steps per decade scanned from Δz/z = 1 down, reading the centre pixel; the
// reported value is the smallest separation at which, and above which, the order always held). Also times one probe frame per mode.
//
//   node bench/camera-depth.bench.mjs [--json bench/results/camera-depth.json]
//
// Builds the playground harness pages into a temporary folder and serves them on its own port (lib/browser.mjs).
import { summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

/** @typedef {import('../playground/harness/camera').CameraDepthProbe} CameraDepthProbe (types window.cameraDepth) */

const RATIOS = [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];
const DISTANCES = [1, 100, 1e4];
const NEAR = 0.01;

const playground = await openPlayground();
const browser = playground.browser;
try {
  const page = await browser.newPage();
  await page.goto(playground.url('harness/camera.html'));
  await page.waitForFunction(() => document.getElementById('viewport')?.dataset.ready === 'true');
  const modes = await page.evaluate(() => window.cameraDepth.modes);
  const active = await page.evaluate((ms) => ms.map((m) => window.cameraDepth.activeMode(m)), modes);
  /** @type {{ mode: string, active: string, ratio: number, near: number, far: number, z: number, minSeparation: number | null }[]} */
  const rows = [];
  for (const [i, mode] of modes.entries()) {
    for (const ratio of RATIOS) {
      for (const z of DISTANCES) {
        const far = NEAR * ratio;
        const minSeparation = await page.evaluate(
          ([m, n, f, d]) => window.cameraDepth.threshold(m, n, f, d),
          /** @type {const} */ ([mode, NEAR, far, z]),
        );
        rows.push({ mode, active: active[i], ratio, near: NEAR, far, z, minSeparation });
      }
    }
  }
  // Cost of one probe frame (render + 1×1 readPixels) per mode, milliseconds.
  /** @type {Record<string, ReturnType<typeof summarize>>} */
  const frameTimes = {};
  for (const mode of modes) {
    const times = await page.evaluate((m) => {
      const t = [];
      for (let i = 0; i < 25; i++) {
        const t0 = performance.now();
        window.cameraDepth.kept(m, 0.01, 1e6, 1e4, 1e-4);
        t.push(performance.now() - t0);
      }
      return t.slice(5);
    }, mode);
    frameTimes[mode] = summarize(times);
  }

  /** @param {number | null} x */
  const fmt = (x) =>
    x === null ? '—' : x === Number.POSITIVE_INFINITY ? '> 1' : x <= 1e-9 ? '≤ 1e-9' : x.toExponential(1);
  console.log('\nSmallest Δz/z still drawn in the right order (near = 0.01, far = 0.01 · far/near)');
  for (const z of DISTANCES) {
    const ratios = RATIOS.filter((ratio) => z * 2 < NEAR * ratio);
    console.log(`\nz = ${z}\n`);
    console.log(`| mode | ${ratios.map((r) => `far/near 1e${Math.round(Math.log10(r))}`).join(' | ')} |`);
    console.log(`| --- | ${ratios.map(() => '---').join(' | ')} |`);
    for (const mode of modes) {
      const cells = ratios.map((ratio) =>
        fmt(rows.find((r) => r.mode === mode && r.ratio === ratio && r.z === z)?.minSeparation ?? null),
      );
      console.log(`| ${mode} | ${cells.join(' | ')} |`);
    }
  }
  console.log(
    '\n| mode | renderer reports | probe frame median (ms) | min | max |\n| --- | --- | --- | --- | --- |',
  );
  for (const [i, mode] of modes.entries()) {
    const t = frameTimes[mode];
    console.log(
      `| ${mode} | ${active[i]} | ${t.median.toFixed(3)} | ${t.min.toFixed(3)} | ${t.max.toFixed(3)} |`,
    );
  }
  const userAgent = await page.evaluate(() => navigator.userAgent);
  writeResults({
    name: 'camera-depth',
    date: new Date().toISOString(),
    browser: userAgent,
    method:
      'Δz/z scanned down a log grid (20 per decade) from 1 to 1e-9; value = smallest separation with the order kept there and at every larger grid point; 8×8 canvas; red quad at z, green at z(1+Δz/z) drawn after it; centre pixel',
    near: NEAR,
    rows: rows.map((r) => ({
      ...r,
      minSeparation: r.minSeparation === Number.POSITIVE_INFINITY ? 'lost' : r.minSeparation,
    })),
    frameTimes,
  });
} finally {
  await playground.close();
}
