// BENCHMARKS.md, generated from bench/results/*.json: never edit it, change the JSON (npm run bench, or the
// commands listed in the page) and run this.
//
//   node scripts/benchmarks.mjs           # (npm run benchmarks) writes BENCHMARKS.md
//   node scripts/benchmarks.mjs --check   # exits 1 when BENCHMARKS.md differs from what the JSON renders (npm test)
//
// Every number in the page comes from a results file, and so does how it was measured: each file's `meta`
// block (bench/lib/meta.mjs: date, commit, machine, load average, Node, Chromium and three versions), shown in
// the Runs table; a field a file does not have reads "not recorded".
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { FIRST_FRAME_TITLE, firstFrameSection } from './firstFrameReport.mjs';
import { gateSection } from './gateReport.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
export const OUTPUT = 'BENCHMARKS.md';
const NOT_RECORDED = '_not recorded_';

/**
 * Where each results file comes from, in the order of the page: the script that writes it and the command
 * that regenerates it.
 * @type {{ name: string, writer: string, command: string }[]}
 */
export const SOURCES = [
  { name: 'sphere', writer: 'bench/sphere.bench.mjs', command: 'npm run bench -- sphere' },
  { name: 'autodetail', writer: 'bench/autodetail.bench.mjs', command: 'npm run bench -- autodetail' },
  { name: 'tradeoff', writer: 'bench/tradeoff.bench.mjs', command: 'npm run bench -- tradeoff' },
  { name: 'material', writer: 'bench/material.bench.mjs', command: 'npm run bench -- material' },
  { name: 'scene', writer: 'bench/scene.bench.mjs', command: 'npm run bench -- scene' },
  { name: 'swap', writer: 'bench/swap.bench.mjs', command: 'npm run bench -- swap' },
  { name: 'webgpu', writer: 'bench/webgpu.bench.mjs', command: 'npm run bench -- webgpu' },
  {
    name: 'lecture-refactor',
    writer: 'bench/lecture-refactor.bench.mjs',
    command: 'npm run bench -- lecture-refactor',
  },
  { name: 'lighting', writer: 'bench/lighting.bench.mjs', command: 'npm run bench -- lighting' },
  { name: 'adaptive', writer: 'bench/adaptive.bench.mjs', command: 'npm run bench -- adaptive' },
  { name: 'camera-depth', writer: 'bench/camera-depth.bench.mjs', command: 'npm run bench -- camera-depth' },
  { name: 'trackball', writer: 'bench/trackball.bench.mjs', command: 'npm run bench -- trackball' },
  {
    name: 'size',
    writer: 'scripts/size.mjs',
    command: 'node scripts/size.mjs --json bench/results/size.json',
  },
  {
    name: 'pack',
    writer: 'scripts/pack.mjs',
    command: 'node scripts/pack.mjs --json bench/results/pack.json',
  },
  {
    name: 'playground-bundle',
    writer: 'scripts/bundle-size.mjs',
    command: 'node scripts/bundle-size.mjs --json bench/results/playground-bundle.json',
  },
  {
    name: 'playground-first-frame',
    writer: 'tests/playground-perf.spec.ts',
    command:
      'SHADELAB_FIRST_FRAME_JSON=bench/results/playground-first-frame.json CI=1 npx playwright test tests/playground-perf.spec.ts',
  },
  {
    name: 'playground-refactor',
    writer: 'bench/playground-refactor.bench.mjs',
    command: 'npm run bench -- playground-refactor',
  },
  {
    name: 'playground-learn',
    writer: 'bench/playground-learn.bench.mjs',
    command: 'npm run bench -- playground-learn',
  },
  { name: 'first-frame', writer: 'bench/first-frame.bench.mjs', command: 'npm run bench -- first-frame' },
  { name: 'reliability', writer: 'bench/reliability.bench.mjs', command: 'npm run bench -- reliability' },
  { name: 'rasterisers', writer: 'bench/rasterisers.bench.mjs', command: 'npm run bench -- rasterisers' },
  { name: 'gate', writer: 'scripts/test.mjs', command: 'npm test -- --record' },
];

// ── Formatting ─────────────────────────────────────────────────────────────────────────────────────────────

