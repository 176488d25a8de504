// `npm test`: every set-up step, then type check, lint, unit and end-to-end/visual tests.
// Runs every stage even when one fails, then prints one summary and exits non-zero on any failure. The summary
// says what the run cost (scripts/gateReport.mjs): the machine's CPU, each stage's time (the set-up's too: a fresh
// clone's npm ci, and Chromium and Xvfb where the machine has none), the spec files that took
// the most worker time and the tests nearest their timeouts; reports/gate.json holds it, and
// `npm test -- --record` also writes it to bench/results/gate.json, which BENCHMARKS.md renders.
// The unit stages run beside the documentation stages and Playwright (see `stages`), on cores they would leave idle.
import { execFileSync, spawn } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { recordBrowser, writeJson } from '../bench/lib/meta.mjs';
import { chromiumExecutable } from './browser.mjs';
import { gateLines, gateSummary, singleCoreMs } from './gateReport.mjs';
import { ensureBrowser, ensureDependencies, root } from './setup.mjs';

/** This machine's speed today, read before the run loads it. */
const coreMs = singleCoreMs();
const started = performance.now();
const seconds = (/** @type {number} */ t0) => (performance.now() - t0) / 1000;
/** @type {import('./gateReport.mjs').StageTime[]} each stage's wall time */
const times = [];
ensureDependencies();
times.push({ name: 'set-up: node modules (npm ci on a fresh clone)', seconds: seconds(started) });
const browserStarted = performance.now();
await ensureBrowser();
times.push({
  name: 'set-up: Chromium and Xvfb (installed once, on a machine without them)',
  seconds: seconds(browserStarted),
});
// Reports go to reports/: Playwright empties test-results/ (its output folder) when it starts.
rmSync(join(root, 'reports'), { recursive: true, force: true });
mkdirSync(join(root, 'reports'), { recursive: true });

/** Playwright's port, and so its build folder (playwright.config.ts). */
const E2E_PORT = Number(process.env.SHADELAB_E2E_PORT ?? 4173);
/** The build stage below made the pages: Playwright's web server serves them without building again. */
process.env.SHADELAB_E2E_BUILT = '1';

/** @typedef {[string, string, string[]]} Stage */
/**
 * A stage, or tracks run at once, each a chain of stages one after another. The unit and documentation stages use
 * about one core each and leave the other idle for part of their time, so Playwright (which keeps both busy)
 * starts beside the unit stages, after the stages it needs: the docs site (the link check reads it,
 * tests/docs-site.spec.ts serves it) and its own build. The first track prints as it goes; the others print each
 * stage's output when it ends.
 * @type {(Stage | Stage[][])[]}
 */
const stages = [
  ['type check (tsc -b, tests)', 'npx', ['tsc', '-b']],
  ['type check (tests, playground, bench)', 'npx', ['tsc', '-p', 'tsconfig.test.json']],
  ['code in the docs type-checks (snippets)', 'node', ['scripts/snippets.mjs', '--check']],
  ['lint (biome)', 'npx', ['biome', 'ci', '.']],
  [
    'BENCHMARKS.md rendered from bench/results (npm run benchmarks)',
    'node',
    ['scripts/benchmarks.mjs', '--check'],
  ],
  [
    'size budget (minified + gzipped, without three)',
    'node',
    ['scripts/size.mjs', '--json', 'reports/size.json'],
  ],
  [
    [
      ['API reference (TypeDoc, every export documented)', 'node', ['scripts/docs.mjs', '--check']],
      ['links in the Markdown and the docs site resolve', 'node', ['scripts/check-links.mjs']],
      [
        'build the playground and the harness pages for Playwright',
        'node',
        ['scripts/e2e-build.mjs', '--port', String(E2E_PORT)],
      ],
      ['end-to-end and visual (playwright)', 'npx', ['playwright', 'test']],
    ],
    [
      [
        'unit (vitest)',
        'npx',
        [
          'vitest',
          'run',
          '--reporter=./scripts/vitestReporter.mjs',
          '--reporter=json',
          '--outputFile.json=reports/vitest.json',
        ],
      ],
    ],
    [['unit (vitest) against the oldest supported three', 'node', ['scripts/three-compat.mjs']]],
  ],
];

