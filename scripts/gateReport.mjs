// What `npm test` says about its own cost: the machine, each stage's wall time, the spec files that took the most
// worker time, the tests closest to their timeouts and where the Playwright time went (page loads, builds, the
// browsers' GPU processes and renderers). Pure functions of Playwright's JSON report, so that scripts/test.mjs
// prints them and BENCHMARKS.md renders the committed run (bench/results/gate.json) from the same numbers.
import { createHash } from 'node:crypto';
import { cpus } from 'node:os';

/** @typedef {{ name: string, seconds: number }} StageTime */

/**
 * One test's run, flattened from Playwright's JSON report.
 * @typedef {object} TestRun
 * @property {string} file the spec file, relative to tests/
 * @property {number} line
 * @property {string} title
 * @property {string} project
 * @property {number} seconds the test's duration, its hooks and fixtures included
 * @property {number} timeoutSeconds the timeout the test ended with (test.setTimeout included)
 * @property {number} pageLoadSeconds what the test's `page-load` annotations add up to
 * @property {string[]} pageLoads those annotations: "<ms> <id>", the id naming one load (a `beforeAll` load is on
 *   every test of its group, and counted once in a sum over tests)
 * @property {number | null} gpuSeconds CPU time of its browser's GPU process (shader and pipeline compiles, draws,
 *   read-backs): its `gpu-process` annotation (tests/harness-helpers.ts' test records it), null without one
 * @property {number | null} rendererSeconds CPU time of its browser's renderers (the pages' scripts): its
 *   `renderer` annotation, null without one
 * @property {number} setupSeconds the time its worker spent before it since the test before it ended (or since
 *   the run started): its spec's `beforeAll` hooks and worker fixtures, which no test's duration holds
 * @property {string} status
 */

/**
 * What a test's annotations of one type add up to, in seconds (each holds milliseconds).
 * @param {{ type: string, description?: string }[]} annotations @param {string} type
 */
const annotated = (annotations, type) =>
  annotations
    .filter((a) => a.type === type)
    .reduce((sum, a) => sum + Number.parseFloat(a.description ?? ''), 0) / 1000;

/**
 * The same for a measurement not every test records: null when the test has none.
 * @param {{ type: string, description?: string }[]} annotations @param {string} type
 */
const measured = (annotations, type) =>
  annotations.some((a) => a.type === type) ? annotated(annotations, type) : null;

/**
 * The sum of what the runs recorded, or null when none did.
 * @param {(number | null)[]} values
 */
const sumMeasured = (values) =>
  values.some((v) => v !== null)
    ? round1(values.reduce((/** @type {number} */ sum, v) => sum + (v ?? 0), 0))
    : null;

/**
 * Every test run in a Playwright JSON report.
 * @param {any} report @returns {TestRun[]}
 */
export function testRuns(report) {
  /** @type {(TestRun & { parallelIndex: number, start: number })[]} */
  const runs = [];
  /** @param {any} suite */
  const walk = (suite) => {
    for (const spec of suite.specs ?? []) {
      for (const test of spec.tests ?? []) {
        for (const result of test.results ?? []) {
          // A result's annotations are its test's (the report lists them in both places since Playwright 1.52).
          /** @type {{ type: string, description?: string }[]} */
          const annotations = result.annotations ?? test.annotations ?? [];
          runs.push({
            file: spec.file,
            line: spec.line,
            title: spec.title,
            project: test.projectName,
            seconds: result.duration / 1000,
            timeoutSeconds: test.timeout / 1000,
            pageLoadSeconds: annotated(annotations, 'page-load'),
            pageLoads: annotations.filter((a) => a.type === 'page-load').map((a) => String(a.description)),
            gpuSeconds: measured(annotations, 'gpu-process'),
            rendererSeconds: measured(annotations, 'renderer'),
            setupSeconds: 0,
            status: result.status,
            parallelIndex: result.parallelIndex ?? 0,
            start: Date.parse(result.startTime),
          });
        }
      }
    }
    for (const child of suite.suites ?? []) walk(child);
  };
  for (const suite of report.suites ?? []) walk(suite);
  // Each worker slot's tests in the order they ran: the gap before a test is its set-up.
  const started = Date.parse(report.stats?.startTime ?? '') || Math.min(...runs.map((r) => r.start));
  /** @type {Map<number, typeof runs>} */
  const slots = new Map();
  for (const r of runs) slots.set(r.parallelIndex, [...(slots.get(r.parallelIndex) ?? []), r]);
  for (const slot of slots.values()) {
    let free = started;
    for (const r of slot.sort((a, b) => a.start - b.start)) {
      r.setupSeconds = Math.max(0, r.start - free) / 1000;
      free = Math.max(free, r.start + r.seconds * 1000);
    }
  }
  return runs.map(({ parallelIndex, start, ...r }) => r);
}

/** @param {number} x */
const round1 = (x) => Math.round(x * 10) / 10;

