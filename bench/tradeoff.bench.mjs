// The speed/accuracy trade of drawing the lecture's sphere: every shading (flat on flatShadingGeometry,
// Gouraud, Phong meshes of every base at levels 0 … 8, Gouraud and Phong also at the --smooth-levels, and the
// ray-cast impostor) measured against the exact answer (renderReference, once per run)
// at 1280×720 in headless Chromium (SwiftShader): interior RMSE and max error in 8-bit sRGB, silhouette error
// in pixels, frame time (1×1 readPixels after each frame, warm-up, median of pooled round-robin rounds),
// triangles and buffer bytes. Then the Pareto front and, for each error target, the cheapest option meeting
// it. (The auto-detail zoom sweep is bench/autodetail.bench.mjs.)
//
//   node bench/tradeoff.bench.mjs [--json PATH] [--levels 0,1,...,8] [--smooth-levels 9] [--frames 15]
//                                 [--rounds 3] [--no-timing]
//
// --no-timing measures the errors, triangles and bytes only (deterministic: no frame timing, no Pareto front);
// without --json it writes nothing, so it never replaces the timed results.
import { loadavg } from 'node:os';
import { SPHERE_BASES } from '@shadelab/sphere';
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

/** @param {string} list */
const numbers = (list) => (list === '' ? [] : list.split(',').map(Number));
const levels = numbers(arg('--levels', '0,1,2,3,4,5,6,7,8'));
// Indexed (Gouraud, Phong) only: level 9 is 1M–5.2M triangles, 19–94 MB of buffers (flat would be 50–252 MB).
const smoothLevels = numbers(arg('--smooth-levels', '9'));
const timing = !process.argv.includes('--no-timing');
const frames = Number(arg('--frames', '15'));
const rounds = Number(arg('--rounds', '3'));
const WIDTH = 1280;
const HEIGHT = 720;
const loadBefore = loadavg();

const playground = await openPlayground();
const browser = playground.browser;
const page = await browser.newPage({ viewport: { width: WIDTH, height: HEIGHT } });
await page.goto(playground.url('harness/?page=tradeoff'));
await page.waitForFunction(() => document.body.dataset.ready === '1');

/** @typedef {import('../playground/src/tradeoff/tradeoffScene').TradeOption} TradeOption */
/** @typedef {import('../playground/src/tradeoff/tradeoffScene').TradeView} TradeView */
/** @type {TradeView} */
const view = { width: WIDTH, height: HEIGHT };

/** @type {TradeOption[]} */
const options = [{ shading: 'impostor' }];
for (const shading of /** @type {const} */ (['flat', 'gouraud', 'phong'])) {
  const more = shading === 'flat' ? [] : smoothLevels.filter((l) => !levels.includes(l));
  for (const base of SPHERE_BASES)
    for (const level of [...levels, ...more]) options.push({ shading, base, level });
}
/** @param {TradeOption} o */
const key = (o) => (o.shading === 'impostor' ? 'impostor' : `${o.shading} ${o.base} ${o.level}`);

// 3. Errors (one frame each; the reference is computed once in the page and cached).
const referenceMs = await page.evaluate((v) => window.tradeoff.referenceMs(v), view);
const gpuTimer = await page.evaluate(() => window.tradeoff.hasTimer);
console.log(`reference ${WIDTH}×${HEIGHT} in the page: ${referenceMs.toFixed(0)} ms`);
/** @type {Record<string, any>} */
const rows = {};
for (const option of options) {
  const t0 = performance.now();
  const error = await page.evaluate(
    ([v, o]) => window.tradeoff.compare(v, o),
    /** @type {const} */ ([view, option]),
  );
  // Wall time of this step (geometry build on first use, one frame, full readPixels, scoring): only to show
  // what a level costs to include, never a frame time.
  const errorStepMs = performance.now() - t0;
  const cost = await page.evaluate((o) => window.tradeoff.cost(o), option);
  rows[key(option)] = {
    option,
    ...cost,
    error,
    errorStepMs,
    frames: /** @type {number[]} */ ([]),
    gpu: /** @type {number[]} */ ([]),
  };
  if (!timing) {
    console.log(
      `${key(option)}: ${cost.triangles} triangles, ${cost.bytes} B; RMSE ${error.rmse.toFixed(2)}, max ${error.max}, silhouette ${error.silhouettePx.toFixed(2)} px (step ${errorStepMs.toFixed(0)} ms)`,
    );
  }
}

