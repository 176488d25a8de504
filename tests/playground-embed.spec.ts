import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { settle, stateUrl, urlState } from './playground-helpers';

// Embed mode (`?embed`, playground/src/learn/embedStrip.tsx): the canvas and a control strip (shading, lighting,
// cel bands, a link to the full playground) and nothing else, at the two sizes slides and course pages use; the
// state from the URL, the strip's changes written back to it and never to this browser's saved state. Whole-page
// screenshots, exact as everywhere. Update the baselines after an intended change with:
//   SHADELAB_E2E_PORT=4204 CI=1 npx playwright test tests/playground-embed.spec.ts --update-snapshots

const SIZES = [
  [640, 480],
  [1280, 720],
] as const;
const STRIP = 32;

type Box = { x: number; y: number; width: number; height: number };
const overlap = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

const strip = (page: Page) => page.getByTestId('embed-strip');

async function openEmbed(page: Page, state?: object) {
  await page.goto(`/?embed${state ? stateUrl(state).slice(1) : ''}`);
  await settle(page);
}

for (const [width, height] of SIZES) {
  test(`${width} × ${height}: the canvas above, the strip below, nothing else`, async ({ page }) => {
    await page.setViewportSize({ width, height });
    await openEmbed(page, { material: { shading: 'gouraud', celBands: 3 } });
    const canvas = (await page.getByTestId('viewport').boundingBox())!;
    const stripBox = (await strip(page).boundingBox())!;
    expect(canvas).toEqual({ x: 0, y: 0, width, height: height - STRIP });
    expect(stripBox).toEqual({ x: 0, y: height - STRIP, width, height: STRIP });
    expect(overlap(canvas, stripBox)).toBe(false);
    // The drawing buffer is the canvas's size (pixel ratio 1).
    expect(
      await page.getByTestId('viewport').evaluate((c: HTMLCanvasElement) => [c.width, c.height]),
    ).toEqual([width, height - STRIP]);
    const scroll = await page.evaluate(() => {
      const s = document.scrollingElement!;
      return [s.scrollWidth - window.innerWidth, s.scrollHeight - window.innerHeight];
    });
    expect(scroll).toEqual([0, 0]);
    // Every control of the strip is inside the window, and they do not overlap.
    const controls = page.getByTestId('embed-strip').locator('select, a');
    await expect(controls).toHaveCount(4);
    const boxes: Box[] = [];
    for (const control of await controls.all()) {
      const b = (await control.boundingBox())!;
      expect(b.x).toBeGreaterThanOrEqual(0);
      expect(b.x + b.width).toBeLessThanOrEqual(width);
      expect(b.y).toBeGreaterThanOrEqual(height - STRIP);
      expect(b.y + b.height).toBeLessThanOrEqual(height);
      for (const other of boxes) expect(overlap(b, other)).toBe(false);
      boxes.push(b);
    }
    // The strip shows the URL state; the panel, the stats, the hint and the learning tools are hidden.
    await expect(strip(page).getByLabel('shading')).toHaveValue('gouraud');
    await expect(strip(page).getByLabel('lighting')).toHaveValue('blinn-phong');
    await expect(strip(page).getByLabel('cel bands')).toHaveValue('3');
    for (const hidden of ['.side', '.stats', '.hint']) await expect(page.locator(hidden)).toBeHidden();
    await expect(page.getByRole('button', { name: 'intensity profile' })).toHaveCount(0);
    await expect(page.getByRole('button', { name: 'attenuation curve' })).toHaveCount(0);
    await expect(page).toHaveScreenshot(`embed-${width}x${height}.png`);
  });
}

test('the strip edits the URL state, never the saved state; the link opens the same state in the playground', async ({
  page,
}) => {
  await page.goto('/');
  await settle(page);
  await page.evaluate(() => window.localStorage.setItem('shadelab.state', '{"material":{"shininess":7}}'));
  // The embed ignores the saved state: it opens on the lecture's scene.
  await openEmbed(page);
  expect(await urlState(page)).toMatchObject({ material: { shininess: 50, shading: 'phong' } });
  await strip(page).getByLabel('shading').selectOption('flat');
  await strip(page).getByLabel('lighting').selectOption('phong');
  await strip(page).getByLabel('cel bands').selectOption('4');
  await settle(page);
  const state = await urlState(page);
  expect(state).toMatchObject({ material: { shading: 'flat', lighting: 'phong', celBands: 4 } });
  expect(new URL(page.url()).search).toBe('?embed');
  expect(await page.evaluate(() => window.localStorage.getItem('shadelab.state'))).toBe(
    '{"material":{"shininess":7}}',
  );
  const href = (await page.getByTestId('embed-open').getAttribute('href'))!;
  expect(new URL(href).search).toBe('');
  expect(JSON.parse(new URLSearchParams(new URL(href).hash.slice(1)).get('s')!)).toEqual(state);
});

test('a ?embed value the parser does not know is refused with a message, and the full playground opens', async ({
  page,
}) => {
  await page.goto('/?embed=slides');
  await settle(page);
  await expect(page.getByTestId('notice')).toContainText(
    '?embed="slides" is not understood: use ?embed (or ?embed=1, ?embed=0)',
  );
  await expect(page.getByTestId('embed-strip')).toHaveCount(0);
  await expect(page.locator('.side')).toBeVisible();
});
