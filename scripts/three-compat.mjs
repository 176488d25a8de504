// `node scripts/three-compat.mjs [vitest args…]`: the oldest three.js shadelab supports, checked.
// tools/three-compat pins it (three at runtime, @types/three for declarations; see its README). This script
// installs that folder when its node_modules is missing or older than its lockfile, type-checks the package
// sources against its @types/three, then runs the unit tests with `three` resolved to its three.
// The newest three is the repository's own (the normal `npm test`).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { ensureDependencies, root, run } from './setup.mjs';

const compat = join(root, 'tools', 'three-compat');

ensureDependencies(compat);

const version = (/** @type {string} */ name) =>
  JSON.parse(readFileSync(join(compat, 'node_modules', name, 'package.json'), 'utf8')).version;
console.log(`three-compat: three ${version('three')}, @types/three ${version('@types/three')}`);

const failed = [];
console.log('\n── type check of the package sources against the oldest supported @types/three ──');
if (run('npx', ['tsc', '-p', join('tools', 'three-compat', 'tsconfig.json')]) !== 0)
  failed.push('type check');
console.log('\n── unit tests against the oldest supported three ──');
const vitestArgs = ['vitest', 'run', '--config', join('tools', 'three-compat', 'vitest.config.ts')];
// The same text on every run of the same code (scripts/vitestReporter.mjs), unless a reporter is given.
const args = process.argv.slice(2);
if (!args.some((a) => a.startsWith('--reporter'))) vitestArgs.push('--reporter=./scripts/vitestReporter.mjs');
if (run('npx', [...vitestArgs, ...args]) !== 0) failed.push('unit tests');

console.log(failed.length ? `\nthree-compat: failed: ${failed.join(', ')}` : '\nthree-compat: ok');
process.exit(failed.length ? 1 : 0);
