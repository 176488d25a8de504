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
// Issue 23: the realistic scene (bench/harness/realistic-scene.ts: 1,000 instanced level-3 spheres with instance
// colours, three PointLights and a DirectionalLight, Fog) on WebGPURenderer's backends: ShadingNodeMaterial in
// each shading against MeshPhongNodeMaterial (and MeshLambertNodeMaterial), interleaved the same way in
// `--realistic-frames` frames per variant in `--realistic-rounds` rounds (a frame takes hundreds of ms here).
// Targets: phong ≤ 1.0× MeshPhongNodeMaterial, gouraud and flat cheaper (< 1.0×).
//
//   node bench/webgpu.bench.mjs [--json PATH] [--frames 80] [--rounds 8] [--width 1280 --height 720]
//                               [--realistic-frames 30] [--realistic-rounds 6] [--only lecture,realistic]
//                               [--quick] [--experiments NAME,...] [--realistic-experiments NAME,...] [--ab]
//                               [--backends webgpu,webgl2,webgl]
//
// --quick: 6 frames in 2 rounds, the realistic scene 2 in 1 (a smoke check, not a measurement). --only: the
// scenes to time (the results file then holds only those). --experiments: also time the named A/B variants of
// the lighting (the page's experimentalMaterial) on both backends in the lecture's scene; --realistic-experiments:
// the same for phong shading in the realistic scene (each against phong shading as it is: vsBaseline). --ab: only
// phong × phong and three's phong material, in the realistic scene only phong, MeshPhongNodeMaterial (each with
// the experiments), for a quicker A/B run. --backends also limits the realistic scene (drawn on WebGPURenderer's
// backends only).
import { arg, writeResults } from './lib/bench.mjs';
import { openWebgpuBench, Timings } from './lib/webgpuPage.mjs';

const quick = process.argv.includes('--quick');
const frames = Number(arg('--frames', quick ? '6' : '80'));
const rounds = Number(arg('--rounds', quick ? '2' : '8'));
const realisticFrames = Number(arg('--realistic-frames', quick ? '2' : '30'));
const realisticRounds = Number(arg('--realistic-rounds', quick ? '1' : '6'));
const width = Number(arg('--width', '1280'));
const height = Number(arg('--height', '720'));
const onlyBackends = arg('--backends', 'webgpu,webgl2,webgl').split(',');
const only = arg('--only', 'lecture,realistic').split(',');
const experimentList = (/** @type {string} */ flag) =>
  /** @type {import('./harness/webgpu-bench').Experiment[]} */ (
    arg(flag, '')
      .split(',')
      .filter((e) => e !== '')
  );
const experiments = experimentList('--experiments');
const realisticExperiments = experimentList('--realistic-experiments');

/** @typedef {import('./harness/webgpu-bench').BenchSpec} BenchSpec */
/** @typedef {import('./harness/webgpu-bench').Backend} Backend */

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
const ab = process.argv.includes('--ab');
if (ab) {
  const keep = (/** @type {string} */ n) =>
    n.startsWith('three phong') || n === 'phong × phong' || n.startsWith('phong × phong, ');
  VARIANTS.splice(0, VARIANTS.length, ...VARIANTS.filter(([n]) => keep(n)));
}

/** The realistic scene's variants: [name, spec without its backend]. */
/** @type {Array<[string, Omit<BenchSpec, 'backend'>]>} */
const REALISTIC = [
  ['ShadingNodeMaterial phong', { scene: 'realistic', material: 'shadelab', shading: 'phong' }],
  ['ShadingNodeMaterial gouraud', { scene: 'realistic', material: 'shadelab', shading: 'gouraud' }],
  ['ShadingNodeMaterial flat (indexed)', { scene: 'realistic', material: 'shadelab', shading: 'flat' }],
  [
    'ShadingNodeMaterial flat (flatShadingGeometry)',
    { scene: 'realistic', material: 'shadelab', shading: 'flat', flatGeometry: 'prepared' },
  ],
  ['MeshPhongNodeMaterial', { scene: 'realistic', material: 'three-phong' }],
  ['MeshLambertNodeMaterial', { scene: 'realistic', material: 'three-lambert' }],
];

