// Benchmark of @shadelab/sphere (built dist): subdivideSphere build time for levels 4–9 of every base,
// indexed and non-indexed, side by side with three.js's IcosahedronGeometry at the nearest triangle count and
// with a plain loop writing the same bytes into the same typed arrays; then error × triangles per base and
// level, the cheapest base per error budget, and the cost of sphereError itself.
//
//   npx tsc -b packages/sphere && node bench/sphere.bench.mjs [--json bench/results/sphere.json] [--quick]
//     [--levels 4,5]   (only these build levels: a small configuration to check that the script runs)
//
// Sub-millisecond builds (levels 4–5) are timed in batches: each timed sample runs the call enough times to
// last about SAMPLE_MS and reports the time per call, so timer resolution and one-off pauses do not dominate.
import { SPHERE_BASES, sphereCounts, subdivideSphere } from '@shadelab/sphere';
import { sphereError } from '@shadelab/sphere/detail';
import { IcosahedronGeometry } from 'three';
import { arg, summarize, writeResults } from './lib/bench.mjs';

/** @typedef {import('@shadelab/sphere').SphereBase} SphereBase */
/** @typedef {import('@shadelab/sphere').SphereMesh} SphereMesh */
/** @typedef {import('@shadelab/sphere').SubdivideSphereOptions} SubdivideSphereOptions */
/** @typedef {Float32ArrayConstructor | Uint16ArrayConstructor | Uint32ArrayConstructor} ArrayKind */
/** @typedef {[ArrayKind, number]} Slot one output array: its kind and length */
/** @typedef {{ median: number, min: number, max: number, runs: number, batch: number }} Timing per call; batch = calls per timed sample */
/** @typedef {{ ours: Timing, plain: Timing, bytes: number, threeOverOurs: number, oursOverPlain: number }} Variant */
/**
 * @typedef {{ base: SphereBase, level: number, triangles: number, threeDetail: number, threeTriangles: number,
 *   three: Timing, indexed: Variant, nonIndexed: Variant }} BuildRow
 */
/** @typedef {{ base: SphereBase, level: number, triangles: number, error: number, errorTimesTriangles: number }} ErrorRow */

const quick = process.argv.includes('--quick');
const levelsArg = arg('--levels', '');
const LEVELS = levelsArg ? levelsArg.split(',').map(Number) : quick ? [4, 6, 8] : [4, 5, 6, 7, 8, 9];
if (!LEVELS.every((l) => Number.isInteger(l) && l >= 0 && l <= 12)) {
  throw new RangeError(`--levels must be a comma-separated list of integers from 0 to 12; got ${levelsArg}`);
}
/** A timed sample lasts at least this long (ms): faster calls are repeated within it. */
const SAMPLE_MS = 5;
/** Like three's geometry, which also builds normals (and uvs). @type {import('@shadelab/sphere').SphereNormals} */
const NORMALS = 'smooth';

/** Warm-up and run counts: at least 5 timed runs, fewer warm-ups for the multi-second cases. @param {number} triangles */
function plan(triangles) {
  if (triangles >= 2_000_000) return { warmup: 1, runs: 5 };
  if (triangles >= 200_000) return { warmup: 2, runs: 7 };
  return { warmup: 5, runs: 15 };
}

/**
 * Time `fn` per call (ms): `warmup` untimed calls, then `runs` timed samples of `batch` calls each. The batch
 * doubles from 1 until one batch lasts SAMPLE_MS (1 for calls that slow, at most 2^14), so that every sample
 * is long against the timer's resolution.
 * @param {() => unknown} fn @param {{ warmup: number, runs: number }} counts @returns {Timing}
 */
function measure(fn, { warmup, runs }) {
  for (let i = 0; i < warmup; i++) fn();
  /** @param {number} n */
  const timeBatch = (n) => {
    const t0 = performance.now();
    for (let b = 0; b < n; b++) fn();
    return performance.now() - t0;
  };
  let batch = 1;
  while (batch < 2 ** 14 && timeBatch(batch) < SAMPLE_MS) batch *= 2;
  /** @type {number[]} */
  const times = [];
  for (let r = 0; r < runs; r++) times.push(timeBatch(batch) / batch);
  return { ...summarize(times), batch };
}

/** Allocate typed arrays of the given kinds and lengths and write every element in a plain loop. @param {Slot[]} layout */
function plainWrite(layout) {
  const out = [];
  for (const [Kind, length] of layout) {
    const a = new Kind(length);
    if (Kind === Float32Array) for (let i = 0; i < length; i++) a[i] = i * 0.5;
    else for (let i = 0; i < length; i++) a[i] = i;
    out.push(a);
  }
  return out;
}

