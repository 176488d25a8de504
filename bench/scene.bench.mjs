// Issue 14's measurements, in headless Chromium (SwiftShader), every frame followed by a 1×1 readPixels:
// 1. realistic: 1,000 instanced level-3 spheres, three PointLights, a DirectionalLight and fog at 1280×720:
//    ShadingMaterial flat (prepared, non-indexed, and the indexed sphere as it is), gouraud and phong against
//    MeshPhongMaterial and MeshLambertMaterial; targets: phong ≤ 1.0× MeshPhongMaterial, gouraud and flat cheaper.
// 2. lecture: the lecture's scene (the material bench's level-6 sphere) with the ShadingMaterial of the commit
//    before issue 14 began (BEFORE, bundled here from git) and of this checkout; target: after/before ≤ 1.02×.
// 3. flat: flat shading of an indexed TorusKnotGeometry and the level-3 and level-6 spheres, prepared
//    (flatShadingGeometry), non-indexed, and indexed as it is: error against shade() per face, frame time, bytes.
// Variants run interleaved frame by frame (the page's cycle) in `rounds` rounds, so that load from other processes
// hits all of them alike; ratios are the median of the ratios of frames from the same cycle (and of the medians).
//
// The realistic scene is slow in SwiftShader (hundreds of ms a frame): `--frames` frames per variant in
// `--rounds` rounds; the lecture and flat scenes take `--small-frames` in `--small-rounds`.
//
//   node bench/scene.bench.mjs [--json PATH] [--frames 30] [--rounds 10] [--small-frames 120] [--small-rounds 20]
//                              [--only realistic,lecture,flat]
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
/** The last commit before issue 14 began (its first commit is 0f35fee). */
const BEFORE = '0f35fee^';
const frames = Number(arg('--frames', '30'));
const rounds = Number(arg('--rounds', '10'));
const smallFrames = Number(arg('--small-frames', '120'));
const smallRounds = Number(arg('--small-rounds', '20'));
const only = arg('--only', 'realistic,lecture,flat').split(',');

/** @param {string[]} args */
const git = (args) => execFileSync('git', args, { cwd: root, encoding: 'utf8' }).trim();

/**
 * @shadelab/material's sources at `rev`, from git, bundled into one ES module whose `three` is the page's
 * (`globalThis.__shadelabThree`, set by the page's loadModule): both materials then render through one three.
 * @param {string} rev
 */
