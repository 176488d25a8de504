// Shared benchmark helpers: warm-up, then the median, min and max of repeated runs.
import { writeJson } from './meta.mjs';

/**
 * Time `fn` (milliseconds): `warmup` untimed calls, then `runs` timed ones.
 * @param {() => unknown} fn
 * @param {{ warmup?: number, runs?: number }} [options]
 */
export function measure(fn, { warmup = 2, runs = 7 } = {}) {
  for (let i = 0; i < warmup; i++) fn();
  /** @type {number[]} */
  const times = [];
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    fn();
    times.push(performance.now() - t0);
  }
  return summarize(times);
}

/** @param {number[]} times */
export function summarize(times) {
  const sorted = [...times].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  const median = sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
  return { median, min: sorted[0], max: sorted[sorted.length - 1], runs: sorted.length };
}

/** Where `--json PATH` asks results to go, or undefined. */
export function jsonPath() {
  const i = process.argv.indexOf('--json');
  return i >= 0 ? process.argv[i + 1] : undefined;
}

/**
 * Write results as JSON to `--json PATH` when given, with the run's `meta` block (lib/meta.mjs: date, commit,
 * machine, load average, Node, Chromium and three versions). @param {unknown} results
 */
export function writeResults(results) {
  const path = jsonPath();
  if (!path) return;
  writeJson(path, results);
  console.log(`wrote ${path}`);
}

/** The value after `name` on the command line, or `fallback`. @param {string} name @param {string} fallback */
export function arg(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}
