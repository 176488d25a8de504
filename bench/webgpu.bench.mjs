// Issue 15's measurements, in headless Chromium (SwiftShader for WebGL2 and WebGPU): frame time and, where the
// browser offers a timer, GPU time of every ShadingNodeMaterial variant on both backends of three's
// WebGPURenderer (WebGPU; WebGL2 with forceWebGL), against three's MeshPhongNodeMaterial on the same backend and
// against ShadingMaterial (and MeshPhongMaterial) under WebGLRenderer, all in one page and one run.
// Scene: the lecture's (the material bench's level-6 sphere, one PhongLight; three's materials get the
// equivalent AmbientLight + PointLight), and, for phong shading, three's lights (ambient, point, directional).
// Every frame is drawn offscreen into a render target and followed by a 1×1 read-back (harness page:
// bench/harness/webgpu-bench.ts). Variants run interleaved frame by frame (the page's cycle) in `rounds`
// rounds; ratios are the median of the ratios of frames from the same cycle (and of the medians).
// Target: phong shading ≤ 1.0× MeshPhongNodeMaterial on the same backend.
//
//   node bench/webgpu.bench.mjs [--json PATH] [--frames 80] [--rounds 8] [--width 1280 --height 720]
//                               [--quick] [--experiments NAME,...] [--ab] [--backends webgpu,webgl2,webgl]
//
// --quick: 6 frames in 2 rounds (a smoke check, not a measurement). --experiments: also time the named
// A/B variants of the lighting (the page's experimentalMaterial) on both backends; --ab: only phong × phong and
// three's phong material (with the experiments), for a quicker A/B run.
import { chromium } from '@playwright/test';
import { chromiumArgs, chromiumExecutable, webgpuArgs } from '../scripts/browser.mjs';
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

const quick = process.argv.includes('--quick');
const frames = Number(arg('--frames', quick ? '6' : '80'));
const rounds = Number(arg('--rounds', quick ? '2' : '8'));
const width = Number(arg('--width', '1280'));
const height = Number(arg('--height', '720'));
const onlyBackends = arg('--backends', 'webgpu,webgl2,webgl').split(',');
const experiments = /** @type {import('./harness/webgpu-bench').Experiment[]} */ (
  arg('--experiments', '')
    .split(',')
    .filter((e) => e !== '')
);

/** @typedef {import('./harness/webgpu-bench').BenchSpec} BenchSpec */
/** @typedef {import('./harness/webgpu-bench').Backend} Backend */
/** @typedef {{ frameMs: ReturnType<typeof summarize>, gpuMs: ReturnType<typeof summarize> | null } | { error: string }} Row */

/** @type {Array<[Backend, string]>} */
const BACKENDS = [
  ['webgpu', 'WebGPURenderer (WebGPU)'],
  ['webgl2', 'WebGPURenderer (WebGL2)'],
  ['webgl', 'WebGLRenderer'],
];

/** The variants of every backend: [name, spec without its backend]. */
/** @type {Array<[string, Omit<BenchSpec, 'backend'>]>} */
const VARIANTS = [];
for (const shading of /** @type {const} */ (['flat', 'gouraud', 'phong'])) {
  for (const lighting of /** @type {const} */ (['phong', 'blinn-phong'])) {
    VARIANTS.push([`${shading} × ${lighting}`, { material: 'shadelab', shading, lighting }]);
  }
}
for (const lighting of /** @type {const} */ (['phong', 'blinn-phong'])) {
  VARIANTS.push([
    `phong × ${lighting} × cel 4`,
    { material: 'shadelab', shading: 'phong', lighting, celBands: 4 },
  ]);
}
VARIANTS.push(["phong × phong, three's lights", { material: 'shadelab', shading: 'phong', lights: 'three' }]);
const THREE_PHONG = 'three phong';
const THREE_PHONG_LIGHTS = "three phong, three's lights";
VARIANTS.push([THREE_PHONG, { material: 'three-phong' }]);
VARIANTS.push([THREE_PHONG_LIGHTS, { material: 'three-phong', lights: 'three' }]);
for (const name of experiments) {
  for (const lights of /** @type {const} */ (['phong', 'three'])) {
    VARIANTS.push([
      `phong × phong${lights === 'three' ? ", three's lights" : ''}, experiment ${name}`,
      { material: 'shadelab', shading: 'phong', lights, experiment: name },
    ]);
  }
}
// --ab: only phong shading (phong lighting) and three's phong material, with the experiments, for A/B runs.
if (process.argv.includes('--ab')) {
  const keep = (/** @type {string} */ n) =>
    n.startsWith('three phong') || n === 'phong × phong' || n.startsWith('phong × phong, ');
  VARIANTS.splice(0, VARIANTS.length, ...VARIANTS.filter(([n]) => keep(n)));
}

