// Depth precision of @shadelab/camera's depth modes, measured by rendering in headless Chromium (SwiftShader):
// for each mode, far/near from 1e2 to 1e9 and surface distance z = 1, 100, 1e4, the smallest relative separation
// Δz/z at which a red quad at z still hides a green one at z·(1 + Δz/z) drawn after it (a log grid of 20 steps per
// decade scanned from Δz/z = 1 down, reading the centre pixel; the reported value is the smallest separation at
// which, and above which, the order always held). Also times one probe frame per mode (skip with --no-timing).
//
// near per cell: near = max(min(0.01, z/8), 4z/ratio), far = near · ratio. So near = 0.01 wherever that leaves
// z < far/4, and otherwise the largest near that still does (near ≤ z/8 and far ≥ 4z in every cell): every
// (ratio, z) cell is measured, each row of the JSON records its near and far.
//
//   node bench/camera-depth.bench.mjs [--json bench/results/camera-depth.json]
//     [--modes standard,reversed] [--ratios 1e6] [--distances 1e4] [--per-decade 20] [--no-timing]
//
// A quick check of one cell: --modes standard --ratios 1e6 --distances 1e4 --per-decade 2 --no-timing
//
// Builds the harness pages (tests/harness/, the camera page among them) into a temporary folder and serves them on
// its own port (lib/browser.mjs).
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

/** @typedef {import('../tests/harness/camera').CameraDepthProbe} CameraDepthProbe (types window.cameraDepth) */
/** @typedef {import('../tests/harness/camera').ProbeMode} ProbeMode */

/** @param {string} name @param {number[]} fallback */
const numbers = (name, fallback) => {
  const value = arg(name, '');
  return value ? value.split(',').map(Number) : fallback;
};
const RATIOS = numbers('--ratios', [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9]);
const DISTANCES = numbers('--distances', [1, 100, 1e4]);
const PER_DECADE = Number(arg('--per-decade', '20'));
const TIMING = !process.argv.includes('--no-timing');
const NEAR_RULE = 'near = max(min(0.01, z/8), 4z/ratio), far = near · ratio';
/** @param {number} ratio @param {number} z */
const nearFor = (ratio, z) => Math.max(Math.min(0.01, z / 8), (4 * z) / ratio);

const playground = await openPlayground();
const browser = playground.browser;
try {
  const page = await browser.newPage();
  await page.goto(playground.url('harness/?page=camera'));
  await page.waitForFunction(() => document.getElementById('viewport')?.dataset.ready === 'true');
  const allModes = await page.evaluate(() => window.cameraDepth.modes);
  const only = arg('--modes', '');
  /** @type {ProbeMode[]} */
  const modes = only ? /** @type {ProbeMode[]} */ (only.split(',')) : allModes;
  for (const m of modes) if (!allModes.includes(m)) throw new RangeError(`--modes: unknown mode ${m}`);
  const active = await page.evaluate((ms) => ms.map((m) => window.cameraDepth.activeMode(m)), modes);
  /** @type {{ mode: string, active: string, ratio: number, near: number, far: number, z: number, minSeparation: number | null }[]} */
  const rows = [];
  for (const [i, mode] of modes.entries()) {
    for (const ratio of RATIOS) {
      for (const z of DISTANCES) {
        const near = nearFor(ratio, z);
        const far = near * ratio;
        const minSeparation = await page.evaluate(
          ([m, n, f, d, p]) => window.cameraDepth.threshold(m, n, f, d, p),
          /** @type {const} */ ([mode, near, far, z, PER_DECADE]),
        );
        rows.push({ mode, active: active[i], ratio, near, far, z, minSeparation });
      }
    }
  }
  // Cost of one probe frame (render + 1×1 readPixels) per mode, milliseconds.
  /** @type {Record<string, ReturnType<typeof summarize>> | null} */
  let frameTimes = null;
  if (TIMING) {
    frameTimes = {};
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
  }

  /** @param {number | null} x */
  const fmt = (x) =>
    x === null ? '—' : x === Number.POSITIVE_INFINITY ? '> 1' : x <= 1e-9 ? '≤ 1e-9' : x.toExponential(1);
  /** @param {number} x */
  const exp = (x) => `1e${Math.round(Math.log10(x))}`;
  console.log(`\nSmallest Δz/z still drawn in the right order (${NEAR_RULE})`);
  for (const z of DISTANCES) {
    console.log(`\nz = ${z}\n`);
    console.log(`| mode | ${RATIOS.map((r) => `far/near ${exp(r)}`).join(' | ')} |`);
    console.log(`| --- | ${RATIOS.map(() => '---').join(' | ')} |`);
    console.log(`| _near_ | ${RATIOS.map((r) => `_${Number(nearFor(r, z).toPrecision(2))}_`).join(' | ')} |`);
    for (const mode of modes) {
      const cells = RATIOS.map((ratio) =>
        fmt(rows.find((r) => r.mode === mode && r.ratio === ratio && r.z === z)?.minSeparation ?? null),
      );
      console.log(`| ${mode} | ${cells.join(' | ')} |`);
    }
  }
  if (frameTimes) {
    console.log(
      '\n| mode | renderer reports | probe frame median (ms) | min | max |\n| --- | --- | --- | --- | --- |',
    );
    for (const [i, mode] of modes.entries()) {
      const t = frameTimes[mode];
      console.log(
        `| ${mode} | ${active[i]} | ${t.median.toFixed(3)} | ${t.min.toFixed(3)} | ${t.max.toFixed(3)} |`,
      );
    }
  }
  const userAgent = await page.evaluate(() => navigator.userAgent);
  writeResults({
    name: 'camera-depth',
    date: new Date().toISOString(),
    browser: userAgent,
    method: `Δz/z scanned down a log grid (${PER_DECADE} per decade) from 1 to 1e-9; value = smallest separation with the order kept there and at every larger grid point; 8×8 canvas; red quad at z, green at z(1+Δz/z) drawn after it; centre pixel; ${NEAR_RULE}`,
    nearRule: NEAR_RULE,
    rows: rows.map((r) => ({
      ...r,
      minSeparation: r.minSeparation === Number.POSITIVE_INFINITY ? 'lost' : r.minSeparation,
    })),
    frameTimes,
  });
} finally {
  await playground.close();
}