/**
 * Run a stage with its output captured; resolves with its exit code and output.
 * @param {Stage} stage @returns {Promise<{ code: number, output: string }>}
 */
function capture([, cmd, args]) {
  return new Promise((resolve) => {
    const child = spawn(cmd, args, { cwd: root, stdio: ['ignore', 'pipe', 'pipe'] });
    /** @type {Buffer[]} */
    const chunks = [];
    child.stdout.on('data', (c) => chunks.push(c));
    child.stderr.on('data', (c) => chunks.push(c));
    child.on('error', (error) => chunks.push(Buffer.from(`${error}\n`)));
    child.on('close', (code) => resolve({ code: code ?? 1, output: Buffer.concat(chunks).toString() }));
  });
}

/**
 * Run a stage with its output shown as it comes; resolves with its exit code.
 * @param {Stage} stage @returns {Promise<number>}
 */
function live([, cmd, args]) {
  return new Promise((resolve) => {
    const child = spawn(cmd, args, { cwd: root, stdio: 'inherit' });
    child.on('error', () => resolve(1));
    child.on('close', (code) => resolve(code ?? 1));
  });
}

/** @type {string[]} the stages that failed */
const failed = [];
/**
 * Run one stage, showing its output as it comes (`shown`) or when it ends; records its time and any failure.
 * @param {Stage} stage @param {boolean} shown
 */
async function runStage(stage, shown) {
  const t0 = performance.now();
  let code;
  if (shown) {
    console.log(`\n── ${stage[0]} ──`);
    code = await live(stage);
  } else {
    const result = await capture(stage);
    console.log(`\n── ${stage[0]} ──`);
    process.stdout.write(result.output);
    code = result.code;
  }
  if (code !== 0) failed.push(stage[0]);
  times.push({ name: stage[0], seconds: seconds(t0) });
}

for (const step of stages) {
  if (typeof step[0] === 'string') {
    await runStage(/** @type {Stage} */ (step), true);
    continue;
  }
  const tracks = /** @type {Stage[][]} */ (step);
  const t0 = performance.now();
  await Promise.all(
    tracks.map(async (track, i) => {
      for (const stage of track) await runStage(stage, i === 0);
    }),
  );
  const names = tracks.map((track) => track.map(([name]) => name).join(', then '));
  times.push({ name: `in all, at once: ${names.join('; ')}`, seconds: seconds(t0) });
}

let passed = 0;
let failedTests = 0;
const vitest = join(root, 'reports', 'vitest.json');
if (existsSync(vitest)) {
  const r = JSON.parse(readFileSync(vitest, 'utf8'));
  passed += r.numPassedTests ?? 0;
  failedTests += r.numFailedTests ?? 0;
}
const pw = join(root, 'reports', 'playwright.json');
const report = existsSync(pw) ? JSON.parse(readFileSync(pw, 'utf8')) : undefined;
if (report) {
  const s = report.stats ?? {};
  passed += (s.expected ?? 0) + (s.flaky ?? 0);
  failedTests += s.unexpected ?? 0;
}
// A failed stage whose tests are not counted above (vitest against the oldest three, the type checks, lint, ...)
// counts as one failure: the summary line never says 0 failed, or fewer, when a stage failed.
const counted = new Set(['unit (vitest)', 'end-to-end and visual (playwright)']);
failedTests += failed.filter((name) => !counted.has(name)).length;
if (failed.length && failedTests === 0) failedTests = failed.length;
const gate = gateSummary({
  stages: times,
  totalSeconds: seconds(started),
  singleCoreMs: coreMs,
  report,
  passed,
  failed: failedTests,
});
console.log(`\n${gateLines(gate).join('\n')}\n`);
writeFileSync(join(root, 'reports', 'gate.json'), `${JSON.stringify(gate, null, 2)}\n`);
if (process.argv.includes('--record')) {
  const chromium = chromiumExecutable();
  if (chromium) recordBrowser(execFileSync(chromium, ['--version'], { encoding: 'utf8' }).trim());
  writeJson(join(root, 'bench', 'results', 'gate.json'), gate);
}
if (failed.length) console.log(`failed stages: ${failed.join('; ')}`);
console.log(`${passed} passed, ${failedTests} failed`);
process.exit(failed.length ? 1 : 0);