/** Thousands with commas, independent of the locale. @param {number} n */
export const int = (n) => {
  const [whole, frac] = String(n).split('.');
  const sign = whole.startsWith('-') ? '-' : '';
  const digits = sign ? whole.slice(1) : whole;
  const grouped = digits.replace(/\B(?=(\d{3})+(?!\d))/g, ',');
  return `${sign}${grouped}${frac === undefined ? '' : `.${frac}`}`;
};
/** A number with d decimals and thousands commas. @param {number} x @param {number} d */
const fixed = (x, d) => {
  const [whole, frac] = x.toFixed(d).split('.');
  return `${int(Number(whole))}${frac === undefined ? '' : `.${frac}`}`;
};
/** Milliseconds as the sphere bench prints them. @param {number} x */
const ms = (x) => (x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
/** A ratio as the sphere bench prints it. @param {number} x */
const ratio = (x) => (x >= 10 ? x.toFixed(0) : x.toFixed(1));
/** @param {number} x */
const exp1 = (x) => (x === 0 ? '0' : x.toExponential(1));
/** @param {number} bytes */
const kB = (bytes) => `${fixed(bytes / 1000, 1)} kB`;
/** @param {number} bytes */
const MB = (bytes) => `${(bytes / 1e6).toFixed(2)} MB`;
/** @param {number} bytes */
const B = (bytes) => `${int(bytes)} B`;
const SUPERSCRIPT = '⁰¹²³⁴⁵⁶⁷⁸⁹';
/** 1000 → 10³ for exact powers of ten, else the number. @param {number} n */
const power10 = (n) => {
  const k = Math.round(Math.log10(n));
  return 10 ** k === n ? `10${[...String(k)].map((c) => SUPERSCRIPT[Number(c)]).join('')}` : int(n);
};

/**
 * A Markdown table. @param {string[]} header @param {string} align one letter per column: l or r
 * @param {(string | number)[][]} rows @returns {string[]}
 */
export function table(header, align, rows) {
  return [
    `| ${header.join(' | ')} |`,
    `| ${[...align].map((a) => (a === 'r' ? '---:' : '---')).join(' | ')} |`,
    ...rows.map((r) => `| ${r.join(' | ')} |`),
  ];
}

/** @param {string | null | undefined} iso */
function showDate(iso) {
  if (!iso) return NOT_RECORDED;
  const d = new Date(iso);
  return Number.isNaN(d.getTime()) ? iso : `${d.toISOString().slice(0, 16).replace('T', ' ')} UTC`;
}

/** @param {number[] | null | undefined} load */
const showLoad = (load) => (Array.isArray(load) ? load.map((x) => x.toFixed(2)).join(' / ') : null);

/** The Runs table's cells for one file's meta. @param {any} meta */
function metaCells(meta) {
  const m = meta ?? {};
  const commit = m.commit
    ? `\`${m.commit.slice(0, 7)}\`${m.dirty ? ' + uncommitted changes' : ''}`
    : NOT_RECORDED;
  const machine = m.machine
    ? `${m.machine.cpus} × ${m.machine.cpuModel}, ${m.machine.memoryGiB} GiB, ${m.machine.platform}`
    : NOT_RECORDED;
  const start = showLoad(m.loadavg);
  const end = showLoad(m.loadavgEnd);
  const load = start ? (end ? `${start} → ${end}` : start) : NOT_RECORDED;
  return [
    showDate(m.date),
    commit,
    machine,
    load,
    m.node ?? NOT_RECORDED,
    m.chromium ?? NOT_RECORDED,
    m.three ?? NOT_RECORDED,
  ];
}

/** The line under a section's heading: which file, and its run. @param {string} name @param {any} data */
function fromLine(name, data) {
  const m = data.meta ?? {};
  const commit = m.commit ? `commit \`${m.commit.slice(0, 7)}\`` : 'commit not recorded';
  return `From [\`bench/results/${name}.json\`](bench/results/${name}.json), run of ${showDate(m.date)} (${commit}; machine and versions in [Runs](#runs)).`;
}

/** @param {string} name */
const missing = (name) => {
  const source = SOURCES.find((s) => s.name === name);
  return `_No committed results: \`${source?.command ?? `bench/results/${name}.json`}\` writes them._`;
};

// ── Sections ───────────────────────────────────────────────────────────────────────────────────────────────

/** @param {Record<string, any>} results @returns {string[]} */
function runs(results) {
  const names = [...SOURCES.map((s) => s.name), ...Object.keys(results).sort()].filter(
    (n, i, all) => all.indexOf(n) === i && results[n],
  );
  const rows = names.map((name) => {
    const source = SOURCES.find((s) => s.name === name);
    return [
      `[\`${name}.json\`](bench/results/${name}.json)`,
      source ? `[\`${source.writer}\`](${source.writer})` : NOT_RECORDED,
      ...metaCells(results[name].meta),
    ];
  });
  const notes = names
    .filter((n) => results[n].meta?.backfilled)
    .map((n) => `- \`${n}.json\`: ${results[n].meta.backfilled}`);
  return [
    '## Runs',
    '',
    'Each results file records the run that wrote it. Load average: 1, 5 and 15 minutes, at the start → at the end.',
    '',
    ...table(
      ['results', 'written by', 'date', 'commit', 'machine', 'load average', 'Node', 'Chromium', 'three'],
      'lllllllll',
      rows,
    ),
    ...(notes.length ? ['', 'Files written before runs recorded their meta:', '', ...notes] : []),
    '',
    'To refresh a file, run its command on a quiet machine, then `npm run benchmarks`:',
    '',
    ...SOURCES.filter((s) => names.includes(s.name)).map((s) => `- \`${s.name}.json\`: \`${s.command}\``),
  ];
}

/** @param {any} r @returns {string[]} */
function sphereBuild(r) {
  const out = [
    '## Sphere build time',
    '',
    fromLine('sphere', r),
    '',
    `\`subdivideSphere\` with ${r.normals} normals, median of at least 5 timed samples after warm-up, ms per call; a sample shorter than ${r.sampleMs} ms repeats the call and reports the time per call${r.quick ? ' (a `--quick` run)' : ''}. \`plain write\` allocates the same typed arrays as the build and fills them in a simple loop: the floor for producing those bytes. The peer is three's \`IcosahedronGeometry(1, d)\` at the detail d whose 20·(d + 1)² triangles are nearest.`,
    '',
    ...table(
      [
        'base',
        'level',
        'triangles',
        'indexed',
        'plain write (idx)',
        'non-indexed',
        'plain write (non-idx)',
        'three `IcosahedronGeometry` (detail → triangles)',
        'three ÷ indexed',
        'indexed ÷ plain',
        'three ÷ non-idx',
        'non-idx ÷ plain',
      ],
      'lrrrrrrrrrrr',
      r.builds.map((/** @type {any} */ b) => [
        b.base,
        b.level,
        int(b.triangles),
        ms(b.indexed.ours.median),
        ms(b.indexed.plain.median),
        ms(b.nonIndexed.ours.median),
        ms(b.nonIndexed.plain.median),
        `${ms(b.three.median)} (${b.threeDetail} → ${int(b.threeTriangles)})`,
        `${ratio(b.indexed.threeOverOurs)}×`,
        `${ratio(b.indexed.oursOverPlain)}×`,
        `${ratio(b.nonIndexed.threeOverOurs)}×`,
        `${ratio(b.nonIndexed.oursOverPlain)}×`,
      ]),
    ),
  ];
  const t = r.builds.find((/** @type {any} */ b) => b.base === 'tetrahedron' && b.level === 8);
  if (t) {
    const ok = t.indexed.threeOverOurs >= 10 && t.indexed.oursOverPlain <= 5;
    out.push(
      '',
      `Target (indexed level 8 tetrahedron, ${int(t.triangles)} triangles): ${ratio(t.indexed.threeOverOurs)}× faster than three (goal ≥ 10×), ${ratio(t.indexed.oursOverPlain)}× the plain write (goal ≤ 5×): **${ok ? 'met' : 'not met'}**.`,
    );
  }
  return out;
}

/** @param {any} r @returns {string[]} */
function sphereError(r) {
  const bases = [...new Set(r.errors.map((/** @type {any} */ e) => e.base))];
  const levels = [...new Set(r.errors.map((/** @type {any} */ e) => e.level))];
  /** @param {unknown} base @param {unknown} level */
  const at = (base, level) => r.errors.find((/** @type {any} */ e) => e.base === base && e.level === level);
  /** @param {any} p */
  const pick = (p) =>
    p ? `L${p.level}: ${int(p.triangles)}` : `> L${Math.max(.../** @type {number[]} */ (levels))}`;
  const costLevels = [...new Set(r.errorCost.map((/** @type {any} */ c) => c.levels))];
  return [
    '## Sphere error',
    '',
    fromLine('sphere', r),
    '',
    'The exact radial error of the unit sphere (`sphereError`) and the triangle count T of each base and level: error·T tends to a constant per base, and the lowest constant buys accuracy cheapest.',
    '',
    ...table(
      ['level', ...bases.flatMap((b) => [`${b} T`, 'error', 'error·T'])],
      `r${'rrr'.repeat(bases.length)}`,
      levels.map((level) => [
        level,
        ...bases.flatMap((base) => {
          const e = at(base, level);
          return e
            ? [int(e.triangles), e.error.toExponential(3), e.errorTimesTriangles.toFixed(3)]
            : ['—', '—', '—'];
        }),
      ]),
    ),
    '',
    '### Fewest triangles for a relative error budget',
    '',
    ...table(
      ['error ≤', ...bases.map(String), 'cheapest'],
      `r${'r'.repeat(bases.length)}l`,
      r.budgets.map((/** @type {any} */ b) => [
        b.budget.toExponential(0),
        ...b.picks.map(pick),
        b.best ? `${b.best.base} L${b.best.level}` : '—',
      ]),
    ),
    '',
    '### sphereError first-call cost',
    '',
    'Milliseconds; later calls are a memo lookup.',
    '',
    ...table(
      ['base', ...costLevels.map((l) => (l === '0-10' ? 'levels 0–10 (all)' : `level ${l}`))],
      `l${'r'.repeat(costLevels.length)}`,
      bases.map((base) => [
        base,
        ...costLevels.map((l) => {
          const c = r.errorCost.find((/** @type {any} */ x) => x.base === base && x.levels === l);
          return c ? ms(c.firstCallMs) : '—';
        }),
      ]),
    ),
  ];
}

/** @param {any} r @returns {string[]} */
function autodetail(r) {
  const t = r.totals;
  const first = r.points[0];
  const last = r.points.at(-1);
  /** @param {number} n */
  const saved = (n) => `${((1 - n / t.fixed.triangles) * 100).toFixed(1)} %`;
  /** @param {any} a */
  const show = (a) => `${a.base} ${a.level} (${int(a.triangles)})`;
  /** @param {string} label @param {any} x @param {boolean} [isFixed] */
  const row = (label, x, isFixed = false) => [
    label,
    int(x.triangles),
    isFixed ? '—' : saved(x.triangles),
    `${x.worstMeasuredPx.toFixed(3)} px`,
    x.overBudget,
  ];
  const budget = r.budgetPx;
  return [
    '## Automatic detail',
    '',
    fromLine('autodetail', r),
    '',
    `\`AutoDetailSphere\` over a zoom sweep of the lecture scene: ellipsoid scale (${r.scale.join(', ')}), eye on +z, ${r.fovy}° perspective, ${r.width}×${r.height}, ${r.points.length} distances from ${first.distance.toFixed(2)} to ${last.distance.toFixed(1)} units. Errors are measured in the image: the largest distance between the mesh's projected outline and the exact ellipsoid's (${int(r.outlineSamples)} outline samples, [\`bench/lib/silhouetteGap.mjs\`](bench/lib/silhouetteGap.mjs)).`,
    '',
    ...table(
      [
        '',
        'triangles drawn over the sweep',
        `saved vs fixed ${r.fixed.base} level ${r.fixed.level}`,
        'worst measured error',
        `distances over ${budget} px`,
      ],
      'lrrrr',
      [
        row(`fixed ${r.fixed.base} level ${r.fixed.level} (the lecture's)`, t.fixed, true),
        row(`\`AutoDetailSphere\`, budget ${budget} px`, t.auto),
        row(
          `\`AutoDetailSphere\`, budget ${r.equalBudgetPx.toFixed(3)} px (level ${r.fixed.level}'s worst measured error)`,
          t.autoEqual,
        ),
        row(
          `\`AutoDetailSphere\`, budget ${r.equalBoundPx.toFixed(3)} px (level ${r.fixed.level}'s worst bound)`,
          t.autoEqualBound,
        ),
        row(`projected radius × error (the model before the bound), budget ${budget} px`, t.radiusModel),
      ],
    ),
    '',
    `The bound costs ${int(t.auto.triangles - t.radiusModel.triangles)} triangles (${(t.auto.triangles / t.radiusModel.triangles).toFixed(1)}×) more than the radius model over the sweep. Level ${r.fixed.level}'s error depends on how the sphere is turned: turned ${r.fixedRotated.rotations} seeded random ways at ${r.fixedRotated.distance} units it measures up to ${r.fixedRotated.worstMeasuredPx.toFixed(2)} px (its bound there: ${first.fixed.boundPx.toFixed(2)} px); the bound holds for every orientation.`,
    '',
    '### Automatic detail at each distance',
    '',
    'Measured error in px, the bound `AutoDetailSphere` budgets in brackets; a mesh is base, level (triangles).',
    '',
    ...table(
      [
        'distance',
        'radius px',
        `${r.fixed.base} ${r.fixed.level}`,
        `auto ${budget} px`,
        'radius model (before)',
        'auto at equal error',
        'auto at equal bound',
      ],
      'rrlllll',
      r.points.map((/** @type {any} */ p) => [
        p.distance.toFixed(2),
        p.radiusPx.toFixed(1),
        `${p.fixed.measuredPx.toFixed(3)} [${p.fixed.boundPx.toFixed(3)}]`,
        `${show(p.auto)}: ${p.auto.measuredPx.toFixed(3)} [${p.auto.boundPx.toFixed(3)}]`,
        `${show(p.radiusModel)}: ${p.radiusModel.measuredPx.toFixed(3)}`,
        `${show(p.autoEqual)}: ${p.autoEqual.measuredPx.toFixed(3)}`,
        `${show(p.autoEqualBound)}: ${p.autoEqualBound.measuredPx.toFixed(3)}`,
      ]),
    ),
  ];
}

/** @param {any} r @returns {string[]} */
function tradeoff(r) {
  const rows = Object.entries(r.rows);
  const cheapest = Object.entries(r.cheapest ?? {});
  const columns = cheapest.length ? Object.keys(cheapest[0][1]) : [];
  /** @param {string} key `rmse≤1` or `silhouette≤0.5px` */
  const target = (key) =>
    key.replace(/^rmse≤/, 'RMSE ≤ ').replace(/^silhouette≤([\d.]+)px$/, 'silhouette ≤ $1 px');
  const levels = [...r.levels, ...(r.smoothLevels ?? [])];
  return [
    '## Speed against accuracy',
    '',
    fromLine('tradeoff', r),
    '',
    `The lecture scene at ${r.width}×${r.height}, every option (\`ShadingMaterial\` flat on \`flatShadingGeometry\`, Gouraud and Phong on every base at levels ${r.levels.join(', ')}${r.smoothLevels?.length ? `, Gouraud and Phong also at ${r.smoothLevels.join(', ')}` : ''}, and \`SphereImpostor\`) scored against \`renderReference\` (rendered once, in ${r.referenceMs.toFixed(0)} ms): RMSE and max over the interior in 8-bit sRGB, silhouette error in px. Frame: median of ${r.frames} frames pooled over ${r.rounds} round-robin rounds, a 1×1 \`readPixels\` after each${r.gpuTimer ? '; GPU: the median of EXT_disjoint_timer_query_webgl2' : ''}. The bench's note: ${r.note}.`,
    '',
    ...table(
      ['option', 'triangles', 'buffer bytes', 'RMSE', 'max', 'silhouette px', 'frame ms', 'GPU ms'],
      'lrrrrrrr',
      rows.map(([name, x]) => [
        name === 'phong tetrahedron 6' ? `${name} (the lecture's)` : name,
        int(x.triangles),
        int(x.bytes),
        x.error.rmse.toFixed(2),
        x.error.max,
        x.error.silhouettePx.toFixed(2),
        x.frameMs ? x.frameMs.median.toFixed(1) : 'n/a',
        x.gpuMs ? x.gpuMs.median.toFixed(1) : 'n/a',
      ]),
    ),
    '',
    `Levels measured: ${levels.join(', ')}.`,
    '',
    '### Pareto fronts',
    '',
    `Frame time against RMSE: ${(r.paretoRmse ?? []).join(' → ')}.`,
    '',
    `Frame time against silhouette error: ${(r.paretoSilhouette ?? []).join(' → ')}.`,
    '',
    '### Cheapest option for an error target',
    '',
    'The option with the shortest frame meeting both targets:',
    '',
    ...table(
      ['cheapest meeting', ...columns.map(target)],
      `l${'l'.repeat(columns.length)}`,
      cheapest.map(([rk, cells]) => [
        target(rk),
        ...columns.map((c) => /** @type {any} */ (cells)[c] ?? '—'),
      ]),
    ),
  ];
}

const MATERIAL_TARGETS = /** @type {const} */ ([
  ['phongVsMeshPhong', 'phong × phong / MeshPhongMaterial ≤ 1'],
  ['gouraudVsPhong', 'gouraud × phong / phong × phong < 1'],
  ['flatVsPhong', 'flat × phong / phong × phong < 1'],
  ['flatSoupVsPhong', 'flat (triangle soup) / phong × phong'],
  ['twoLightsVsOne', '2 lights / 1 light < 2 (phong × phong)'],
]);

/** @param {any} r @returns {string[]} */
function material(r) {
  const levels = Object.keys(r.levels).sort((a, b) => Number(a) - Number(b));
  const variants = [...new Set(levels.flatMap((l) => Object.keys(r.levels[l].rows)))];
  /** @param {string} l @param {string} v */
  const cell = (l, v) => r.levels[l].rows[v];
  const out = [
    '## Material frame time',
    '',
    fromLine('material', r),
    '',
    `Every \`ShadingMaterial\` variant against three's \`MeshPhongMaterial\` (point light with decay 0 plus an ambient light, shininess 32), \`MeshLambertMaterial\` and \`MeshToonMaterial\` on the same sphere in the same run, and \`MeshBasicMaterial\` (no lighting) as the floor: what transforming and rasterising the sphere costs by itself. ${r.width}×${r.height}, ${r.frames} frames per variant in ${r.rounds} interleaved rounds, a 1×1 \`readPixels\` after each. Gouraud, Phong and three's materials draw the indexed sphere, flat shading \`flatShadingGeometry\` of it, and the soup row the non-indexed sphere. Frame ms: median, the minimum in brackets${r.gpuTimer ? '; GPU ms: the median of EXT_disjoint_timer_query_webgl2' : ''}.`,
    '',
    ...table(
      [
        'variant',
        ...levels.map((l) => `level ${l} (${int(r.levels[l].triangles)} tris) frame`),
        ...levels.map((l) => `level ${l} GPU`),
      ],
      `l${'r'.repeat(levels.length * 2)}`,
      variants.map((v) => [
        v,
        ...levels.map((l) => {
          const c = cell(l, v);
          return c ? `${c.frameMs.median.toFixed(1)} (${c.frameMs.min.toFixed(1)})` : '—';
        }),
        ...levels.map((l) => {
          const c = cell(l, v);
          return c?.gpuMs ? c.gpuMs.median.toFixed(1) : 'n/a';
        }),
      ]),
    ),
    '',
    '### Material targets',
    '',
    'Ratios of the medians, and of the minima (the least disturbed frames) in brackets:',
    '',
    ...table(
      ['target', ...levels.map((l) => `level ${l}`)],
      `l${'r'.repeat(levels.length)}`,
      MATERIAL_TARGETS.map(([key, label]) => [
        label,
        ...levels.map((l) => {
          const t = r.levels[l].targets?.[key];
          return t ? `${t.median.toFixed(2)} (min ${t.min.toFixed(2)})` : '—';
        }),
      ]),
    ),
  ];
  const top = levels.at(-1);
  const floor = top && cell(top, 'three MeshBasicMaterial (no lighting)');
  if (top && floor) {
    /** @param {string} v */
    const above = (v) => {
      const c = cell(top, v);
      return c ? `${(c.frameMs.median - floor.frameMs.median).toFixed(0)} ms` : 'not measured';
    };
    out.push(
      '',
      `At level ${top} (${int(r.levels[top].triangles)} triangles) the unlit floor is ${floor.frameMs.median.toFixed(0)} ms a frame; above it gouraud × phong adds ${above('gouraud × phong')}, phong × phong ${above('phong × phong')}, flat × phong ${above('flat × phong')} and flat × phong on the triangle soup ${above('flat × phong (triangle soup)')} (medians).`,
    );
  }
  out.push(
    '',
    '### Geometry each shading needs',
    '',
    ...table(
      [
        'level',
        'triangles',
        'flat (flatShadingGeometry): vertices, positions + corners + index',
        'flat (soup): vertices, positions + face texture',
        'gouraud/phong (indexed): vertices, positions + index',
        "three's: + normals",
      ],
      'rrlllr',
      levels.map((l) => {
        const m = r.levels[l].memory;
        return [
          l,
          int(r.levels[l].triangles),
          `${int(m.flat.vertices)}: ${MB(m.flat.positionsBytes)} + ${MB(m.flat.cornersBytes)} + ${MB(m.flat.indexBytes)}`,
          `${int(m.flatSoup.vertices)}: ${MB(m.flatSoup.positionsBytes)} + ${MB(m.flatSoup.flatTextureBytes)}`,
          `${int(m.indexed.vertices)}: ${MB(m.indexed.positionsBytes)} + ${MB(m.indexed.indexBytes)}`,
          `+ ${MB(m.indexed.normalsBytes)}`,
        ];
      }),
    ),
  );
  return out;
}

/** A row's frame time: median (minimum), or why it did not render. @param {any} row */
const frameCell = (row) =>
  !row
    ? '—'
    : row.error
      ? 'does not render'
      : `${row.frameMs.median.toFixed(1)} (${row.frameMs.min.toFixed(1)})`;
/**
 * A ratio of frame times: the median of the ratios of frames timed in the same cycle, and the ratio of the
 * medians in brackets. @param {{ paired?: number, median: number, min: number } | null | undefined} x
 */
const ratioCell = (x) =>
  !x ? '—' : x.paired === undefined ? x.median.toFixed(2) : `${x.paired.toFixed(2)} (${x.median.toFixed(2)})`;
/** Whether a target was met. @param {boolean | null | undefined} met */
const metCell = (met) => (met === true ? 'met' : met === false ? '**not met**' : '—');

/** @param {any} r @returns {string[]} */
function sceneRealistic(r) {
  const s = r.realistic;
  if (!s) return ['## Material in a realistic scene', '', missing('scene')];
  const errors = Object.entries(s.rows).filter(([, row]) => /** @type {any} */ (row).error);
  return [
    '## Material in a realistic scene',
    '',
    fromLine('scene', r),
    '',
    `Issue 14's scene: ${s.scene}. \`ShadingMaterial\` in each shading against three's \`MeshPhongMaterial\` (shininess 32) and \`MeshLambertMaterial\` in the same run: ${r.frames} frames per variant in ${r.rounds} rounds, the variants interleaved frame by frame (each cycle renders one frame of every variant), a 1×1 \`readPixels\` after each; ratios are the median of the ratios of frames from the same cycle, and the ratio of the medians in brackets. Flat shading draws \`flatShadingGeometry\` of the sphere, the non-indexed sphere, or the indexed sphere as it is (no preparation). Frame ms: median (minimum)${r.gpuTimer ? '; GPU ms: the median of EXT_disjoint_timer_query_webgl2' : ''}. ${r.note ?? ''}`.trim(),
    '',
    ...table(
      ['variant', 'frame ms', 'GPU ms', '/ MeshPhongMaterial'],
      'lrrr',
      Object.entries(s.rows).map(([name, row]) => [
        name,
        frameCell(row),
        /** @type {any} */ (row).gpuMs ? /** @type {any} */ (row).gpuMs.median.toFixed(1) : 'n/a',
        ratioCell(s.ratiosVsMeshPhong[name]),
      ]),
    ),
    ...(errors.length
      ? ['', ...errors.map(([name, row]) => `- ${name} does not render: ${/** @type {any} */ (row).error}`)]
      : []),
    '',
    "Issue 14's targets (the median of the ratios of frames from the same cycle; the ratio of the medians in brackets):",
    '',
    ...table(
      ['ratio', 'measured', 'target', 'result'],
      'lrll',
      [
        ['phong / MeshPhongMaterial', 'phongVsMeshPhong'],
        ['gouraud / MeshPhongMaterial', 'gouraudVsMeshPhong'],
        ['flat (flatShadingGeometry) / MeshPhongMaterial', 'flatVsMeshPhong'],
        ['flat (indexed, no preparation) / MeshPhongMaterial', 'flatIndexedVsMeshPhong'],
        ['MeshLambertMaterial / MeshPhongMaterial', 'lambertVsMeshPhong'],
      ].map(([label, key]) => {
        const t = s.targets[key];
        return [label, ratioCell(t?.ratio), t?.target ?? '—', metCell(t?.met)];
      }),
    ),
  ];
}

/** @param {any} r @returns {string[]} */
function sceneLecture(r) {
  const s = r.lecture;
  if (!s) return ['## Lecture scene before and after issue 14', '', missing('scene')];
  return [
    '## Lecture scene before and after issue 14',
    '',
    fromLine('scene', r),
    '',
    `What the lecture's scene pays for issue 14's features (instancing, skinning, fog, three's lights, …) that it does not use: ${s.scene}, rendered in the same run with the \`ShadingMaterial\` of \`${s.before.rev}\` (\`${s.before.commit.slice(0, 7)}\`, the commit before issue 14 began, bundled from git by the bench) and of the run's commit. ${r.smallFrames ?? r.frames} frames per variant in ${r.smallRounds ?? r.rounds} rounds, interleaved frame by frame; frame ms: median (minimum); after / before: the median of the ratios of frames from the same cycle (the ratio of the medians in brackets).`,
    '',
    ...table(
      ['shading', 'before', 'after', 'after / before', 'target', 'result'],
      'lrrrll',
      Object.entries(s.afterVsBefore).map(([shading, t]) => [
        shading,
        frameCell(s.rows[`${shading} before`]),
        frameCell(s.rows[`${shading} after`]),
        ratioCell(/** @type {any} */ (t).ratio),
        /** @type {any} */ (t).target,
        metCell(/** @type {any} */ (t).met),
      ]),
    ),
  ];
}

const FLAT_MODES = /** @type {const} */ ([
  ['prepared', 'prepared: `flatShadingGeometry`'],
  ['non-indexed', 'non-indexed: `toNonIndexed()`'],
  ['indexed', 'indexed as it is (no preparation)'],
]);

/** @param {any} r @returns {string[]} */
function sceneFlat(r) {
  const s = r.flat;
  if (!s) return ['## Flat shading without preparation', '', missing('scene')];
  const meshes = Object.keys(s.meshes);
  const flatSummary = meshes.flatMap((mesh) => {
    const { prepared, indexed } = s.meshes[mesh].modes;
    if (!indexed?.error || indexed.error.error || !indexed.vsPrepared) return [];
    const bytes =
      (prepared.bytes.geometry + prepared.bytes.gpuExtra) / (indexed.bytes.geometry + indexed.bytes.gpuExtra);
    return [
      `- ${mesh}: without preparation, up to ${indexed.error.max}/255 off the face's colour (RMS ${indexed.error.rms.toFixed(2)}) at ${ratioCell(indexed.vsPrepared)} × the prepared frame time; the prepared geometry takes ${bytes.toFixed(1)} × its bytes.`,
    ];
  });
  if (flatSummary.length) flatSummary.unshift('');
  return [
    '## Flat shading without preparation',
    '',
    fromLine('scene', r),
    '',
    `The lecture's flat shading is one colour per face. Three ways to get it from an indexed mesh: the prepared \`flatShadingGeometry\` (each face's last vertex carries the face), the non-indexed mesh (each triangle owns its vertices; the material reads the face from a texture of positions), and the indexed mesh as it is, with a face normal from screen-space derivatives and the lighting per fragment. Scene: ${s.scene}. Error against ${s.reference}; 1/255 per channel. Frame ms: median (minimum) of ${r.smallFrames ?? r.frames} frames in ${r.smallRounds ?? r.rounds} rounds, interleaved frame by frame; / prepared: the median of the ratios of frames from the same cycle (the ratio of the medians in brackets). Bytes: the geometry's attributes and index as given to the material (the sources keep three's normals and uvs, which flat shading does not read), and what the GPU holds besides (the non-indexed path's face-position texture).`,
    '',
    ...table(
      [
        'mesh',
        'triangles',
        'flat shading of',
        'max error',
        'RMS error',
        'pixels > 1/255',
        'frame ms',
        '/ prepared',
        'geometry bytes',
        'GPU extra',
      ],
      'lrlrrrrrrr',
      meshes.flatMap((mesh) =>
        FLAT_MODES.map(([mode, label]) => {
          const m = s.meshes[mesh].modes[mode];
          const e = m.error;
          const ok = e && !e.error;
          return [
            mesh,
            int(s.meshes[mesh].triangles),
            label,
            ok ? String(e.max) : 'does not render',
            ok ? e.rms.toFixed(2) : '—',
            ok ? `${(e.over1 * 100).toFixed(1)} % of ${int(e.pixels)}` : '—',
            frameCell(m.time),
            ratioCell(m.vsPrepared),
            B(m.bytes.geometry),
            m.bytes.gpuExtra ? B(m.bytes.gpuExtra) : '0',
          ];
        }),
      ),
    ),
    ...flatSummary,
  ];
}

const SWAP_TITLE = 'Swapped materials in a realistic scene';

/** A ratio to 3 decimals, the ratio of the medians in brackets. @param {any} x */
const ratio3 = (x) => (!x ? '—' : `${x.paired.toFixed(3)} (${x.median.toFixed(3)})`);
/** A luma ratio to 4 decimals. @param {number | null | undefined} x */
const luma4 = (x) => (typeof x === 'number' ? x.toFixed(4) : '—');

/**
 * Issue 22: the realistic scene with MeshPhongMaterial against the same scene after swapMaterials, frame time and
 * mean luma, and a ShadingMaterial built by hand with the options the swap carried over. @param {any} r
 * @returns {string[]}
 */
function swap(r) {
  const names = Object.keys(r.rows);
  const t = r.targets;
  const d = r.diffuseOnly;
  const dRatio = d?.swappedVsMeshPhong;
  const swapped = r.materials?.['swapped phong'];
  const o = swapped?.options;
  /** @param {number[]} c */
  const rgb = (c) => (c[0] === c[1] && c[1] === c[2] ? String(c[0]) : `(${c.join(', ')})`);
  const carried = o
    ? `The swap made ${swapped.swap?.materials ?? '?'} material (${swapped.swap?.skipped.length ? `skipped: ${swapped.swap.skipped.join('; ')}` : 'nothing skipped'}) and carried over: lighting \`${o.lighting}\`, ka = ${rgb(o.ka)}, kd = ${rgb(o.kd)}, ks = ${rgb(o.ks)}, shininess ${o.shininess}${o.celBands ? `, ${o.celBands} cel bands` : ''}.`
    : '';
  const diff = r.swappedVsByHandProgram;
  // Where the swap costs more than MeshPhongMaterial: whether the swap adds anything to the material built by hand,
  // and what the lighting it carries over costs against the lecture's Phong lighting.
  const phongLit = r.ratiosVsByHand?.['ShadingMaterial phong (by hand, lighting phong)'];
  const costCause =
    t.cost.met === false && diff?.length === 0 && phongLit && o
      ? `Cost: the swap adds nothing to the material (swapped / by hand ${ratio3(r.ratiosVsByHand['swapped phong'])}, one program); the same material with the lecture's Phong lighting (reflection vector) in place of the \`${o.lighting}\` the swap carries over costs ${ratio3(phongLit)} × it and ${ratio3(r.ratiosVsMeshPhong['ShadingMaterial phong (by hand, lighting phong)'])} × MeshPhongMaterial: what puts the swap above MeshPhongMaterial is the Blinn-Phong half vector (h = l + v normalised: an add, two dots, a max and an inversesqrt per light and fragment, where Phong's r·v = 2(l·n)(v·n) − v·l takes one dot per light, v·n being the same for every light), which the swap takes to match MeshPhongMaterial's highlight.`
      : '';
  const program = !diff
    ? ''
    : diff.length === 0
      ? 'The swapped material compiles the same program as the one built by hand (identical program cache keys).'
      : `The swapped material's program differs from the one built by hand in ${diff.length} parameter${diff.length === 1 ? '' : 's'}: ${diff.map((/** @type {any} */ x) => `#${x.index} \`${x.swapped}\` (by hand \`${x.byHand}\`)`).join(', ')}.`;
  return [
    `## ${SWAP_TITLE}`,
    '',
    fromLine('swap', r),
    '',
    `Issue 22: the scene as an app has it, with \`${r.source}\`, against the same scene after ${r.swap}, and against ${r.byHand}, all in one run. Scene: ${r.scene}. ${r.frames} frames per variant in ${r.rounds} rounds, the variants interleaved frame by frame (each cycle renders one frame of every variant; each round starts its cycles at the next variant, so that no row always follows the same one: the swapped and the by-hand rows compile the same program, and their ratio is the method's control), a 1×1 \`readPixels\` after each; ratios are the median of the ratios of frames from the same cycle, and the ratio of the medians in brackets. Frame ms: median (minimum)${r.gpuTimer ? '; GPU ms: the median of EXT_disjoint_timer_query_webgl2' : ''}. Luma: ${r.luma}. ${r.note ?? ''}`.trim(),
    '',
    ...table(
      [
        'variant',
        'frame ms',
        'GPU ms',
        '/ MeshPhongMaterial',
        '/ by hand',
        'mean luma, frame',
        'mean luma, covered',
        'luma / MeshPhongMaterial (frame, covered)',
        'max channel Δ',
        'RMS luma Δ',
      ],
      'lrrrrrrlrr',
      names.map((name) => {
        const row = r.rows[name];
        const l = r.luminance[name];
        const lr = r.luminanceVsMeshPhong[name];
        return [
          name,
          frameCell(row),
          row.gpuMs ? row.gpuMs.median.toFixed(1) : 'n/a',
          ratio3(r.ratiosVsMeshPhong[name]),
          ratio3(r.ratiosVsByHand?.[name]),
          l && !l.error ? l.frame.toFixed(2) : '—',
          l && !l.error ? l.covered.toFixed(2) : '—',
          lr ? `${luma4(lr.frame)}, ${luma4(lr.covered)}` : '—',
          l && !l.error ? String(l.vsFirst.maxChannel) : '—',
          l && !l.error ? l.vsFirst.rmsLuma.toFixed(2) : '—',
        ];
      }),
    ),
    ...names
      .filter((name) => r.rows[name].error)
      .map((name, i) => `${i === 0 ? '\n' : ''}- ${name} does not render: ${r.rows[name].error}`),
    '',
    "Issue 22's targets (swapped phong, the swap's default, against MeshPhongMaterial):",
    '',
    ...table(['measure', 'measured', 'target', 'result'], 'lrll', [
      [
        `frame time, swapped / MeshPhongMaterial${t.cost.ratio?.pairedQuartiles ? ` (quartiles of the same-cycle ratios ${t.cost.ratio.pairedQuartiles.map((/** @type {number} */ q) => q.toFixed(3)).join(' … ')})` : ''}`,
        ratio3(t.cost.ratio),
        t.cost.target,
        metCell(t.cost.met),
      ],
      [
        'mean luma over the frame, swapped / MeshPhongMaterial',
        luma4(t.luminanceFrame.ratio),
        t.luminanceFrame.target,
        metCell(t.luminanceFrame.met),
      ],
      [
        'mean luma over the covered pixels, swapped / MeshPhongMaterial',
        luma4(t.luminanceCovered.ratio),
        t.luminanceCovered.target,
        metCell(t.luminanceCovered.met),
      ],
    ]),
    '',
    [
      carried,
      program,
      dRatio
        ? `The diffuse term alone (the same two scenes with MeshPhongMaterial's specular 0, so ks = 0): luma / MeshPhongMaterial ${luma4(dRatio.frame)} over the frame, ${luma4(dRatio.covered)} over the covered pixels${d.specularLuma ? `; the highlights' share of the mean covered luma (full − diffuse alone): ${d.specularLuma.meshPhong.toFixed(2)} codes with MeshPhongMaterial, ${d.specularLuma.swapped.toFixed(2)} swapped (${d.specularLuma.ratio.toFixed(2)} ×)` : ''}.`
        : '',
      r.cause ?? '',
      costCause,
    ]
      .filter(Boolean)
      .join(' '),
  ];
}

const WEBGPU_TITLE = 'Material on WebGPURenderer';
const WEBGPU_BACKENDS = /** @type {const} */ (['webgpu', 'webgl2', 'webgl']);

/**
 * Issue 15: ShadingNodeMaterial on both backends of WebGPURenderer against three's phong material on the same
 * renderer and against ShadingMaterial under WebGLRenderer. @param {any} r @returns {string[]}
 */
function webgpu(r) {
  const backends = WEBGPU_BACKENDS.filter((b) => r.perBackend?.[b]);
  const gpuLine = backends
    .map((b) => `${r.perBackend[b].label}: ${r.perBackend[b].gpuTimer ?? NOT_RECORDED}`)
    .join('; ');
  const tables = backends.flatMap((b) => {
    const pb = r.perBackend[b];
    const node = b !== 'webgl';
    const rows = Object.entries(pb.variants).map(([name, v]) => {
      const row = /** @type {any} */ (v);
      const three = name.startsWith('three phong');
      return [
        three ? name.replace('three phong', pb.threePhong) : name,
        frameCell(row),
        row.gpuMs ? row.gpuMs.median.toFixed(1) : row.error ? '—' : 'n/a',
        three ? '—' : ratioCell(row.vsThreePhong),
        ...(node ? [ratioCell(row.vsWebGLRenderer)] : []),
      ];
    });
    return [
      '',
      `### ${pb.label}: \`${pb.material}\` and \`${pb.threePhong}\``,
      '',
      ...table(
        [
          'variant',
          'frame ms',
          'GPU ms',
          `/ ${pb.threePhong}`,
          ...(node ? [`/ WebGLRenderer (\`ShadingMaterial\`, \`MeshPhongMaterial\`)`] : []),
        ],
        node ? 'lrrrr' : 'lrrr',
        rows,
      ),
    ];
  });
  const errors = backends.flatMap((b) =>
    Object.entries(r.perBackend[b].variants)
      .filter(([, v]) => /** @type {any} */ (v).error)
      .map(
        ([name, v]) => `- ${r.perBackend[b].label}, ${name} does not render: ${/** @type {any} */ (v).error}`,
      ),
  );
  return [
    `## ${WEBGPU_TITLE}`,
    '',
    fromLine('webgpu', r),
    '',
    `Issue 15: \`ShadingNodeMaterial\` (\`@shadelab/material/webgpu\`) on both backends of three's \`WebGPURenderer\` (WebGPU; WebGL2 with \`forceWebGL\`) against three's \`MeshPhongNodeMaterial\` on the same backend, and \`ShadingMaterial\` and \`MeshPhongMaterial\` under \`WebGLRenderer\`, all in one page and one run at ${r.width}×${r.height}. Scene: ${r.scene}. ${r.frames} frames per variant in ${r.rounds} rounds, the variants of all three renderers interleaved frame by frame (each cycle renders one frame of every variant); ratios are the median of the ratios of frames from the same cycle, and the ratio of the medians in brackets. Frame ms: median (minimum), the render call and the read-back. GPU ms: the median of ${gpuLine}. ${r.note ?? ''}`.trim(),
    ...tables,
    ...(errors.length ? ['', ...errors] : []),
    '',
    "Issue 15's target, phong shading ≤ 1.0× `MeshPhongNodeMaterial` on the same backend (the median of the ratios of frames from the same cycle; the ratio of the medians in brackets):",
    '',
    ...table(
      ['backend: variant', 'measured', 'GPU-time ratio', 'target', 'result'],
      'lrrll',
      Object.entries(r.targets ?? {}).map(([name, t]) => {
        const x = /** @type {any} */ (t);
        return [
          name.replace(/^webgpu:/, 'WebGPU:').replace(/^webgl2:/, 'WebGL2:'),
          ratioCell(x.ratio),
          x.ratio?.gpu ? x.ratio.gpu.toFixed(2) : 'n/a',
          x.target,
          metCell(x.met),
        ];
      }),
    ),
  ];
}

const WEBGPU_REALISTIC_TITLE = 'Realistic scene on WebGPURenderer';

/**
 * Issue 23: the realistic scene on WebGPURenderer's backends, ShadingNodeMaterial in each shading against
 * MeshPhongNodeMaterial (webgpu.json's `realistic`). @param {any} r @returns {string[]}
 */
function webgpuRealistic(r) {
  const s = r.realistic;
  if (!s) return [`## ${WEBGPU_REALISTIC_TITLE}`, '', missing('webgpu')];
  const backends = WEBGPU_BACKENDS.filter((b) => s.perBackend?.[b]);
  const tables = backends.flatMap((b) => {
    const pb = s.perBackend[b];
    const rows = Object.entries(pb.variants).map(([name, v]) => {
      const row = /** @type {any} */ (v);
      return [
        row.vsBaseline ? `${name} (/ phong as it is: ${ratioCell(row.vsBaseline)})` : name,
        frameCell(row),
        row.gpuMs ? row.gpuMs.median.toFixed(1) : row.error ? '—' : 'n/a',
        name === 'MeshPhongNodeMaterial' ? '—' : ratioCell(row.vsMeshPhong),
        row.vsMeshPhong?.gpu ? row.vsMeshPhong.gpu.toFixed(2) : '—',
      ];
    });
    return [
      '',
      `### ${pb.label}`,
      '',
      ...table(['variant', 'frame ms', 'GPU ms', '/ MeshPhongNodeMaterial', 'GPU-time ratio'], 'lrrrr', rows),
    ];
  });
  return [
    `## ${WEBGPU_REALISTIC_TITLE}`,
    '',
    fromLine('webgpu', r),
    '',
    `Issue 23: \`ShadingNodeMaterial\` in each shading against three's \`MeshPhongNodeMaterial\` (and \`MeshLambertNodeMaterial\`) on both backends of \`WebGPURenderer\`, in the scene an app has (the realistic scene of [Material in a realistic scene](#material-in-a-realistic-scene), drawn by the same module) at ${r.width}×${r.height}. Scene: ${s.scene}. ${s.frames} frames per variant in ${s.rounds} rounds, the variants of both backends interleaved frame by frame (each cycle renders one frame of every variant); ratios are the median of the ratios of frames from the same cycle, and the ratio of the medians in brackets. Frame ms: median (minimum), the render call and the read-back; GPU ms: the median of the backend's timer (see [Material on WebGPURenderer](#material-on-webgpurenderer)). ${r.note ?? ''}`.trim(),
    ...tables,
    '',
    "Issue 23's targets against `MeshPhongNodeMaterial` on the same backend, phong shading ≤ 1.0×, Gouraud and flat cheaper (the median of the ratios of frames from the same cycle; the ratio of the medians in brackets):",
    '',
    ...table(
      ['backend: shading', 'measured', 'GPU-time ratio', 'target', 'result'],
      'lrrll',
      Object.entries(s.targets ?? {}).map(([name, t]) => {
        const x = /** @type {any} */ (t);
        return [
          name.replace(/^webgpu:/, 'WebGPU:').replace(/^webgl2:/, 'WebGL2:'),
          ratioCell(x.ratio),
          x.ratio?.gpu ? x.ratio.gpu.toFixed(2) : 'n/a',
          x.target,
          metCell(x.met),
        ];
      }),
    ),
    ...realisticShaderOps(s.shaderOps?.webgpu),
    ...(s.cause ? ['', s.cause] : []),
  ];
}

/**
 * The realistic scene's generated WGSL per variant: statements and calls in the vertex and fragment stages'
 * main functions. @param {Record<string, { vertex: Record<string, number> | null, fragment: Record<string, number> | null }> | undefined} ops
 * @returns {string[]}
 */
function realisticShaderOps(ops) {
  if (!ops) return [];
  const cols = /** @type {const} */ ([
    'normalize',
    'length',
    'dot',
    'pow',
    'exp2',
    'divisions',
    'derivatives',
  ]);
  return [
    '',
    "What each variant's WGSL (the WebGPU backend) does in its main functions: statements and branches (`if` blocks) per vertex and per fragment, and the fragment stage's calls:",
    '',
    ...table(
      [
        'variant',
        'vertex statements',
        'vertex branches',
        'fragment statements',
        'fragment branches',
        ...cols,
      ],
      `l${'r'.repeat(4 + cols.length)}`,
      Object.entries(ops).map(([name, o]) => [
        name,
        o.vertex?.statements ?? '—',
        o.vertex?.branches ?? '—',
        o.fragment?.statements ?? '—',
        o.fragment?.branches ?? '—',
        ...cols.map((c) => o.fragment?.[c] ?? '—'),
      ]),
    ),
  ];
}

const LECTURE_REFACTOR_TITLE = 'Lecture scene before and after issue 23';

/**
 * Issue 23: the lecture scene with @shadelab/material before its refactor and as checked out, on WebGLRenderer
 * and WebGPURenderer's backends (lecture-refactor.json). @param {any} r @returns {string[]}
 */
function lectureRefactor(r) {
  /** @param {{ paired: number, median: number } | null | undefined} x */
  const cell3 = (x) => (x ? `${x.paired.toFixed(3)} (${x.median.toFixed(3)})` : '—');
  const rows = Object.entries(r.targets ?? {}).map(([name, t]) => {
    const x = /** @type {any} */ (t);
    const [backend, shading] = name.split(': ');
    const pb = r.perBackend?.[backend] ?? {};
    const s = pb.shadings?.[shading] ?? {};
    return [
      `${pb.label ?? backend} (\`${pb.material ?? '?'}\`): ${shading}`,
      frameCell(s.before),
      frameCell(s.after),
      cell3(x.ratio),
      x.ratio?.gpu ? x.ratio.gpu.toFixed(3) : 'n/a',
      x.target,
      metCell(x.met),
      cell3(s.afterVsStaticBindings),
    ];
  });
  return [
    `## ${LECTURE_REFACTOR_TITLE}`,
    '',
    fromLine('lecture-refactor', r),
    '',
    `What issue 23's refactor (one definition of the options and of the lecture's equation, the GLSL as named chunks, the node material's surface) costs the lecture's scene: ${r.scene}. Drawn in the same run and page with the \`@shadelab/material\` of \`${r.before.rev}\` (\`${r.before.commit.slice(0, 7)}\`, before the refactor, bundled from git by the bench and drawn through the page's three.js) and of the run's commit, at ${r.width}×${r.height}. ${r.frames} frames per variant in ${r.rounds} rounds, both builds and every renderer interleaved frame by frame; frame ms: median (minimum); after / before: the median of the ratios of frames from the same cycle (the ratio of the medians in brackets); GPU: the ratio of the GPU-time medians.${r.staticBindings ? ` Static bindings: ${r.staticBindings} (same-cycle ratio; the ratio of the medians in brackets).` : ''} ${r.note ?? ''}`.trim(),
    '',
    ...table(
      [
        'renderer: shading',
        'before ms',
        'after ms',
        'after / before',
        'GPU',
        'target',
        'result',
        'after / after with static bindings',
      ],
      'lrrrrllr',
      rows,
    ),
    ...(r.cause ? ['', r.cause] : []),
  ];
}

const LIGHTING_TITLE = 'The lighting itself';

/**
 * Issue 23: the lighting of ShadingMaterial (the lecture's equation, written once in GLSL) against
 * MeshPhongMaterial's, above MeshBasicMaterial's unlit floor, in the vertex-heavy realistic scene. @param {any} r
 * @returns {string[]}
 */
function lighting(r) {
  /** @param {{ paired: number, median: number } | null} x */
  const cell = (x) => (x ? `${x.paired.toFixed(3)} (${x.median.toFixed(3)})` : '—');
  const rows = Object.entries(r.rows).map(([name, v]) => {
    const row = /** @type {any} */ (v);
    return [
      name,
      `${ms(row.frameMs.median)} (${ms(row.frameMs.min)})`,
      ms(row.cpuMs.median),
      cell(row.vsMeshPhong),
      cell(row.lightingVsMeshPhong),
      cell(row.cpuLightingVsMeshPhong),
    ];
  });
  const t = r.target;
  return [
    `## ${LIGHTING_TITLE}`,
    '',
    fromLine('lighting', r),
    '',
    `Issue 23: what the lighting costs on WebGLRenderer, in the vertex-heavy realistic scene: ${r.scene}. ${r.frames} cycles, each rendering one frame of every variant in turn, a 1×1 \`readPixels\` after each. The lighting above the floor is (frame − ${r.floor}'s) / (MeshPhongMaterial's − ${r.floor}'s) from the frames of one cycle, the median over the cycles (the same of the medians in brackets); of the wall time, and of the CPU time the browser's processes used for the frame (SwiftShader draws on the CPU, on every core: a frame's CPU time can exceed its wall time, and does not depend on what else the machine runs). ${r.note ?? ''}`.trim(),
    '',
    ...table(
      [
        'variant',
        'wall ms: median (min)',
        'CPU ms',
        'wall / MeshPhongMaterial',
        "lighting above the floor / MeshPhongMaterial's (wall)",
        '(CPU)',
      ],
      'lrrrrr',
      rows,
    ),
    '',
    `Target: ${t.variant}, ${t.measure} ${t.target}: **${t.ratio.toFixed(3)}** (${t.met ? 'met' : 'not met'}; CPU time: ${t.cpuRatio.toFixed(3)}).`,
  ];
}

/** @param {any} r @returns {string[]} */
function cameraDepth(r) {
  /** @type {any[]} */
  const rows = r.rows;
  const modes = [...new Set(rows.map((x) => x.mode))];
  const ratios = [...new Set(rows.map((x) => x.ratio))].sort((a, b) => a - b);
  const zs = [...new Set(rows.map((x) => x.z))].sort((a, b) => a - b);
  /** @param {number} x */
  const e = (x) => `1e${Math.round(Math.log10(x))}`;
  /** @param {unknown} x */
  const fmt = (x) =>
    typeof x !== 'number' ? (x === 'lost' ? '> 1' : '—') : x <= 1e-9 ? '≤ 1e-9' : x.toExponential(1);
  const out = [
    '## Camera depth precision',
    '',
    fromLine('camera-depth', r),
    '',
    `The smallest relative separation Δz/z at which a red quad at distance z still hides a green one at z·(1 + Δz/z) drawn after it, per depth mode of \`@shadelab/camera\` (\`-float\` rows draw into a render target with a 32-bit float depth texture). The bench's method: ${r.method}. The _near_ row gives each cell's near plane.`,
    '',
    "SwiftShader stores every depth format as 32-bit float, the canvas's 24-bit depth buffer included, so the plain `reversed` row is float-depth reversed-Z. On a GPU with a true 24-bit fixed-point depth buffer, reversed-Z into the canvas keeps only about 2⁻²⁴ · z/near, like `standard` (not measured here): use a float depth target there. `reversed-or-logarithmic` runs reversed-Z here (SwiftShader has `EXT_clip_control`).",
  ];
  for (const z of zs) {
    out.push(
      '',
      `**z = ${int(z)}**`,
      '',
      ...table(
        ['mode', ...ratios.map((x, i) => (i === 0 ? `far/near ${e(x)}` : e(x)))],
        `l${'l'.repeat(ratios.length)}`,
        [
          [
            '_near_',
            ...ratios.map((ratio) => {
              const c = rows.find((x) => x.ratio === ratio && x.z === z);
              return c ? `_${Number(c.near.toPrecision(2))}_` : '—';
            }),
          ],
          ...modes.map((mode) => [
            mode,
            ...ratios.map((ratio) =>
              fmt(rows.find((x) => x.mode === mode && x.ratio === ratio && x.z === z)?.minSeparation),
            ),
          ]),
        ],
      ),
    );
  }
  if (r.frameTimes) {
    out.push(
      '',
      '### Depth probe frame cost',
      '',
      'One probe frame (8×8 canvas, two quads, render and a 1×1 `readPixels`), milliseconds: too small to show the fill-rate cost of writing `gl_FragDepth`; it shows that no mode adds a per-frame overhead.',
      '',
      ...table(
        ['mode', 'renderer reports', 'median', 'min', 'max'],
        'llrrr',
        Object.entries(r.frameTimes).map(([mode, t]) => [
          mode,
          rows.find((x) => x.mode === mode)?.active ?? '—',
          /** @type {any} */ (t).median.toFixed(3),
          /** @type {any} */ (t).min.toFixed(3),
          /** @type {any} */ (t).max.toFixed(3),
        ]),
      ),
    );
  }
  return out;
}

/** Ball radius of the trackball bench's feel table, px (bench/trackball.bench.mjs). */
const BALL_RADIUS_PX = 250;

/** @param {any} r @returns {string[]} */
function trackball(r) {
  /** @type {any[]} */
  const feel = r.degreesPerRadialPixel;
  /** @param {number} rPx */
  const rLabel = (rPx) =>
    rPx === BALL_RADIUS_PX
      ? `${rPx} (rim)`
      : Math.abs(rPx - BALL_RADIUS_PX / Math.SQRT2) < 1
        ? `${rPx} (≈ R/√2)`
        : String(rPx);
  /** @param {number} deg @param {number} rPx */
  const arc = (deg, rPx) => (deg === 0 ? (rPx === BALL_RADIUS_PX ? '0 (roll only)' : '0') : deg.toFixed(3));
  const c = r.coreNsPerDragStep;
  const p = r.pointerMoveUs;
  return [
    '## Trackball',
    '',
    fromLine('trackball', r),
    '',
    `Rotation of a one-pixel radial move at distance r from the centre of a ${BALL_RADIUS_PX} px-radius ball, degrees:`,
    '',
    ...table(['r (px)', ...feel.map((x) => rLabel(x.rPx))], `l${'r'.repeat(feel.length)}`, [
      ['arcball (°)', ...feel.map((x) => arc(x.arcballDeg, x.rPx))],
      ['Bell (°, the default)', ...feel.map((x) => x.bellDeg.toFixed(3))],
    ]),
    '',
    `Angle of a tiny drag from the centre (${BALL_RADIUS_PX} px-radius ball), relative error against the exact 2·asin(x):`,
    '',
    ...table(
      ['drag (px)', ...r.tinyDragAngle.map((/** @type {any} */ x) => String(x.dragPx))],
      `l${'r'.repeat(r.tinyDragAngle.length)}`,
      [
        ['`atan2` (ours)', ...r.tinyDragAngle.map((/** @type {any} */ x) => exp1(x.atan2RelError))],
        ['`acos(a·b)`', ...r.tinyDragAngle.map((/** @type {any} */ x) => exp1(x.acosRelError))],
      ],
    ),
    '',
    "Orthonormality error of the rotation accumulated with three's `Quaternion` after N random drags (double precision):",
    '',
    ...table(
      ['drags', ...r.orthonormalityAfterDrags.map((/** @type {any} */ x) => power10(x.drags))],
      `l${'r'.repeat(r.orthonormalityAfterDrags.length)}`,
      [
        [
          'renormalised (ours)',
          ...r.orthonormalityAfterDrags.map((/** @type {any} */ x) => exp1(x.renormalised)),
        ],
        [
          'not renormalised',
          ...r.orthonormalityAfterDrags.map((/** @type {any} */ x) => exp1(x.notRenormalised)),
        ],
      ],
    ),
    '',
    '### Trackball speed',
    '',
    `Median and fastest of the timed runs after warm-up${r.quick ? ' (a `--quick` run: its numbers mean nothing)' : ''}:`,
    '',
    ...table(['step', 'median (arcball / Bell)', 'fastest (arcball / Bell)'], 'lrr', [
      [
        'one drag step of the core (2 × `projectToBall` + `arcRotation` + three `Quaternion` multiply + normalise)',
        `${(c.arcball.medianNs / 1000).toFixed(2)} / ${(c.bell.medianNs / 1000).toFixed(2)} µs`,
        `${(c.arcball.minNs / 1000).toFixed(2)} / ${(c.bell.minNs / 1000).toFixed(2)} µs`,
      ],
      [
        'one `pointermove` through `Trackball`, with an object and a camera (handler work only)',
        `${p.arcball.medianUs.toFixed(2)} / ${p.bell.medianUs.toFixed(2)} µs`,
        `${p.arcball.minUs.toFixed(2)} / ${p.bell.minUs.toFixed(2)} µs`,
      ],
    ]),
  ];
}

/** @param {any} r @returns {string[]} */
function sizes(r) {
  /** @type {any[]} */
  const rows = r.rows;
  const entries = [...new Set(rows.filter((x) => x.measure !== 'total').map((x) => x.entry))];
  const totals = rows.filter((x) => x.measure === 'total');
  return [
    '## Package sizes',
    '',
    fromLine('size', r),
    '',
    'Minified and gzipped, without dependencies (three, a peer; `@shadelab/material` inside `@shadelab/reference`, which has its own row). A main entry is measured as a whole; a subpath entry also by what it adds to an app that already imports the main entry, and that is what its budget gates. `npm test` measures and checks them again on every run (`scripts/size.mjs`).',
    '',
    ...table(
      ['entry point', 'minified', 'gzip', 'added to the main entry (gzip)', 'budget', 'within budget'],
      'lrrrrl',
      entries.map((entry) => {
        const whole = rows.find((x) => x.entry === entry && x.measure === 'whole entry');
        const added = rows.find((x) => x.entry === entry && x.measure === 'added to main');
        const gated = added ?? whole;
        return [
          `\`${entry}\``,
          whole ? B(whole.minified) : '—',
          whole ? B(whole.gzipped) : '—',
          added ? B(added.gzipped) : '',
          gated?.budget ? B(gated.budget) : '—',
          gated ? (gated.ok ? 'yes' : '**no**') : '—',
        ];
      }),
    ),
    ...(totals.length
      ? [
          '',
          `All entries of a package together: ${totals.map((x) => `\`${x.package}\` ${B(x.gzipped)}`).join(', ')}.`,
        ]
      : []),
  ];
}

/** @param {any} r @returns {string[]} */
function tarballs(r) {
  return [
    '## Tarballs',
    '',
    fromLine('pack', r),
    '',
    'What `npm run pack` puts in each package tarball (README, changelog, licence, `src/`, and `dist/` with declarations and source maps).',
    '',
    ...table(
      ['package', 'version', 'tarball (gzip)', 'unpacked', 'files'],
      'llrrr',
      r.packages.map((/** @type {any} */ p) => [
        `\`${p.name}\``,
        p.version,
        kB(p.size),
        kB(p.unpackedSize),
        p.entryCount,
      ]),
    ),
  ];
}

