// Issue 25's measurement, on WebGLRenderer in headless Chromium (SwiftShader): the realistic scene (1,000
// instanced level-3 tetrahedron spheres, three's PointLights and DirectionalLight, linear fog, 1280×720;
// bench/harness/realistic-scene.ts) in the published view and in a deeper one (the camera 3× as far, a 30° field
// of view in place of 50°, the fog moved back with it), with
// - MeshPhongMaterial (the scene as an app has it),
// - after swapMaterials: all-Phong (ShadingMaterial, Phong shading, full detail: the reference of the error),
//   fixed Gouraud, fixed flat,
// - AdaptiveShading at maxError 8 and 32 (update() every frame, included in the frame time; the camera is still,
//   so that is the cached update),
// interleaved frame by frame (each cycle draws one frame of every variant), after a warm-up. Per variant: frame
// time (wall) and the CPU time of the browser's processes (/proc; load-independent), the median of the
// same-cycle ratios against all-Phong and against MeshPhongMaterial; the measured error of its picture against
// all-Phong's (p99 and max of the per-pixel max |Δ| over RGB, fractions over 2, 8 and 32 levels, over the drawn
// pixels); for adaptive, the choices taken, the time to measure its error table (at add), and update() alone
// when everything moved (the camera nudged: no cache). Targets: adaptive 8 ≤ 0.7× all-Phong, adaptive 32 ≤ 0.5×.
// Only this bench's own page is built (not the playground): vite builds bench/harness/adaptive-bench.html.
//
//   node bench/adaptive.bench.mjs [--json PATH] [--frames 30] [--views published,deep]
// The smallest run: --frames 2.
import { loadavg } from 'node:os';
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { browserCpuSeconds, openBenchPage } from './lib/browser.mjs';

const frames = Number(arg('--frames', '30'));
const views = /** @type {import('./harness/adaptive-bench').AdaptiveView[]} */ (
  arg('--views', 'published,deep').split(',').filter(Boolean)
);
const loadAtStart = loadavg();

/** @typedef {import('./harness/adaptive-bench').AdaptiveVariant} AdaptiveVariant */
const MESH_PHONG = 'MeshPhongMaterial';
const ALL_PHONG = 'all-Phong';
/** @type {Array<[string, AdaptiveVariant]>} */
const variants = [
  [MESH_PHONG, { kind: 'three-phong' }],
  [ALL_PHONG, { kind: 'fixed', shading: 'phong' }],
  ['fixed Gouraud', { kind: 'fixed', shading: 'gouraud' }],
  ['fixed flat', { kind: 'fixed', shading: 'flat' }],
  ['adaptive, maxError 8', { kind: 'adaptive', maxError: 8 }],
  ['adaptive, maxError 32', { kind: 'adaptive', maxError: 32 }],
];
/** The targets against all-Phong (issue 25). */
const TARGETS = { 'adaptive, maxError 8': 0.7, 'adaptive, maxError 32': 0.5 };

const pages = await openBenchPage('adaptive-bench');
const page = await pages.browser.newPage({ viewport: { width: 1280, height: 720 } });
page.on('console', (m) => {
  if (m.type() === 'warning' || m.type() === 'error') console.log(`[page ${m.type()}] ${m.text()}`);
});
await page.goto(pages.url('harness/adaptive-bench.html'));
await page.waitForFunction(() => document.body.dataset.ready === '1');

const median = (/** @type {number[]} */ xs) => summarize(xs).median;
const at = (/** @type {string} */ name) => variants.findIndex(([n]) => n === name);
const round = (/** @type {number} */ x, digits = 4) => Math.round(x * 10 ** digits) / 10 ** digits;

/** The median of the same-cycle ratios of `times[k]` against `times[ref]`, and the ratio of the medians. */
function ratio(/** @type {number[][]} */ times, /** @type {number} */ k, /** @type {number} */ ref) {
  const a = times[k];
  const b = times[ref];
  return {
    paired: round(median(a.map((t, i) => t / b[i]))),
    median: round(median(a) / median(b)),
  };
}

