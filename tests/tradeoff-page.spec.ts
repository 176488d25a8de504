// The trade-off page: live heat map against the reference, the measured Pareto chart with the current
// choice marked, picking the cheapest option for a target, and the scene taken from the playground's URL state.
import { expect } from '@playwright/test';
import { chooseSphereDetail, silhouetteErrorScalePx } from '@shadelab/sphere/detail';
import { Matrix4, PerspectiveCamera } from 'three';
import { test } from './harness-helpers';

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

test.describe('at 1280×720', () => {
  test.use({ viewport: { width: 1280, height: 720 } });

  test('trade-off page: auto detail keeps the silhouette within 0.5 px as the eye moves, near the camera too', async ({
    page,
  }) => {
    await page.goto('/tradeoff.html');
    await expect(page.getByTestId('stats')).toBeVisible();
    // The measured stats of the last render: every field but the timing, so that a new render shows as a change.
    const stats = async () => {
      const text = async (id: string) => (await page.getByTestId(id).textContent()) ?? '';
      return `${await text('rmse')} ${await text('silhouette')} ${await page.locator('[data-testid=stats] dd').nth(3).textContent()}`;
    };
    await page.getByTestId('auto').check();
    // The page draws 640×360 (its canvas size at any window size): the expected detail is the library's choice
    // for that view (lecture scene: eye on +z at 3 × zoom, 90°, ellipsoid (2, 1, 2)), within the image error bound.
    const expected = (zoom: number) => {
      const camera = new PerspectiveCamera(90, 640 / 360, 0.1, 10);
      camera.position.set(0, 0, 3 * zoom);
      camera.updateMatrixWorld();
      const view = { camera, matrixWorld: new Matrix4().makeScale(2, 1, 2), viewportHeightPx: 360 };
      return chooseSphereDetail({ radiusPx: silhouetteErrorScalePx(view), maxErrorPx: 0.5, maxLevel: 7 });
    };
    // 0.8 and 0.9 are near (eye 2.4 and 2.7 from the centre, 0.4 and 0.7 from the surface), where the budget binds
    // hardest; each step changes the detail.
    for (const zoom of [0.8, 1.5, 3, 0.9]) {
      const before = await stats();
      const { base, level } = expected(zoom);
      await page.getByTestId('zoom').fill(String(zoom));
      // Wait for the new detail and for a render with it (the stats change), never reading the stale ones.
      await expect(page.getByTestId('base')).toHaveValue(base);
      await expect(page.getByTestId('level')).toHaveValue(String(level));
      await expect.poll(stats).not.toBe(before);
      const silhouette = Number.parseFloat((await page.getByTestId('silhouette').textContent()) ?? 'NaN');
      expect(silhouette, `zoom ${zoom}: ${base} ${level}`).toBeLessThanOrEqual(0.5);
    }
  });
});

test("trade-off page reads the playground's URL state", async ({ page }) => {
  const state = { material: { shading: 'gouraud' }, sphere: { base: 'octahedron', level: 3 } };
  await page.goto(`/tradeoff.html#s=${encodeURIComponent(JSON.stringify(state))}`);
  await expect(page.getByTestId('stats')).toBeVisible();
  await expect(page.getByTestId('shading')).toHaveValue('gouraud');
  await expect(page.getByTestId('base')).toHaveValue('octahedron');
  await expect(page.getByTestId('level')).toHaveValue('3');
});

test('trade-off page opened from another scene says it draws the lecture’s sphere; from the sphere it says nothing', async ({
  page,
}) => {
  await page.goto(`/tradeoff.html#s=${encodeURIComponent(JSON.stringify({ scene: 'instanced' }))}`);
  await expect(page.getByTestId('stats')).toBeVisible();
  await expect(page.getByTestId('other-scene')).toContainText('instanced scene');
  await expect(page.getByTestId('other-scene')).toContainText('draws the sphere');
  await page.goto(`/tradeoff.html#s=${encodeURIComponent(JSON.stringify({ scene: 'sphere' }))}`);
  await page.reload(); // a new hash alone does not reload the page
  await expect(page.getByTestId('stats')).toBeVisible();
  await expect(page.getByTestId('other-scene')).toHaveCount(0);
});

test('the charts: the axes are labelled over the range of the points, and each legend entry shows the marker its series draws', async ({
  page,
}) => {
  await page.goto('/tradeoff.html');
  await expect(page.locator('.recharts-scatter-symbol').first()).toBeVisible();
  const chart = page.locator('.recharts-wrapper').first();
  // Every dot lies between the first and the last labelled tick of each axis (on screen: x grows to the right,
  // y upwards).
  const ticks = async (axis: 'x' | 'y') =>
    chart
      .locator(`.recharts-${axis}Axis-tick-labels .recharts-cartesian-axis-tick-value`)
      .evaluateAll((nodes) =>
        nodes.map((n) => {
          const box = n.getBoundingClientRect();
          return { text: n.textContent ?? '', x: box.x + box.width / 2, y: box.y + box.height / 2 };
        }),
      );
  const dots = await chart.locator('.recharts-scatter-symbol').evaluateAll((nodes) =>
    nodes
      .map((n) => n.getBoundingClientRect())
      // The front's points draw nothing (its line joins them): no box.
      .filter((b) => b.width > 0 && b.height > 0)
      .map((b) => ({ x: b.x + b.width / 2, y: b.y + b.height / 2 })),
  );
  const x = await ticks('x');
  const y = await ticks('y');
  expect(x.length, JSON.stringify(x)).toBeGreaterThan(3);
  const left = Math.min(...x.map((t) => t.x));
  const right = Math.max(...x.map((t) => t.x));
  const top = Math.min(...y.map((t) => t.y));
  const bottom = Math.max(...y.map((t) => t.y));
  for (const d of dots) {
    expect(d.x, JSON.stringify({ d, x })).toBeGreaterThanOrEqual(left - 1);
    expect(d.x, JSON.stringify({ d, x })).toBeLessThanOrEqual(right + 1);
    expect(d.y, JSON.stringify({ d, y })).toBeGreaterThanOrEqual(top - 1);
    expect(d.y, JSON.stringify({ d, y })).toBeLessThanOrEqual(bottom + 1);
  }
  // The frame-time axis names times past the slowest measured option (the log axis once stopped at 23 ms).
  expect(Math.max(...x.map((t) => Number.parseFloat(t.text)))).toBeGreaterThan(23);

  // The legends: the star of the current option, and in the adaptive chart a circle for the published view's
  // series and a triangle for the deeper view's, the shapes the series draw.
  const legendIcon = (name: RegExp) =>
    page
      .locator('.recharts-legend-item')
      .filter({ hasText: name })
      .first()
      .locator('.recharts-symbols')
      .getAttribute('d');
  expect(await legendIcon(/current option/)).not.toBe(await legendIcon(/^flat$/));
  // The Pareto front's entry is its dashed line, drawn in the line's colour.
  await expect(
    page
      .locator('.recharts-legend-item')
      .filter({ hasText: /^Pareto front$/ })
      .first()
      .locator('line'),
  ).toHaveAttribute('stroke', '#ddd');
  const published = await legendIcon(/^adaptive \(published view\)$/);
  const deeper = await legendIcon(/^adaptive \(deeper view\)$/);
  expect(published).not.toBe(deeper);
});