/** The operations countOps counts: name → pattern (WGSL and GLSL spellings). */
const OPS = {
  statements: /;\s*$/gm,
  branches: /\bif\s*\(/g,
  normalize: /\bnormalize\s*\(/g,
  length: /\blength\s*\(/g,
  dot: /\bdot\s*\(/g,
  pow: /\bpow\s*\(/g,
  exp2: /\bexp2\s*\(/g,
  divisions: /\s\/\s/g,
  derivatives: /\b(dpdx|dpdy|dFdx|dFdy)\s*\(/g,
  inverse: /inverse/g,
};

/**
 * Counts of OPS in the main function of a generated shader stage (from `start`, the entry point, to the end).
 * @param {string | null} code @param {RegExp} start @returns {Record<string, number> | null}
 */
function countOps(code, start) {
  if (code === null) return null;
  const at = code.search(start);
  const main = at < 0 ? code : code.slice(at);
  return Object.fromEntries(Object.entries(OPS).map(([name, re]) => [name, (main.match(re) ?? []).length]));
}

/** The row name of variant `name` on `backend`. @param {Backend} backend @param {string} name */
const rowName = (backend, name) => `${backend}: ${name}`;

const { page, info, close } = await openWebgpuBench({ width, height });
const timings = new Timings();
/** @type {Record<string, unknown>} */
const results = {
  note: 'The machine was shared with other work during the run (2 cores; load average in Runs): the same-cycle ratios are the result, the absolute milliseconds are not.',
  frames,
  rounds,
  quick,
};
try {
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

  if (only.includes('lecture')) await lecture();
  if (only.includes('realistic')) await realistic();
} finally {
  await close();
}
writeResults(results);

/** Issue 15's lecture scene: every variant on every backend; results.perBackend and results.targets. */
async function lecture() {
  /** @type {Array<[string, BenchSpec]>} */
  const specs = [];
  for (const [backend] of BACKENDS) {
    if (!onlyBackends.includes(backend)) continue;
    for (const [name, spec] of VARIANTS) {
      if (backend === 'webgl' && spec.experiment !== undefined) continue;
      specs.push([rowName(backend, name), { ...spec, backend }]);
    }
  }
  await timings.time(page, specs, { frames, rounds, label: 'lecture ' });
  const rows = timings.rows;

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
          spec.material === 'shadelab' ? timings.ratio(rowName(backend, name), reference(name)) : null,
        vsBaseline:
          spec.experiment === undefined
            ? undefined
            : timings.ratio(rowName(backend, name), rowName(backend, name.replace(/, experiment .*$/, ''))),
        vsWebGLRenderer:
          backend === 'webgl' || spec.experiment !== undefined
            ? null
            : timings.ratio(rowName(backend, name), rowName('webgl', name)),
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
      const r = timings.ratio(rowName(backend, name), rowName(backend, reference));
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
}

/**
 * Issue 23's realistic scene on WebGPURenderer's backends: ShadingNodeMaterial in each shading against
 * MeshPhongNodeMaterial, all variants of both backends interleaved; results.realistic.
 */
async function realistic() {
  const backends = /** @type {const} */ (['webgpu', 'webgl2']).filter((b) => onlyBackends.includes(b));
  const row = (/** @type {Backend} */ backend, /** @type {string} */ name) => `realistic/${backend}: ${name}`;
  /** @type {Array<[string, Omit<BenchSpec, 'backend'>]>} */
  const timed = [
    ...REALISTIC.filter(([name]) => !ab || name.endsWith('phong') || name === 'MeshPhongNodeMaterial'),
    ...realisticExperiments.map(
      (name) =>
        /** @type {[string, Omit<BenchSpec, 'backend'>]} */ ([
          `ShadingNodeMaterial phong, experiment ${name}`,
          { scene: 'realistic', material: 'shadelab', shading: 'phong', experiment: name },
        ]),
    ),
  ];
  const specs = backends.flatMap((backend) =>
    timed.map(
      ([name, spec]) => /** @type {[string, BenchSpec]} */ ([row(backend, name), { ...spec, backend }]),
    ),
  );
  await timings.time(page, specs, { frames: realisticFrames, rounds: realisticRounds, label: 'realistic ' });
  /** @type {Record<string, unknown>} */
  const perBackend = {};
  /** @type {Record<string, unknown>} */
  const targets = {};
  for (const backend of backends) {
    const label = BACKENDS.find(([b]) => b === backend)?.[1] ?? backend;
    /** @type {Record<string, unknown>} */
    const variants = {};
    for (const [name, spec] of timed) {
      variants[name] = {
        ...timings.rows[row(backend, name)],
        vsMeshPhong:
          name === 'MeshPhongNodeMaterial'
            ? null
            : timings.ratio(row(backend, name), row(backend, 'MeshPhongNodeMaterial')),
        vsBaseline:
          spec.experiment === undefined
            ? undefined
            : timings.ratio(row(backend, name), row(backend, 'ShadingNodeMaterial phong')),
      };
    }
    perBackend[backend] = { label, variants };
    if (ab) continue;
    for (const [shading, target] of [
      ['phong', '≤ 1.0'],
      ['gouraud', '< 1.0 (cheaper)'],
      ['flat (flatShadingGeometry)', '< 1.0 (cheaper)'],
      ['flat (indexed)', '< 1.0 (cheaper)'],
    ]) {
      const r = timings.ratio(
        row(backend, `ShadingNodeMaterial ${shading}`),
        row(backend, 'MeshPhongNodeMaterial'),
      );
      targets[`${backend}: ${shading}`] = {
        ratio: r,
        target,
        met: r === null ? null : target.startsWith('≤') ? r.paired <= 1 : r.paired < 1,
      };
    }
  }
  // What each variant's generated shaders do per vertex and per fragment (the WGSL of the WebGPU backend, the
  // GLSL of the WebGL2 one): calls and statements in the stage's main function.
  /** @type {Record<string, Record<string, unknown>>} */
  const shaderOps = {};
  for (const backend of backends) {
    shaderOps[backend] = {};
    for (const [name, spec] of timed) {
      if ('error' in (timings.rows[row(backend, name)] ?? {})) continue;
      const code = await page.evaluate((sp) => window.webgpuBench.shader(sp), { ...spec, backend });
      shaderOps[backend][name] = {
        vertex: countOps(code.vertexShader, /@vertex|void main\s*\(/),
        fragment: countOps(code.fragmentShader, /@fragment|void main\s*\(/),
      };
    }
  }
  results.realistic = {
    scene:
      "bench/harness/realistic-scene.ts: 1,000 instances (10 × 10 × 10, spacing 3) of the level-3 tetrahedron sphere (256 triangles, indexed, smooth normals) with instance colours, three PointLights (decay 2) and a DirectionalLight, linear Fog, perspective camera 50°; ShadingNodeMaterial ka = kd = 0.6 grey, ks = 0.5, α = 32, phong lighting, three's lights; its flat shading draws the indexed sphere as it is (lit per fragment with the face normal from screen-space derivatives), or its flatShadingGeometry made for the backend's provoking vertex (each face lit once, at its centroid, in the vertex stage); MeshPhongNodeMaterial colour 0.6 grey, specular 0.5, shininess 32; MeshLambertNodeMaterial colour 0.6 grey. Each frame drawn offscreen into a linear RGBA8 render target, then a 1×1 read-back",
    frames: realisticFrames,
    rounds: realisticRounds,
    perBackend,
    targets,
    shaderOps,
  };
  for (const backend of backends) {
    console.log(
      `\nrealistic scene, ${BACKENDS.find(([b]) => b === backend)?.[1]}, ${info.width}×${info.height}`,
    );
    console.log('| variant | frame ms | min | GPU ms | / MeshPhongNodeMaterial (GPU) |');
    for (const [name] of timed) {
      const v = /** @type {any} */ (/** @type {any} */ (perBackend[backend]).variants[name]);
      if (v.error) {
        console.log(`| ${name} | does not render: ${v.error} |`);
        continue;
      }
      const r = v.vsMeshPhong;
      console.log(
        `| ${name} | ${v.frameMs.median.toFixed(1)} | ${v.frameMs.min.toFixed(1)} | ${v.gpuMs ? v.gpuMs.median.toFixed(1) : 'n/a'} | ${r ? `${r.paired.toFixed(3)} (${r.median.toFixed(3)}) GPU ${r.gpu?.toFixed(3) ?? 'n/a'}` : '—'} |${v.vsBaseline ? ` / without: ${v.vsBaseline.paired.toFixed(3)} (GPU ${v.vsBaseline.gpu?.toFixed(3)})` : ''}`,
      );
    }
  }
  for (const [name, t] of Object.entries(targets)) {
    const x = /** @type {any} */ (t);
    console.log(
      `realistic ${name} / MeshPhongNodeMaterial: ${x.ratio ? x.ratio.paired.toFixed(3) : 'n/a'} (target ${x.target}: ${x.met ? 'met' : 'not met'})`,
    );
  }
}