/** @type {Record<string, any>} */
const byView = {};
for (const view of views) {
  console.log(`view ${view}: building ${variants.length} scenes (adaptive: measuring the error tables)`);
  const prepared = await page.evaluate((a) => window.adaptiveBench.prepare(a.variants, a.view, a.warmup), {
    variants: variants.map(([, v]) => v),
    view,
    warmup: 3,
  });
  const wall = variants.map(() => /** @type {number[]} */ ([]));
  const cpu = variants.map(() => /** @type {number[]} */ ([]));
  for (let i = 0; i < frames; i++) {
    for (let k = 0; k < variants.length; k++) {
      const c0 = browserCpuSeconds();
      wall[k].push(await page.evaluate((n) => window.adaptiveBench.frame(n), k));
      cpu[k].push((browserCpuSeconds() - c0) * 1000);
    }
    if ((i + 1) % 10 === 0) console.log(`  ${i + 1}/${frames} cycles`);
  }
  const errors = await page.evaluate((ref) => window.adaptiveBench.errors(ref), at(ALL_PHONG));
  /** @type {Record<string, any>} */
  const rows = {};
  for (let k = 0; k < variants.length; k++) {
    const [name, variant] = variants[k];
    const e = errors[k];
    rows[name] = {
      frameMs: summarize(wall[k]),
      cpuMs: summarize(cpu[k]),
      vsAllPhong: ratio(wall, k, at(ALL_PHONG)),
      cpuVsAllPhong: ratio(cpu, k, at(ALL_PHONG)),
      vsMeshPhong: ratio(wall, k, at(MESH_PHONG)),
      triangles: prepared[k].triangles,
      drawCalls: prepared[k].calls,
      error: {
        drawn: e.drawn,
        p99: e.p99,
        max: e.max,
        over2: round(e.over2, 6),
        over8: round(e.over8, 6),
        over32: round(e.over32, 6),
      },
    };
    if (variant.kind === 'adaptive') {
      const budget = variant.maxError;
      rows[name].maxError = budget;
      rows[name].overBudget = round(budget === 8 ? e.over8 : budget === 32 ? e.over32 : Number.NaN, 6);
      rows[name].choices = await page.evaluate((n) => window.adaptiveBench.choices(n), k);
      rows[name].model = (await page.evaluate((n) => window.adaptiveBench.model(n), k)).map(
        (/** @type {any} */ m) => ({ ...m, over8: round(m.over8, 6), over32: round(m.over32, 6) }),
      );
      rows[name].tableAndBuildMs = round(prepared[k].buildMs, 1);
      rows[name].updateMovedMs = summarize(
        await page.evaluate((n) => window.adaptiveBench.updateCost(n, 9), k),
      );
    }
  }
  /** @type {Record<string, any>} */
  const targets = {};
  for (const [name, limit] of Object.entries(TARGETS)) {
    const r = rows[name];
    targets[name] = {
      ratio: r.vsAllPhong.paired,
      cpuRatio: r.cpuVsAllPhong.paired,
      target: `≤ ${limit} × all-Phong`,
      met: r.vsAllPhong.paired <= limit,
      honest: {
        p99: r.error.p99,
        budget: r.maxError,
        overBudget: r.overBudget,
        withinBudget: r.error.p99 <= r.maxError && r.overBudget <= 0.005,
      },
    };
  }
  byView[view] = { rows, targets };
  console.log(`\n${view} view, 1280×720, ${frames} cycles`);
  console.log('| variant | frame ms | / all-Phong (wall; CPU) | / MeshPhong | p99 | max | > 8 | > 32 |');
  console.log('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
  for (const [name, r] of Object.entries(rows)) {
    console.log(
      `| ${name} | ${r.frameMs.median.toFixed(1)} | ${r.vsAllPhong.paired.toFixed(3)}; ${r.cpuVsAllPhong.paired.toFixed(3)} | ${r.vsMeshPhong.paired.toFixed(3)} | ${r.error.p99} | ${r.error.max} | ${(100 * r.error.over8).toFixed(2)} % | ${(100 * r.error.over32).toFixed(2)} % |`,
    );
  }
  for (const [name, t] of Object.entries(targets)) {
    console.log(
      `${name}: ${t.ratio} (target ${t.target}) ${t.met ? 'met' : 'NOT met'}; ${JSON.stringify(rows[name].choices)}`,
    );
  }
}
/**
 * Why the targets are (not) met, from this run's numbers: the budget's allowance against what fixed Gouraud and
 * coarser levels put over it, and how far inside the budget the adaptive picture stayed.
 */
function why() {
  const v = byView.published ?? Object.values(byView)[0];
  if (!v) return null;
  const g = v.rows['fixed Gouraud'].error;
  const a8 = v.rows['adaptive, maxError 8'];
  const a32 = v.rows['adaptive, maxError 32'];
  const full = (/** @type {any} */ r) => r.choices?.['phong full'] ?? 0;
  /** @param {any} row @param {string} choice */
  const modelRow = (row, choice) => row.model?.find((/** @type {any} */ m) => m.choice === choice) ?? null;
  /** @param {any} m @param {'over8' | 'over32'} key */
  const pctOf = (m, key) => (m ? `${(100 * m[key]).toFixed(1)} %` : 'n/a');
  const share = (/** @type {number} */ over) => (over > 0 ? `${((100 * 0.004) / over).toFixed(1)} %` : 'all');
  return `Why (${views[0] === 'published' ? 'published view' : views[0]}): the budget is a percentile: all but 0.4 % of the drawn pixels within maxError of all-Phong's picture (the issue allows 0.5 %). Fixed Gouraud puts ${(100 * g.over8).toFixed(1)} % of the drawn pixels over 8 and ${(100 * g.over32).toFixed(1)} % over 32, so under that allowance Gouraud may cover at most about ${share(g.over8)} of the spheres' pixels at budget 8 and ${share(g.over32)} at 32, which bounds what it can save; fixed flat costs ${v.rows['fixed flat'].vsAllPhong.paired.toFixed(2)} × all-Phong here, with more pixels over than Gouraud (${(100 * v.rows['fixed flat'].error.over8).toFixed(1)} % over 8). A coarser level saves vertex work, but it moves the outline (every outline pixel that moves is over any budget) and, the sphere's normals being its vertices' (\`normals: 'smooth'\`), changes the interior too: the error model puts Phong shading at level 2 ${pctOf(modelRow(a8, 'phong 2'), 'over8')} over 8. So AdaptiveShading kept ${full(a8)} and ${full(a32)} of the 1,000 instances at Phong shading and full detail at budgets 8 and 32, and its pictures stayed inside the budgets (p99 ${a8.error.p99} and ${a32.error.p99}, largest ${a8.error.max} and ${a32.error.max}). Its error model (the worst over sampled light and view directions of one white light Id = Is = 1, no fog) predicts Gouraud at full detail ${pctOf(modelRow(a8, 'gouraud full'), 'over8')} over 8 and ${pctOf(modelRow(a8, 'gouraud full'), 'over32')} over 32, against the ${(100 * g.over8).toFixed(1)} % and ${(100 * g.over32).toFixed(1)} % measured in this picture; the allowance it leaves unspent goes to the outlines of the coarser levels (estimated from each level's largest radial error: an upper bound) and to the hysteresis margin (the choice aims at the allowance / 1.15).`;
}

await pages.close();

const loadAtEnd = loadavg();
const load = (/** @type {number[]} */ l) => l.map((x) => x.toFixed(2)).join(' / ');
writeResults({
  note: `The machine was shared with other work during the run (2 cores; load average ${load(loadAtStart)} at the start, ${load(loadAtEnd)} at the end: 1, 5, 15 minutes): the same-cycle ratios are the result, the absolute milliseconds are not.`,
  scene:
    "issue 14's realistic scene: 1,000 instances (10 × 10 × 10, spacing 3) of the level-3 tetrahedron sphere (256 triangles, indexed, smooth normals), instanceColor, three PointLights (intensity 400, decay 2) and a DirectionalLight (0.8), linear Fog, 1280×720; MeshPhongMaterial({ color 0.6, specular 0.5, shininess 32 }), and swapMaterials(scene) for the ShadingMaterial rows",
  views: {
    published: 'camera (30, 22, 38) looking at the centre, 50° field of view, fog 35 … 95',
    deep: 'camera 3× as far on the same line (90, 66, 114), 30° field of view, the fog moved back by as much as the camera (141 … 201)',
  },
  error:
    "each picture against all-Phong's (ShadingMaterial, Phong shading, full detail) over the drawn pixels (covered by the full-detail spheres, or different): the per-pixel max |Δ| over RGB in 8-bit sRGB levels; its 99th percentile and largest value, the fractions over 2, 8 and 32",
  frames,
  width: 1280,
  height: 720,
  variants: variants.map(([name, v]) => ({ name, ...v })),
  results: byView,
  why: why(),
});
