// The browser side of the benchmarks: build the playground and the harness pages (tests/harness/ and
// bench/harness/, each at /harness/<name>.html) into one temporary folder, serve it on a free loopback port and
// launch the same Chromium, with the same flags, as the tests.
import { spawnSync } from 'node:child_process';
import { createReadStream, existsSync, mkdtempSync, rmSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { chromiumArgs, chromiumExecutable } from '../../scripts/browser.mjs';
import { recordBrowser } from './meta.mjs';

const root = fileURLToPath(new URL('../..', import.meta.url));

/** @type {Record<string, string>} */
const types = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.json': 'application/json',
};

/**
 * Build and serve the playground and the harness pages, and launch Chromium. Call `close()` when done.
 * @returns {Promise<{ url: (path: string) => string, browser: import('@playwright/test').Browser, close: () => Promise<void> }>}
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
    const build = spawnSync('npx', ['vite', 'build', ...args, '--outDir', outDir, '--logLevel', 'warn'], {
      cwd: root,
      stdio: 'inherit',
    });
    if (build.status !== 0) throw new Error(`vite build of ${what} failed (exit ${build.status})`);
  }

  const server = createServer((req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname)).replace(
      /^(\.\.[/\\])+/,
      '',
    );
    const file = join(outDir, path === '/' || path === '\\' ? 'index.html' : path);
    if (!file.startsWith(outDir) || !existsSync(file) || !statSync(file).isFile()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' });
    createReadStream(file).pipe(res);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(undefined)));
  const address = server.address();
  const port = typeof address === 'object' && address ? address.port : 0;

  const browser = await chromium.launch({
    executablePath: chromiumExecutable() ?? undefined,
    args: chromiumArgs,
  });
  recordBrowser(`Chromium ${browser.version()}`);
  return {
    url: (path) => `http://127.0.0.1:${port}/${path.replace(/^\//, '')}`,
    browser,
    async close() {
      await browser.close();
      server.close();
      rmSync(outDir, { recursive: true, force: true });
    },
  };
}