async function bundleMaterialAt(rev) {
  const dir = mkdtempSync(join(tmpdir(), 'shadelab-material-'));
  try {
    const files = git(['ls-tree', '-r', '--name-only', rev, 'packages/material/src'])
      .split('\n')
      .filter((f) => f.endsWith('.ts') && !f.endsWith('.test.ts'));
    for (const file of files) {
      const out = join(dir, file);
      mkdirSync(dirname(out), { recursive: true });
      writeFileSync(out, execFileSync('git', ['show', `${rev}:${file}`], { cwd: root }));
    }
    const names = Object.keys(await import('three')).filter((n) => /^[A-Za-z_$][\w$]*$/.test(n));
    const shim = `const T = globalThis.__shadelabThree;\nexport const { ${names.join(', ')} } = T;\n`;
    const result = await build({
      configFile: false,
      root: dir,
      logLevel: 'warn',
      plugins: [
        {
          name: 'three-of-the-page',
          enforce: 'pre',
          resolveId: (id) => (id === 'three' ? '\0three-of-the-page' : null),
          load: (id) => (id === '\0three-of-the-page' ? shim : null),
        },
      ],
      build: {
        write: false,
        minify: false,
        lib: { entry: join(dir, 'packages/material/src/index.ts'), formats: ['es'], fileName: 'material' },
      },
    });
    const outputs = Array.isArray(result) ? result : [result];
    const chunk = outputs.flatMap((o) => ('output' in o ? o.output : [])).find((o) => o.type === 'chunk');
    if (chunk?.type !== 'chunk') throw new Error(`bundling @shadelab/material at ${rev} gave no chunk`);
    return { code: chunk.code, commit: git(['rev-parse', rev]) };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** @typedef {import('./harness/scene-bench').TimedResult} TimedResult */
/** @typedef {{ frameMs: ReturnType<typeof summarize>, gpuMs: ReturnType<typeof summarize> | null, programs: number } | { error: string }} Row */

/** Every timed frame of each variant, in the order of the cycles (for the paired ratios). */
/** @type {Map<string, number[]>} */
const framesOf = new Map();

/**
 * Time `variants` interleaved frame by frame (the page's cycle) in `count.rounds` rounds, and summarise each:
 * frame-time (and GPU-time) median, min, max. Frame k of every variant comes from the same cycle.
 * @param {import('@playwright/test').Page} page
 * @param {string} prefix a name for this group, which keeps its frames apart from other groups'
 * @param {Array<[string, import('./harness/scene-bench').TimedScene]>} variants
 * @param {{ frames: number, rounds: number }} count frames per variant, in this many rounds
 * @returns {Promise<Record<string, Row>>}
 */
async function roundRobin(page, prefix, variants, count) {
  /** @type {Record<string, { frames: number[], gpu: number[], programs: number, error?: string }>} */
  const pooled = Object.fromEntries(variants.map(([name]) => [name, { frames: [], gpu: [], programs: 0 }]));
  for (let round = 0; round < count.rounds; round++) {
    const live = variants.filter(([name]) => !pooled[name].error);
    const results = await page.evaluate((a) => window.sceneBench.cycle(a.specs, a.frames, a.warmup), {
      specs: live.map(([, spec]) => spec),
      frames: Math.ceil(count.frames / count.rounds),
      warmup: round === 0 ? 3 : 1,
    });
    live.forEach(([name], k) => {
      const r = results[k];
      if (r.error) pooled[name].error = r.error;
      pooled[name].frames.push(...r.frames);
      pooled[name].gpu.push(...r.gpu);
      pooled[name].programs = r.programs;
    });
  }
  /** @type {Record<string, Row>} */
  const rows = {};
  for (const [name, p] of Object.entries(pooled)) {
    framesOf.set(`${prefix}/${name}`, p.frames);
    rows[name] = p.error
      ? { error: p.error }
      : { frameMs: summarize(p.frames), gpuMs: p.gpu.length ? summarize(p.gpu) : null, programs: p.programs };
  }
  return rows;
}

/**
 * Rows `a` against `b` of group `prefix`: `paired`, the median of the ratios of frames timed in the same cycle
 * (what a change of load during the run moves least); `median` and `min`, the ratios of the medians and of the
 * minima. Null when either did not render.
 * @param {string} prefix @param {Record<string, Row>} rows @param {string} a @param {string} b
 */
function ratio(prefix, rows, a, b) {
  const ra = rows[a];
  const rb = rows[b];
  if (!ra || !rb || 'error' in ra || 'error' in rb) return null;
  const fa = framesOf.get(`${prefix}/${a}`) ?? [];
  const fb = framesOf.get(`${prefix}/${b}`) ?? [];
  const pairs = fa.slice(0, Math.min(fa.length, fb.length)).map((t, i) => t / fb[i]);
  return {
    paired: summarize(pairs).median,
    median: ra.frameMs.median / rb.frameMs.median,
    min: ra.frameMs.min / rb.frameMs.min,
  };
}

/** @param {Record<string, Row>} rows */
function printRows(rows) {
  console.log('| variant | frame ms (median) | min | max | GPU ms |');
  console.log('| --- | ---: | ---: | ---: | ---: |');
  for (const [name, r] of Object.entries(rows)) {
    if ('error' in r) {
      console.log(`| ${name} | does not render: ${r.error} | | | |`);
      continue;
    }
    const f = r.frameMs;
    const g = r.gpuMs === null ? 'n/a' : r.gpuMs.median.toFixed(2);
    console.log(`| ${name} | ${f.median.toFixed(2)} | ${f.min.toFixed(2)} | ${f.max.toFixed(2)} | ${g} |`);
  }
}

const before = only.includes('lecture') ? await bundleMaterialAt(BEFORE) : null;
const playground = await openPlayground();
const page = await playground.browser.newPage({ viewport: { width: 1280, height: 720 } });
await page.goto(playground.url('harness/scene-bench.html'));
await page.waitForFunction(() => document.body.dataset.ready === '1');
const hasTimer = await page.evaluate(() => window.sceneBench.hasTimer);

/** @type {Record<string, unknown>} */
const results = {
  note: 'The machine was shared with other work during the run (2 cores; load average in Runs): the same-cycle ratios are the result, the absolute milliseconds are not.',
  width: 1280,
  height: 720,
  frames,
  rounds,
  smallFrames,
  smallRounds,
  gpuTimer: hasTimer,
};

if (only.includes('realistic')) {
  /** @type {Array<[string, import('./harness/scene-bench').RealisticVariant]>} */
  const realisticVariants = [
    ['ShadingMaterial phong', { kind: 'shadelab', shading: 'phong' }],
    ['ShadingMaterial gouraud', { kind: 'shadelab', shading: 'gouraud' }],
    [
      'ShadingMaterial flat (flatShadingGeometry)',
      { kind: 'shadelab', shading: 'flat', geometry: 'prepared' },
    ],
    ['ShadingMaterial flat (non-indexed)', { kind: 'shadelab', shading: 'flat', geometry: 'non-indexed' }],
    [
      'ShadingMaterial flat (indexed, no preparation)',
      { kind: 'shadelab', shading: 'flat', geometry: 'indexed' },
    ],
    ['MeshPhongMaterial', { kind: 'three-phong' }],
    ['MeshLambertMaterial', { kind: 'three-lambert' }],
  ];
  /** @type {Array<[string, import('./harness/scene-bench').TimedScene]>} */
  const variants = realisticVariants.map(([name, variant]) => [name, { scene: 'realistic', variant }]);
  const rows = await roundRobin(page, 'realistic', variants, { frames, rounds });
  const vsPhong = (/** @type {string} */ name) => ratio('realistic', rows, name, 'MeshPhongMaterial');
  const targets = {
    phongVsMeshPhong: { ratio: vsPhong('ShadingMaterial phong'), target: '≤ 1.0' },
    gouraudVsMeshPhong: { ratio: vsPhong('ShadingMaterial gouraud'), target: '< 1.0 (cheaper)' },
    flatVsMeshPhong: {
      ratio: vsPhong('ShadingMaterial flat (flatShadingGeometry)'),
      target: '< 1.0 (cheaper)',
    },
    flatIndexedVsMeshPhong: {
      ratio: vsPhong('ShadingMaterial flat (indexed, no preparation)'),
      target: '< 1.0 (cheaper)',
    },
    lambertVsMeshPhong: { ratio: vsPhong('MeshLambertMaterial'), target: null },
  };
  for (const t of Object.values(targets)) {
    /** @type {{ ratio: { paired: number } | null, target: string | null, met?: boolean | null }} */ (t).met =
      t.ratio === null || t.target === null
        ? null
        : t.target.startsWith('≤')
          ? t.ratio.paired <= 1
          : t.ratio.paired < 1;
  }
  results.realistic = {
    scene:
      '1,000 instances (10 × 10 × 10, spacing 3) of the level-3 tetrahedron sphere (256 triangles, indexed, smooth normals), instanceColor, three PointLights (decay 2) and a DirectionalLight, linear Fog, perspective camera 50°, 1280×720',
    instances: 1000,
    trianglesPerInstance: 256,
    rows,
    ratiosVsMeshPhong: Object.fromEntries(Object.keys(rows).map((name) => [name, vsPhong(name)])),
    targets,
  };
  console.log(`\nrealistic scene, 1280×720, median of ${frames} frames in ${rounds} rounds`);
  printRows(rows);
  for (const [name, t] of Object.entries(targets)) {
    console.log(`${name}: ${t.ratio ? t.ratio.paired.toFixed(3) : 'n/a'} (target ${t.target ?? 'none'})`);
  }
}

if (only.includes('lecture') && before) {
  const exported = await page.evaluate((code) => window.sceneBench.loadModule('before', code), before.code);
  /** @type {Array<[string, import('./harness/scene-bench').TimedScene]>} */
  const variants = [];
  for (const shading of /** @type {const} */ (['flat', 'gouraud', 'phong'])) {
    variants.push([`${shading} before`, { scene: 'lecture', variant: { build: 'before', shading } }]);
    variants.push([`${shading} after`, { scene: 'lecture', variant: { build: 'after', shading } }]);
  }
  const rows = await roundRobin(page, 'lecture', variants, { frames: smallFrames, rounds: smallRounds });
  /** @type {Record<string, { ratio: { paired: number, median: number, min: number } | null, target: string, met: boolean | null }>} */
  const afterVsBefore = {};
  for (const shading of ['flat', 'gouraud', 'phong']) {
    const r = ratio('lecture', rows, `${shading} after`, `${shading} before`);
    afterVsBefore[shading] = { ratio: r, target: '≤ 1.02', met: r === null ? null : r.paired <= 1.02 };
  }
  results.lecture = {
    scene:
      "the material bench's lecture scene: the level-6 tetrahedron sphere (16,384 triangles, radius 2, analytic normals; flat: its flatShadingGeometry), one PhongLight at (−5, 10, 20), perspective camera 90° at z = 3, 1280×720",
    before: { rev: BEFORE, commit: before.commit, exports: exported.length },
    after: 'this checkout (meta.commit)',
    rows,
    afterVsBefore,
  };
  console.log(
    `\nlecture scene, before (${before.commit.slice(0, 7)}) and after, median of ${smallFrames} frames`,
  );
  printRows(rows);
  for (const [shading, t] of Object.entries(afterVsBefore)) {
    console.log(`${shading}: after/before ${t.ratio ? t.ratio.paired.toFixed(3) : 'n/a'} (target ≤ 1.02)`);
  }
}

if (only.includes('flat')) {
  /** @type {Array<import('./harness/scene-bench').FlatMesh>} */
  const meshes = ['torus-knot', 'sphere-3', 'sphere-6'];
  /** @type {Array<import('./harness/scene-bench').FlatMode>} */
  const modes = ['prepared', 'non-indexed', 'indexed'];
  /** @type {Array<[string, import('./harness/scene-bench').TimedScene]>} */
  const variants = meshes.flatMap((mesh) =>
    modes.map(
      (mode) =>
        /** @type {[string, import('./harness/scene-bench').TimedScene]} */ ([
          `${mesh} ${mode}`,
          { scene: 'flat', mesh, mode },
        ]),
    ),
  );
  const rows = await roundRobin(page, 'flat', variants, { frames: smallFrames, rounds: smallRounds });
  /** @type {Record<string, unknown>} */
  const perMesh = {};
  for (const mesh of meshes) {
    const bytes = await page.evaluate((m) => window.sceneBench.flatBytes(m), mesh);
    /** @type {Record<string, unknown>} */
    const perMode = {};
    for (const mode of modes) {
      const error = await page.evaluate((a) => window.sceneBench.flatError(a.mesh, a.mode), { mesh, mode });
      perMode[mode] = {
        error,
        time: rows[`${mesh} ${mode}`],
        vsPrepared: ratio('flat', rows, `${mesh} ${mode}`, `${mesh} prepared`),
        bytes: bytes[mode],
      };
    }
    perMesh[mesh] = { triangles: bytes.prepared.triangles, modes: perMode };
  }
  results.flat = {
    scene:
      "one mesh, flat shading, the lecture's PhongLight at (−5, 10, 20), ka = kd = (0.6, 0.35, 0.2), ks = 0.5, α = 32, perspective camera 90° at z = 3, 1280×720; three's default TorusKnotGeometry (1, 0.4, 64, 8) scaled 1.4, the spheres radius 2; rotated (0.3, 0.5, 0.1)",
    reference:
      "shade() at each face's world centroid with its world face normal, 8-bit sRGB; every pixel whose 3×3 neighbourhood lies on one face (face ids from an id pass of the non-indexed mesh)",
    meshes: perMesh,
  };
  console.log(`\nflat shading without preparation, 1280×720, median of ${smallFrames} frames`);
  printRows(rows);
  console.log(JSON.stringify(perMesh, null, 1));
}

await playground.close();
writeResults(results);