/** @param {any} bundle @param {any} first @param {any} refactor @param {any} learn @returns {string[]} */
function playground(bundle, first, refactor, learn) {
  const out = ['## Playground', ''];
  if (bundle) {
    const labels = /** @type {Record<string, string>} */ ({
      three: 'three.js',
      app: 'React, react-dom, leva and the app',
      shadelab: 'the @shadelab packages',
    });
    out.push(
      fromLine('playground-bundle', bundle),
      '',
      "What `playground/index.html` loads at start (`vite build`: its entry chunk and every chunk it imports statically); kB = 1000 B. The total is exact; the groups share each chunk by its modules' rendered (unminified) lengths, an estimate (the bundler puts three, the packages and the app in one chunk or several as the pages share them):",
      '',
      ...table(['what `index.html` loads', 'raw', 'gzip -9'], 'lrr', [
        ...Object.entries(bundle.groups).map(([k, g]) => [
          labels[k] ?? k,
          kB(/** @type {any} */ (g).raw),
          kB(/** @type {any} */ (g).gzip),
        ]),
        ['**total**', `**${kB(bundle.total.raw)}**`, `**${kB(bundle.total.gzip)}**`],
      ]),
    );
  } else out.push(missing('playground-bundle'));
  out.push('', '### First frame', '');
  if (first) {
    /** @type {number[] | null} */
    const samples = first.samplesMs;
    const sorted = samples ? [...samples].sort((a, b) => a - b) : null;
    const median = sorted ? sorted[Math.floor(sorted.length / 2)] : first.medianMs;
    const min = sorted ? sorted[0] : first.minMs;
    const cold = samples ? samples[0] : first.firstMs;
    const vp = first.viewport;
    out.push(
      fromLine('playground-first-frame', first),
      '',
      `Navigation to the first rendered frame of the built playground (\`${first.test}\`${vp ? `, ${vp.width}×${vp.height}` : ''}, ${first.loads} loads): median ${int(Math.round(median))} ms, fastest ${int(Math.round(min))} ms, first (cold) load ${int(Math.round(cold))} ms${samples ? ` (every load: ${samples.map((s) => int(Math.round(s))).join(', ')} ms)` : ''}.`,
    );
  } else out.push(missing('playground-first-frame'));
  out.push('', '### Before and after issue 17', '');
  if (refactor) {
    const { before, after, ratios } = refactor;
    const medianMs = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
    const within = (/** @type {number} */ r) => (r <= 1.1 ? 'yes' : '**no**');
    out.push(
      fromLine('playground-refactor', refactor),
      '',
      `Issue 17 (one table of fields, the viewer in small parts, the layout, the scene in React) against the playground of \`${before.commit}\`, the commit before it, both built from the packages as checked out and without the test pages (only the playground's own change is measured); first frame at ${refactor.viewport.width}×${refactor.viewport.height}, ${refactor.rounds} loads of each build interleaved (ratio: the median of the per-round ratios). Target: after ≤ 1.10 × before.`,
      '',
      ...table(['', 'before', 'after', 'after / before', '≤ 1.10'], 'lrrrl', [
        [
          '`index.html` bundle, gzip -9',
          kB(before.bundle.gzip),
          kB(after.bundle.gzip),
          ratios.bundleGzip.toFixed(3),
          within(ratios.bundleGzip),
        ],
        [
          '`index.html` bundle, raw',
          kB(before.bundle.raw),
          kB(after.bundle.raw),
          ratios.bundleRaw.toFixed(3),
          within(ratios.bundleRaw),
        ],
        [
          'first frame, median',
          `${int(Math.round(medianMs(before.firstFrameMs)))} ms`,
          `${int(Math.round(medianMs(after.firstFrameMs)))} ms`,
          ratios.firstFrame.toFixed(3),
          within(ratios.firstFrame),
        ],
      ]),
      ...(refactor.note ? ['', refactor.note] : []),
    );
  } else out.push(missing('playground-refactor'));
  out.push('', '### Before and after issue 24', '', ...playgroundLearn(learn));
  return out;
}

