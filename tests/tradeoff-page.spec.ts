// The trade-off page: live heat map against the reference, the measured Pareto chart with the current
// choice marked, picking the cheapest option for a target, and the scene taken from the playground's URL state.
import { expect, test } from '@playwright/test';

test('trade-off page: live error of the current option, chart, cheapest pick', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto('/tradeoff.html');
  await expect(page.getByTestId('stats')).toBeVisible();
  // The lecture default (phong, tetrahedron 6): measured live against the reference.
  const rmse = Number(await page.getByTestId('rmse').textContent());
  expect(rmse).toBeGreaterThan(0);
  expect(rmse).toBeLessThan(2);
  // The chart: one symbol per measured option plus the marked current choice.
  await expect(page.locator('.recharts-scatter-symbol').first()).toBeVisible();
  expect(await page.locator('.recharts-scatter-symbol').count()).toBeGreaterThan(60);
  // The impostor is exact: silhouette 0.00 px.
  await page.getByTestId('shading').selectOption('impostor');
  await expect(page.getByTestId('silhouette')).toHaveText('0.00 px');
  // A coarse mesh is not.
  await page.getByTestId('shading').selectOption('flat');
  await page.getByTestId('level').fill('1');
  await expect
    .poll(async () => Number.parseFloat((await page.getByTestId('silhouette').textContent()) ?? '0'))
    .toBeGreaterThan(5);
  // The cheapest option for the default targets is picked from the measurements.
  const label = (await page.getByTestId('cheapest').textContent()) ?? '';
  expect(label).toMatch(/^cheapest: /);
  await page.getByTestId('cheapest').click();
  const [shading] = label.replace('cheapest: ', '').split(' ');
  await expect(page.getByTestId('shading')).toHaveValue(shading);
  expect(errors).toEqual([]);
});

test('trade-off page: auto detail keeps the silhouette within 0.5 px as the eye moves', async ({ page }) => {
  await page.goto('/tradeoff.html');
  await expect(page.getByTestId('stats')).toBeVisible();
  await page.getByTestId('auto').check();
  for (const zoom of ['0.9', '1.5', '3']) {
    await page.getByTestId('zoom').fill(zoom);
    await expect
      .poll(async () => Number.parseFloat((await page.getByTestId('silhouette').textContent()) ?? 'NaN'))
      .toBeLessThanOrEqual(0.5);
  }
  // Farther away needs fewer triangles: the level or base dropped from the nearest view.
  const level = Number(await page.getByTestId('level').inputValue());
  expect(level).toBeLessThanOrEqual(4);
});

test("trade-off page reads the playground's URL state", async ({ page }) => {
  const state = { material: { shading: 'gouraud' }, sphere: { base: 'octahedron', level: 3 } };
  await page.goto(`/tradeoff.html#s=${encodeURIComponent(JSON.stringify(state))}`);
  await expect(page.getByTestId('stats')).toBeVisible();
  await expect(page.getByTestId('shading')).toHaveValue('gouraud');
  await expect(page.getByTestId('base')).toHaveValue('octahedron');
  await expect(page.getByTestId('level')).toHaveValue('3');
});
