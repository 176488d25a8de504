// `npm run fuzz -- [--runs N] [--seed S] [--all] [--three-compat] [test files…]`: exploration, outside the gate.
// `npm test` runs every fast-check property from one fixed seed (test-utils/fastCheckSeed.ts); this script runs
// the fuzz suites (packages/*/src/fuzz.test.ts) N times (default 10), each time from a fresh random seed (or
// from S, S+1, … with --seed), and prints for every failure the suite, the test, the seed and fast-check's path
// of the counterexample, with the command that reproduces it. Exits 1 when anything failed.
//   --all           every unit-test file that uses fast-check, not only the fuzz suites (slower)
//   --three-compat  against the oldest supported three (tools/three-compat), as the second vitest stage does
//   test files      run only these files (paths as vitest takes them)
// DEVELOPERS.md ("Fuzzing") says how to turn a counterexample into a named regression test.
import { spawnSync } from 'node:child_process';
import { randomInt } from 'node:crypto';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative } from 'node:path';
import { ensureDependencies, root } from './setup.mjs';

const USAGE = 'usage: npm run fuzz -- [--runs N] [--seed S] [--all] [--three-compat] [test files…]';
const INT32 = 2 ** 31;

/** @param {string} message @returns {never} */
function fail(message) {
  console.error(`fuzz: ${message}\n${USAGE}`);
  process.exit(2);
}

/**
 * The command line, checked.
 * @param {string[]} argv
 * @returns {{ runs: number, seed: number | undefined, all: boolean, threeCompat: boolean, files: string[] }}
 */
function parseArguments(argv) {
  /** @type {{ runs: number | undefined, seed: number | undefined, all: boolean, threeCompat: boolean, files: string[] }} */
  const options = { runs: undefined, seed: undefined, all: false, threeCompat: false, files: [] };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (arg === '--runs' || arg === '--seed') {
      const value = argv[++i];
      const n = Number(value);
      if (value === undefined || !/^-?\d+$/.test(value)) fail(`${arg} needs an integer, got ${value}`);
      if (arg === '--runs') {
        if (!(n >= 1 && n <= 100_000)) fail(`--runs must be an integer from 1 to 100000, got ${value}`);
        options.runs = n;
      } else {
        if (!(n >= -INT32 && n < INT32))
          fail(`--seed must be an integer from ${-INT32} to ${INT32 - 1}, got ${value}`);
        options.seed = n;
      }
    } else if (arg === '--all') options.all = true;
    else if (arg === '--three-compat') options.threeCompat = true;
    else if (arg === '--help' || arg === '-h') {
      console.log(USAGE);
      process.exit(0);
    } else if (arg.startsWith('-')) fail(`unknown option ${arg}`);
    else options.files.push(arg);
  }
  // A given seed is a reproduction: one run unless --runs asks for more (then S, S+1, …).
  return { ...options, runs: options.runs ?? (options.seed === undefined ? 10 : 1) };
}

/** The unit-test files to run: the fuzz suites, or (--all) every test file that imports fast-check. */
function testFiles(/** @type {boolean} */ all) {
  const packages = join(root, 'packages');
  const fuzz = readdirSync(packages)
    .map((name) => join('packages', name, 'src', 'fuzz.test.ts'))
    .filter((file) => existsSync(join(root, file)));
  if (!all) return fuzz;
  /** @type {string[]} */
  const files = [];
  for (const dir of [
    ...readdirSync(packages).map((name) => join('packages', name, 'src')),
    'playground/src',
    'bench',
  ].filter((dir) => existsSync(join(root, dir)))) {
    for (const entry of readdirSync(join(root, dir), { recursive: true, withFileTypes: true })) {
      if (!entry.isFile() || !entry.name.endsWith('.test.ts')) continue;
      const file = relative(root, join(entry.parentPath ?? entry.path, entry.name));
      if (file.includes('node_modules')) continue;
      if (/from 'fast-check'/.test(readFileSync(join(root, file), 'utf8'))) files.push(file);
    }
  }
  return files.sort();
}

/**
 * The failures of one vitest JSON report: each failed test with fast-check's seed and path when its message
 * carries them (`{ seed: -318908392, path: "239:0:0", endOnFailure: true }`), and the counterexample line.
 * @param {any} report vitest's `--reporter=json` output
 */
