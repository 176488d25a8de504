// Tests of the set-up scripts: which Chromium is used, what `npm test` says when there is none, that `npm start`
// serves the playground at the URL it prints (drawn in a page, with a quiet console), and that a signal stops it.
import { spawn, spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import { DEBIAN_CHROMIUM, describeBrowserSearch, lookupChromium } from '../scripts/browser.mjs';
import { browserSetup, root } from '../scripts/setup.mjs';
import { listening } from './net-helpers';
import { choose, settle } from './playground-helpers';

const PLAYWRIGHT_OWN = '/home/u/.cache/ms-playwright/chromium-1/chrome-linux/chrome';

/** lookupChromium with a fake file system: `present` files exist; records every path checked. */
function fakeLookup(
  env: Record<string, string | undefined>,
  present: string[],
  own: string | null = PLAYWRIGHT_OWN,
) {
  const checked: string[] = [];
  const result = lookupChromium({
    env,
    exists: (path: string) => {
      checked.push(path);
      return present.includes(path);
    },
    playwrightPath: () => own ?? undefined,
  });
  return { ...result, checked };
}

test.describe('chromiumExecutable lookup order', () => {
  test('1. SHADELAB_CHROMIUM when it names a file, before the others', () => {
    const r = fakeLookup({ SHADELAB_CHROMIUM: '/opt/chrome' }, [
      '/opt/chrome',
      DEBIAN_CHROMIUM,
      PLAYWRIGHT_OWN,
    ]);
    expect(r.executable).toBe('/opt/chrome');
    expect(r.source).toBe('SHADELAB_CHROMIUM');
    expect(r.checked).toEqual(['/opt/chrome']);
  });

  test('SHADELAB_CHROMIUM naming a missing file is an error naming the variable; nothing else is tried', () => {
    const r = fakeLookup({ SHADELAB_CHROMIUM: '/opt/missing' }, [DEBIAN_CHROMIUM, PLAYWRIGHT_OWN]);
    expect(r.executable).toBeNull();
    expect(r.problem).toContain('SHADELAB_CHROMIUM is set to /opt/missing, which does not exist');
    expect(r.checked).toEqual(['/opt/missing']);
  });

  test("2. Debian's /usr/bin/chromium when the variable is unset (or empty), before Playwright's own", () => {
    for (const env of [{}, { SHADELAB_CHROMIUM: '' }]) {
      const r = fakeLookup(env, [DEBIAN_CHROMIUM, PLAYWRIGHT_OWN]);
      expect(r.executable).toBe(DEBIAN_CHROMIUM);
      expect(r.source).toBe('debian');
      expect(r.checked).toEqual([DEBIAN_CHROMIUM]);
    }
  });

  test("3. Playwright's own browser (executable undefined: Playwright picks it) when it is installed", () => {
    const r = fakeLookup({}, [PLAYWRIGHT_OWN]);
    expect(r.executable).toBeUndefined();
    expect(r.source).toBe('playwright');
    expect(r.checked).toEqual([DEBIAN_CHROMIUM, PLAYWRIGHT_OWN]);
  });

  test('4. none: null, and the message lists everything searched', () => {
    for (const own of [PLAYWRIGHT_OWN, null]) {
      const r = fakeLookup({}, [], own);
      expect(r.executable).toBeNull();
      expect(r.source).toBe('none');
      const message = describeBrowserSearch(r);
      expect(message).toContain('$SHADELAB_CHROMIUM (not set)');
      expect(message).toContain(DEBIAN_CHROMIUM);
      expect(message).toContain(own ? `Playwright's own browser (${own})` : 'playwright-core not installed');
    }
  });
});

test.describe('npm test without a browser (browserSetup)', () => {
  const none = () => fakeLookup({}, []);
  const setup = (overrides: Partial<Parameters<typeof browserSetup>[0]>) => {
    const commands: string[] = [];
    const message = browserSetup({
      lookup: none,
      describe: describeBrowserSearch,
      hasAptGet: true,
      isRoot: true,
      runCommand: (cmd: string, args: string[]) => {
        commands.push([cmd, ...args].join(' '));
        return 0;
      },
      log: () => {},
      ...overrides,
    });
    return { message, commands };
  };

  test('a missing SHADELAB_CHROMIUM fails at once, without installing anything', () => {
    const { message, commands } = setup({ lookup: () => fakeLookup({ SHADELAB_CHROMIUM: '/x/chrome' }, []) });
    expect(message).toMatch(/^SHADELAB_CHROMIUM is set to \/x\/chrome, which does not exist/);
    expect(commands).toEqual([]);
  });

  test('a browser found: nothing to do', () => {
    const { message, commands } = setup({ lookup: () => fakeLookup({}, [DEBIAN_CHROMIUM]) });
    expect(message).toBeUndefined();
    expect(commands).toEqual([]);
  });

  test('apt-get but not root: says it needs root (sudo) and what was searched, installs nothing', () => {
    const { message, commands } = setup({ isRoot: false });
    expect(message).toContain('needs root');
    expect(message).toContain('sudo apt-get install chromium');
    expect(message).toContain(`Looked at $SHADELAB_CHROMIUM (not set), ${DEBIAN_CHROMIUM}`);
    expect(commands).toEqual([]);
  });

  test('no apt-get: what was searched and how to install one', () => {
    const { message, commands } = setup({ hasAptGet: false });
    expect(message).toMatch(/^no Chromium for Playwright\. Looked at .*npx playwright install chromium/);
    expect(commands).toEqual([]);
  });

  test('root with apt-get: installs chromium; when apt-get fails, the failing command and what was searched', () => {
    const ok = setup({});
    expect(ok.commands).toEqual(['apt-get update -qq', 'apt-get install -y -qq chromium']);
    expect(ok.message).toContain('no Chromium was found afterwards'); // the fake lookup still finds none
    let calls = 0;
    const installed = setup({ lookup: () => fakeLookup({}, calls++ === 0 ? [] : [DEBIAN_CHROMIUM]) });
    expect(installed.message).toBeUndefined();
    const failing = setup({
      runCommand: (_cmd: string, args: string[]) => (args[0] === 'install' ? 100 : 0),
    });
    expect(failing.message).toMatch(/^`apt-get install -y -qq chromium` failed with exit code 100/);
    expect(failing.message).toContain(`Looked at $SHADELAB_CHROMIUM (not set), ${DEBIAN_CHROMIUM}`);
  });

  test('the real ensureBrowser exits 1 at once naming SHADELAB_CHROMIUM when it names a missing file', () => {
    const result = spawnSync(
      process.execPath,
      ['--input-type=module', '-e', "import('./scripts/setup.mjs').then((m) => m.ensureBrowser())"],
      { cwd: root, env: { ...process.env, SHADELAB_CHROMIUM: '/nonexistent/chromium' }, encoding: 'utf8' },
    );
    expect(result.status).toBe(1);
    expect(result.stderr).toContain(
      'SHADELAB_CHROMIUM is set to /nonexistent/chromium, which does not exist',
    );
    expect(result.stdout).not.toContain('apt-get');
  });
});

/** A port nobody listens on now (the OS picks it). */
async function freePort(): Promise<number> {
  const server = createServer();
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const address = server.address();
  await new Promise((resolve) => server.close(resolve));
  if (address === null || typeof address === 'string') throw new Error('no port');
  return address.port;
}

/**
 * `npm start` on a free port, as `node scripts/start.mjs` (what npm runs) or through `npm start` itself, in a
 * process group of its own; resolves once Vite prints the URL it serves.
 */
async function startPlayground(via: 'node' | 'npm') {
  const port = await freePort();
  const args = ['--port', String(port)];
  const [command, commandArgs] =
    via === 'node' ? [process.execPath, ['scripts/start.mjs', ...args]] : ['npm', ['start', '--', ...args]];
  const child = spawn(command, commandArgs, {
    cwd: root,
    env: { ...process.env, CI: '1' },
    detached: true,
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let output = '';
  child.stdout.on('data', (d) => {
    output += d;
  });
  child.stderr.on('data', (d) => {
    output += d;
  });
  const exited = new Promise<void>((resolve) => child.once('exit', () => resolve()));
  const url = `http://127.0.0.1:${port}/`;
  // Vite prints the port in bold: compare without terminal colour codes.
  // biome-ignore lint/suspicious/noControlCharactersInRegex: ANSI escape sequences
  const plain = () => output.replace(/\u001b\[[0-9;]*m/g, '');
  /** Whatever still runs in the group is killed (after a failure; the tests stop it by a signal first). */
  const cleanUp = async () => {
    try {
      if (child.pid !== undefined) process.kill(-child.pid, 'SIGKILL');
    } catch {
      // The group is gone already.
    }
    if (child.exitCode === null && child.signalCode === null) await exited;
  };
  try {
    await expect.poll(plain, { timeout: 200_000, intervals: [500] }).toContain(url);
  } catch (error) {
    await cleanUp();
    throw error;
  }
  return { child, port, url, exited, cleanUp };
}

/** Send `signal` to the process alone (not its group, as `kill PID` does): the port is free within 2 s. */
async function expectStopsOn(started: Awaited<ReturnType<typeof startPlayground>>, signal: NodeJS.Signals) {
  expect(await listening(started.port)).toBe(true);
  started.child.kill(signal);
  await expect
    .poll(() => listening(started.port), {
      timeout: 2_000,
      intervals: [50],
      message: `the port still accepts connections 2 s after ${signal}`,
    })
    .toBe(false);
  await started.exited;
}

test.describe('npm start', () => {
  // One after another: each builds the packages (tsc -b) in the same tree.
  test.describe.configure({ mode: 'default', timeout: 240_000 });

  test('prints the 127.0.0.1 URL and serves the playground there, which draws with a quiet console (React in development, StrictMode); SIGTERM to its process frees the port within 2 s', async ({
    page,
  }) => {
    const started = await startPlayground('node');
    try {
      const response = await fetch(started.url);
      expect(response.status).toBe(200);
      const html = await response.text();
      const title = /<title>[^<]*<\/title>/.exec(
        readFileSync(join(root, 'playground', 'index.html'), 'utf8'),
      )![0];
      expect(html).toContain(title);
      expect(html).toContain('id="root"');
      // Development React mounts the app twice (StrictMode): the viewer takes its canvas's R3F root back, and
      // R3F's THREE.Clock deprecation is not printed. Warnings and errors: none, on the first frame and after a
      // scene change.
      const loud: string[] = [];
      page.on('console', (m) => {
        if (m.type() === 'warning' || m.type() === 'error') loud.push(`${m.type()}: ${m.text()}`);
      });
      page.on('pageerror', (e) => loud.push(`pageerror: ${e.message}`));
      const firstFrame = page.waitForEvent('console', {
        predicate: (m) => m.text().includes('first frame rendered'),
        timeout: 120_000,
      });
      await page.goto(started.url);
      await firstFrame;
      await choose(page, 'View.scene', "three's lights, fog, clipping");
      await expect(
        page.getByRole('img', { name: /^Lit scene: three's lights, fog, clipping\./ }),
      ).toBeVisible();
      await settle(page);
      expect(loud).toEqual([]);
      await expectStopsOn(started, 'SIGTERM');
    } finally {
      await started.cleanUp();
    }
  });

  test("SIGINT to its process (kill -INT PID, not the terminal's whole group) frees the port within 2 s", async () => {
    const started = await startPlayground('node');
    try {
      await expectStopsOn(started, 'SIGINT');
    } finally {
      await started.cleanUp();
    }
  });

  test('SIGTERM to the npm process itself (npm passes it to its shell only) frees the port within 2 s', async () => {
    const started = await startPlayground('npm');
    try {
      await expectStopsOn(started, 'SIGTERM');
    } finally {
      await started.cleanUp();
    }
  });
});