/** Issue 24's learning tools: the first load and first frame against two befores, the lazy parts. @param {any} learn @returns {string[]} */
function playgroundLearn(learn) {
  if (!learn) return [missing('playground-learn')];
  const { before, committed, after, ratios, ratiosToCommitted } = learn;
  const medianMs = (/** @type {number[]} */ xs) =>
    `${int(Math.round([...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]))} ms`;
  const within = (/** @type {number} */ r) => (r <= 1.1 ? 'yes' : '**no**');
  return [
    fromLine('playground-learn', learn),
    '',
    `Issue 24 (the pixel probe, the term views, the intensity profile, the attenuation curve, the normal-matrix view, copy as code, the compiled shader view, \`?embed\`) against the playground of \`${before.commit}\`, the last commit before it, and of \`${committed.commit}\`, where the figures above were measured before issue 24 (issues 22, 23 and 25 changed the playground in between: the glTF model, WebGPU mode, the adaptive tool); each build from its own commit's playground and packages. What \`index.html\` loads at start (as above), and the first frame at ${learn.viewport.width}×${learn.viewport.height}, ${learn.rounds} loads of each build interleaved (each ratio: the median of the per-round ratios). Target: the first frame ≤ 1.10 × before; the first-load bytes within a budget of ${kB(learn.budgetGzip)} gzip (\`bench/lib/playground-budget.mjs\`, gated with the lazy parts by \`tests/playground-learn.spec.ts\`).`,
    '',
    ...table(
      [
        '',
        `\`${committed.commit}\``,
        `before (\`${before.commit}\`)`,
        'after',
        'after / before',
        '≤ 1.10',
        `after / \`${committed.commit}\``,
      ],
      'lrrrrlr',
      [
        [
          '`index.html` bundle, gzip -9',
          kB(committed.bundle.gzip),
          kB(before.bundle.gzip),
          kB(after.bundle.gzip),
          ratios.bundleGzip.toFixed(3),
          after.bundle.gzip <= learn.budgetGzip
            ? `yes (budget ${kB(learn.budgetGzip)})`
            : `**no** (budget ${kB(learn.budgetGzip)})`,
          ratiosToCommitted.bundleGzip.toFixed(3),
        ],
        [
          '`index.html` bundle, raw',
          kB(committed.bundle.raw),
          kB(before.bundle.raw),
          kB(after.bundle.raw),
          ratios.bundleRaw.toFixed(3),
          '',
          ratiosToCommitted.bundleRaw.toFixed(3),
        ],
        [
          'first frame, median',
          medianMs(committed.firstFrameMs),
          medianMs(before.firstFrameMs),
          medianMs(after.firstFrameMs),
          ratios.firstFrame.toFixed(3),
          within(ratios.firstFrame),
          ratiosToCommitted.firstFrame.toFixed(3),
        ],
      ],
    ),
    '',
    "Loaded on first use only (each part's own chunks, those `index.html` does not load):",
    '',
    ...table(
      ['part', 'module', 'raw', 'gzip -9'],
      'llrr',
      learn.lazyParts.map((/** @type {any} */ p) => [
        p.label,
        `\`${p.module.replace(/^playground\//, '')}\``,
        p.raw === null ? '**not a chunk of its own**' : kB(p.raw),
        p.gzip === null ? '' : kB(p.gzip),
      ]),
    ),
    ...(learn.note ? ['', learn.note] : []),
  ];
}