/**
 * How fast one core of this machine is now: the median time of a fixed single-threaded workload (a SHA-256 of
 * 16 MiB and a floating-point loop), in ms. Machines of one kind differ, and one machine differs from day to day
 * (noisy neighbours): a run's times are judged against this reading, taken while nothing else of the run works.
 * @returns {number}
 */
export function singleCoreMs() {
  const data = Buffer.alloc(16 << 20, 7);
  const times = [];
  for (let round = 0; round < 5; round++) {
    const t0 = performance.now();
    createHash('sha256').update(data).digest();
    let x = 0;
    for (let i = 1; i <= 20_000_000; i++) x += Math.sqrt(i) / i;
    if (!Number.isFinite(x)) throw new Error('unreachable');
    times.push(performance.now() - t0);
  }
  return round1(times.sort((a, b) => a - b)[2]);
}

/**
 * The seconds the runs spent loading pages, each load once: a load without an id (an older annotation) is its own.
 * @param {TestRun[]} of
 */
function pageLoadSeconds(of) {
  /** @type {Map<string, number>} */
  const loads = new Map();
  for (const [i, r] of of.entries()) {
    for (const [j, load] of r.pageLoads.entries()) {
      const [ms, id] = load.split(' ');
      loads.set(id ?? `${i}.${j}`, Number.parseFloat(ms) / 1000);
    }
  }
  return [...loads.values()].reduce((sum, x) => sum + x, 0);
}

/**
 * The summary of one gate run.
 * @param {{ stages: StageTime[], totalSeconds: number, singleCoreMs: number, report?: any, passed: number,
 *   failed: number }} run
 */
export function gateSummary({ stages, totalSeconds, singleCoreMs, report, passed, failed }) {
  const runs = report ? testRuns(report) : [];
  /** @param {TestRun[]} of */
  const parts = (of) => ({
    setupSeconds: round1(of.reduce((sum, r) => sum + r.setupSeconds, 0)),
    pageLoadSeconds: round1(pageLoadSeconds(of)),
    gpuSeconds: sumMeasured(of.map((r) => r.gpuSeconds)),
    rendererSeconds: sumMeasured(of.map((r) => r.rendererSeconds)),
  });
  /** @param {TestRun[]} of */
  const workerSeconds = (of) => round1(of.reduce((sum, r) => sum + r.seconds + r.setupSeconds, 0));
  /** @type {Map<string, TestRun[]>} */
  const specs = new Map();
  for (const r of runs) {
    const key = r.project === 'swiftshader' ? r.file : `${r.file} [${r.project}]`;
    specs.set(key, [...(specs.get(key) ?? []), r]);
  }
  return {
    cpuModel: cpus()[0]?.model.trim() ?? 'unknown',
    cpus: cpus().length,
    singleCoreMs,
    totalSeconds: round1(totalSeconds),
    passed,
    failed,
    stages: stages.map((s) => ({ name: s.name, seconds: round1(s.seconds) })),
    playwright: {
      tests: runs.length,
      wallSeconds: report ? round1((report.stats?.duration ?? 0) / 1000) : 0,
      workerSeconds: workerSeconds(runs),
      ...parts(runs),
    },
    slowestSpecs: [...specs]
      .map(([file, of]) => ({ file, tests: of.length, seconds: workerSeconds(of), ...parts(of) }))
      .sort((a, b) => b.seconds - a.seconds)
      .slice(0, 20),
    slowestTests: [...runs]
      .sort((a, b) => b.seconds / b.timeoutSeconds - a.seconds / a.timeoutSeconds)
      .slice(0, 10)
      .map((r) => ({
        test: `${r.file}:${r.line} ${r.title}`,
        project: r.project,
        seconds: round1(r.seconds),
        timeoutSeconds: r.timeoutSeconds,
        shareOfTimeout: Math.round((r.seconds / r.timeoutSeconds) * 1000) / 1000,
      })),
  };
}

/** @typedef {ReturnType<typeof gateSummary>} GateSummary */

/** @param {number} s */
const secs = (s) => `${s.toFixed(0).padStart(5)} s`;

/** Seconds in three columns, or – for what no test recorded. @param {number | null} x */
const n = (x) => (x === null ? '–' : x.toFixed(0)).padStart(3);

/**
 * The summary as the lines `npm test` prints.
 * @param {GateSummary} g @returns {string[]}
 */