/** Every timed frame of each row, in the order of the cycles (for the paired ratios). */
/** @type {Map<string, number[]>} */
const framesOf = new Map();

/**
 * Time `specs` interleaved frame by frame in `rounds` rounds and summarise each: frame time (and GPU time)
 * median, min, max. Frame k of every spec comes from the same cycle.
 * @param {import('@playwright/test').Page} page
 * @param {Array<[string, BenchSpec]>} specs
 * @returns {Promise<Record<string, Row>>}
 */
async function roundRobin(page, specs) {
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
    console.log(`round ${round + 1}/${rounds}: ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  }
  /** @type {Record<string, Row>} */
  const rows = {};
  for (const [name, p] of Object.entries(pooled)) {
    framesOf.set(name, p.frames);
    rows[name] = p.error
      ? { error: p.error }
      : { frameMs: summarize(p.frames), gpuMs: p.gpu.length ? summarize(p.gpu) : null };
  }
  return rows;
}

/**
 * Row `a` against row `b`: `paired`, the median of the ratios of frames timed in the same cycle (what a change
 * of load during the run moves least); `median` and `min`, the ratios of the medians and of the minima; `gpu`,
 * the ratio of the GPU-time medians when both have them. Null when either did not render.
 * @param {Record<string, Row>} rows @param {string} a @param {string} b
 */
function ratio(rows, a, b) {
  const ra = rows[a];
  const rb = rows[b];
  if (!ra || !rb || 'error' in ra || 'error' in rb) return null;
  const fa = framesOf.get(a) ?? [];
  const fb = framesOf.get(b) ?? [];
  const pairs = fa.slice(0, Math.min(fa.length, fb.length)).map((t, i) => t / fb[i]);
  return {
    paired: summarize(pairs).median,
    median: ra.frameMs.median / rb.frameMs.median,
    min: ra.frameMs.min / rb.frameMs.min,
    gpu: ra.gpuMs && rb.gpuMs ? ra.gpuMs.median / rb.gpuMs.median : null,
  };
}

/** The row name of variant `name` on `backend`. @param {Backend} backend @param {string} name */
const rowName = (backend, name) => `${backend}: ${name}`;

const playground = await openPlayground();
const browser = await chromium.launch({
  executablePath: chromiumExecutable() ?? undefined,
  args: [...chromiumArgs, ...webgpuArgs],
});
/** @type {Record<string, unknown>} */
const results = {
  note: 'The machine was shared with other work during the run (2 cores; load average in Runs): the same-cycle ratios are the result, the absolute milliseconds are not.',
  frames,
  rounds,
  quick,
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
  console.log(JSON.stringify(info));
  results.width = info.width;
  results.height = info.height;
  results.backends = {
    webgpu: {
      ...info.webgpu,
      adapter: info.adapter,
      gpuTimer: info.webgpu.timestamps
        ? "three's trackTimestamp (timestamp-query)"
        : info.adapter?.timestampQuery
          ? 'timestamp-query offered but not tracked by three'
          : 'not available on SwiftShader (the adapter offers no timestamp-query)',
    },
    webgl2: {
      ...info.webgl2,
      gpuTimer: info.webgl2.timestamps
        ? "three's trackTimestamp (EXT_disjoint_timer_query_webgl2)"
        : 'not available (no EXT_disjoint_timer_query_webgl2)',
    },
    webgl: {
      ...info.webgl,
      gpuTimer: info.webgl.timer
        ? 'EXT_disjoint_timer_query_webgl2'
        : 'not available (no EXT_disjoint_timer_query_webgl2)',
    },
  };

  /** @type {Array<[string, BenchSpec]>} */
  const specs = [];
  for (const [backend] of BACKENDS) {
    if (!onlyBackends.includes(backend)) continue;
    for (const [name, spec] of VARIANTS) {
      if (backend === 'webgl' && spec.experiment !== undefined) continue;
      specs.push([rowName(backend, name), { ...spec, backend }]);
    }
  }
  const rows = await roundRobin(page, specs);

  /** @type {Record<string, unknown>} */
  const perBackend = {};
  for (const [backend, label] of BACKENDS) {
    const reference = (/** @type {string} */ name) =>
      rowName(backend, name.includes("three's lights") ? THREE_PHONG_LIGHTS : THREE_PHONG);
    /** @type {Record<string, unknown>} */
    const variants = {};
    for (const [name, spec] of VARIANTS) {
      const row = rows[rowName(backend, name)];
      if (!row) continue;
      variants[name] = {
        ...row,
        vsThreePhong:
          spec.material === 'shadelab' ? ratio(rows, rowName(backend, name), reference(name)) : null,
        vsBaseline:
          spec.experiment === undefined
            ? undefined
            : ratio(rows, rowName(backend, name), rowName(backend, name.replace(/, experiment .*$/, ''))),
        vsWebGLRenderer:
          backend === 'webgl' || spec.experiment !== undefined
            ? null
            : ratio(rows, rowName(backend, name), rowName('webgl', name)),
      };
    }
    const node = backend !== 'webgl';
    perBackend[backend] = {
      label,
      material: node ? 'ShadingNodeMaterial' : 'ShadingMaterial',
      threePhong: node ? 'MeshPhongNodeMaterial' : 'MeshPhongMaterial',
      gpuTimer: /** @type {Record<string, { gpuTimer: string }>} */ (results.backends)[backend].gpuTimer,
      variants,
    };
  }
  /** @type {Record<string, unknown>} */
  const targets = {};
  for (const backend of /** @type {const} */ (['webgpu', 'webgl2'])) {
    for (const name of ['phong × phong', 'phong × blinn-phong', "phong × phong, three's lights"]) {
      const reference = name.includes("three's lights") ? THREE_PHONG_LIGHTS : THREE_PHONG;
      const r = ratio(rows, rowName(backend, name), rowName(backend, reference));
      targets[`${backend}: ${name}`] = { ratio: r, target: '≤ 1.0', met: r === null ? null : r.paired <= 1 };
    }
  }
  results.scene =
    "the material bench's lecture scene: the level-6 tetrahedron sphere (16,384 triangles, radius 2; ours without normals: the analytic sphere normal; three's with smooth normals), perspective camera 90° at z = 3; ka = kd = (0.6, 0.35, 0.2), ks = 0.5, α = 32 for every material. Lecture lights: one PhongLight at (−5, 10, 20) (Ia 0.2, Id 1, Is 0.8); three's materials get AmbientLight(0.2) and PointLight(1, decay 0) there. Three's lights: AmbientLight(0.2), PointLight(400, decay 2) at (−5, 10, 20), DirectionalLight(0.8) from (5, 10, 7). Flat shading: ShadingNodeMaterial draws the triangle soup (its exact per-face path), ShadingMaterial flatShadingGeometry; everything else the indexed sphere. Each frame drawn offscreen into a linear RGBA8 render target, then a 1×1 read-back (WebGPU: readRenderTargetPixelsAsync; WebGL2 backend and WebGLRenderer: readPixels)";
  results.variants = VARIANTS.map(([name, spec]) => ({ name, ...spec }));
  results.perBackend = perBackend;
  results.targets = targets;

  for (const [backend, label] of BACKENDS) {
    console.log(`\n${label}, ${info.width}×${info.height}, median of ${frames} frames in ${rounds} rounds`);
    console.log('| variant | frame ms | min | GPU ms | / three phong | / WebGLRenderer |');
    const pb = /** @type {{ variants: Record<string, any> }} */ (perBackend[backend]);
    for (const [name, v] of Object.entries(pb.variants)) {
      if (v.error) {
        console.log(`| ${name} | does not render: ${v.error} |`);
        continue;
      }
      const fmt = (/** @type {any} */ r) => (r ? `${r.paired.toFixed(3)} (${r.median.toFixed(3)})` : '—');
      console.log(
        `| ${name} | ${v.frameMs.median.toFixed(2)} | ${v.frameMs.min.toFixed(2)} | ${v.gpuMs ? v.gpuMs.median.toFixed(2) : 'n/a'} | ${fmt(v.vsThreePhong)} | ${fmt(v.vsWebGLRenderer)} |${v.vsBaseline ? ` / without: ${fmt(v.vsBaseline)} (GPU ${v.vsBaseline.gpu?.toFixed(3)})` : ''}`,
      );
    }
  }
  for (const [name, t] of Object.entries(targets)) {
    const r = /** @type {any} */ (t).ratio;
    console.log(`${name} / three phong: ${r ? r.paired.toFixed(3) : 'n/a'} (target ≤ 1.0)`);
  }
} finally {
  await browser.close();
  await playground.close();
}
writeResults(results);
