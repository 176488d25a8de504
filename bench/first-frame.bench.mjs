// Issue 35's measurement: the playground's first frame against the README's Quick start page, and the first
// probe, in one run on one browser.
// - The pages: the production builds (`vite build`) of the playground (playground/vite.config.ts: the packages
//   from their sources) on its default state, and of the README's Quick start block as tests/snippets.spec.ts
//   builds it (scripts/snippets.mjs' writeRunPages: the block verbatim as the page's main.ts, bundled against
//   the packages' built dist/, as a user's app; `npm run bench` builds them first).
// - The first frame, the same way in both (bench/lib/firstFrame.mjs' init script): from navigation start to the
//   animation frame after the page's first WebGL draw into its canvas. Each load in a fresh 800 × 600 page (its
//   own context: nothing cached); the pages interleaved in rounds, each round starting at the other page; the
//   first round a discarded warm-up. Reported: each page's median, and the median of the per-round ratios
//   playground / Quick start. Target (issue 35): ≤ 1.5.
// - The first probe: in each round's playground page, once it rests after its first frame, an Alt+click at the
//   canvas's centre (on the sphere), timed from the click's event time to the frame after the probe panel shows
//   its values.
// - Then (unless --no-profile) one more load of each page (and its probe) under Chromium's tracing, with V8's
//   sampling profiler, from builds split into chunks by origin (three, React, the packages, the app): where each
//   page's time goes (bench/lib/traceSummary.mjs). The timed rounds are never traced.
//
//   node bench/first-frame.bench.mjs [--json PATH] [--rounds 9] [--no-profile]
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { serveFolder } from '../scripts/serve.mjs';
import { collectBlocks, quickStartBlock, runPageName, writeRunPages } from '../scripts/snippets.mjs';
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { launchBrowser } from './lib/browser.mjs';
import {
  FIRST_FRAME_MARKS,
  firstFrameInit,
  PROBE_MARKS,
  pairedSummary,
  phaseMedians,
  probeTimer,
  readLoad,
  settleInPage,
} from './lib/firstFrame.mjs';
import { summarizeTrace } from './lib/traceSummary.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const rounds = Number(arg('--rounds', '9'));
const profile = !process.argv.includes('--no-profile');
const VIEWPORT = { width: 800, height: 600 };
/** How long the playground must rest after its first frame before the probe's click (ms). */
const QUIET_MS = 400;
/** Where the probe clicks: the canvas's centre, on the default sphere. */
const PROBE_AT = { fx: 0.5, fy: 0.5 };
const TARGET = 1.5;
const TIMEOUT = 180_000;

/**
 * The chunk a module goes to in the profile builds, so that a sample's script names where its code comes from.
 * @param {string} id
 */