/** @param {any} r @returns {string[]} */
function reliability(r) {
  const s = r.session;
  /** @param {any} c */
  const counts = (c) => `${c.geometries} / ${c.textures} / ${c.programs} / ${c.listeners}`;
  return [
    '## Reliability',
    '',
    fromLine('reliability', r),
    '',
    `**A long session.** ${int(s.changes)} random option changes in the playground through its URL hash, as a pasted link does (seeded; \`npm test\` runs a short version): programs never above ${s.maxPrograms}; heap after a forced GC ${s.heapMiBAfterWarmUp.toFixed(1)} MiB after warm-up and ${s.heapMiBAtEnd.toFixed(1)} MiB at the end; ${s.consoleErrors} console errors; ${s.stalls} stalls; ${s.changeMs.median.toFixed(0)} ms median per change (${(s.seconds / 60).toFixed(0)} min in all).`,
    '',
    ...table(
      ['after change', 'heap after GC (MiB)', 'programs'],
      'rrr',
      s.samples.map((/** @type {any} */ x) => [int(x.change), x.heapMiB.toFixed(1), x.programs]),
    ),
    '',
    '**Create, render and dispose.** `renderer.info.memory`, `renderer.info.programs` and DOM listener counts (geometries / textures / programs / listeners) before, at the peak and after:',
    '',
    ...table(
      ['kind', 'cycles', 'before', 'peak', 'after', 'back to baseline', 'ms'],
      'lrlllll',
      Object.values(r.leaks).map((/** @type {any} */ x) => [
        x.kind,
        int(x.cycles),
        counts(x.before),
        counts(x.peak),
        counts(x.after),
        x.backToBaseline ? 'yes' : '**no**',
        int(Math.round(x.ms)),
      ]),
    ),
    '',
    "**What every `npm test` tries** (`tests/reliability.spec.ts`, `tests/playground-session.spec.ts` and every package's `fuzz.test.ts`, from fixed seeds):",
    '',
    '- hostile values (NaN, ±Infinity, ±0, 1e±308, subnormals, wrong types, missing fields) into every public constructor, option, setter and method: finite results (geometry arrays, camera matrices and frames, trackball matrices, every uniform) or a TypeError/RangeError naming the parameter;',
    '- create, render and dispose each geometry, material and control 1,000 times: the counts above back to their baseline;',
    '- WebGL context loss after several edits, and an edit while lost: a message, recovery by itself, the pixels of a fresh page with the same state;',
    '- `__proto__`/`constructor`/`prototype` keys, script and `javascript:` strings, 1e999, deep nesting, 1 MB state and non-object roots through the URL hash and through storage: refused with a message, nothing executed, prototypes untouched;',
    '- sphere levels 13–16 from the URL: refused with the byte estimate before allocating, and the page keeps rendering.',
  ];
}

