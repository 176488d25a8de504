// Issue 17's measurement: the playground before its refactor (BEFORE, the commit before issue 17's first: one
// table of fields, the viewer in parts, the layout, the scene in React) and as checked out, both built with the
// packages as checked out, so that only the playground's own change is measured:
// - the bundle index.html loads at start (raw and gzip -9, grouped as scripts/bundle-size.mjs groups it);
// - the first frame: navigation to the canvas's data-first-frame-ms, loads of the two builds interleaved in
//   rounds (so that load from other processes hits both alike); the ratio is the median of the per-round ratios.
// Target (issue 17): after ≤ 1.10 × before for both, or the reason stated (NOTE, printed with the table).
//
//   node bench/playground-refactor.bench.mjs [--json PATH] [--rounds 15]
import { execFileSync } from 'node:child_process';
import {
  createReadStream,
  existsSync,
  mkdirSync,
  mkdtempSync,
  readdirSync,
  rmSync,
  statSync,
  symlinkSync,
} from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { build } from 'vite';
import { chromiumArgs, chromiumExecutable } from '../scripts/browser.mjs';
import { arg, writeResults } from './lib/bench.mjs';
import { indexBundle } from './lib/bundle.mjs';
import { recordBrowser } from './lib/meta.mjs';

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

/** @type {Record<string, string>} */
const types = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.json': 'application/json',
};

/** Serves `dir` on a free loopback port. */
async function serve(/** @type {string} */ dir) {
  const server = createServer((req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname)).replace(
      /^(\.\.[/\\])+/,
      '',
    );
    const file = join(dir, path === '/' || path === '\\' ? 'index.html' : path);
    if (!file.startsWith(dir) || !existsSync(file) || !statSync(file).isFile()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' });
    createReadStream(file).pipe(res);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(undefined)));
  const address = server.address();
  return { server, url: `http://127.0.0.1:${typeof address === 'object' && address ? address.port : 0}/` };
}

const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const beforeDir = beforeCheckout();
mkdirSync(join(root, 'bench', 'results'), { recursive: true });
try {
  const before = await buildPlayground(join(beforeDir, 'playground'));
  const after = await buildPlayground(join(root, 'playground'));
  const servers = [await serve(before.outDir), await serve(after.outDir)];
  const browser = await chromium.launch({
    executablePath: chromiumExecutable() ?? undefined,
    args: chromiumArgs,
  });
  recordBrowser(`Chromium ${browser.version()}`);
  /** @type {number[][]} */
  const samples = [[], []];
  try {
    // One warm-up load each (compiles the browser's caches for both alike), then the rounds.
    for (let round = -1; round < rounds; round++) {
      for (let k = 0; k < 2; k++) {
        const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
        await page.goto(servers[k].url);
        const canvas = page.getByTestId('viewport');
        await canvas.and(page.locator('[data-first-frame-ms]')).waitFor({ timeout: 60_000 });
        const ms = Number(await canvas.getAttribute('data-first-frame-ms'));
        await page.close();
        if (round >= 0) samples[k].push(ms);
      }
    }
  } finally {
    await browser.close();
    for (const { server } of servers) server.close();
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
