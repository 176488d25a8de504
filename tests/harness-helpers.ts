import type { Page } from '@playwright/test';

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
  await page.goto(`/harness/${name}.html`);
  await page.waitForFunction(() => document.body.dataset.ready === '1');
  return problems;
}
