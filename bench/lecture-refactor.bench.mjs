// Issue 23's measurement of its refactor (one definition of the options and of the lecture's equation, the GLSL
// as named chunks, the node material's surface): the lecture's scene drawn with @shadelab/material as it was
// before the refactor (BEFORE, the commit before the 1/π light mapping, bundled from git by
// bench/lib/materialAt.mjs) and as checked out, in one page (bench/harness/webgpu-bench.ts, whose loadModule
// takes the older build and draws it through the page's three.js), on both renderers: WebGLRenderer with
// ShadingMaterial, and WebGPURenderer with ShadingNodeMaterial on its WebGPU and WebGL2 backends. Every variant
// of both builds and every backend run interleaved frame by frame (the page's cycle) in `rounds` rounds, so
// that load from other processes hits both builds alike; after / before is the median of the ratios of frames
// from the same cycle (and the ratio of the medians). Each frame is drawn offscreen and followed by a 1×1
// read-back. Scene: the material bench's level-6 sphere (analytic normals; flat: ShadingMaterial's
// flatShadingGeometry, ShadingNodeMaterial's exact per-face path on the triangle soup) and one PhongLight.
// Target (issue 23): after ≤ 1.02× before, every shading on both renderers.
// On WebGPURenderer the checkout's ShadingNodeMaterial is also timed with three's own observer ('static-bindings',
// the page's experimentalMaterial): what refreshing its bindings on every frame (its observer's hasNode, which
// the build before did not have) costs here.
//
//   node bench/lecture-refactor.bench.mjs [--json PATH] [--frames 120] [--rounds 12] [--width 1280 --height 720]
//                                         [--backends webgl,webgpu,webgl2] [--no-experiment] [--quick]
//
// --quick: 6 frames in 2 rounds (a smoke check, not a measurement). --no-experiment: without the static-bindings
// rows.
import { arg, writeResults } from './lib/bench.mjs';
import { bundleMaterialAt } from './lib/materialAt.mjs';
import { openWebgpuBench, Timings } from './lib/webgpuPage.mjs';

/** The last commit before issue 23's refactor of the materials (3390eb4: the 1/π light mapping). */
const BEFORE = '3390eb4^';
const TARGET = 1.02;
const quick = process.argv.includes('--quick');
const frames = Number(arg('--frames', quick ? '6' : '120'));
const rounds = Number(arg('--rounds', quick ? '2' : '12'));
const width = Number(arg('--width', '1280'));
const height = Number(arg('--height', '720'));
const backends = /** @type {import('./harness/webgpu-bench').Backend[]} */ (
  arg('--backends', 'webgl,webgpu,webgl2').split(',')
);
const SHADINGS = /** @type {const} */ (['flat', 'gouraud', 'phong']);
const experiment = !process.argv.includes('--no-experiment');
const STATIC = 'after, static bindings';

/** @type {Record<string, { label: string, material: string }>} */
const RENDERERS = {
  webgl: { label: 'WebGLRenderer', material: 'ShadingMaterial' },
  webgpu: { label: 'WebGPURenderer (WebGPU)', material: 'ShadingNodeMaterial' },
  webgl2: { label: 'WebGPURenderer (WebGL2)', material: 'ShadingNodeMaterial' },
};

