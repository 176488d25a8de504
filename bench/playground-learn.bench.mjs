// Issue 24's measurement (the playground teaches the lecture: the probe, term views, profile, attenuation plot,
// normal-matrix view, copy as code, the compiled shader view, ?embed): the playground as checked out against
// the playground before it, each built from its own commit's playground/ and packages/ (issue 24 changed both:
// the material's output and normalMatrix options, explainShade), with the node_modules as installed:
// - the bundle index.html loads at start (raw and gzip -9, as scripts/bundle-size.mjs counts it);
// - the first frame: navigation to the canvas's data-first-frame-ms, loads of the builds interleaved in rounds
//   (each round starting at the next build, so that load from other processes and the order hit them alike);
//   each ratio is the median of the per-round ratios.
// Two befores: BEFORE, the last commit before issue 24's first (93437a3, explainShade), and COMMITTED, the commit
// the playground's committed bundle and first-frame figures were measured at before issue 24 (issues 22, 23 and
// 25 changed the playground between the two: the glTF model, WebGPU mode, the adaptive tool).
// Target (issue 24): the first frame ≤ 1.10 × before; the first-load bytes within BUDGET_GZIP (also gated,
// with the lazy parts, by tests/playground-learn.spec.ts).
//
//   node bench/playground-learn.bench.mjs [--json PATH] [--rounds 15]
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { serveFolder } from '../scripts/serve.mjs';
import { arg, writeResults } from './lib/bench.mjs';
import { firstFrames } from './lib/browser.mjs';
import { indexBundle } from './lib/bundle.mjs';
import { PLAYGROUND_FIRST_LOAD_BUDGET_GZIP, PLAYGROUND_LAZY_PARTS } from './lib/playground-budget.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
/** The last commit before issue 24 began (its first commit, 93437a3, adds explainShade). */
const BEFORE = '93437a3^';
/** The commit of the playground-bundle.json and playground-first-frame.json committed before issue 24. */
const COMMITTED = '02e3ab6';
const rounds = Number(arg('--rounds', '25'));
/** Why the playground costs what it costs, printed under the table. */
const NOTE =
  "Issue 24 adds to the first load only the learning tools' toggles, the embed strip and the compiled-shader view (the GLSL view shows it on open; its off-screen compile runs after the first frame); the probe, the plots, the normal-matrix view, the code generators and the adaptive run load on first use (the second table). The first frame is mostly loading, parsing and running that JavaScript (the first shader compile starts a few tens of ms before the frame). Single loads vary widely on this shared two-core machine (every load is in the JSON): the per-round ratio compares loads made seconds apart, the medians of each column do not.";

const git = (/** @type {string[]} */ args) =>
  execFileSync('git', args, { cwd: root, encoding: 'utf8' }).trim();

/**
 * The playground and the packages at `commit`, from git, in a folder inside the repository (so that bare imports
 * resolve to its node_modules) beside links to the checked-out rest of the repository.
 */
function checkout(/** @type {string} */ commit) {
  const dir = mkdtempSync(join(root, '.playground-learn-'));
  execFileSync('sh', ['-c', `git archive ${commit} playground packages | tar -x -C "${dir}"`], { cwd: root });
  // The packages' own node_modules (workspace links, types) as installed.
  for (const pkg of readdirSync(join(root, 'packages'))) {
    const modules = join(root, 'packages', pkg, 'node_modules');
    if (existsSync(modules) && existsSync(join(dir, 'packages', pkg)))
      symlinkSync(modules, join(dir, 'packages', pkg, 'node_modules'));
  }
  for (const entry of readdirSync(root)) {
    if (
      entry === 'playground' ||
      entry === 'packages' ||
      entry === '.git' ||
      entry.startsWith('.playground-')
    )
      continue;
    symlinkSync(join(root, entry), join(dir, entry));
  }
  return dir;
}

/**
 * Builds the playground of `repo` (a checkout's folder, with a trailing separator) into a temporary folder: the
 * index bundle and where it was written. @shadelab/react, which the playground's Vite config leaves to
 * node_modules (the checked-out package's dist), is taken from the same commit's sources, as the other packages
 * are.
 */
async function buildPlayground(/** @type {string} */ repo) {
  const outDir = mkdtempSync(join(tmpdir(), 'shadelab-learn-'));
  const result = await build({
    configFile: join(repo, 'playground', 'vite.config.ts'),
    logLevel: 'warn',
    resolve: { alias: { '@shadelab/react': join(repo, 'packages', 'react', 'src', 'index.ts') } },
    build: { outDir, emptyOutDir: true },
  });
  return { outDir, bundle: indexBundle(result, repo), lazy: lazyParts(result, repo) };
}

