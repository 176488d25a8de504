// The docs site (`npm run docs` builds it into docs/api/; npm test's docs stage builds it before Playwright runs)
// carries the playground (docs/api/playground/), and the concept page embeds its `?embed` view set to each
// concept (the iframes of docs/concepts.md): served from the site's own folder, each opens the playground's embed
// on the state its src names, with its control strip, and says nothing went wrong.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from '@playwright/test';
import { serveFolder } from '../scripts/serve.mjs';

const site = fileURLToPath(new URL('../docs/api', import.meta.url));
let served: Awaited<ReturnType<typeof serveFolder>> | undefined;

test.beforeAll(async () => {
  if (!existsSync(join(site, 'playground', 'index.html'))) {
    throw new Error(
      'docs/api/ has no playground: run `npm run docs` first (npm test builds the site before Playwright)',
    );
  }
  served = await serveFolder(site);
});
test.afterAll(() => served?.close());

test('the concept page embeds the playground’s ?embed view at each concept’s state, served with the site', async ({
  page,
}) => {
  test.setTimeout(90_000);
  const errors: string[] = [];
  // (The site's pages name no icon, so the browser asks the server's root for /favicon.ico: not the embeds'.)
  const theirs = (url: string) => !url.endsWith('/favicon.ico');
  page.on('console', (m) => {
    if (m.type() === 'error' && theirs(m.location().url)) errors.push(`${m.text()} ${m.location().url}`);
  });
  await page.goto(served?.url('documents/concepts.html') ?? '');
  const frames = page.locator('iframe.playground-embed');
  await expect(frames).toHaveCount(6);
  for (let i = 0; i < 6; i++) {
    const element = frames.nth(i);
    await element.scrollIntoViewIfNeeded();
    const src = (await element.getAttribute('src')) ?? '';
    expect(src).toMatch(/^\.\.\/playground\/index\.html\?embed#s=/);
    const asked = JSON.parse(new URLSearchParams(src.split('#')[1]).get('s') ?? 'null');
    const frame = page.frameLocator('iframe.playground-embed').nth(i);
    await expect(frame.getByTestId('embed-strip')).toBeVisible();
    await expect(frame.getByTestId('viewport')).toBeVisible();
    await expect(frame.getByRole('alert')).toHaveCount(0);
    // The state the embed shows (its "open in the playground" link) is the one the src asked for.
    const href = (await frame.getByTestId('embed-open').getAttribute('href')) ?? '';
    const shown = JSON.parse(new URLSearchParams(new URL(href).hash.slice(1)).get('s') ?? 'null');
    expect(shown, src).toMatchObject(asked);
    const strip = frame.getByTestId('embed-strip');
    await expect(strip.getByLabel('shading')).toHaveValue(shown.material.shading);
    await expect(strip.getByLabel('lighting')).toHaveValue(shown.material.lighting);
    await expect(strip.getByLabel('cel bands')).toHaveValue(String(shown.material.celBands));
  }
  expect(errors).toEqual([]);
});