/** @param {any} r @returns {string[]} */
function rasterisers(r) {
  /** @param {any} t */
  const tol = (t) =>
    `${t.maxChannelDiff} codes beyond the ${2 * t.radiusPx + 1} × ${2 * t.radiusPx + 1} range, ${t.maxDiffPixels} pixels beyond`;
  return [
    '## Rasteriser variation',
    '',
    fromLine('rasterisers', r),
    '',
    `How far pictures of one scene differ between rasterisers and between three's renderers: the measurement behind \`@shadelab/playwright\`'s \`toMatchScreenshotAcrossGpus\` and \`toMatchAcrossRenderers\` tolerances (a real GPU is not measured: these are the variations that can be produced here). The kit's lecture scene at ${r.size.width} × ${r.size.height}, each pair scored exactly (the largest channel difference, in 8-bit codes, and the pixels that differ) and within a neighbourhood (how far a pixel lies outside the range its 3 × 3 or 5 × 5 neighbourhood spans in the other picture). "Same settings" pairs stand for another GPU drawing the app as it is; the others show what the tolerance does not cover. WebGPURenderer's backends: ${(r.backends ?? []).join(' and ')}, rows ${r.webgpuRows ?? 'not recorded'}. The bench's note: ${r.note}`,
    '',
    ...table(
      [
        'scene',
        'pair',
        'same settings',
        'max difference',
        'pixels differing',
        '3 × 3 excess',
        '5 × 5 excess',
      ],
      'lllrrrr',
      r.pairs.map((/** @type {any} */ p) => [
        p.scene,
        p.pair,
        p.sameSettings ? 'yes' : 'no',
        p.maxChannelDiff,
        int(p.differingPixels),
        p.maxExcess3x3,
        p.maxExcess5x5,
      ]),
    ),
    '',
    `**Tolerances** (the largest 3 × 3 excess of the same-settings pairs): smooth shading (\`GPU_TOLERANCE\`): ${tol(r.tolerance.smooth)}; pictures with hard edges inside them, flat facets and cel bands (\`GPU_TOLERANCE_HARD_EDGES\`): ${tol(r.tolerance.hardEdges)}${r.tolerance.renderers ? `; three's renderers, the pairs of WebGLRenderer against WebGPURenderer (\`RENDERER_TOLERANCE\`, \`toMatchAcrossRenderers\`): ${tol(r.tolerance.renderers)}` : ''}.`,
    ...(r.llvmpipe
      ? [
          '',
          `**The second rasteriser** (\`shadelabPreset({ rasteriser: 'llvmpipe' })\`: headed Chromium on Xvfb without the SwiftShader flags): WebGL is drawn by ${r.llvmpipe.webgl}, WebGPU by the ${r.llvmpipe.webgpu} adapter. Run to run (each scene drawn again in a second browser): ${(r.llvmpipeRunToRun ?? []).map((/** @type {any} */ x) => `${x.scene} ${int(x.differingPixels)}`).join(', ')} pixels differ.`,
        ]
      : []),
  ];
}