// 4. Frame times, round-robin so that load from other processes spreads over every option.
for (let round = 0; timing && round < rounds; round++) {
  for (const option of options) {
    const times = await page.evaluate(
      ([v, o, n, w]) => window.tradeoff.time(v, o, n, w),
      /** @type {const} */ ([view, option, Math.ceil(frames / rounds), round === 0 ? 3 : 1]),
    );
    rows[key(option)].frames.push(...times.frames);
    rows[key(option)].gpu.push(...times.gpu);
  }
}
for (const row of Object.values(rows)) {
  row.frameMs = timing ? summarize(row.frames) : null;
  row.gpuMs = row.gpu.length ? summarize(row.gpu) : null;
  delete row.frames;
  delete row.gpu;
}

// 5. Pareto front (frame time against each error) and the cheapest option per error target.
const list = Object.entries(rows).map(([name, r]) => ({ name, ...r }));
/** @param {(r: any) => number} err */
function front(err) {
  if (!timing) return [];
  const sorted = [...list].sort((a, b) => a.frameMs.median - b.frameMs.median || err(a) - err(b));
  const out = [];
  let best = Number.POSITIVE_INFINITY;
  for (const r of sorted) {
    if (err(r) < best) {
      out.push(r.name);
      best = err(r);
    }
  }
  return out;
}
const paretoRmse = front((r) => r.error.rmse);
const paretoSilhouette = front((r) => r.error.silhouettePx);
const rmseTargets = [1, 2, 4, 8];
const silhouetteTargets = [0.5, 1, 2, 4];
/** @type {Record<string, Record<string, string | null>>} */
const cheapest = {};
for (const rt of timing ? rmseTargets : []) {
  cheapest[`rmse≤${rt}`] = {};
  for (const st of silhouetteTargets) {
    const meets = list.filter((r) => r.error.rmse <= rt && r.error.silhouettePx <= st);
    meets.sort((a, b) => a.frameMs.median - b.frameMs.median || a.bytes - b.bytes);
    cheapest[`rmse≤${rt}`][`silhouette≤${st}px`] = meets[0]?.name ?? null;
  }
}

await playground.close();

const results = {
  width: WIDTH,
  height: HEIGHT,
  frames: timing ? frames : 0,
  rounds: timing ? rounds : 0,
  levels,
  smoothLevels,
  referenceMs,
  gpuTimer,
  load: { before: loadBefore, after: loadavg() },
  note: 'headless Chromium, SwiftShader WebGL2 (CPU rendering): frame times are CPU-bound and relative; shared, loaded machine unless rerun quietly',
  rows,
  paretoRmse,
  paretoSilhouette,
  cheapest,
};

// 6. Tables.
console.log(
  `\nlecture scene ${WIDTH}×${HEIGHT}; frame ms = median of ${frames} (load ${loadBefore.map((x) => x.toFixed(1)).join(' ')})`,
);
console.log('| option | triangles | bytes | RMSE | max | silhouette px | frame ms (median) | min | GPU ms |');
console.log('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
for (const r of list) {
  const frame = r.frameMs ? `${r.frameMs.median.toFixed(2)} | ${r.frameMs.min.toFixed(2)}` : 'n/a | n/a';
  console.log(
    `| ${r.name} | ${r.triangles} | ${r.bytes} | ${r.error.rmse.toFixed(2)} | ${r.error.max} | ${r.error.silhouettePx.toFixed(2)} | ${frame} | ${r.gpuMs ? r.gpuMs.median.toFixed(2) : 'n/a'} |`,
  );
}
console.log(`\nPareto front (frame time vs RMSE): ${paretoRmse.join(' → ')}`);
console.log(`Pareto front (frame time vs silhouette): ${paretoSilhouette.join(' → ')}`);
console.log(`\n| cheapest meeting | ${silhouetteTargets.map((s) => `silhouette ≤ ${s} px`).join(' | ')} |`);
console.log(`| --- | ${silhouetteTargets.map(() => '---').join(' | ')} |`);
for (const rt of timing ? rmseTargets : []) {
  console.log(
    `| RMSE ≤ ${rt} | ${silhouetteTargets.map((s) => cheapest[`rmse≤${rt}`][`silhouette≤${s}px`] ?? '—').join(' | ')} |`,
  );
}
writeResults(results);
