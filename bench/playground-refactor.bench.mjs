// Issue 17's measurement: the playground before its refactor (BEFORE, the commit before issue 17's first: one
// table of fields, the viewer in parts, the layout, the scene in React) and as checked out, both built with the
// packages as checked out, so that only the playground's own change is measured:
// - the bundle index.html loads at start (raw and gzip -9, grouped as scripts/bundle-size.mjs groups it);
// - the first frame: navigation to the canvas's data-first-frame-ms, loads of the two builds interleaved in
//   rounds, each round starting with the other build (so that load from other processes and the order hit both
//   alike); the ratio is the median of the per-round ratios.
// Target (issue 17): after ≤ 1.10 × before for both, or the reason stated (NOTE, printed with the table).
//
//   node bench/playground-refactor.bench.mjs [--json PATH] [--rounds 15]
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { serveFolder } from '../scripts/serve.mjs';
import { arg, writeResults } from './lib/bench.mjs';
import { firstFrames } from './lib/browser.mjs';
import { indexBundle } from './lib/bundle.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
/** The last commit before issue 17 began (its first commit is 3fce741). */
const BEFORE = '3fce741^';
const rounds = Number(arg('--rounds', '15'));
/** Why the playground costs what it costs, printed under the table. */
const NOTE =
  "Both grow with React Three Fiber and its reconciler, which composing the scene with @shadelab/react (issue 17's request: the playground as the package's first user, its single view, compare view and picked scenes in JSX, R3F driving each frame) brings into what index.html loads: the bundle by that code, the first frame by the time to load, parse and run it and to mount the scene through it. The rest of issue 17's change (fields table, viewer parts, layout) is within a few per cent. Single loads vary by about ±15 % here (each load is in the JSON), so the first-frame ratio moves by a few per cent between runs.";

const git = (/** @type {string[]} */ args) =>
  execFileSync('git', args, { cwd: root, encoding: 'utf8' }).trim();

/**
 * The playground at BEFORE, from git, in a folder inside the repository (so that bare imports resolve to its
 * node_modules) beside links to the checked-out rest of the repository (its Vite config reads ../packages, its
 * pages ../bench/results).
 */
function beforeCheckout() {
  const dir = mkdtempSync(join(root, '.playground-before-'));
  execFileSync('sh', ['-c', `git archive ${BEFORE} playground | tar -x -C "${dir}"`], { cwd: root });
  // Its test pages left out, as issue 17 moved them out of the app: the two builds then differ by the app alone
  // (the bundler splits chunks by the pages that share them).
  rmSync(join(dir, 'playground', 'harness'), { recursive: true, force: true });
  mkdirSync(join(dir, 'playground', 'harness'));
  for (const entry of readdirSync(root)) {
    if (entry === 'playground' || entry === '.git' || entry.startsWith('.playground-before-')) continue;
    symlinkSync(join(root, entry), join(dir, entry));
  }
  return dir;
}

/** Builds `playground` (its folder) into a temporary folder: the index bundle and where it was written. */
async function buildPlayground(/** @type {string} */ playground) {
  const outDir = mkdtempSync(join(tmpdir(), 'shadelab-refactor-'));
  const result = await build({
    configFile: join(playground, 'vite.config.ts'),
    logLevel: 'warn',
    build: { outDir, emptyOutDir: true },
  });
  return { outDir, bundle: indexBundle(result, root) };
}

const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const beforeDir = beforeCheckout();
mkdirSync(join(root, 'bench', 'results'), { recursive: true });
try {
  const before = await buildPlayground(join(beforeDir, 'playground'));
  const after = await buildPlayground(join(root, 'playground'));
  const servers = [await serveFolder(before.outDir), await serveFolder(after.outDir)];
  let samples;
  try {
    samples = await firstFrames(
      servers.map((served) => served.url('')),
      rounds,
    );
  } finally {
    for (const served of servers) await served.close();
  }
  const ratios = samples[1].map((ms, i) => ms / samples[0][i]);
  const results = {
    before: {
      commit: git(['rev-parse', '--short', BEFORE]),
      bundle: before.bundle.total,
      firstFrameMs: samples[0],
    },
    after: {
      commit: git(['rev-parse', '--short', 'HEAD']),
      bundle: after.bundle.total,
      firstFrameMs: samples[1],
    },
    viewport: { width: 800, height: 600 },
    rounds,
    note: NOTE,
    ratios: {
      bundleGzip: after.bundle.total.gzip / before.bundle.total.gzip,
      bundleRaw: after.bundle.total.raw / before.bundle.total.raw,
      firstFrame: median(ratios),
    },
  };
  console.log(JSON.stringify(results.ratios));
  writeResults(results);
  rmSync(before.outDir, { recursive: true, force: true });
  rmSync(after.outDir, { recursive: true, force: true });
} finally {
  rmSync(beforeDir, { recursive: true, force: true });
}
