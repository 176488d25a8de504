// The long session of issue 8 at full count: 10,000 random option changes in the playground (through its URL
// hash, as a pasted link does), with the programs, the heap after a forced GC and the console errors recorded;
// then the leaks harness at 10,000 create/render/dispose cycles per kind. `npm test` runs the short versions
// (tests/playground-session.spec.ts, tests/reliability.spec.ts).
//
// node bench/reliability.bench.mjs [--changes 10000] [--cycles 10000] [--json PATH]
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

const changes = Number(arg('--changes', '10000'));
const cycles = Number(arg('--cycles', '10000'));

const playground = await openPlayground();
const browser = playground.browser;
const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
/** @type {string[]} */
const errors = [];
page.on('console', (m) => {
  if (m.type() === 'error') errors.push(m.text());
});
page.on('pageerror', (e) => errors.push(e.message));
const cdp = await page.context().newCDPSession(page);
const heap = async () => {
  await cdp.send('HeapProfiler.collectGarbage');
  return (await cdp.send('Runtime.getHeapUsage')).usedSize;
};

/** A small deterministic PRNG (mulberry32), so a failing session can be replayed. @param {number} seed */
function random(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const rand = random(1234);
/** @template T @param {readonly T[]} xs @returns {T} */
const pick = (xs) => xs[Math.floor(rand() * xs.length)];

/** A random state (every section), different from the previous one so that each change draws a frame. @param {number} i */
function randomState(i) {
  const lights = Array.from({ length: pick([0, 1, 2, 3]) }, (_, k) => ({
    position: [k * 3 - 4, 8, 15],
    attenuation: { a: 1, b: pick([0, 0.02]), c: 0 },
  }));
  return {
    view: pick(['single', 'single', 'compare']),
    material: {
      shading: pick(['flat', 'gouraud', 'phong']),
      lighting: pick(['phong', 'blinn-phong']),
      celBands: pick([0, 0, 2, 3, 5]),
      outline: rand() < 0.3,
      shininess: 1 + (i % 997),
    },
    lights,
    sphere: { base: pick(['tetrahedron', 'octahedron', 'icosahedron']), level: pick([0, 1, 2, 3, 4]) },
    camera: { projection: pick(['perspective', 'orthographic']) },
  };
}

await page.goto(playground.url('/'));
await page.waitForFunction(
  () => Number(document.querySelector('[data-testid="viewport"]')?.getAttribute('data-frames')) > 0,
);

const BATCH = 50;
/** @type {number[]} */
const latencies = [];
/** @type {{ change: number, heapMiB: number, programs: number }[]} */
const samples = [];
let maxPrograms = 0;
let stalls = 0;
const t0 = performance.now();
for (let i = 0; i < changes; i += BATCH) {
  const texts = Array.from({ length: Math.min(BATCH, changes - i) }, (_, k) =>
    JSON.stringify(randomState(i + k)),
  );
  // In the page: apply each state through the hash and wait (by animation frames) for the frame it draws.
  const r = await page.evaluate(async (states) => {
    const canvas = /** @type {HTMLElement} */ (document.querySelector('[data-testid="viewport"]'));
    const programs = () => Number(document.querySelector('[data-testid="stats-programs"]')?.textContent ?? 0);
    const out = { ms: /** @type {number[]} */ ([]), maxPrograms: 0, stalls: 0 };
    for (const text of states) {
      const before = Number(canvas.dataset.frames);
      const params = new URLSearchParams();
      params.set('s', text);
      const start = performance.now();
      window.location.hash = params.toString();
      while (Number(canvas.dataset.frames) <= before) {
        if (performance.now() - start > 5000) {
          out.stalls++;
          break;
        }
        await new Promise((resolve) => requestAnimationFrame(resolve));
      }
      out.ms.push(performance.now() - start);
      out.maxPrograms = Math.max(out.maxPrograms, programs());
    }
    return out;
  }, texts);
  latencies.push(...r.ms);
  maxPrograms = Math.max(maxPrograms, r.maxPrograms);
  stalls += r.stalls;
  const done = i + texts.length;
  if (done % 1000 === 0 || done === changes || done === BATCH * 2) {
    const programs = Number(await page.getByTestId('stats-programs').textContent());
    samples.push({ change: done, heapMiB: (await heap()) / 2 ** 20, programs });
    console.log(
      `${done} changes: heap ${samples.at(-1)?.heapMiB.toFixed(1)} MiB, programs ${programs}, max ${maxPrograms}`,
    );
  }
}
const sessionSeconds = (performance.now() - t0) / 1000;
const afterWarmUp = samples[0]?.heapMiB ?? 0;
const atEnd = samples.at(-1)?.heapMiB ?? 0;

// The leaks harness at the full count (the program-compiling kind at 1,000: ~20 ms a compile).
await page.goto(playground.url('harness/?page=leaks'));
await page.waitForFunction(() => document.getElementById('viewport')?.dataset.ready === 'true');
/** @type {Record<string, unknown>} */
const leaks = {};
for (const kind of await page.evaluate(() => window.leaks.kinds)) {
  const n = kind === 'ShadingMaterial (new variants)' ? Math.min(cycles, 1000) : cycles;
  await page.evaluate((k) => window.leaks.run(k, 3), kind);
  const start = performance.now();
  const report = await page.evaluate(
    ([k, c]) => window.leaks.run(/** @type {never} */ (k), Number(c)),
    [kind, n],
  );
  const ms = performance.now() - start;
  const held = JSON.stringify(report.after) === JSON.stringify(report.before);
  leaks[kind] = { ...report, ms, backToBaseline: held };
  console.log(
    `leaks ${kind} × ${n}: ${held ? 'back to baseline' : 'LEAK'} ${JSON.stringify(report.after)} (${ms.toFixed(0)} ms)`,
  );
}

await playground.close();

const results = {
  session: {
    changes,
    seconds: sessionSeconds,
    changeMs: summarize(latencies),
    maxPrograms,
    stalls,
    heapMiBAfterWarmUp: afterWarmUp,
    heapMiBAtEnd: atEnd,
    heapGrowthMiB: atEnd - afterWarmUp,
    samples,
    consoleErrors: errors.length,
    firstErrors: errors.slice(0, 5),
  },
  leaks,
};
console.log(JSON.stringify(results.session, null, 2));
writeResults(results);
const ok =
  errors.length === 0 &&
  stalls === 0 &&
  maxPrograms <= 32 &&
  atEnd < afterWarmUp * 1.5 + 8 &&
  Object.values(leaks).every((l) => /** @type {{ backToBaseline: boolean }} */ (l).backToBaseline);
if (!ok) console.error('reliability: a bound did not hold (see above)');
process.exit(ok ? 0 : 1);