/**
 * What each of PLAYGROUND_LAZY_PARTS loads on first use: its chunk and the chunks that chunk imports which
 * index.html does not load at start, raw and gzip -9 (null: the part is not a chunk of its own in this build).
 */
function lazyParts(/** @type {unknown} */ result, /** @type {string} */ repo) {
  /** @type {Map<string, import('vite').Rolldown.OutputChunk>} */
  const chunks = new Map();
  for (const output of /** @type {import('vite').Rolldown.RolldownOutput[]} */ (
    Array.isArray(result) ? result : [result]
  ))
    for (const o of output.output) if (o.type === 'chunk') chunks.set(o.fileName, o);
  const reach = (/** @type {string[]} */ from) => {
    const seen = new Set();
    const visit = (/** @type {string} */ f) => {
      if (seen.has(f) || !chunks.has(f)) return;
      seen.add(f);
      for (const i of chunks.get(f)?.imports ?? []) visit(i);
    };
    for (const f of from) visit(f);
    return seen;
  };
  const index = [...chunks.values()].find(
    (c) => c.isEntry && c.facadeModuleId?.endsWith('/playground/index.html'),
  );
  const atStart = reach(index ? [index.fileName] : []);
  return PLAYGROUND_LAZY_PARTS.map(({ module, label }) => {
    const chunk = [...chunks.values()].find((c) => c.facadeModuleId === join(repo, module));
    if (!chunk || atStart.has(chunk.fileName)) return { module, label, raw: null, gzip: null };
    let raw = 0;
    let gzip = 0;
    for (const f of reach([chunk.fileName])) {
      if (atStart.has(f)) continue;
      const code = Buffer.from(/** @type {import('vite').Rolldown.OutputChunk} */ (chunks.get(f)).code);
      raw += code.length;
      gzip += gzipSync(code, { level: 9 }).length;
    }
    return { module, label, raw, gzip };
  });
}

const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const builds = [
  { name: 'committed', commit: COMMITTED, dir: checkout(COMMITTED) },
  { name: 'before', commit: BEFORE, dir: checkout(BEFORE) },
  { name: 'after', commit: 'HEAD', dir: root },
];
try {
  const built = /** @type {Awaited<ReturnType<typeof buildPlayground>>[]} */ ([]);
  for (const b of builds) built.push(await buildPlayground(b.dir === root ? root : `${b.dir}/`));
  const servers = [];
  for (const b of built) servers.push(await serveFolder(b.outDir));
  let samples;
  try {
    samples = await firstFrames(
      servers.map((served) => served.url('')),
      rounds,
    );
  } finally {
    for (const served of servers) await served.close();
  }
  const after = builds.length - 1;
  const ratioTo = (/** @type {number} */ k) => ({
    bundleGzip: built[after].bundle.total.gzip / built[k].bundle.total.gzip,
    bundleRaw: built[after].bundle.total.raw / built[k].bundle.total.raw,
    firstFrame: median(samples[after].map((ms, i) => ms / samples[k][i])),
  });
  const entry = (/** @type {number} */ k) => ({
    commit: git(['rev-parse', '--short', builds[k].commit]),
    bundle: built[k].bundle.total,
    firstFrameMs: samples[k],
  });
  const results = {
    before: entry(1),
    committed: entry(0),
    after: entry(after),
    viewport: { width: 800, height: 600 },
    rounds,
    note: NOTE,
    budgetGzip: PLAYGROUND_FIRST_LOAD_BUDGET_GZIP,
    ratios: ratioTo(1),
    ratiosToCommitted: ratioTo(0),
    lazyParts: built[after].lazy,
  };
  console.log(JSON.stringify({ ratios: results.ratios, ratiosToCommitted: results.ratiosToCommitted }));
  console.log(JSON.stringify(results.lazyParts));
  for (const [k, b] of builds.entries())
    console.log(
      `${b.name} ${results[/** @type {'before'} */ (b.name)].commit}: median ${median(samples[k])} ms`,
    );
  writeResults(results);
  for (const b of built) rmSync(b.outDir, { recursive: true, force: true });
} finally {
  for (const b of builds) if (b.dir !== root) rmSync(b.dir, { recursive: true, force: true });
}