export function gateLines(g) {
  const lines = [
    `machine: ${g.cpuModel}, ${g.cpus} cores${g.singleCoreMs ? `; one core's fixed workload (singleCoreMs in scripts/gateReport.mjs): ${g.singleCoreMs} ms` : ''}`,
    '',
    'stages (wall time):',
  ];
  for (const s of g.stages) lines.push(`${secs(s.seconds)}  ${s.name}`);
  lines.push(`${secs(g.totalSeconds)}  in all`);
  if (g.playwright.tests > 0) {
    lines.push(
      '',
      `Playwright: ${g.playwright.tests} tests, ${g.playwright.workerSeconds.toFixed(0)} worker-seconds (set-up outside tests ${g.playwright.setupSeconds.toFixed(0)}, page loads ${g.playwright.pageLoadSeconds.toFixed(0)}), ${g.playwright.wallSeconds.toFixed(0)} s of wall time; CPU in the browsers' GPU processes ${n(g.playwright.gpuSeconds).trim()} s, in their renderers ${n(g.playwright.rendererSeconds).trim()} s`,
      '',
      'the 20 spec files that took the most worker time (set-up outside tests / page loads; CPU in the GPU process / the renderers):',
    );
    for (const s of g.slowestSpecs)
      lines.push(
        `${secs(s.seconds)}  (${n(s.setupSeconds)} / ${n(s.pageLoadSeconds)} s; ${n(s.gpuSeconds)} / ${n(s.rendererSeconds)} s)  ${String(s.tests).padStart(3)} tests  ${s.file}`,
      );
    lines.push('', 'the 10 tests nearest their timeout (duration / timeout):');
    for (const t of g.slowestTests)
      lines.push(
        `${(t.shareOfTimeout * 100).toFixed(0).padStart(4)} %  ${t.seconds.toFixed(1).padStart(5)} s of ${t.timeoutSeconds} s  ${t.project === 'swiftshader' ? '' : `[${t.project}] `}${t.test}`,
      );
  }
  return lines;
}

/**
 * BENCHMARKS.md's section on the gate, from a recorded summary (bench/results/gate.json).
 * @param {GateSummary & { meta?: any }} g
 * @param {(header: string[], align: string, rows: (string | number)[][]) => string[]} table
 * @returns {string[]}
 */
export function gateSection(g, table) {
  const s = (/** @type {number} */ x) => x.toFixed(0);
  const minutes = (/** @type {number} */ x) => `${(x / 60).toFixed(1)} min`;
  return [
    '## The gate',
    '',
    `What \`npm test\` cost in one recorded run (\`npm test -- --record\`) on ${g.cpuModel} (${g.cpus} cores${g.singleCoreMs ? `; one core's fixed workload took ${g.singleCoreMs} ms, the reading that tells a slow day from a slow change` : ''}): **${minutes(g.totalSeconds)}** in all, ending ${g.passed} passed, ${g.failed} failed. Its budget is 12 minutes on an Intel Xeon machine of this kind and 15 on an AMD EPYC one ([DEVELOPERS.md](DEVELOPERS.md#the-gates-budget)); every run prints the same summary.`,
    '',
    ...table(
      ['stage', 'seconds'],
      'lr',
      g.stages.map((x) => [x.name, s(x.seconds)]),
    ),
    '',
    `Playwright: ${g.playwright.tests} tests, ${s(g.playwright.workerSeconds)} worker-seconds over ${s(g.playwright.wallSeconds)} s of wall time. Of them, ${s(g.playwright.setupSeconds)} were set-up outside the tests (\`beforeAll\` hooks such as the tarball apps' installs and builds, browser launches: a worker's time between two tests), and ${s(g.playwright.pageLoadSeconds)} loading pages (from \`goto\` until a harness page or the playground says it is ready). The browsers' GPU processes (SwiftShader: shader and pipeline compiles, draws, read-backs) spent ${s(g.playwright.gpuSeconds ?? 0)} s of CPU on the tests, their renderers (the pages' scripts) ${s(g.playwright.rendererSeconds ?? 0)} s, as the tests on \`tests/harness-helpers.ts\`' \`test\` record them (– for a spec whose tests are on Playwright's own). The spec files that took the most worker time:`,
    '',
    ...table(
      [
        'spec',
        'tests',
        'worker-seconds',
        'set-up outside tests',
        'page loads',
        'GPU process CPU',
        'renderer CPU',
      ],
      'lrrrrrr',
      g.slowestSpecs.map((x) => [
        `\`${x.file}\``,
        x.tests,
        s(x.seconds),
        s(x.setupSeconds),
        s(x.pageLoadSeconds),
        x.gpuSeconds === null ? '–' : s(x.gpuSeconds),
        x.rendererSeconds === null ? '–' : s(x.rendererSeconds),
      ]),
    ),
    '',
    'The tests nearest their timeout (a test stays under a quarter of it):',
    '',
    ...table(
      ['test', 'seconds', 'timeout', 'share'],
      'lrrr',
      g.slowestTests.map((t) => [
        `${t.project === 'swiftshader' ? '' : `[${t.project}] `}\`${t.test.replace(/\|/g, '\\|')}\``,
        t.seconds.toFixed(1),
        s(t.timeoutSeconds),
        `${(t.shareOfTimeout * 100).toFixed(0)} %`,
      ]),
    ),
  ];
}