const before = await bundleMaterialAt(BEFORE);
const { page, info, close } = await openWebgpuBench({ width, height });
const timings = new Timings();
/** @type {Record<string, unknown>} */
const results = {
  note: 'The machine was shared with other work during the run (2 cores; load average in Runs): the same-cycle ratios are the result, the absolute milliseconds are not.',
  width,
  height,
  frames,
  rounds,
  quick,
};
try {
  const exported = await page.evaluate((code) => window.webgpuBench.loadModule('before', code), before.code);
  const row = (/** @type {string} */ backend, /** @type {string} */ shading, /** @type {string} */ build) =>
    `${backend}: ${shading} ${build}`;
  /** @type {Array<[string, import('./harness/webgpu-bench').BenchSpec]>} */
  const specs = [];
  for (const backend of backends) {
    for (const shading of SHADINGS) {
      specs.push([
        row(backend, shading, 'before'),
        { backend, material: 'shadelab', shading, build: 'before' },
      ]);
      specs.push([row(backend, shading, 'after'), { backend, material: 'shadelab', shading }]);
      if (experiment && backend !== 'webgl') {
        specs.push([
          row(backend, shading, STATIC),
          { backend, material: 'shadelab', shading, experiment: 'static-bindings' },
        ]);
      }
    }
  }
  await timings.time(page, specs, { frames, rounds });

  /** @type {Record<string, unknown>} */
  const perBackend = {};
  /** @type {Record<string, { ratio: import('./lib/webgpuPage.mjs').Ratio | null, target: string, met: boolean | null }>} */
  const targets = {};
  for (const backend of backends) {
    /** @type {Record<string, unknown>} */
    const shadings = {};
    for (const shading of SHADINGS) {
      const r = timings.ratio(row(backend, shading, 'after'), row(backend, shading, 'before'));
      shadings[shading] = {
        before: timings.rows[row(backend, shading, 'before')],
        after: timings.rows[row(backend, shading, 'after')],
        afterVsBefore: r,
        ...(experiment && backend !== 'webgl'
          ? {
              staticBindings: timings.rows[row(backend, shading, STATIC)],
              staticBindingsVsBefore: timings.ratio(
                row(backend, shading, STATIC),
                row(backend, shading, 'before'),
              ),
              afterVsStaticBindings: timings.ratio(
                row(backend, shading, 'after'),
                row(backend, shading, STATIC),
              ),
            }
          : {}),
      };
      targets[`${backend}: ${shading}`] = {
        ratio: r,
        target: `≤ ${TARGET}`,
        met: r === null ? null : r.paired <= TARGET,
      };
    }
    perBackend[backend] = { ...RENDERERS[backend], shadings };
  }
  Object.assign(results, {
    scene:
      "the material bench's lecture scene: the level-6 tetrahedron sphere (16,384 triangles, radius 2, no normal attribute: the analytic sphere normal), perspective camera 90° at z = 3, one PhongLight at (−5, 10, 20) (Ia 0.2, Id 1, Is 0.8), the default ka = kd = (0.6, 0.35, 0.2), ks = 0.5, α = 32, phong lighting. Flat: ShadingMaterial draws each build's flatShadingGeometry, ShadingNodeMaterial the triangle soup (its exact per-face path). Each frame drawn offscreen into a linear RGBA8 render target, then a 1×1 read-back (WebGPU: readRenderTargetPixelsAsync; WebGL2 backend and WebGLRenderer: readPixels)",
    before: { rev: BEFORE, commit: before.commit, exports: exported.length },
    after: 'this checkout (meta.commit; meta.dirty: with uncommitted changes)',
    staticBindings: experiment
      ? "on WebGPURenderer, the checkout's ShadingNodeMaterial with three's own observer (without hasNode: its bindings not refreshed on every frame), timed in the same cycles: what the per-frame refresh costs here"
      : null,
    gpuTimer: {
      webgl: info.webgl.timer ? 'EXT_disjoint_timer_query_webgl2' : 'not available',
      webgpu: info.webgpu.timestamps ? "three's trackTimestamp (timestamp-query)" : 'not available',
      webgl2: info.webgl2.timestamps
        ? "three's trackTimestamp (EXT_disjoint_timer_query_webgl2)"
        : 'not available',
    },
    perBackend,
    targets,
  });

  console.log(
    `\nlecture scene, before (${before.commit.slice(0, 7)}) and after, ${frames} frames in ${rounds} rounds`,
  );
  console.log('| renderer: shading | before ms | after ms | after / before (medians) | GPU | target |');
  for (const [name, t] of Object.entries(targets)) {
    const [backend, shading] = name.split(': ');
    const s = /** @type {any} */ (perBackend[backend]).shadings[shading];
    const ms = (/** @type {any} */ r) => (r && !r.error ? r.frameMs.median.toFixed(2) : `error: ${r?.error}`);
    const r = t.ratio;
    const x = s.afterVsStaticBindings;
    console.log(
      `| ${RENDERERS[backend].label}: ${shading} | ${ms(s.before)} | ${ms(s.after)} | ${r ? `${r.paired.toFixed(3)} (${r.median.toFixed(3)})` : 'n/a'} | ${r?.gpu?.toFixed(3) ?? 'n/a'} | ${t.target}: ${t.met === null ? 'n/a' : t.met ? 'met' : 'NOT MET'} |${x ? ` after / static bindings ${x.paired.toFixed(3)} (GPU ${x.gpu?.toFixed(3)})` : ''}`,
    );
  }
} finally {
  await close();
}
writeResults(results);
