// Frame and GPU time of ShadingMaterial variants against three's MeshPhongMaterial, MeshLambertMaterial and
// MeshToonMaterial: a sphere filling most of a 1280×720 canvas in headless Chromium (SwiftShader), levels
// 4, 6 and 8 of the lecture's tetrahedron sphere. Each frame is followed by a 1×1 readPixels (SwiftShader's
// gl.finish() does not wait); GPU time from EXT_disjoint_timer_query_webgl2.
//
//   node bench/material.bench.mjs [--json PATH] [--levels 4,6,8] [--frames 27] [--rounds 3] [--only NAME,...]
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

const levels = arg('--levels', '4,6,8').split(',').map(Number);
const frames = Number(arg('--frames', '27'));
// Variants run round-robin in `rounds` rounds of frames/rounds frames each, so that load from other
// processes spreads over all variants instead of hitting one; the frames of all rounds are pooled.
const rounds = Number(arg('--rounds', '3'));
const only = arg('--only', ''); // run only the variants whose name contains one of these (comma-separated)

// 1. Build and serve the harness pages (bench/harness/material-bench.html), launch Chromium.
const playground = await openPlayground();
const browser = playground.browser;
const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
await page.goto(playground.url('harness/material-bench.html'));
await page.waitForFunction(() => document.body.dataset.ready === '1');
const hasTimer = await page.evaluate(() => window.materialBench.hasTimer);

/** @type {Array<[string, import('./harness/material-bench').BenchVariant]>} */
const variants = [];
for (const shading of /** @type {const} */ (['flat', 'gouraud', 'phong'])) {
  for (const lighting of /** @type {const} */ (['phong', 'blinn-phong'])) {
    for (const celBands of [0, 4]) {
      variants.push([
        `${shading} × ${lighting}${celBands ? ' × cel 4' : ''}`,
        { kind: 'shadelab', shading, lighting, celBands },
      ]);
    }
  }
}
variants.push([
  'flat × phong (triangle soup)',
  { kind: 'shadelab', shading: 'flat', lighting: 'phong', soup: true },
]);
variants.push([
  'phong × phong, 2 lights',
  { kind: 'shadelab', shading: 'phong', lighting: 'phong', lights: 2 },
]);
variants.push([
  'gouraud × phong, 2 lights',
  { kind: 'shadelab', shading: 'gouraud', lighting: 'phong', lights: 2 },
]);
variants.push(['three MeshPhongMaterial', { kind: 'three-phong' }]);
variants.push(['three MeshPhongMaterial, 2 lights', { kind: 'three-phong', lights: 2 }]);
variants.push(['three MeshLambertMaterial', { kind: 'three-lambert' }]);
variants.push(['three MeshToonMaterial', { kind: 'three-toon' }]);
// No lighting: what transforming and rasterising the sphere costs by itself.
variants.push(['three MeshBasicMaterial (no lighting)', { kind: 'three-basic' }]);

/** @typedef {import('./harness/material-bench').BenchResult} BenchResult */
/** @type {{ width: number, height: number, frames: number, rounds: number, gpuTimer: boolean, levels: Record<number, unknown> }} */
const results = { width: 1280, height: 720, frames, rounds, gpuTimer: hasTimer, levels: {} };
for (const level of levels) {
  const memory = await page.evaluate((l) => window.materialBench.memory(l), level);
  const selected = variants.filter(
    ([name]) =>
      !only ||
      only.split(',').some((o) => name.includes(o)) ||
      /^phong × phong$|^three MeshPhongMaterial$|^gouraud × phong$|^flat × phong$|^phong × phong, 2 lights$|Basic|soup/.test(
        name,
      ),
  );
  /** @type {Record<string, { frames: number[], gpu: number[], programs: number }>} */
  const pooled = {};
  for (let round = 0; round < rounds; round++) {
    for (const [name, variant] of selected) {
      /** @type {BenchResult} */
      const r = await page.evaluate((a) => window.materialBench.run(a.variant, a.level, a.frames, a.warmup), {
        variant,
        level,
        frames: Math.ceil(frames / rounds),
        warmup: round === 0 ? 5 : 2,
      });
      pooled[name] ??= { frames: [], gpu: [], programs: 0 };
      pooled[name].frames.push(...r.frames);
      pooled[name].gpu.push(...r.gpu);
      pooled[name].programs = r.programs;
    }
  }
  /** @type {Record<string, { frameMs: ReturnType<typeof summarize>, gpuMs: ReturnType<typeof summarize> | null }>} */
  const rows = {};
  for (const [name, p] of Object.entries(pooled)) {
    rows[name] = { frameMs: summarize(p.frames), gpuMs: p.gpu.length ? summarize(p.gpu) : null };
  }
  /** Ratios of medians, and of minima (the least disturbed frames). */
  const ratio = (/** @type {string} */ a, /** @type {string} */ b) => ({
    median: rows[a].frameMs.median / rows[b].frameMs.median,
    min: rows[a].frameMs.min / rows[b].frameMs.min,
  });
  const targets = {
    phongVsMeshPhong: ratio('phong × phong', 'three MeshPhongMaterial'),
    gouraudVsPhong: ratio('gouraud × phong', 'phong × phong'),
    flatVsPhong: ratio('flat × phong', 'phong × phong'),
    flatSoupVsPhong: ratio('flat × phong (triangle soup)', 'phong × phong'),
    twoLightsVsOne: ratio('phong × phong, 2 lights', 'phong × phong'),
  };
  results.levels[level] = { triangles: 4 * 4 ** level, memory, rows, targets };
  console.log(`\nlevel ${level} (${4 * 4 ** level} triangles), 1280×720, median of ${frames} frames`);
  console.log('| variant | frame ms (median) | min | max | GPU ms |');
  console.log('| --- | ---: | ---: | ---: | ---: |');
  for (const [name, r] of Object.entries(rows)) {
    const f = r.frameMs;
    const g = r.gpuMs === null ? 'n/a' : r.gpuMs.median.toFixed(2);
    console.log(`| ${name} | ${f.median.toFixed(2)} | ${f.min.toFixed(2)} | ${f.max.toFixed(2)} | ${g} |`);
  }
  /** @param {{ median: number, min: number }} r */
  const show = (r) => `${r.median.toFixed(2)} (min ${r.min.toFixed(2)})`;
  console.log(
    `targets (ratio of medians, of minima): phong/MeshPhong ${show(targets.phongVsMeshPhong)} (≤ 1), gouraud/phong ${show(targets.gouraudVsPhong)} (< 1), flat/phong ${show(targets.flatVsPhong)} (< 1), 2 lights/1 light ${show(targets.twoLightsVsOne)} (< 2)`,
  );
}
await playground.close();
writeResults(results);
