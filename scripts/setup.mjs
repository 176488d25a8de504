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
 * /usr/bin/chromium, or Playwright's own download. When none is found and apt-get is usable,
 * install Debian's chromium.
 */
export async function ensureBrowser() {
  const { chromiumExecutable, describeBrowserSearch } = await import('./browser.mjs');
  if (chromiumExecutable() !== null) return;
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  if (existsSync('/usr/bin/apt-get') && isRoot) {
    console.log('shadelab: no Chromium found; installing Debian chromium (apt-get)…');
    must('apt-get', ['update', '-qq']);
    must('apt-get', ['install', '-y', '-qq', 'chromium']);
    if (chromiumExecutable() !== null) return;
  }
  console.error(`shadelab: no Chromium for Playwright. ${describeBrowserSearch()}`);
  process.exit(1);
}