function chunkGroup(id) {
  if (/node_modules\/three\//.test(id)) return 'three';
  if (/node_modules\/(react|react-dom|scheduler)\//.test(id)) return 'react';
  // React Three Fiber and what it alone brings (its reconciler among them).
  if (/node_modules\/(@react-three|react-reconciler|its-fine|suspend-react|react-use-measure)\//.test(id))
    return 'r3f';
  // leva and what it alone brings (zustand, shared with R3F, included).
  if (
    /node_modules\/(leva|@radix-ui|@stitches|@use-gesture|colord|dequal|merge-value|react-colorful|react-dropzone|v8n|zustand)\//.test(
      id,
    )
  )
    return 'leva';
  if (/node_modules\//.test(id)) return 'other-deps';
  if (/\/packages\//.test(id)) return 'shadelab';
  return undefined;
}
const splitChunks = { output: { manualChunks: chunkGroup } };

/** Builds the playground into a temporary folder (split into chunk groups for a profile). */
async function buildPlayground(/** @type {boolean} */ split) {
  const outDir = mkdtempSync(join(tmpdir(), 'shadelab-first-frame-playground-'));
  if (!split) {
    const result = spawnSync(
      'npx',
      ['vite', 'build', 'playground', '--outDir', outDir, '--emptyOutDir', '--logLevel', 'warn'],
      {
        cwd: root,
        stdio: 'inherit',
      },
    );
    if (result.status !== 0) throw new Error(`vite build of the playground failed (exit ${result.status})`);
    return outDir;
  }
  await build({
    configFile: join(root, 'playground', 'vite.config.ts'),
    logLevel: 'warn',
    build: { outDir, emptyOutDir: true, rollupOptions: splitChunks },
  });
  return outDir;
}

/**
 * Builds the README's Quick start page as tests/snippets.spec.ts builds its pages (its folder under reports/,
 * inside the repository, so that `three` and `@shadelab/*` resolve through the workspace's node_modules; the
 * options of tests/picture-helpers.ts' buildAndServePages). Returns the built folder and the page's path.
 */
async function buildQuickStart(/** @type {boolean} */ split) {
  const block = quickStartBlock(collectBlocks({ files: ['README.md'] }));
  mkdirSync(join(root, 'reports'), { recursive: true });
  const dir = mkdtempSync(join(root, 'reports', 'first-frame-'));
  const input = writeRunPages([block], join(dir, 'src'));
  await build({
    configFile: false,
    root: join(dir, 'src'),
    base: './',
    logLevel: 'warn',
    build: {
      outDir: join(dir, 'dist'),
      emptyOutDir: true,
      chunkSizeWarningLimit: 4096,
      rollupOptions: { input, ...(split ? splitChunks : {}) },
    },
  });
  return { dir, outDir: join(dir, 'dist'), path: `${runPageName(block)}/`, block };
}

/**
 * One load in a fresh page: the first-frame marks (and, for the playground, its own data-first-frame-ms and the
 * first probe). `trace`: run it under tracing and return the summaries too.
 * @param {import('@playwright/test').Browser} browser @param {string} url
 * @param {{ playground: boolean, trace?: boolean }} options @returns {Promise<Record<string, any>>}
 */
async function load(browser, url, { playground, trace = false }) {
  const page = await browser.newPage({ viewport: VIEWPORT });
  try {
    await page.addInitScript(firstFrameInit);
    if (trace)
      await browser.startTracing(undefined, {
        categories: [
          'devtools.timeline',
          'disabled-by-default-devtools.timeline',
          'v8',
          'v8.execute',
          'disabled-by-default-v8.cpu_profiler',
          'blink.user_timing',
          'gpu',
        ],
      });
    await page.goto(url);
    await page.waitForFunction(() => /** @type {any} */ (window).__firstFrame?.firstFrameMs != null, null, {
      timeout: TIMEOUT,
      polling: 50,
    });
    const record = await page.evaluate(readLoad);
    /** @type {Record<string, any>} */
    const result = { ...record };
    if (playground) {
      const canvas = page.getByTestId('viewport');
      await canvas.and(page.locator('[data-first-frame-ms]')).waitFor({ timeout: TIMEOUT });
      result.ownFirstFrameMs = Number(await canvas.getAttribute('data-first-frame-ms'));
      await page.evaluate(settleInPage, QUIET_MS);
      await page.evaluate(probeTimer);
      const box = await canvas.boundingBox();
      if (!box) throw new Error('the playground canvas has no box');
      await canvas.click({
        modifiers: ['Alt'],
        position: {
          x: Math.floor(box.width * PROBE_AT.fx) + 0.5,
          y: Math.floor(box.height * PROBE_AT.fy) + 0.5,
        },
      });
      await page.waitForFunction(() => /** @type {any} */ (window).__probe?.paintedMs != null, null, {
        timeout: TIMEOUT,
        polling: 50,
      });
      const probe = await page.evaluate(() => /** @type {any} */ (window).__probe);
      result.probeMs = probe.paintedMs - probe.clickMs;
      result.probeShownMs = probe.shownMs - probe.clickMs;
    }
    if (trace) {
      const buffer = await browser.stopTracing();
      const events = JSON.parse(buffer.toString('utf8')).traceEvents;
      result.trace = {
        firstFrame: summarizeTrace(events, FIRST_FRAME_MARKS),
        ...(playground ? { probe: summarizeTrace(events, PROBE_MARKS) } : {}),
      };
    }
    return result;
  } finally {
    await page.close();
  }
}

/**
 * One traced load of each page, from the builds split into chunk groups (the playground's with its probe).
 * @param {import('@playwright/test').Browser} browser
 */
async function traceLoads(browser) {
  const splitPlayground = await buildPlayground(true);
  const splitQuickStart = await buildQuickStart(true);
  const a = await serveFolder(splitPlayground);
  const b = await serveFolder(splitQuickStart.outDir);
  try {
    return {
      playground: (await load(browser, a.url(''), { playground: true, trace: true })).trace,
      quickStart: (await load(browser, b.url(splitQuickStart.path), { playground: false, trace: true }))
        .trace,
    };
  } finally {
    await a.close();
    await b.close();
    rmSync(splitPlayground, { recursive: true, force: true });
    rmSync(splitQuickStart.dir, { recursive: true, force: true });
  }
}

/** @param {number} x */
const round1 = (x) => Math.round(x * 10) / 10;

const playgroundDir = await buildPlayground(false);
const quickStart = await buildQuickStart(false);
const servedPlayground = await serveFolder(playgroundDir);
const servedQuickStart = await serveFolder(quickStart.outDir);
const pages = [
  { name: 'playground', url: servedPlayground.url(''), playground: true },
  { name: 'quickStart', url: servedQuickStart.url(quickStart.path), playground: false },
];
const browser = await launchBrowser();
/** @type {Record<string, any>[][]} */
const loads = pages.map(() => []);
/** @type {Record<string, any> | null} */
let profiled = null;
try {
  for (let round = -1; round < rounds; round++) {
    for (let j = 0; j < pages.length; j++) {
      const k = (j + Math.max(round, 0)) % pages.length;
      const record = await load(browser, pages[k].url, pages[k]);
      if (round >= 0) loads[k].push(record);
      console.log(
        `${round < 0 ? 'warm-up' : `round ${round + 1}`} ${pages[k].name}: first frame ${round1(record.firstFrameMs)} ms${record.probeMs ? `, probe ${round1(record.probeMs)} ms` : ''}`,
      );
    }
  }
  // The profile is extra: a failure to trace leaves the timed rounds' results as they are.
  if (profile)
    profiled = await traceLoads(browser).catch((error) => {
      console.error(`--profile failed: ${error instanceof Error ? error.stack : error}`);
      return null;
    });
} finally {
  await browser.close();
  await servedPlayground.close();
  await servedQuickStart.close();
  rmSync(playgroundDir, { recursive: true, force: true });
  rmSync(quickStart.dir, { recursive: true, force: true });
}

const [playground, quick] = loads;
const firstFrame = pairedSummary(
  playground.map((l) => l.firstFrameMs),
  quick.map((l) => l.firstFrameMs),
);
const probeMs = playground.map((l) => round1(l.probeMs));
const results = {
  viewport: VIEWPORT,
  rounds,
  target: TARGET,
  quickStart: `${quickStart.block.file}:${quickStart.block.line}`,
  note: "Both pages are timed the same way, by one init script (bench/lib/firstFrame.mjs): from navigation start to the animation frame after the page's first WebGL draw into its canvas; each load in a fresh page, the pages interleaved in rounds (the first round a discarded warm-up), the ratio the median of the per-round ratios. The phases are the medians of the same loads: the scripts' last response, DOMContentLoaded (after the module scripts ran), the first shader compile, the first draw, and the time the main thread waited inside WebGL calls for the GPU process before the first draw (SwiftShader compiles the shaders there). The probe: from the Alt+click's event time to the frame after the panel shows the probe's values, once the page rests after its first frame (what it loads on first use included).",
  firstFrame: {
    playground: { ...firstFrame.a, samplesMs: playground.map((l) => round1(l.firstFrameMs)) },
    quickStart: { ...firstFrame.b, samplesMs: quick.map((l) => round1(l.firstFrameMs)) },
    ratios: firstFrame.ratios.map((r) => Math.round(r * 1000) / 1000),
    ratio: firstFrame.ratio,
    met: firstFrame.ratio <= TARGET,
  },
  phases: {
    playground: phaseMedians(/** @type {any} */ (playground)),
    quickStart: phaseMedians(/** @type {any} */ (quick)),
  },
  playgroundOwnFirstFrameMs: playground.map((l) => l.ownFirstFrameMs),
  probe: {
    at: PROBE_AT,
    quietMs: QUIET_MS,
    ...summarize(probeMs),
    samplesMs: probeMs,
    shownMs: playground.map((l) => round1(l.probeShownMs)),
  },
  ...(profiled ? { profile: profiled } : {}),
};
console.log(
  `first frame: playground ${round1(firstFrame.a.median)} ms, Quick start ${round1(firstFrame.b.median)} ms, ratio ${firstFrame.ratio.toFixed(3)} (target ≤ ${TARGET}: ${results.firstFrame.met ? 'met' : 'not met'}); first probe ${round1(results.probe.median)} ms`,
);
if (profiled) console.log(JSON.stringify(profiled, null, 1));
writeResults(results);