/** The kinds and lengths of a mesh's arrays. @param {SphereMesh} mesh @returns {Slot[]} */
function layoutOf(mesh) {
  /** @type {Slot[]} */
  const out = [];
  for (const a of [mesh.positions, mesh.normals, mesh.indices]) {
    if (a) out.push([/** @type {ArrayKind} */ (a.constructor), a.length]);
  }
  return out;
}

/** @param {Slot[]} layout */
function bytesOf(layout) {
  return layout.reduce((sum, [Kind, length]) => sum + Kind.BYTES_PER_ELEMENT * length, 0);
}

/** three's detail d gives 20·(d + 1)² triangles: the d nearest to `triangles`. @param {number} triangles */
function nearestThreeDetail(triangles) {
  const d = Math.max(0, Math.round(Math.sqrt(triangles / 20)) - 1);
  const candidates = [d - 1, d, d + 1].filter((x) => x >= 0);
  return candidates.reduce((a, b) =>
    Math.abs(20 * (a + 1) ** 2 - triangles) <= Math.abs(20 * (b + 1) ** 2 - triangles) ? a : b,
  );
}

/** @param {number} x */
const ms = (x) => (x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
/** @param {number} x */
const ratio = (x) => (x >= 10 ? x.toFixed(0) : x.toFixed(1));
/** @param {number} x */
const count = (x) => x.toLocaleString('en-US');

console.log(`node ${process.version}, build levels ${LEVELS.join(', ')}; times are medians in ms per call`);

// ── Build times ────────────────────────────────────────────────────────────────────────────────────────────
/** @type {Map<number, Timing>} */
const threeCache = new Map();
/** @param {number} detail @returns {Timing} */
function threeTime(detail) {
  let timing = threeCache.get(detail);
  if (!timing) {
    timing = measure(() => new IcosahedronGeometry(1, detail), plan(20 * (detail + 1) ** 2));
    threeCache.set(detail, timing);
  }
  return timing;
}

/** @param {SubdivideSphereOptions} options @param {number} triangles @param {Timing} three @returns {Variant} */
function measureVariant(options, triangles, three) {
  const layout = layoutOf(subdivideSphere(options));
  const ours = measure(() => subdivideSphere(options), plan(triangles));
  const plain = measure(() => plainWrite(layout), plan(triangles));
  return {
    ours,
    plain,
    bytes: bytesOf(layout),
    threeOverOurs: three.median / ours.median,
    oursOverPlain: ours.median / plain.median,
  };
}

/** @type {BuildRow[]} */
const builds = [];
for (const base of SPHERE_BASES) {
  for (const level of LEVELS) {
    const { triangles } = sphereCounts(base, level);
    const detail = nearestThreeDetail(triangles);
    const three = threeTime(detail);
    const common = { base, level, normals: NORMALS, maxBytes: Number.POSITIVE_INFINITY };
    const i = measureVariant({ ...common, indexed: true }, triangles, three);
    const n = measureVariant({ ...common, indexed: false }, triangles, three);
    const threeTriangles = 20 * (detail + 1) ** 2;
    builds.push({
      base,
      level,
      triangles,
      threeDetail: detail,
      threeTriangles,
      three,
      indexed: i,
      nonIndexed: n,
    });
    console.log(
      `${base} L${level} (${triangles} tris): indexed ${ms(i.ours.median)} ms (${ratio(i.threeOverOurs)}× faster than three, ${ratio(i.oursOverPlain)}× plain), ` +
        `non-indexed ${ms(n.ours.median)} ms (${ratio(n.threeOverOurs)}×, ${ratio(n.oursOverPlain)}× plain), three d=${detail} ${ms(three.median)} ms`,
    );
  }
}

console.log(
  `\n### Build time (smooth normals; median of ≥ 5 samples after warm-up, ms per call; a sample under ${SAMPLE_MS} ms repeats the call)\n`,
);
console.log(
  '| base | level | triangles | indexed | plain write (idx) | non-indexed | plain write (non-idx) | three `IcosahedronGeometry` (detail → triangles) | three ÷ indexed | indexed ÷ plain | three ÷ non-idx | non-idx ÷ plain |',
);
console.log('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
for (const r of builds) {
  const i = r.indexed;
  const n = r.nonIndexed;
  console.log(
    `| ${r.base} | ${r.level} | ${count(r.triangles)} | ${ms(i.ours.median)} | ${ms(i.plain.median)} | ${ms(n.ours.median)} | ${ms(n.plain.median)} | ${ms(r.three.median)} (${r.threeDetail} → ${count(r.threeTriangles)}) | ${ratio(i.threeOverOurs)}× | ${ratio(i.oursOverPlain)}× | ${ratio(n.threeOverOurs)}× | ${ratio(n.oursOverPlain)}× |`,
  );
}

const target = builds.find((r) => r.base === 'tetrahedron' && r.level === 8);
if (target) {
  const t = target.indexed;
  const ok = t.threeOverOurs >= 10 && t.oursOverPlain <= 5;
  console.log(
    `\nTarget (indexed level 8 tetrahedron, 262,144 triangles): ${ratio(t.threeOverOurs)}× faster than three (goal ≥ 10×), ${ratio(t.oursOverPlain)}× the plain write (goal ≤ 5×): ${ok ? 'met' : 'NOT met'}`,
  );
}

// ── sphereError cost (the first call per base and level computes; later calls are a memo lookup) ───────────
/** @type {{ base: SphereBase, levels: string, firstCallMs: number }[]} */
const errorCost = [];
for (const base of SPHERE_BASES) {
  let t0 = performance.now();
  for (let level = 0; level <= 10; level++) sphereError(base, level);
  errorCost.push({ base, levels: '0-10', firstCallMs: performance.now() - t0 });
  for (const level of [15, 20]) {
    t0 = performance.now();
    sphereError(base, level);
    errorCost.push({ base, levels: String(level), firstCallMs: performance.now() - t0 });
  }
}

// ── Error × triangles ──────────────────────────────────────────────────────────────────────────────────────
/** @type {ErrorRow[]} */
const errors = [];
for (const base of SPHERE_BASES) {
  for (let level = 0; level <= 10; level++) {
    const { triangles } = sphereCounts(base, level);
    const error = sphereError(base, level);
    errors.push({ base, level, triangles, error, errorTimesTriangles: error * triangles });
  }
}
/** @param {SphereBase} base @param {number} level */
const errorRow = (base, level) =>
  /** @type {ErrorRow} */ (errors.find((x) => x.base === base && x.level === level));

console.log('\n### Error × triangles (unit sphere; lower error·T buys accuracy cheaper)\n');
console.log(
  '| level | tetrahedron T | error | error·T | octahedron T | error | error·T | icosahedron T | error | error·T |',
);
console.log('| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
for (let level = 0; level <= 10; level++) {
  const cells = SPHERE_BASES.map((base) => {
    const e = errorRow(base, level);
    return `${count(e.triangles)} | ${e.error.toExponential(3)} | ${e.errorTimesTriangles.toFixed(3)}`;
  });
  console.log(`| ${level} | ${cells.join(' | ')} |`);
}

// Cheapest sphere for a relative error budget (radiusPx · error ≤ maxErrorPx ⇔ error ≤ maxErrorPx / radiusPx).
console.log('\n### Fewest triangles for a relative error budget (levels ≤ 10)\n');
console.log('| error ≤ | tetrahedron | octahedron | icosahedron | cheapest |');
console.log('| ---: | ---: | ---: | ---: | --- |');
const budgets = [];
for (const budget of [1e-2, 1e-3, 1e-4, 1e-5, 1e-6]) {
  const picks = SPHERE_BASES.map((base) => errors.find((e) => e.base === base && e.error <= budget));
  /** @type {ErrorRow[]} */
  const found = [];
  for (const p of picks) if (p) found.push(p);
  const best = found.sort((a, b) => a.triangles - b.triangles)[0];
  budgets.push({ budget, picks, best });
  /** @param {ErrorRow | undefined} p */
  const cell = (p) => (p ? `L${p.level}: ${count(p.triangles)}` : '> L10');
  console.log(
    `| ${budget.toExponential(0)} | ${picks.map(cell).join(' | ')} | ${best ? `${best.base} L${best.level}` : '—'} |`,
  );
}

console.log('\n### sphereError first-call cost (ms; later calls are a memo lookup)\n');
console.log('| base | levels 0–10 (all) | level 15 | level 20 |');
console.log('| --- | ---: | ---: | ---: |');
for (const base of SPHERE_BASES) {
  const c = errorCost.filter((e) => e.base === base).map((e) => ms(e.firstCallMs));
  console.log(`| ${base} | ${c.join(' | ')} |`);
}

writeResults({
  node: process.version,
  quick,
  levels: LEVELS,
  sampleMs: SAMPLE_MS,
  normals: NORMALS,
  builds,
  errors,
  budgets,
  errorCost,
});