const ADAPTIVE_TITLE = 'Adaptive shading under an error budget';

/**
 * Issue 25: AdaptiveShading in the realistic scene (published and deeper view) against all-Phong and
 * MeshPhongMaterial in the same run, the measured error of each picture beside its frame time. @param {any} r
 * @returns {string[]}
 */
function adaptive(r) {
  /** @param {{ paired: number, median: number }} x */
  const cell = (x) => `${x.paired.toFixed(3)} (${x.median.toFixed(3)})`;
  /** @param {number} x */
  const pct = (x) => `${(100 * x).toFixed(2)} %`;
  /** @param {Record<string, number> | undefined} c */
  const choices = (c) =>
    c
      ? Object.entries(c)
          .sort((a, b) => b[1] - a[1])
          .map(([k, n]) => `${k}: ${int(n)}`)
          .join(', ')
      : '—';
  const out = [
    `## ${ADAPTIVE_TITLE}`,
    '',
    fromLine('adaptive', r),
    '',
    `Issue 25: \`AdaptiveShading\` (\`@shadelab/material/adaptive\`) in the realistic scene: ${r.scene}. ${r.frames} cycles after a warm-up, each rendering one frame of every variant in turn (adaptive: its \`update(camera, renderer)\` included, cached with the camera still), a 1×1 \`readPixels\` after each; ratios are the median of the same-cycle ratios (the ratio of the medians in brackets), of the wall time and of the CPU time of the browser's processes. Error: ${r.error}. ${r.note ?? ''}`.trim(),
  ];
  for (const view of Object.keys(r.results ?? {})) {
    const v = r.results[view];
    out.push(
      '',
      `### ${view === 'published' ? 'Published view' : 'Deeper view'}`,
      '',
      `${r.views?.[view] ?? view}.`,
      '',
      ...table(
        [
          'variant',
          'wall ms: median (min)',
          'wall / all-Phong',
          'CPU / all-Phong',
          'wall / MeshPhongMaterial',
          'error p99',
          'max',
          '> 8',
          '> 32',
        ],
        'lrrrrrrrr',
        Object.entries(v.rows).map(([name, x]) => {
          const row = /** @type {any} */ (x);
          return [
            name,
            `${ms(row.frameMs.median)} (${ms(row.frameMs.min)})`,
            cell(row.vsAllPhong),
            cell(row.cpuVsAllPhong),
            cell(row.vsMeshPhong),
            String(row.error.p99),
            String(row.error.max),
            pct(row.error.over8),
            pct(row.error.over32),
          ];
        }),
      ),
      '',
    );
    for (const [name, t] of Object.entries(v.targets)) {
      const target = /** @type {any} */ (t);
      const row = v.rows[name];
      out.push(
        `- ${name}: **${target.ratio.toFixed(3)}** × all-Phong, target ${target.target}: ${target.met ? 'met' : '**not met**'} (CPU ${target.cpuRatio.toFixed(3)}). Measured error p99 ${target.honest.p99}, ${pct(target.honest.overBudget)} of the drawn pixels over ${target.honest.budget} (${target.honest.withinBudget ? 'within' : '**outside**'} the budget). Choices: ${choices(row.choices)}. Error tables and scene built in ${ms(row.tableAndBuildMs)} ms; \`update\` when everything moved (camera nudged, nothing cached): ${ms(row.updateMovedMs.median)} ms.`,
      );
    }
  }
  // What the fastest fixed shading gets in each view: the floor any choice of shading alone can reach here.
  const floors = Object.entries(r.results ?? {}).map(([view, v]) => {
    const fastest = Object.entries(/** @type {Record<string, any>} */ (v.rows))
      .filter(([name]) => name.startsWith('fixed') || name === 'all-Phong')
      .sort((a, b) => a[1].vsAllPhong.paired - b[1].vsAllPhong.paired)[0];
    return `${fastest[0]} ${fastest[1].vsAllPhong.paired.toFixed(3)} × all-Phong in the ${view === 'published' ? 'published' : 'deeper'} view (error p99 ${fastest[1].error.p99}, ${pct(fastest[1].error.over8)} over 8)`;
  });
  if (floors.length > 0) {
    out.push(
      '',
      `The fastest single shading everywhere: ${floors.join('; ')}: the floor that choosing shadings alone can reach in this scene, whatever the budget.`,
    );
  }
  if (r.why) out.push('', r.why);
  return out;
}

