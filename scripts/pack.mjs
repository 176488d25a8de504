// `node scripts/pack.mjs [--out DIR] [--json PATH]`: build every package with `tsc -b`, then `npm pack` each one
// into DIR (a new temporary folder by default) and print what each tarball holds: packed and unpacked size and
// file count. The tests install the tarballs of the packages as `npm test` built them (`packBuilt`) into fresh
// apps.
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { basename, dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { writeJson } from '../bench/lib/meta.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/**
 * The published packages: every non-private workspace under packages/, in the root package.json's order
 * (dependencies first), as folder names.
 */
export const PACKAGES = /* @__PURE__ */ (() => {
  /** @type {{ workspaces: string[] }} */
  const rootPackage = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));
  return rootPackage.workspaces
    .filter((w) => w.startsWith('packages/'))
    .filter((w) => !JSON.parse(readFileSync(join(root, w, 'package.json'), 'utf8')).private)
    .map((w) => w.slice('packages/'.length));
})();

/**
 * @typedef {object} PackedPackage
 * @property {string} name package name, e.g. `@shadelab/camera`
 * @property {string} version
 * @property {string} tarball absolute path of the `.tgz`
 * @property {number} size packed size, bytes
 * @property {number} unpackedSize bytes
 * @property {number} entryCount files in the tarball
 * @property {string[]} files paths inside the package
 */

/**
 * Run a command in the repository root; throws with its output when it fails.
 * @param {string} cmd @param {string[]} args @returns {string} stdout
 */
function mustRun(cmd, args) {
  const r = spawnSync(cmd, args, { cwd: root, encoding: 'utf8', maxBuffer: 64 * 1024 * 1024 });
  if (r.error) throw r.error;
  if (r.status !== 0) {
    throw new Error(
      `\`${cmd} ${args.join(' ')}\` failed with exit code ${r.status}\n${r.stdout}\n${r.stderr}`,
    );
  }
  return r.stdout;
}

/**
 * Build the packages from scratch (`tsc -b` into emptied `dist/` folders) and `npm pack` each into `outDir`.
 * @param {string} [outDir] folder for the tarballs; a new one in the OS temp folder when omitted
 * @returns {PackedPackage[]}
 */
export function packPackages(outDir = mkdtempSync(join(tmpdir(), 'shadelab-pack-'))) {
  // A clean build: tsc -b never deletes the output of a source file that was removed or renamed, and npm
  // pack would ship it.
  for (const p of PACKAGES) rmSync(join(root, 'packages', p, 'dist'), { recursive: true, force: true });
  mustRun('npx', ['tsc', '-b', ...PACKAGES.map((p) => join('packages', p))]);
  return packBuilt(outDir);
}

/**
 * `npm pack` the packages `folders` (under packages/) as they are built now (their dist/, from `npx tsc -b`),
 * without building them: what the tests install (`npm test` builds first; nothing empties dist/ while they run).
 * Throws, naming them, when a source file of the package has no build.
 * @param {string} outDir folder for the tarballs
 * @param {readonly string[]} [folders] the packages, as folder names; every published one by default
 * @returns {PackedPackage[]}
 */
export function packBuilt(outDir, folders = PACKAGES) {
  mkdirSync(outDir, { recursive: true });
  return folders.map((p) => {
    // --ignore-scripts: packing must not depend on lifecycle scripts; the build is the only step.
    const out = mustRun('npm', [
      'pack',
      // A leading ./ so npm reads a folder, not a GitHub shorthand (`packages/sphere`).
      `./packages/${p}`,
      '--pack-destination',
      outDir,
      '--json',
      '--ignore-scripts',
      '--loglevel',
      'error',
    ]);
    const [info] = JSON.parse(out);
    /** @type {string[]} */
    const files = info.files.map((/** @type {{ path: string }} */ f) => f.path);
    const unbuilt = files
      .filter((f) => /^src\/[^/]+\.tsx?$/.test(f) && !/\.(test|d)\.tsx?$/.test(f))
      .map((f) => f.replace(/^src\/(.*)\.tsx?$/, 'dist/$1.js'))
      .filter((js) => !files.includes(js));
    if (unbuilt.length > 0) {
      throw new Error(
        `packages/${p} is not built (${unbuilt.slice(0, 3).join(', ')} missing): run \`npx tsc -b\``,
      );
    }
    return {
      name: info.name,
      version: info.version,
      tarball: join(outDir, info.filename),
      size: info.size,
      unpackedSize: info.unpackedSize,
      entryCount: info.entryCount,
      files,
    };
  });
}

/** @param {number} bytes */
const kB = (bytes) => `${(bytes / 1000).toFixed(1)} kB`;

/** @param {PackedPackage[]} packed @returns {string} a Markdown table */
export function packTable(packed) {
  const lines = [
    '| package | version | tarball (gzip) | unpacked | files |',
    '| --- | --- | ---: | ---: | ---: |',
    ...packed.map(
      (p) => `| \`${p.name}\` | ${p.version} | ${kB(p.size)} | ${kB(p.unpackedSize)} | ${p.entryCount} |`,
    ),
  ];
  return lines.join('\n');
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const arg = (/** @type {string} */ flag) => {
    const i = process.argv.indexOf(flag);
    return i >= 0 ? process.argv[i + 1] : undefined;
  };
  const outArg = arg('--out');
  const packed = packPackages(outArg ? resolve(outArg) : undefined);
  console.log(packTable(packed));
  console.log(`\ntarballs in ${dirname(packed[0].tarball)}`);
  const json = arg('--json');
  // With the run's meta block; the tarball's file name only (its folder is this machine's).
  if (json) {
    writeJson(resolve(json), { packages: packed.map((p) => ({ ...p, tarball: basename(p.tarball) })) });
  }
}
