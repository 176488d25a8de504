// The docs site (`npm run docs` builds it into docs/api/; npm test's docs stage builds it before Playwright runs)
// carries the playground (docs/api/playground/), and the concept page embeds its `?embed` view set to each
// concept (the iframes of docs/concepts.md): served from the site's own folder, each opens the playground's embed
// on the state its src names, with its control strip, and says nothing went wrong.
import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer, type Server } from 'node:http';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from '@playwright/test';

const site = fileURLToPath(new URL('../docs/api', import.meta.url));
const types: Record<string, string> = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.json': 'application/json',
};
let server: Server | undefined;
let origin = '';

test.beforeAll(async () => {
  if (!existsSync(join(site, 'playground', 'index.html'))) {
    throw new Error(
      'docs/api/ has no playground: run `npm run docs` first (npm test builds the site before Playwright)',
    );
  }
  server = createServer((req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname)).replace(
      /^(\.\.[/\\])+/,
      '',
    );
    let file = join(site, path);
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!file.startsWith(site) || !existsSync(file)) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' });
    createReadStream(file).pipe(res);
  });
  await new Promise<void>((resolve) => server?.listen(0, '127.0.0.1', resolve));
  const address = server.address();
  origin = `http://127.0.0.1:${typeof address === 'object' && address ? address.port : 0}`;
});
test.afterAll(() => server?.close());

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
  await page.goto(`${origin}/documents/concepts.html`);
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
