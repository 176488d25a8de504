// What every results file in bench/results/ records about its run, and the one writer that puts it there:
// the benches (through writeResults in bench.mjs), scripts/size.mjs, scripts/bundle-size.mjs and
// scripts/pack.mjs all write through writeJson, so each file carries a `meta` block that BENCHMARKS.md shows
// (scripts/benchmarks.mjs renders it; a field that is missing there reads "not recorded").
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, freemem, loadavg, totalmem } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../..', import.meta.url));

/**
 * @typedef {object} RunMeta
 * @property {string | null} date ISO 8601, when the results were written
 * @property {string | null} commit the checkout's HEAD
 * @property {boolean | null} dirty whether tracked files in packages/, playground/, bench/ (results aside) or scripts/ had uncommitted changes
 * @property {{ cpus: number, cpuModel: string, memoryGiB: number, freeMemoryGiB: number, platform: string } | null} machine
 * @property {number[] | null} loadavg the 1, 5 and 15 minute load averages when the script started
 * @property {number[] | null} loadavgEnd the same when it wrote its results
 * @property {string | null} node `process.version`
 * @property {string | null} chromium the browser's version, or `'not used'` for a run without a browser
 * @property {string | null} three the installed three.js version
 * @property {string} [backfilled] for files written before meta existed: what was filled in afterwards, and from where
 */

/** The load average when this module was first imported: the start of the script that writes results. */
const loadAtStart = loadavg();
/** @type {string | null} */
let browserVersion = null;

/** Record the browser a run uses (bench/lib/browser.mjs calls it on launch). @param {string} version */
export function recordBrowser(version) {
  browserVersion = version;
}

/** @param {string[]} args @returns {string | null} */
function git(args) {
  try {
    return execFileSync('git', args, {
      cwd: root,
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'ignore'],
    }).trim();
  } catch {
    return null;
  }
}

/** @param {number[]} load */
const round2 = (load) => load.map((x) => Math.round(x * 100) / 100);
/** @param {number} bytes */
const gib = (bytes) => Math.round((bytes / 2 ** 30) * 10) / 10;

/** The meta block of a run that writes its results now. @returns {RunMeta} */
export function runMeta() {
  const status = git([
    'status',
    '--porcelain',
    '--untracked-files=no',
    '--',
    'packages',
    'playground',
    'bench',
    'scripts',
  ]);
  const changed =
    status === null
      ? null
      : status.split('\n').filter((line) => line.trim() !== '' && !line.slice(3).startsWith('bench/results/'))
          .length > 0;
  /** @type {string | null} */
  let three = null;
  try {
    three = JSON.parse(readFileSync(join(root, 'node_modules', 'three', 'package.json'), 'utf8')).version;
  } catch {
    three = null;
  }
  const cpuList = cpus();
  return {
    date: new Date().toISOString(),
    commit: git(['rev-parse', 'HEAD']),
    dirty: changed,
    machine: {
      cpus: cpuList.length,
      cpuModel: cpuList[0]?.model.trim() ?? 'unknown',
      memoryGiB: gib(totalmem()),
      freeMemoryGiB: gib(freemem()),
      platform: `${process.platform} ${process.arch}`,
    },
    loadavg: round2(loadAtStart),
    loadavgEnd: round2(loadavg()),
    node: process.version,
    chromium: browserVersion ?? 'not used',
    three,
  };
}

/**
 * Write `data` as JSON to `path` with this run's meta block first (`{ meta, ...data }`; an array goes under
 * `rows`). Creates the folder. @param {string} path @param {unknown} data
 */
export function writeJson(path, data) {
  const body = Array.isArray(data) ? { rows: data } : /** @type {Record<string, unknown>} */ (data);
  mkdirSync(dirname(path), { recursive: true });
  writeFileSync(path, `${JSON.stringify({ meta: runMeta(), ...body }, null, 2)}\n`);
}
