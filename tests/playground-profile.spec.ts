import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { choose, frames, open, picture, settle, urlRotation } from './playground-helpers';

// The learning plots over the canvas (playground/src/learn/): the Mach-band intensity profile and the attenuation
// curve. The profile's values are checked against the canvas itself: each shading's series, read while another
// shading was shown, must be the pixels the canvas shows once that shading is chosen. The attenuation curve is
// checked against the formula 1/max(a + b·t + c·t², 1e-6) (the materials' clamp) and its range against the
// distances from each light to the sphere's bounding sphere, computed here from the state.

/** The plots' view box (profileAxes.tsx's FRAME): x from 38 to 310, y from 150 (0) up to 8. */
const PLOT = { x0: 38, x1: 310, y0: 150, y1: 8 };
const luma = ([r, g, b]: number[]) => 0.2126 * r! + 0.7152 * g! + 0.0722 * b!;
const SHADINGS = ['flat', 'gouraud', 'phong'] as const;

/** Canvas pixels (`[x, y]`, y down from the top) read back from the WebGL canvas, RGB. */
function canvasPixels(page: Page, pixels: number[][]): Promise<number[][]> {
  return page.getByTestId('viewport').evaluate((canvas: HTMLCanvasElement, points) => {
    const gl = canvas.getContext('webgl2')!;
    const out = new Uint8Array(4);
    return points.map(([x, y]) => {
      gl.readPixels(x!, canvas.height - 1 - y!, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
      return [out[0]!, out[1]!, out[2]!];
    });
  }, pixels);
}

/** The plot's pixels along the line and each shading's luma series. */
async function readPlot(page: Page) {
  const plot = page.getByTestId('profile-plot');
  const pixels = ((await plot.getAttribute('data-pixels')) ?? '')
    .split(' ')
    .map((p) => p.split(',').map(Number));
  const series: Record<string, { values: number[]; points: number[][] }> = {};
  for (const shading of SHADINGS) {
    const line = plot.locator(`polyline[data-shading="${shading}"]`);
    series[shading] = {
      values: ((await line.getAttribute('data-values')) ?? '').split(' ').map(Number),
      points: ((await line.getAttribute('points')) ?? '').split(' ').map((p) => p.split(',').map(Number)),
    };
  }
  return { pixels, series };
}

/** Drags with the mouse between two points given as fractions of the canvas box; returns them in pixels. */
async function dragLine(page: Page, from: [number, number], to: [number, number]) {
  const box = (await page.getByTestId('viewport').boundingBox())!;
  const at = ([fx, fy]: [number, number]) => [box.x + box.width * fx, box.y + box.height * fy] as const;
  await page.mouse.move(...at(from));
  await page.mouse.down();
  await page.mouse.move(...at(to), { steps: 8 });
  await page.mouse.up();
  return [from, to].map(([fx, fy]) => [Math.floor(box.width * fx), Math.floor(box.height * fy)]);
}

test('the profile plot is the canvas’s pixels along the line, in flat, Gouraud and Phong shading', async ({
  page,
}) => {
  // A coarse sphere, so that the facets and the Gouraud triangles are many pixels wide.
  await open(page, { sphere: { level: 3 }, model: { scale: [1, 1, 1] }, camera: { eye: [0, 0, 2.2] } });
  const before = await picture(page);
  const rotation = await urlRotation(page);
  await page.getByRole('button', { name: 'intensity profile' }).click();
  await expect(page.getByTestId('profile-panel')).toContainText('Drag a line');
  const [start, end] = await dragLine(page, [0.15, 0.55], [0.85, 0.4]);
  await expect(page.getByTestId('profile-plot')).toBeVisible({ timeout: 15_000 });
  await settle(page);
  // Drawing the line turned nothing, and the three shadings' draws left the view as it was.
  expect(await urlRotation(page)).toEqual(rotation);
  expect(await picture(page)).toBe(before);

  const { pixels, series } = await readPlot(page);
  // The pixels run from the pixel under the press to the one under the release, one per step along x.
  expect(pixels[0]).toEqual(start);
  expect(pixels.at(-1)).toEqual(end);
  expect(pixels.length).toBe(Math.abs(end![0]! - start![0]!) + 1);
  // The series differ (the sphere is faceted in flat shading) and each polyline draws its values.
  expect(series['flat']!.values).not.toEqual(series['phong']!.values);
  for (const shading of SHADINGS) {
    const { values, points } = series[shading]!;
    expect(values).toHaveLength(pixels.length);
    points.forEach(([x, y], i) => {
      expect(x).toBeCloseTo(PLOT.x0 + ((PLOT.x1 - PLOT.x0) * i) / (pixels.length - 1), 1);
      expect(y).toBeCloseTo(PLOT.y0 + ((PLOT.y1 - PLOT.y0) * values[i]!) / 255, 1);
    });
  }
  // Flat and Gouraud's slope jumps are marked; the plot of Phong has none.
  expect(await page.locator('[data-testid="profile-plot"] [data-break]').count()).toBeGreaterThan(0);

  // Each series equals what the canvas shows when that shading is chosen (the plot then reads it again, the same).
  for (const shading of ['phong', 'flat', 'gouraud'] as const) {
    if (shading !== 'phong') await choose(page, 'Material.shading', shading);
    const shown = (await canvasPixels(page, pixels)).map(luma);
    for (const [i, v] of shown.entries()) {
      expect(Math.abs(v - series[shading]!.values[i]!), `${shading} at ${i}`).toBeLessThan(6e-4);
    }
    await expect
      .poll(async () => (await readPlot(page)).series[shading]!.values, { timeout: 15_000 })
      .toEqual(series[shading]!.values);
  }
});

test('the legend counts the slope jumps it marks, and says what a profile without one means', async ({
  page,
}) => {
  await open(page, { sphere: { level: 3 }, model: { scale: [1, 1, 1] }, camera: { eye: [0, 0, 2.2] } });
  await page.getByRole('button', { name: 'intensity profile' }).click();
  await expect(page.getByTestId('profile-panel')).toContainText('Drag a line');
  await dragLine(page, [0.15, 0.55], [0.85, 0.4]);
  const plot = page.getByTestId('profile-plot');
  await expect(plot).toBeVisible({ timeout: 15_000 });
  const legend = page.getByTestId('profile-panel');
  for (const shading of ['flat', 'gouraud'] as const) {
    const marks = await plot.locator(`g:has(> polyline[data-shading="${shading}"]) > [data-break]`).count();
    const label = shading === 'flat' ? 'flat' : 'Gouraud';
    // Gouraud's slope changes at its triangle edges by less than the flat facets' steps: often under the mark's
    // threshold in 8-bit codes, and then the legend says so instead of "0 slope jumps" under a text saying they
    // are there.
    if (marks > 0) await expect(legend).toContainText(`${label}: ${marks} slope jumps`);
    else
      await expect(legend).toContainText(
        `${label}: no slope jump of 3 or more per pixel² (its slope still changes at every triangle edge`,
      );
  }
  await expect(plot.locator('g:has(> polyline[data-shading="flat"]) > [data-break]')).not.toHaveCount(0);
  await expect(legend).not.toContainText(' 0 slope jumps');
});

test('a zero-length line does nothing; outside profile mode a drag turns the trackball', async ({ page }) => {
  await open(page, { sphere: { level: 3 } });
  const rotation = await urlRotation(page);
  const button = page.getByRole('button', { name: 'intensity profile' });
  await button.click();
  await expect(button).toHaveAttribute('aria-pressed', 'true');
  await expect(page.getByTestId('profile-overlay')).toBeVisible();
  await settle(page);
  const box = (await page.getByTestId('viewport').boundingBox())!;
  const [x, y] = [box.x + box.width * 0.5, box.y + box.height * 0.5];
  const count = await frames(page);
  const shown = await picture(page);
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.up();
  await page.mouse.move(x + 0.4, y + 0.3);
  await page.mouse.down();
  await page.mouse.up();
  await page.waitForTimeout(600);
  await expect(page.getByTestId('profile-plot')).toHaveCount(0);
  await expect(page.getByTestId('profile-panel')).toContainText('Drag a line');
  expect(await frames(page)).toBe(count);
  expect(await picture(page)).toBe(shown);
  expect(await urlRotation(page)).toEqual(rotation);

  // After a real profile, a click (zero length) keeps it as it was.
  await dragLine(page, [0.3, 0.5], [0.7, 0.5]);
  await expect(page.getByTestId('profile-plot')).toBeVisible({ timeout: 15_000 });
  await settle(page);
  const pixels = await page.getByTestId('profile-plot').getAttribute('data-pixels');
  const after = await frames(page);
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.up();
  await page.waitForTimeout(600);
  expect(await page.getByTestId('profile-plot').getAttribute('data-pixels')).toBe(pixels);
  expect(await frames(page)).toBe(after);

  // Esc, or the button again (the view's controls keep their clicks in profile mode), leaves the mode and gives
  // the drag back to the trackball.
  await page.keyboard.press('Escape');
  await expect(button).toHaveAttribute('aria-pressed', 'false');
  await expect(page.getByTestId('profile-overlay')).toHaveCount(0);
  await button.click();
  await expect(page.getByTestId('profile-overlay')).toBeVisible();
  await button.click();
  await expect(button).toHaveAttribute('aria-pressed', 'false');
  await expect(page.getByTestId('profile-overlay')).toHaveCount(0);
  await dragLine(page, [0.3, 0.5], [0.6, 0.45]);
  await settle(page);
  expect(await urlRotation(page)).not.toEqual(rotation);
});

test('the attenuation curve is 1/(a + b·t + c·t²) of each light, the object’s range of t from its bounding sphere', async ({
  page,
}) => {
  const light = (position: number[], attenuation: object) => ({ position, attenuation });
  const lights = [
    light([-5, 10, 20], { a: 1, b: 0.05, c: 0.002 }),
    light([3, -1, 2], { a: 0, b: 0.2, c: 0.3 }),
  ];
  const radius = 1.3;
  const scale = [0.5, 1.5, 1];
  await open(page, {
    lights,
    sphere: { radius },
    model: { scale },
    trackball: { rotation: [0.25881904510252074, 0, 0, 0.9659258262890683] },
  });
  await page.getByRole('button', { name: 'attenuation curve' }).click();
  const plot = page.getByTestId('attenuation-plot');
  await expect(plot).toBeVisible({ timeout: 15_000 });
  // The sphere's bounding sphere: its centre at the origin, its radius the largest scaled semi-axis.
  const bound = radius * Math.max(...scale);
  const [cx, cy, cz, r] = ((await plot.getAttribute('data-bounds')) ?? '').split(',').map(Number);
  for (const v of [cx, cy, cz]) expect(Math.abs(v!)).toBeLessThan(1e-9);
  expect(r).toBeCloseTo(bound, 9);
  const tMax = Number(await plot.getAttribute('data-t-max'));
  const yMax = Number(await plot.getAttribute('data-y-max'));
  const ranges: number[][] = [];
  for (const [i, l] of lights.entries()) {
    const group = plot.locator(`[data-light="${i + 1}"]`);
    const d = Math.hypot(...(l.position as [number, number, number]));
    const range = ((await group.locator('[data-range]').getAttribute('data-range')) ?? '')
      .split(',')
      .map(Number);
    expect(range[0]).toBeCloseTo(Math.max(0, d - bound), 9);
    expect(range[1]).toBeCloseTo(d + bound, 9);
    ranges.push(range);
    const { a, b, c } = l.attenuation as { a: number; b: number; c: number };
    const values = ((await group.locator('polyline[data-values]').getAttribute('data-values')) ?? '')
      .split(' ')
      .map((p) => p.split(',').map(Number));
    expect(values.length).toBeGreaterThan(50);
    expect(values[0]![0]).toBe(0);
    expect(values.at(-1)![0]).toBeCloseTo(tMax, 9);
    for (const [t, v] of values) expect(v).toBeCloseTo(1 / Math.max(a + b * t! + c * t! * t!, 1e-6), 12);
    // The thick range part starts and ends on the curve at the range's ends.
    const thick = ((await group.getByTestId('attenuation-range').getAttribute('points')) ?? '')
      .split(' ')
      .map((p) => p.split(',').map(Number));
    const sx = (t: number) => PLOT.x0 + ((PLOT.x1 - PLOT.x0) * t) / tMax;
    const sy = (v: number) => PLOT.y0 + ((PLOT.y1 - PLOT.y0) * v) / yMax;
    const f = (t: number) => 1 / Math.max(a + b * t + c * t * t, 1e-6);
    for (const [[x, y], t] of [
      [thick[0]!, range[0]!],
      [thick.at(-1)!, range[1]!],
    ] as const) {
      expect(x).toBeCloseTo(sx(t), 1);
      expect(y).toBeCloseTo(sy(f(t)), 1);
    }
  }
  // The plot spans the scene: 1.15 × the farthest distance from a light to the object.
  expect(tMax).toBeCloseTo(1.15 * Math.max(...ranges.map((r) => r[1]!)), 9);
  await expect(page.getByTestId('attenuation-light')).toHaveCount(2);
});
