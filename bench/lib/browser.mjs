// The browser side of the benchmarks: the same Chromium, with the same flags, as the tests; the pages they open,
// built into a temporary folder and served on a free loopback port (scripts/serve.mjs); and the CPU time of the
// browser's processes.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { build } from 'vite';
import { chromiumArgs, chromiumExecutable } from '../../scripts/browser.mjs';
import { serveFolder } from '../../scripts/serve.mjs';
import { recordBrowser } from './meta.mjs';

const root = fileURLToPath(new URL('../..', import.meta.url));

/** Launch the tests' Chromium with their flags, and record its version in the run's meta. */
export async function launchBrowser() {
  const browser = await chromium.launch({
    executablePath: chromiumExecutable() ?? undefined,
    args: chromiumArgs,
  });
  recordBrowser(`Chromium ${browser.version()}`);
  return browser;
}

/**
 * @typedef {{ url: (path: string) => string, browser: import('@playwright/test').Browser, close: () => Promise<void> }} BenchPages
 */

/**
 * Serve `dir` (a temporary folder of built pages, removed by `close()`) and launch the browser.
 * @param {string} dir @returns {Promise<BenchPages>}
 */
async function serveAndLaunch(dir) {
  const served = await serveFolder(dir);
  const browser = await launchBrowser();
  return {
    url: served.url,
    browser,
    async close() {
      await browser.close();
      await served.close();
      rmSync(dir, { recursive: true, force: true });
    },
  };
}

/**
 * Build and serve the playground and the harness pages (tests/harness/'s at /harness/?page=<name>, bench/harness/'s
 * at /harness/<name>.html), and launch Chromium. Call `close()` when done.
 * @returns {Promise<BenchPages>}
 */
export async function openPlayground() {
  const outDir = mkdtempSync(join(tmpdir(), 'shadelab-bench-'));
  /** @type {[string, string[]][]} */
  const builds = [
    ['the playground', ['playground', '--emptyOutDir']],
    ['tests/harness', ['--config', 'tests/harness/vite.config.ts']],
    ['bench/harness', ['--config', 'bench/harness/vite.config.ts']],
  ];
  for (const [what, args] of builds) {
    const result = spawnSync('npx', ['vite', 'build', ...args, '--outDir', outDir, '--logLevel', 'warn'], {
      cwd: root,
      stdio: 'inherit',
    });
    if (result.status !== 0) throw new Error(`vite build of ${what} failed (exit ${result.status})`);
  }
  return serveAndLaunch(outDir);
}

/**
 * Build one bench page alone (bench/harness/<name>.html, at /harness/<name>.html, as bench/harness/vite.config.ts
 * builds the pages: from the packages' sources), serve it and launch Chromium. Call `close()` when done.
 * @param {string} name @returns {Promise<BenchPages>}
 */
export async function openBenchPage(name) {
  const outDir = mkdtempSync(join(tmpdir(), `shadelab-${name}-`));
  const packages = ['sphere', 'camera', 'trackball', 'material', 'reference'];
  await build({
    configFile: false,
    root: join(root, 'bench'),
    publicDir: false,
    logLevel: 'warn',
    resolve: {
      alias: Object.fromEntries(packages.map((p) => [`@shadelab/${p}`, join(root, 'packages', p, 'src')])),
      dedupe: ['three'],
    },
    build: {
      target: 'es2022',
      outDir,
      emptyOutDir: true,
      chunkSizeWarningLimit: 2000,
      rollupOptions: { input: { [`harness/${name}`]: join(root, `bench/harness/${name}.html`) } },
    },
  });
  return serveAndLaunch(outDir);
}

/** Clock ticks per second of /proc's CPU times (USER_HZ, 100 on Linux). */
const TICKS_PER_SECOND = 100;

/**
 * CPU seconds used so far by this process's descendants (the browser, its GPU process where SwiftShader draws, its
 * renderer): utime + stime of every live descendant, from /proc. What a frame costs in CPU time does not depend on
 * how much of the machine other work takes, where its wall time does.
 */
export function browserCpuSeconds() {
  /** @type {Map<number, number[]>} */
  const children = new Map();
  /** @type {Map<number, number>} */
  const ticks = new Map();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    let stat;
    try {
      stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
    } catch {
      continue; // ended meanwhile
    }
    const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    const pid = Number(entry);
    const parent = Number(fields[1]);
    children.set(parent, [...(children.get(parent) ?? []), pid]);
    ticks.set(pid, Number(fields[11]) + Number(fields[12]));
  }
  let total = 0;
  const stack = [...(children.get(process.pid) ?? [])];
  while (stack.length > 0) {
    const pid = /** @type {number} */ (stack.pop());
    total += ticks.get(pid) ?? 0;
    stack.push(...(children.get(pid) ?? []));
  }
  return total / TICKS_PER_SECOND;
}

/**
 * The playground's first frame (its canvas's `data-first-frame-ms`, ms) at each of `urls` (builds served side by
 * side), each load in a fresh 800 × 600 page: one untimed warm-up load of each, then `rounds` rounds, each starting
 * at the next build so that none always loads first. Returns each build's samples, in round order (sample i of
 * every build comes from round i).
 * @param {string[]} urls @param {number} rounds @returns {Promise<number[][]>}
 */
export async function firstFrames(urls, rounds) {
  const browser = await launchBrowser();
  /** @type {number[][]} */
  const samples = urls.map(() => []);
  try {
    for (let round = -1; round < rounds; round++) {
      for (let j = 0; j < urls.length; j++) {
        const k = (j + Math.max(round, 0)) % urls.length;
        const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
        await page.goto(urls[k]);
        const canvas = page.getByTestId('viewport');
        await canvas.and(page.locator('[data-first-frame-ms]')).waitFor({ timeout: 60_000 });
        const ms = Number(await canvas.getAttribute('data-first-frame-ms'));
        await page.close();
        if (round >= 0) samples[k].push(ms);
      }
    }
  } finally {
    await browser.close();
  }
  return samples;
}
