import {
  type Browser,
  type BrowserContext,
  test as base,
  type CDPSession,
  type Page,
} from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';

/** Loads timed in this worker: each load's id. */
let loads = 0;

/**
 * Records how long a page took to load (from `goto` until it said it was ready) as the test's `page-load`
 * annotation, "<ms> <id>", which `npm test`'s summary adds up per spec file (scripts/gateReport.mjs). A load in a
 * `beforeAll` hook is on every test of its group; the id has the summary count it once.
 */
export async function timedLoad(load: () => Promise<unknown>): Promise<void> {
  const t0 = performance.now();
  await load();
  const ms = Math.round(performance.now() - t0);
  base.info().annotations.push({ type: 'page-load', description: `${ms} ${process.pid}.${++loads}` });
}

/**
 * Opens a harness page (`/harness/?page=<name>`: tests/harness/main.ts) and waits until it says it is ready;
 * returns the page errors and console errors seen while the test runs (none are expected; the browser's favicon
 * 404 is not one).
 */
export async function openHarness(page: Page, name: string): Promise<string[]> {
  const problems: string[] = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('console', (m) => {
    if (m.type() === 'error' && !m.text().includes('favicon') && !m.text().includes('404'))
      problems.push(m.text());
  });
  await timedLoad(async () => {
    await page.goto(`/harness/?page=${name}`);
    await page.waitForFunction(() => document.body.dataset.ready === '1');
  });
  return problems;
}

/** A harness page and the page and console errors seen since the test that asked for it began. */
export interface SharedHarness {
  page: Page;
  problems: string[];
}

/**
 * The page one worker's tests take in turn, its context, the options it was made with, and whether the last test
 * left it in a state the next must not see.
 */
interface ReusedPage {
  key: string;
  context: BrowserContext;
  page: Page;
  dirty: boolean;
}

/**
 * Page and context methods whose effect outlives a navigation (init scripts, bindings, routes, headers,
 * permissions, timeouts, emulation, other pages): a test that calls one gets the page to itself, and the next
 * test a new context.
 */
const LASTING = {
  page: [
    'addInitScript',
    'exposeBinding',
    'exposeFunction',
    'route',
    'routeFromHAR',
    'routeWebSocket',
    'setExtraHTTPHeaders',
    'setDefaultTimeout',
    'setDefaultNavigationTimeout',
    'emulateMedia',
  ],
  context: [
    'addCookies',
    'addInitScript',
    'exposeBinding',
    'exposeFunction',
    'grantPermissions',
    'newCDPSession',
    'newPage',
    'route',
    'routeFromHAR',
    'routeWebSocket',
    'setDefaultTimeout',
    'setDefaultNavigationTimeout',
    'setExtraHTTPHeaders',
    'setGeolocation',
    'setHTTPCredentials',
    'setOffline',
  ],
} as const satisfies {
  page: readonly (keyof Page & string)[];
  context: readonly (keyof BrowserContext & string)[];
};

/** Makes `object`'s `methods` mark `reused` dirty when called, until the returned function restores them. */
function watch(object: object, methods: readonly string[], reused: { dirty: boolean }): () => void {
  const own = object as Record<string, unknown>;
  for (const name of methods) {
    const method = own[name] as (...args: unknown[]) => unknown;
    own[name] = (...args: unknown[]) => {
      reused.dirty = true;
      return method.apply(object, args);
    };
  }
  return () => {
    for (const name of methods) delete own[name];
  };
}

/**
 * Leaves the page as a new one would be for the next test: the keys and the mouse button up, listeners removed,
 * the origin's storage (local, session, IndexedDB, cookies, caches) cleared, at about:blank. Returns false when
 * that cannot be promised (a crashed page, or one that ended on another origin, whose session storage stays).
 */
async function resetPage(context: BrowserContext, page: Page, origin: string): Promise<boolean> {
  try {
    page.removeAllListeners();
    const url = page.url();
    if (url.startsWith(origin)) {
      await page.evaluate(() => {
        localStorage.clear();
        sessionStorage.clear();
      });
    } else if (url !== 'about:blank') return false;
    await page.goto('about:blank');
    for (const key of ['Alt', 'Control', 'Meta', 'Shift']) await page.keyboard.up(key);
    await page.mouse.up();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Storage.clearDataForOrigin', {
      origin,
      storageTypes: 'cookies,local_storage,indexeddb,service_workers,cache_storage,file_systems,websql',
    });
    await cdp.detach();
    return true;
  } catch {
    return false;
  }
}

/** CPU seconds of each of the browser's GPU and renderer processes so far, by process id. */
async function processSeconds(cdp: CDPSession): Promise<Map<number, { type: string; seconds: number }>> {
  const { processInfo } = (await cdp.send('SystemInfo.getProcessInfo')) as {
    processInfo: { type: string; id: number; cpuTime: number }[];
  };
  return new Map(processInfo.map((p) => [p.id, { type: p.type, seconds: p.cpuTime }]));
}

/**
 * Records the CPU time the worker's browser spent on the test as its `gpu-process` and `renderer` annotations
 * (milliseconds), which `npm test`'s summary adds up per spec file: the GPU process compiles the shaders and
 * pipelines, draws and reads back (SwiftShader); the renderers run the pages' scripts. One worker runs one test at
 * a time in its own browser, so the time is the test's; a renderer that exits during the test takes its time with
 * it.
 */
