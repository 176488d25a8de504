// The playground's adaptive shading tool (issue 25; playground/src/learn/adaptiveTool.tsx): in the instanced
// scene and a loaded glTF model, the toggle lets AdaptiveShading choose per object and instance; the measured
// error it shows (the adaptive picture against the same scene at Phong shading and full detail, read back) is
// within the budget (p99 ≤ budget, ≤ 0.5 % of the drawn pixels over), every object and instance is listed once
// in the choices, the heat map draws over the view, and turning it off gives back the exact picture it started
// from. Where it cannot run (compare view), it says why.
import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { open, picture, settle } from './playground-helpers';

/** Opens the tool's panel and turns adaptive on; waits for the measured error. */
async function turnOn(page: Page): Promise<void> {
  await page.getByRole('button', { name: 'adaptive shading' }).click();
  await page.getByTestId('adaptive-toggle').check();
  await expect(page.getByTestId('adaptive-error')).toContainText('p99', { timeout: 20_000 });
  await settle(page);
}

/** The measured error the panel shows: p99, max, % over, budget. */
async function measured(page: Page) {
  const text = (await page.getByTestId('adaptive-error').textContent()) ?? '';
  const m = /p99 (\d+), max (\d+), ([\d.]+) % over ([\d.]+)/.exec(text);
  if (!m) throw new Error(`no measured error in “${text}”`);
  return { p99: Number(m[1]), max: Number(m[2]), over: Number(m[3]) / 100, budget: Number(m[4]) };
}

/** The choices listed: { "phong full": 38, … }. */
async function choices(page: Page): Promise<Record<string, number>> {
  const items = await page.getByTestId('adaptive-choices').locator('li').allTextContents();
  return Object.fromEntries(
    items.map((t) => {
      const [key, n] = t.trim().split(/: (?=\d+$)/);
      return [key, Number(n)];
    }),
  );
}

const sum = (c: Record<string, number>) => Object.values(c).reduce((s, n) => s + n, 0);

/** Pixels of the heat map overlay that are drawn (alpha > 0). */
const heatPixels = (page: Page) =>
  page.getByTestId('adaptive-heatmap').evaluate((c: HTMLCanvasElement) => {
    const data = c.getContext('2d')?.getImageData(0, 0, c.width, c.height).data ?? new Uint8ClampedArray();
    let n = 0;
    for (let i = 3; i < data.length; i += 4) if (data[i] > 0) n++;
    return n;
  });

/**
 * How the heat map fits the objects drawn: of the canvas's object pixels (any channel more than 2 levels from
 * the background, the corner's colour), the share under the heat map; of the heat map's pixels, the share off
 * the objects.
 */
const heatFit = (page: Page) =>
  page.evaluate(() => {
    const view = document.querySelector<HTMLCanvasElement>('[data-testid=viewport]')!;
    const heat = document.querySelector<HTMLCanvasElement>('[data-testid=adaptive-heatmap]')!;
    const { width: w, height: h } = heat;
    const copy = document.createElement('canvas');
    copy.width = w;
    copy.height = h;
    const ctx = copy.getContext('2d')!;
    ctx.drawImage(view, 0, 0, w, h);
    const picture = ctx.getImageData(0, 0, w, h).data;
    const overlay = heat.getContext('2d')!.getImageData(0, 0, w, h).data;
    let objects = 0;
    let covered = 0;
    let heated = 0;
    let off = 0;
    for (let i = 0; i < picture.length; i += 4) {
      const object = [0, 1, 2].some((c) => Math.abs(picture[i + c] - picture[c]) > 2);
      const hot = overlay[i + 3] > 0;
      if (object) objects++;
      if (object && hot) covered++;
      if (hot) heated++;
      if (hot && !object) off++;
    }
    return { objects, covered: covered / objects, off: off / heated };
  });