// ── The page ───────────────────────────────────────────────────────────────────────────────────────────────

/**
 * Render BENCHMARKS.md from results keyed by file name without `.json` (`sphere`, `tradeoff`, …). Pure: the
 * same results give the same page.
 * @param {Record<string, any>} results @returns {string}
 */
export function renderBenchmarks(results) {
  /** @param {string} name @param {(r: any) => string[]} render */
  const section = (name, render, title = '') =>
    results[name] ? render(results[name]) : [`## ${title}`, '', missing(name)];
  const parts = [
    [
      '# Benchmarks',
      '',
      '<!-- Generated by `npm run benchmarks` (scripts/benchmarks.mjs) from bench/results/*.json: do not edit. -->',
      '',
      'Every number below is rendered from the results files in [`bench/results/`](bench/results/), and so is how it was measured: the machine, date, load average, versions and commit of each run are in [Runs](#runs). `npm test` fails when this page differs from what `npm run benchmarks` renders from the committed results. Frame times come from headless Chromium with SwiftShader (WebGL on the CPU), so they compare options within one run rather than predict a GPU; errors, triangle counts and bytes are exact.',
      '',
      '- [Sphere build time](#sphere-build-time) · [Sphere error](#sphere-error) · [Automatic detail](#automatic-detail)',
      '- [Speed against accuracy](#speed-against-accuracy) · [Material frame time](#material-frame-time)',
      '- [Material in a realistic scene](#material-in-a-realistic-scene) · [Lecture scene before and after issue 14](#lecture-scene-before-and-after-issue-14) · [Flat shading without preparation](#flat-shading-without-preparation)',
      '- [Swapped materials in a realistic scene](#swapped-materials-in-a-realistic-scene)',
      '- [Material on WebGPURenderer](#material-on-webgpurenderer) · [Realistic scene on WebGPURenderer](#realistic-scene-on-webgpurenderer) · [Lecture scene before and after issue 23](#lecture-scene-before-and-after-issue-23)',
      '- [The lighting itself](#the-lighting-itself) · [Adaptive shading under an error budget](#adaptive-shading-under-an-error-budget)',
      '- [Camera depth precision](#camera-depth-precision) · [Trackball](#trackball)',
      '- [Package sizes](#package-sizes) · [Tarballs](#tarballs) · [Playground](#playground) · [First frame against the Quick start](#first-frame-against-the-quick-start) · [Reliability](#reliability)',
      '- [Rasteriser variation](#rasteriser-variation) · [The gate](#the-gate)',
    ],
    runs(results),
    section('sphere', sphereBuild, 'Sphere build time'),
    section('sphere', sphereError, 'Sphere error'),
    section('autodetail', autodetail, 'Automatic detail'),
    section('tradeoff', tradeoff, 'Speed against accuracy'),
    section('material', material, 'Material frame time'),
    section('scene', sceneRealistic, 'Material in a realistic scene'),
    section('scene', sceneLecture, 'Lecture scene before and after issue 14'),
    section('scene', sceneFlat, 'Flat shading without preparation'),
    section('swap', swap, SWAP_TITLE),
    section('webgpu', webgpu, WEBGPU_TITLE),
    section('webgpu', webgpuRealistic, WEBGPU_REALISTIC_TITLE),
    section('lecture-refactor', lectureRefactor, LECTURE_REFACTOR_TITLE),
    section('lighting', lighting, LIGHTING_TITLE),
    section('adaptive', adaptive, ADAPTIVE_TITLE),
    section('camera-depth', cameraDepth, 'Camera depth precision'),
    section('trackball', trackball, 'Trackball'),
    section('size', sizes, 'Package sizes'),
    section('pack', tarballs, 'Tarballs'),
    playground(
      results['playground-bundle'],
      results['playground-first-frame'],
      results['playground-refactor'],
      results['playground-learn'],
    ),
    section('first-frame', (r) => firstFrameSection(r, { table, fromLine }), FIRST_FRAME_TITLE),
    section('reliability', reliability, 'Reliability'),
    section('rasterisers', rasterisers, 'Rasteriser variation'),
    section('gate', (g) => gateSection(g, table), 'The gate'),
  ];
  return `${parts.map((p) => p.join('\n')).join('\n\n')}\n`;
}

/** Every `*.json` in `dir`, keyed by its name without `.json`. @param {string} dir @returns {Record<string, any>} */
export function loadResults(dir) {
  /** @type {Record<string, any>} */
  const results = {};
  for (const file of readdirSync(dir).sort()) {
    if (file.endsWith('.json'))
      results[file.slice(0, -5)] = JSON.parse(readFileSync(join(dir, file), 'utf8'));
  }
  return results;
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const page = renderBenchmarks(loadResults(join(root, 'bench', 'results')));
  const path = join(root, OUTPUT);
  if (process.argv.includes('--check')) {
    /** @type {string | null} */
    let current = null;
    try {
      current = readFileSync(path, 'utf8');
    } catch {
      current = null;
    }
    if (current !== page) {
      const a = (current ?? '').split('\n');
      const b = page.split('\n');
      let line = 0;
      while (line < Math.max(a.length, b.length) && a[line] === b[line]) line++;
      console.error(
        current === null
          ? `${OUTPUT} is missing: run \`npm run benchmarks\` and commit it.`
          : `${OUTPUT} differs from what bench/results/*.json renders (first at line ${line + 1}): it is generated, never edited; run \`npm run benchmarks\` and commit it.\n  in the file: ${a[line] ?? '(end of file)'}\n  rendered:    ${b[line] ?? '(end of file)'}`,
      );
      process.exit(1);
    }
    console.log(`${OUTPUT} matches bench/results/*.json`);
  } else {
    writeFileSync(path, page);
    console.log(`wrote ${OUTPUT}`);
  }
}
