// Issue 23's "the lighting itself", on WebGLRenderer in headless Chromium (SwiftShader): the vertex-heavy variant of
// the realistic scene (bench/harness/realistic-scene.ts with the level-3 icosahedron sphere: 1,280 triangles a
// sphere, 1,000 instances, three's three PointLights and DirectionalLight, linear fog, 1280×720) wearing
// MeshBasicMaterial (the unlit floor: the same vertices, instancing, fog and output, no lighting),
// MeshPhongMaterial and ShadingMaterial (phong shading with Phong and with Blinn-Phong lighting; gouraud), the
// variants interleaved frame by frame (bench/harness/lighting-bench.ts), so that load from
// other processes hits all of them alike.
// - frame time / MeshPhongMaterial's, the median of the ratios of frames from the same cycle;
// - the lighting above the floor, (frame − MeshBasic's) / (MeshPhong's − MeshBasic's), frames of one cycle, the
//   median over the cycles (and the same of the medians). Target: ShadingMaterial phong ≤ 0.9.
// Only this bench's own page is built (not the playground): vite builds bench/harness/lighting-bench.html.
//
//   node bench/lighting.bench.mjs [--json PATH] [--frames 40]
// The smallest run: --frames 2.
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { browserCpuSeconds, openBenchPage } from './lib/browser.mjs';

const frames = Number(arg('--frames', '40'));

/** @typedef {import('./harness/lighting-bench').LightingVariant} LightingVariant */
const FLOOR = 'MeshBasicMaterial (unlit floor)';
const PHONG = 'MeshPhongMaterial';
/** @type {Array<[string, LightingVariant]>} */
const variants = [
  [FLOOR, { kind: 'three-basic' }],
  [PHONG, { kind: 'three-phong' }],
  ['ShadingMaterial phong, Phong lighting', { kind: 'shadelab', shading: 'phong', lighting: 'phong' }],
  [
    'ShadingMaterial phong, Blinn-Phong lighting',
    { kind: 'shadelab', shading: 'phong', lighting: 'blinn-phong' },
  ],
  ['ShadingMaterial gouraud, Phong lighting', { kind: 'shadelab', shading: 'gouraud', lighting: 'phong' }],
];
const TARGET = 'ShadingMaterial phong, Phong lighting';

const pages = await openBenchPage('lighting-bench');
const page = await pages.browser.newPage({ viewport: { width: 1280, height: 720 } });
await page.goto(pages.url('harness/lighting-bench.html'));
await page.waitForFunction(() => document.body.dataset.ready === '1');

/** Every timed frame of each variant, in cycle order (frame i of every variant comes from cycle i): wall ms, CPU ms. */
const wall = variants.map(() => /** @type {number[]} */ ([]));
const cpu = variants.map(() => /** @type {number[]} */ ([]));
const triangles = await page.evaluate((a) => window.lightingBench.prepare(a.variants, a.warmup), {
  variants: variants.map(([, v]) => v),
  warmup: 3,
});
for (let i = 0; i < frames; i++) {
  for (let k = 0; k < variants.length; k++) {
    const c0 = browserCpuSeconds();
    wall[k].push(await page.evaluate((n) => window.lightingBench.frame(n), k));
    cpu[k].push((browserCpuSeconds() - c0) * 1000);
  }
  if ((i + 1) % 10 === 0) console.log(`${i + 1}/${frames} cycles`);
}
await pages.close();

const median = (/** @type {number[]} */ xs) => summarize(xs).median;
const at = (/** @type {string} */ name) => variants.findIndex(([n]) => n === name);
/**
 * Each variant's frames against MeshPhongMaterial's: the median of the same-cycle ratios (and the ratio of the
 * medians), of the frame and of the lighting above the floor. @param {number[][]} times
 */
function ratios(times) {
  const floor = times[at(FLOOR)];
  const phong = times[at(PHONG)];
  return variants.map(([name], k) => {
    const f = times[k];
    return {
      frame: { paired: median(f.map((t, i) => t / phong[i])), median: median(f) / median(phong) },
      lighting:
        name === FLOOR
          ? null
          : {
              paired: median(f.map((t, i) => (t - floor[i]) / (phong[i] - floor[i]))),
              median: (median(f) - median(floor)) / (median(phong) - median(floor)),
            },
    };
  });
}
const wallRatios = ratios(wall);
const cpuRatios = ratios(cpu);
/** @type {Record<string, any>} */
const rows = {};
variants.forEach(([name], k) => {
  rows[name] = {
    frameMs: summarize(wall[k]),
    cpuMs: summarize(cpu[k]),
    trianglesPerFrame: triangles[k],
    vsMeshPhong: wallRatios[k].frame,
    lightingVsMeshPhong: wallRatios[k].lighting,
    cpuVsMeshPhong: cpuRatios[k].frame,
    cpuLightingVsMeshPhong: cpuRatios[k].lighting,
  };
});
const target = rows[TARGET].lightingVsMeshPhong;
const cpuTarget = rows[TARGET].cpuLightingVsMeshPhong;
const results = {
  scene:
    '1,000 instances (10 × 10 × 10, spacing 3) of the level-3 icosahedron sphere (1,280 triangles, 642 vertices, indexed, smooth normals), instanceColor, three PointLights (decay 2) and a DirectionalLight, linear Fog, perspective camera 50°, 1280×720; every material grey 0.6 (ka = kd = colour), specular ks 0.5, shininess 32',
  note: 'The machine was shared with other work during the run (2 cores; load average in meta): the same-cycle ratios are the result, the absolute milliseconds are not.',
  width: 1280,
  height: 720,
  frames,
  floor: FLOOR,
  rows,
  target: {
    variant: TARGET,
    measure: 'lighting above the unlit floor / MeshPhongMaterial’s, median over the cycles',
    ratio: target.paired,
    cpuRatio: cpuTarget.paired,
    target: '≤ 0.9',
    met: target.paired <= 0.9,
  },
};
const cell = (/** @type {{ paired: number, median: number } | null} */ x) =>
  x ? `${x.paired.toFixed(3)} (${x.median.toFixed(3)})` : '—';
console.log(
  '| variant | wall ms | CPU ms | / MeshPhong (wall; CPU) | lighting above the floor / MeshPhong’s (wall; CPU) |',
);
console.log('| --- | ---: | ---: | ---: | ---: |');
for (const [name, row] of Object.entries(rows)) {
  console.log(
    `| ${name} | ${row.frameMs.median.toFixed(1)} | ${row.cpuMs.median.toFixed(1)} | ${cell(row.vsMeshPhong)}; ${cell(row.cpuVsMeshPhong)} | ${cell(row.lightingVsMeshPhong)}; ${cell(row.cpuLightingVsMeshPhong)} |`,
  );
}
writeResults(results);
