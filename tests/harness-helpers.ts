import { test as base, type Page } from '@playwright/test';

/**
 * Records how long a page took to load (from `goto` until it said it was ready) as the test's `page-load`
 * annotation, which `npm test`'s summary adds up per spec file (scripts/gateReport.mjs).
 */
export async function timedLoad(load: () => Promise<unknown>): Promise<void> {
  const t0 = performance.now();
  await load();
  base
    .info()
    .annotations.push({ type: 'page-load', description: String(Math.round(performance.now() - t0)) });
}

/**
 * Opens a harness page (`/harness/<name>.html`) and waits until it says it is ready; returns the page errors and
 * console errors seen while the test runs (none are expected; the browser's favicon 404 is not one).
 */
export async function openHarness(page: Page, name: string): Promise<string[]> {
  const problems: string[] = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('console', (m) => {
    if (m.type() === 'error' && !m.text().includes('favicon') && !m.text().includes('404'))
      problems.push(m.text());
  });
  await timedLoad(async () => {
    await page.goto(`/harness/${name}.html`);
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
 * Playwright's test with `harness(name)`: the harness page shared by the tests one worker runs in a row, so that
 * the page loads, its renderers are made and SwiftShader compiles their programs and pipelines once rather than
 * once per test. Tests that count what a fresh page holds (programs, pipelines, console messages since load) or
 * that break the page (a lost device) open their own with {@link openHarness}.
 */
export const test = base.extend<
  { harness: (name: string) => Promise<SharedHarness> },
  { sharedHarnessSlot: { current?: SharedHarness & { key: string } } }
>({
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
