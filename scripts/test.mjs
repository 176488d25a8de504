// `npm test`: every set-up step, then type check, lint, unit and end-to-end/visual tests.
// Runs every stage even when one fails, then prints one summary and exits non-zero on any failure.
import { existsSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { ensureBrowser, ensureDependencies, root, run } from './setup.mjs';

ensureDependencies();
await ensureBrowser();
// Reports go to reports/: Playwright empties test-results/ (its output folder) when it starts.
rmSync(join(root, 'reports'), { recursive: true, force: true });
mkdirSync(join(root, 'reports'), { recursive: true });

/** @type {[string, string, string[]][]} */
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
  ['unit (vitest) against the oldest supported three', 'node', ['scripts/three-compat.mjs']],
  ['API reference (TypeDoc, every export documented)', 'node', ['scripts/docs.mjs', '--check']],
  ['links in the Markdown and the docs site resolve', 'node', ['scripts/check-links.mjs']],
  ['end-to-end and visual (playwright)', 'npx', ['playwright', 'test']],
];

const failed = [];
for (const [name, cmd, args] of stages) {
  console.log(`\n── ${name} ──`);
  if (run(cmd, args) !== 0) failed.push(name);
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
if (existsSync(pw)) {
  const s = JSON.parse(readFileSync(pw, 'utf8')).stats ?? {};
  passed += (s.expected ?? 0) + (s.flaky ?? 0);
  failedTests += s.unexpected ?? 0;
}
console.log('');
if (failed.length) console.log(`failed stages: ${failed.join('; ')}`);
if (failed.length && failedTests === 0) failedTests = failed.length;
console.log(`${passed} passed, ${failedTests} failed`);
process.exit(failed.length ? 1 : 0);