function failuresOf(report) {
  /** @type {{ file: string, test: string, seed: number | undefined, path: string | undefined, counterexample: string | undefined, error: string }[]} */
  const failures = [];
  for (const suite of report.testResults ?? []) {
    const file = relative(root, suite.name);
    const failed = (suite.assertionResults ?? []).filter((/** @type {any} */ t) => t.status === 'failed');
    if (failed.length === 0 && suite.status === 'failed') {
      failures.push({
        file,
        test: '(the file itself)',
        seed: undefined,
        path: undefined,
        counterexample: undefined,
        error: firstLines(suite.message ?? '', 5),
      });
    }
    for (const test of failed) {
      const message = (test.failureMessages ?? []).join('\n');
      const found = /\{ seed: (-?\d+), path: "([^"]*)"/.exec(message);
      const counterexample = /^Counterexample: ([\s\S]*?)\n(?:Shrunk|Got|Hint|$)/m
        .exec(message)?.[1]
        .replace(/\s+/g, ' ');
      // fast-check's `Got <error>` line (includeErrorInReport, test-utils/fastCheckSeed.ts), else the message.
      const error = /^Got (.*)$/m.exec(message)?.[1] ?? firstLines(message, 3);
      failures.push({
        file,
        test: [...test.ancestorTitles, test.title].join(' › '),
        seed: found ? Number(found[1]) : undefined,
        path: found?.[2],
        counterexample:
          counterexample && counterexample.length > 400 ? `${counterexample.slice(0, 400)}…` : counterexample,
        error,
      });
    }
  }
  return failures;
}

/** The first `n` lines of an error message, without its stack. @param {string} text @param {number} n */
function firstLines(text, n) {
  return text
    .split('\n')
    .filter((line) => !/^\s+at /.test(line))
    .slice(0, n)
    .join('\n');
}

/** A test name as vitest's `-t` pattern (a regular expression) that matches it literally. */
const pattern = (/** @type {string} */ name) => name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** @param {string} text */
const shellQuote = (text) => `'${text.replaceAll("'", "'\\''")}'`;

function main() {
  const options = parseArguments(process.argv.slice(2));
  const files = options.files.length > 0 ? options.files : testFiles(options.all);
  const config = [];
  if (options.threeCompat) {
    ensureDependencies(join(root, 'tools', 'three-compat'));
    config.push('--config', join('tools', 'three-compat', 'vitest.config.ts'));
  }
  const dir = mkdtempSync(join(tmpdir(), 'shadelab-fuzz-'));
  const report = join(dir, 'report.json');
  console.log(
    `fuzz: ${options.runs} run(s) of ${files.length} file(s)${options.threeCompat ? ' against the oldest supported three' : ''}: ${files.join(', ')}`,
  );

  /** @type {ReturnType<typeof failuresOf>} */
  const all = [];
  let failedRuns = 0;
  for (let run = 0; run < options.runs; run++) {
    const seed =
      options.seed === undefined
        ? randomInt(-INT32, INT32)
        : ((options.seed + run + INT32) % 2 ** 32) - INT32;
    const started = Date.now();
    rmSync(report, { force: true });
    const result = spawnSync(
      'npx',
      ['vitest', 'run', ...config, '--reporter=json', `--outputFile=${report}`, ...files],
      {
        cwd: root,
        env: { ...process.env, SHADELAB_FUZZ_SEED: String(seed) },
        encoding: 'utf8',
        maxBuffer: 1 << 28,
      },
    );
    if (result.error) throw result.error;
    /** @type {any} */
    let parsed;
    try {
      parsed = JSON.parse(readFileSync(report, 'utf8'));
    } catch {
      parsed = undefined;
    }
    const failures = parsed ? failuresOf(parsed) : [];
    if (result.status !== 0 && failures.length === 0) {
      // vitest failed without a test failure (a crash, a bad file name): say so with its output.
      failures.push({
        file: '(vitest)',
        test: `exit code ${result.status}`,
        seed: undefined,
        path: undefined,
        counterexample: undefined,
        error: firstLines(`${result.stderr}\n${result.stdout}`.trim(), 20),
      });
    }
    const seconds = ((Date.now() - started) / 1000).toFixed(1);
    const tests = parsed?.numTotalTests ?? '?';
    console.log(
      `run ${run + 1}/${options.runs}, seed ${seed}: ${tests} tests, ${failures.length} failed (${seconds} s)`,
    );
    for (const f of failures) {
      console.log(`  ✗ ${f.file} › ${f.test}`);
      if (f.seed !== undefined) console.log(`    fast-check { seed: ${f.seed}, path: "${f.path}" }`);
      else console.log(`    run seed ${seed} (no fast-check seed in the message)`);
      if (f.counterexample) console.log(`    counterexample: ${f.counterexample}`);
      console.log(`    ${f.error.split('\n').join('\n    ')}`);
      const name = f.test.split(' › ').at(-1) ?? '';
      console.log(
        `    reproduce: SHADELAB_FUZZ_SEED=${f.seed ?? seed} npx vitest run ${config.join(' ')}${config.length ? ' ' : ''}${f.file} -t ${shellQuote(pattern(name))}`,
      );
    }
    if (failures.length > 0) failedRuns++;
    all.push(...failures);
  }
  rmSync(dir, { recursive: true, force: true });
  console.log(`\nfuzz: ${options.runs} runs, ${all.length} failures in ${failedRuns} runs`);
  process.exit(all.length > 0 ? 1 : 0);
}

main();
