// A fresh app's node_modules, installed once from the packed tarballs and shared: by every spec and worker of a
// Playwright run that asks for the same tarballs and dependencies, and by later runs while they stay the same
// (the folder is named by a hash of the tarballs' bytes and the dependency list). A spec makes its own app folder
// and links its node_modules here, so no spec pays for a second `npm install` of the same app
// (tests/playground-copy-code.spec.ts and tests/pack.spec.ts's R3F app share one; pack.spec.ts's vanilla and Quick
// start apps another).
import { spawn } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

/** What every fresh app depends on, at the versions the repository itself uses (npm's cache usually has them). */
export const APP_DEPENDENCIES = {
  three: '^0.187.0',
  '@types/three': '^0.187.0',
  vite: '^8.3.8',
  // What most users have: our declarations must work with TypeScript 5, not only with the repo's TypeScript 7.
  typescript: '~5.9.3',
};

/** What a React Three Fiber app adds (with the tarball of @shadelab/react). */
export const R3F_DEPENDENCIES = {
  react: '^19.3.1',
  'react-dom': '^19.3.1',
  '@types/react': '^19.3.0',
  '@types/react-dom': '^19.3.0',
  '@react-three/fiber': '^9.4.0',
};

/** Where the shared installs live. */
export const INSTALLS = join(tmpdir(), 'shadelab-pack-apps');

/** An install not used for this long is removed by the next {@link installedApp} (ms). */
const STALE_MS = 24 * 3600 * 1000;
/**
 * Installs kept (the one in use included): a run of tests/pack.spec.ts uses three (the vanilla and Quick start
 * apps', the oldest three's, the R3F app's), so two runs' worth.
 */
const KEEP = 6;
/** A lock older than this is taken to be left by a killed run (ms). */
const LOCK_MS = 15 * 60 * 1000;

/**
 * Run a command; resolves with its output, rejects with the output when it fails.
 * @param {string} cmd @param {string[]} args @param {string} cwd @returns {Promise<string>}
 */
export function run(cmd, args, cwd) {
  return new Promise((resolve, reject) => {
    const child = spawn(cmd, args, { cwd, env: { ...process.env, CI: '1' } });
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
    });
    child.stderr.on('data', (d) => {
      out += d;
    });
    child.on('error', reject);
    child.on('close', (code) => {
      if (code === 0) resolve(out);
      else reject(new Error(`\`${cmd} ${args.join(' ')}\` in ${cwd} failed with exit code ${code}:\n${out}`));
    });
  });
}

/**
 * The folder holding `node_modules` for an app with `dependencies` (name → range) and the `tarballs`, installed
 * once (`npm install --prefer-offline`) and shared; the caller links its app's node_modules to
 * `<folder>/node_modules`. Two callers at once: one installs, the other waits for it.
 * @param {{ dependencies: Record<string, string>; tarballs: { name: string; tarball: string }[] }} spec
 * @returns {Promise<string>}
 */
export async function installedApp({ dependencies, tarballs }) {
  mkdirSync(INSTALLS, { recursive: true });
  // Keys sorted: the same dependencies in another order are the same install.
  const sorted = Object.fromEntries(Object.entries(dependencies).sort(([a], [b]) => a.localeCompare(b)));
  const hash = createHash('sha256').update(JSON.stringify(sorted));
  for (const { name, tarball } of [...tarballs].sort((a, b) => a.name.localeCompare(b.name))) {
    hash.update(name).update(readFileSync(tarball));
  }
  const dir = join(INSTALLS, hash.digest('hex').slice(0, 16));
  const done = join(dir, '.installed');
  const lock = `${dir}.lock`;
  for (;;) {
    if (existsSync(done)) {
      writeFileSync(done, new Date().toISOString()); // used now: not stale
      return dir;
    }
    try {
      mkdirSync(lock); // atomic: only one caller gets it
      break;
    } catch {
      const since = statSync(lock, { throwIfNoEntry: false })?.mtimeMs ?? Date.now();
      if (Date.now() - since > LOCK_MS) rmSync(lock, { recursive: true, force: true });
      await new Promise((resolve) => setTimeout(resolve, 1000));
    }
  }
  try {
    pruneStale(dir);
    if (existsSync(done)) return dir;
    rmSync(dir, { recursive: true, force: true });
    mkdirSync(join(dir, 'tarballs'), { recursive: true });
    /** @type {Record<string, string>} */
    const local = {};
    for (const { name, tarball } of tarballs) {
      const copy = join(dir, 'tarballs', `${name.replace('@', '').replace('/', '-')}.tgz`);
      writeFileSync(copy, readFileSync(tarball));
      local[name] = `file:./tarballs/${copy.split('/').at(-1)}`;
    }
    const pkg = {
      name: 'shadelab-shared-app',
      private: true,
      type: 'module',
      dependencies: { ...dependencies, ...local },
    };
    writeFileSync(join(dir, 'package.json'), `${JSON.stringify(pkg, null, 2)}\n`);
    await run('npm', ['install', '--no-audit', '--no-fund', '--prefer-offline', '--loglevel', 'error'], dir);
    writeFileSync(done, new Date().toISOString());
    return dir;
  } finally {
    rmSync(lock, { recursive: true, force: true });
  }
}

/**
 * Removes the installs not used for a day, and all but the {@link KEEP} most recently used (a package changed
 * between runs gives a new install): never `keep`, nor one being installed.
 * @param {string} keep
 */
function pruneStale(keep) {
  const installs = readdirSync(INSTALLS)
    .filter((name) => !name.endsWith('.lock'))
    .map((name) => join(INSTALLS, name))
    .filter((dir) => dir !== keep && !existsSync(`${dir}.lock`))
    .map((dir) => ({
      dir,
      used:
        statSync(join(dir, '.installed'), { throwIfNoEntry: false })?.mtimeMs ??
        statSync(dir, { throwIfNoEntry: false })?.mtimeMs ??
        0,
    }))
    .sort((a, b) => b.used - a.used);
  installs.forEach(({ dir, used }, i) => {
    if (i >= KEEP - 1 || Date.now() - used > STALE_MS) rmSync(dir, { recursive: true, force: true });
  });
}
