// `node scripts/three-compat.mjs [vitest args…]`: the oldest three.js shadelab supports, checked.
// tools/three-compat pins it (three at runtime, @types/three for declarations; see its README). This script
// installs that folder when its node_modules is missing or older than its lockfile, type-checks the package
// sources against its @types/three, then runs the unit tests with `three` resolved to its three.
// The newest three is the repository's own (the normal `npm test`).
import { spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const compat = join(root, 'tools', 'three-compat');

/** @param {string} cmd @param {string[]} args @param {string} [cwd] @returns {number} exit code */
function run(cmd, args, cwd = root) {
  const r = spawnSync(cmd, args, { cwd, stdio: 'inherit' });
  if (r.error) throw r.error;
  return r.status ?? 1;
}

const lock = join(compat, 'package-lock.json');
const stamp = join(compat, 'node_modules', '.shadelab-lock-hash');
const hash = createHash('sha256').update(readFileSync(lock)).digest('hex');
if (!existsSync(stamp) || readFileSync(stamp, 'utf8') !== hash) {
  console.log('three-compat: installing tools/three-compat (npm ci)…');
  if (run('npm', ['ci', '--no-audit', '--no-fund', '--prefer-offline'], compat) !== 0) process.exit(1);
  writeFileSync(stamp, hash);
}

const version = (/** @type {string} */ name) =>
  JSON.parse(readFileSync(join(compat, 'node_modules', name, 'package.json'), 'utf8')).version;
console.log(`three-compat: three ${version('three')}, @types/three ${version('@types/three')}`);

const failed = [];
console.log('\n── type check of the package sources against the oldest supported @types/three ──');
if (run('npx', ['tsc', '-p', join('tools', 'three-compat', 'tsconfig.json')]) !== 0)
  failed.push('type check');
console.log('\n── unit tests against the oldest supported three ──');
const vitestArgs = ['vitest', 'run', '--config', join('tools', 'three-compat', 'vitest.config.ts')];
if (run('npx', [...vitestArgs, ...process.argv.slice(2)]) !== 0) failed.push('unit tests');

console.log(failed.length ? `\nthree-compat: failed: ${failed.join(', ')}` : '\nthree-compat: ok');
process.exit(failed.length ? 1 : 0);