test('instanced scene: within the budget at 8 and 64 levels, every instance listed, heat map drawn, off restores the picture', async ({
  page,
}) => {
  test.setTimeout(90_000);
  await open(page, { scene: 'instanced' });
  const before = await picture(page);
  await turnOn(page);
  expect(await page.getByTestId('adaptive-budget-value').textContent()).toBe('8');
  let m = await measured(page);
  test
    .info()
    .annotations.push({ type: 'budget 8', description: JSON.stringify({ m, c: await choices(page) }) });
  expect(m.budget).toBe(8);
  expect(m.p99).toBeLessThanOrEqual(8);
  expect(m.over).toBeLessThanOrEqual(0.005);
  // The scene's 40 instances, each once.
  expect(sum(await choices(page))).toBe(40);
  expect(await heatPixels(page)).toBeGreaterThan(1000);
  // The heat map lies on the spheres (each instance's exact outline under the perspective, off-axis too): it
  // covers their pixels and spills only its anti-aliased edge past them.
  const fit = await heatFit(page);
  test.info().annotations.push({ type: 'heat map fit', description: JSON.stringify(fit) });
  expect(fit.objects).toBeGreaterThan(5000);
  expect(fit.covered, JSON.stringify(fit)).toBeGreaterThan(0.995);
  expect(fit.off, JSON.stringify(fit)).toBeLessThan(0.08);
  // Both frame times measured, in the same cycle.
  await expect(page.getByTestId('adaptive-frame-on')).toContainText('ms');
  await expect(page.getByTestId('adaptive-frame-off')).toContainText('ms');
  // The largest budget: measured again, still within it.
  await page.getByTestId('adaptive-budget').fill('24');
  await expect(page.getByTestId('adaptive-budget-value')).toHaveText('64');
  await expect
    .poll(async () => (await measured(page).catch(() => null))?.budget, { timeout: 20_000 })
    .toBe(64);
  m = await measured(page);
  const c = await choices(page);
  test.info().annotations.push({ type: 'budget 64', description: JSON.stringify({ m, c }) });
  expect(m.p99).toBeLessThanOrEqual(64);
  expect(m.over).toBeLessThanOrEqual(0.005);
  expect(sum(c)).toBe(40);
  // Off: the objects are put back, and the picture is the one before, pixel for pixel.
  await page.getByTestId('adaptive-toggle').uncheck();
  await settle(page);
  expect(await picture(page)).toBe(before);
  await expect(page.getByTestId('adaptive-heatmap')).toHaveCount(0);
});

test('a loaded glTF model: its meshes listed, within the budget', async ({ page }) => {
  test.setTimeout(90_000);
  await open(page);
  const maker = await page.context().newPage();
  await maker.goto('/harness/?page=gltf-maker');
  await maker.waitForFunction(() => typeof window.makeModel === 'function');
  const bytes = Buffer.from(await maker.evaluate(() => window.makeModel('vertexColours')));
  await maker.close();
  await page.getByTestId('model-file').setInputFiles({
    name: 'ball.glb',
    mimeType: 'model/gltf-binary',
    buffer: bytes,
  });
  await expect(page.getByTestId('model-note')).toContainText('“ball.glb”', { timeout: 20_000 });
  await settle(page);
  await turnOn(page);
  const m = await measured(page);
  const c = await choices(page);
  test.info().annotations.push({ type: 'model', description: JSON.stringify({ m, c }) });
  expect(sum(c)).toBeGreaterThanOrEqual(1);
  expect(m.p99).toBeLessThanOrEqual(8);
  expect(m.over).toBeLessThanOrEqual(0.005);
  // Turning the view makes the error and the frame times stale: they are measured again for the new view.
  const stats = page.getByTestId('adaptive-stats');
  const count = Number(await stats.getAttribute('data-measurements'));
  await page.getByTestId('viewport').focus();
  await page.keyboard.press('l'); // the trackball turns the field
  await expect
    .poll(async () => Number(await stats.getAttribute('data-measurements')), { timeout: 20_000 })
    .toBeGreaterThan(count);
  await expect(page.getByTestId('adaptive-frame-off')).toContainText('ms');
  await expect(page.getByTestId('adaptive-error')).toContainText('p99');
});

test('in the compare view it says why it does not run, and changes nothing', async ({ page }) => {
  await open(page, { scene: 'instanced', view: 'compare' });
  const before = await picture(page);
  await page.getByRole('button', { name: 'adaptive shading' }).click();
  await page.getByTestId('adaptive-toggle').check();
  await expect(page.getByTestId('adaptive-unavailable')).toContainText('single view');
  await settle(page);
  expect(await picture(page)).toBe(before);
});

test('the trade-off page charts adaptive, fixed flat, fixed Gouraud and all-Phong from the adaptive bench', async ({
  page,
}) => {
  await page.goto('/tradeoff.html');
  const chart = page.getByTestId('adaptive-chart');
  await expect(chart).toBeVisible();
  // One point per variant and view: adaptive at two budgets, flat, Gouraud and all-Phong, in two views.
  await expect
    .poll(() => chart.locator('.recharts-scatter-symbol .recharts-symbols').count(), { timeout: 20_000 })
    .toBe(10);
  for (const kind of ['adaptive', 'flat', 'gouraud', 'phong']) {
    await expect(chart.locator('.recharts-legend-wrapper')).toContainText(`${kind} (published view)`);
  }
  await expect(chart.locator('.recharts-legend-wrapper')).toContainText('deeper view');
});