async function recordProcessTime(browser: Browser, cdp: CDPSession, run: () => Promise<void>) {
  const before = await processSeconds(cdp);
  await run();
  if (!browser.isConnected()) return;
  const spent = { GPU: 0, renderer: 0 };
  for (const [id, now] of await processSeconds(cdp)) {
    if (now.type !== 'GPU' && now.type !== 'renderer') continue;
    spent[now.type] += now.seconds - (before.get(id)?.seconds ?? 0);
  }
  for (const [type, key] of [
    ['gpu-process', 'GPU'],
    ['renderer', 'renderer'],
  ] as const)
    base.info().annotations.push({ type, description: String(Math.round(spent[key] * 1000)) });
}

/**
 * Playwright's test with a page reused across the tests one worker runs in a row, and `harness(name)`, and the
 * CPU time each test's browser processes spent recorded ({@link recordProcessTime}).
 *
 * `page`: each test gets the worker's page, reset to about:blank with its origin's storage cleared
 * ({@link resetPage}). Every test still opens its own document: nothing of one test's page reaches the next. A
 * test that changes more than its document ({@link LASTING}) or fails leaves it to be replaced by a new context.
 * A page load in the tab of the last one costs the browser less than one in a new context (no new renderer
 * process; the scripts' compiled code kept).
 *
 * `harness(name)`: the harness page shared by the tests one worker runs in a row, so that the page loads, its
 * renderers are made and SwiftShader compiles their programs and pipelines once rather than once per test.
 * Tests that count what a fresh page holds (programs, pipelines, console messages since load) or that break the
 * page (a lost device) open their own with {@link openHarness}.
 */
export const test = base.extend<
  { harness: (name: string) => Promise<SharedHarness>; processTime: undefined },
  {
    sharedHarnessSlot: { current?: SharedHarness & { key: string } };
    reusedPageSlot: { current?: ReusedPage };
    browserCdp: CDPSession;
  }
>({
  browserCdp: [async ({ browser }, use) => use(await browser.newBrowserCDPSession()), { scope: 'worker' }],
  processTime: [
    async ({ browser, browserCdp }, use) => recordProcessTime(browser, browserCdp, () => use(undefined)),
    { auto: true },
  ],
  reusedPageSlot: [
    async ({ browser }, use) => {
      const slot: { current?: ReusedPage } = {};
      await use(slot);
      if (browser.isConnected()) await slot.current?.context.close();
    },
    { scope: 'worker' },
  ],
  page: async (
    {
      browser,
      baseURL,
      viewport,
      deviceScaleFactor,
      colorScheme,
      hasTouch,
      isMobile,
      locale,
      reducedMotion,
      reusedPageSlot: slot,
    },
    use,
    testInfo,
  ) => {
    // Everything a context is made with but the viewport, which a page can change.
    const options = { baseURL, deviceScaleFactor, colorScheme, hasTouch, isMobile, locale, reducedMotion };
    const key = JSON.stringify(options);
    if (!slot.current || slot.current.key !== key || slot.current.dirty || slot.current.page.isClosed()) {
      // A new context's first page load is every later test's set-up too: it gets its own two minutes, as a
      // shared harness's does.
      testInfo.setTimeout(testInfo.timeout + 120_000);
      await slot.current?.context.close();
      const context = await browser.newContext({ ...options, viewport });
      slot.current = { key, context, page: await context.newPage(), dirty: false };
    }
    const reused = slot.current;
    const { page } = reused;
    const size = page.viewportSize();
    if (viewport && (size?.width !== viewport.width || size.height !== viewport.height)) {
      await page.setViewportSize(viewport);
    }
    const unwatch = [watch(page, LASTING.page, reused), watch(reused.context, LASTING.context, reused)];
    await use(page);
    for (const restore of unwatch) restore();
    if (testInfo.status !== testInfo.expectedStatus || page.isClosed()) reused.dirty = true;
    if (!reused.dirty)
      reused.dirty = !(await resetPage(reused.context, page, new URL(baseURL ?? 'http://127.0.0.1').origin));
  },
  // The context of the test's page (Playwright's own fixture would make another).
  context: async ({ page }, use) => {
    await use(page.context());
  },
  sharedHarnessSlot: [
    async ({ browser }, use) => {
      const slot: { current?: SharedHarness & { key: string } } = {};
      await use(slot);
      if (browser.isConnected()) await slot.current?.page.close();
    },
    { scope: 'worker' },
  ],
  harness: async ({ browser, baseURL, viewport, sharedHarnessSlot: slot }, use, testInfo) => {
    await use(async (name) => {
      const key = JSON.stringify([name, baseURL, viewport]);
      if (slot.current?.key !== key || slot.current.page.isClosed()) {
        // The page's load and first compiles are every later test's set-up too, not this test's own work: they
        // get their own two minutes.
        testInfo.setTimeout(testInfo.timeout + 120_000);
        await slot.current?.page.close();
        const page = await browser.newPage({ baseURL, viewport });
        slot.current = { key, page, problems: await openHarness(page, name) };
      }
      slot.current.problems.length = 0;
      return slot.current;
    });
  },
});

/**
 * {@link test} in Chromium launched with the kit's WebGPU flags (`shadelabUse({ webgpu: true })`). A spec that
 * takes this rather than calling `test.use` itself shares its workers with every other spec that does: Playwright
 * starts a new worker (and browser) for each set of fixtures, and a `test.use` in a file is a set of its own.
 */
export const webgpuTest = test.extend({
  launchOptions: [
    // biome-ignore lint/correctness/noEmptyPattern: Playwright reads a fixture's dependencies from its first parameter.
    async ({}, use) => use(shadelabUse({ webgpu: true }).launchOptions),
    { scope: 'worker' },
  ],
});
