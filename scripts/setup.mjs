// Set-up steps shared by `npm start`, `npm test` and `npm run bench`. Plain Node, no dependencies:
// it runs before node_modules exists.
import { spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/**
 * Run a command in the repository root, inheriting stdio; returns the exit code.
 * @param {string} cmd @param {string[]} args @param {import('node:child_process').SpawnSyncOptions} [options]
 */
export function run(cmd, args, options = {}) {
  const result = spawnSync(cmd, args, { cwd: root, stdio: 'inherit', ...options });
  if (result.error) throw result.error;
  return result.status ?? 1;
}

/** @param {string} cmd @param {string[]} args */
function must(cmd, args) {
  const code = run(cmd, args);
  if (code !== 0) {
    console.error(`shadelab: \`${cmd} ${args.join(' ')}\` failed with exit code ${code}`);
    process.exit(code);
  }
}

/**
 * Install the node modules of `dir` (the repository root, or a separate tool project under tools/) when they
 * are missing or older than its package-lock.json.
 * @param {string} [dir]
 */
export function ensureDependencies(dir = root) {
  const lock = join(dir, 'package-lock.json');
  const stamp = join(dir, 'node_modules', '.shadelab-lock-hash');
  const hash = existsSync(lock) ? createHash('sha256').update(readFileSync(lock)).digest('hex') : 'none';
  if (existsSync(stamp) && readFileSync(stamp, 'utf8') === hash) return;
  console.log(`shadelab: installing node modules in ${relative(root, dir) || '.'} (npm ci)…`);
  const args = existsSync(lock)
    ? ['ci', '--no-audit', '--no-fund', '--prefer-offline']
    : ['install', '--no-audit', '--no-fund'];
  const code = run('npm', args, { cwd: dir });
  if (code !== 0) {
    console.error(`shadelab: npm ${args[0]} in ${dir} failed with exit code ${code}`);
    process.exit(code);
  }
  writeFileSync(stamp, hash);
}

/** Build every package (JS and declarations) with the native `tsc -b`. */
export function buildPackages() {
  must('npx', ['tsc', '-b']);
}

/**
 * Make sure a Chromium exists for Playwright: the one named by SHADELAB_CHROMIUM, Debian's
 * /usr/bin/chromium, or Playwright's own download. When none is found and apt-get is usable (as root),
 * install Debian's chromium. Exits with a message saying what was searched otherwise. Then the same for Xvfb,
 * the virtual X server of the second rasteriser (@shadelab/playwright's llvmpipe mode: the `llvmpipe` project
 * of playwright.config.ts and bench/rasterisers.bench.mjs): Debian's `xvfb`.
 */
export async function ensureBrowser() {
  const { lookupChromium, describeBrowserSearch } = await import('./browser.mjs');
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  const hasAptGet = existsSync('/usr/bin/apt-get');
  const failure =
    browserSetup({
      lookup: lookupChromium,
      describe: describeBrowserSearch,
      hasAptGet,
      isRoot,
      runCommand: run,
    }) ?? xvfbSetup({ hasXvfb: () => findOnPath('Xvfb') !== null, hasAptGet, isRoot, runCommand: run });
  if (failure !== undefined) {
    console.error(`shadelab: ${failure}`);
    process.exit(1);
  }
}

/** The first `name` on PATH, or null. @param {string} name */
function findOnPath(name) {
  for (const dir of (process.env.PATH ?? '').split(':')) {
    if (dir !== '' && existsSync(join(dir, name))) return join(dir, name);
  }
  return null;
}

/**
 * The decisions of {@link ensureBrowser} for Xvfb, as {@link browserSetup}'s for Chromium: with no `Xvfb` on
 * PATH, apt-get installs Debian's xvfb when run as root; without root, or without apt-get, or when apt-get
 * fails, the message says so.
 * @param {{ hasXvfb: () => boolean, hasAptGet: boolean, isRoot: boolean,
 *   runCommand: (cmd: string, args: string[]) => number, log?: (message: string) => void }} checks
 * @returns {string | undefined} the error message, or undefined when Xvfb is there.
 */
export function xvfbSetup({ hasXvfb, hasAptGet, isRoot, runCommand, log = console.log }) {
  if (hasXvfb()) return undefined;
  const why =
    "no Xvfb (the virtual X server of the llvmpipe rasteriser, which the tests' llvmpipe project and the rasterisers bench use)";
  if (!hasAptGet) return `${why}. Install xvfb with your package manager.`;
  if (!isRoot) {
    return `${why}, and installing Debian's xvfb with apt-get needs root: run \`sudo apt-get install xvfb\` (or npm test as root).`;
  }
  log('shadelab: no Xvfb found; installing Debian xvfb (apt-get)…');
  for (const args of [
    ['update', '-qq'],
    ['install', '-y', '-qq', 'xvfb'],
  ]) {
    const code = runCommand('apt-get', args);
    if (code !== 0) return `\`apt-get ${args.join(' ')}\` failed with exit code ${code}, so there is ${why}.`;
  }
  if (hasXvfb()) return undefined;
  return `apt-get installed xvfb, but there is still ${why} on PATH.`;
}

/**
 * The decisions of {@link ensureBrowser}, with every check and command passed in (tests fake them).
 * A SHADELAB_CHROMIUM naming a missing file fails at once (installing another browser would not help);
 * with no browser, apt-get installs Debian's chromium when run as root; without root, or without apt-get,
 * or when apt-get fails, the message says so and what was searched.
 * @param {{ lookup: () => import('./browser.mjs').ChromiumLookup,
 *   describe: (lookup: import('./browser.mjs').ChromiumLookup) => string, hasAptGet: boolean, isRoot: boolean,
 *   runCommand: (cmd: string, args: string[]) => number, log?: (message: string) => void }} checks
 * @returns {string | undefined} the error message, or undefined when a Chromium is there.
 */
export function browserSetup({ lookup, describe, hasAptGet, isRoot, runCommand, log = console.log }) {
  const first = lookup();
  if (first.problem) return first.problem;
  if (first.executable !== null) return undefined;
  if (!hasAptGet) return `no Chromium for Playwright. ${describe(first)}`;
  if (!isRoot) {
    return `no Chromium for Playwright, and installing Debian's chromium with apt-get needs root: run \`sudo apt-get install chromium\` (or npm test as root). ${describe(first)}`;
  }
  log('shadelab: no Chromium found; installing Debian chromium (apt-get)…');
  for (const args of [
    ['update', '-qq'],
    ['install', '-y', '-qq', 'chromium'],
  ]) {
    const code = runCommand('apt-get', args);
    if (code !== 0) {
      return `\`apt-get ${args.join(' ')}\` failed with exit code ${code}, so there is no Chromium for Playwright. ${describe(first)}`;
    }
  }
  const after = lookup();
  if (after.executable !== null) return undefined;
  return `apt-get installed chromium, but no Chromium was found afterwards. ${describe(after)}`;
}
