import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { HIDE_OVERLAYS, open, panelAtRest } from './playground-helpers';

// The playground's layout at the two common desktop sizes: canvas on the left, the side column (the Learn panel's
// button, the leva panel below it, the shader view at the bottom) on the right; nothing wider than the window, no part overlapping another, each
// at least the size below (measured from the layout: index.html's CSS gives the side column 340 px, 520 px from
// 1800 px up, and splits its height 55 : 45 between the panel and the shader view). Whole-page screenshots
// (maxDiffPixels 0 as everywhere) with the animated overlays (stats, hint) hidden. Update the baselines after an
// intended change with:
//   SHADELAB_E2E_PORT=4316 npx playwright test tests/playground-layout.spec.ts --update-snapshots

const SIZES = [
  { width: 1280, height: 800, canvas: [935, 800], lesson: [320, 24], panel: [340, 390], shader: [340, 320] },
  {
    width: 1920,
    height: 1080,
    canvas: [1395, 1080],
    lesson: [500, 24],
    panel: [520, 545],
    shader: [520, 450],
  },
] as const;

type Box = { x: number; y: number; width: number; height: number };

async function box(page: Page, selector: string): Promise<Box> {
  const found = await page.locator(selector).boundingBox();
  if (!found) throw new Error(`${selector} has no box`);
  return found;
}

const overlap = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

/** A folder's title in the panel and whether its content is open (leva shrinks a closed folder's wrapper to 0). */
const title = (page: Page, name: string) => page.locator('.panel').getByText(name, { exact: true });
const isOpen = (page: Page, name: string) =>
  title(page, name).evaluate((el) => (el.parentElement!.nextElementSibling as HTMLElement).offsetHeight > 0);

for (const size of SIZES) {
  test(`${size.width} × ${size.height}: canvas, panel and shader view fit side by side`, async ({ page }) => {
    await page.setViewportSize({ width: size.width, height: size.height });
    await open(page);
    const scroll = await page.evaluate(() => [document.scrollingElement!.scrollWidth, window.innerWidth]);
    expect(scroll[0]).toBeLessThanOrEqual(scroll[1]!);
    const boxes = {
      canvas: await box(page, '[data-testid="viewport"]'),
      lesson: await box(page, '[data-testid="lesson-open"]'),
      panel: await box(page, '.panel'),
      shader: await box(page, '.shader-view'),
    };
    for (const [name, b] of Object.entries(boxes)) {
      const [width, height] = size[name as keyof typeof boxes];
      expect(b.width, `${name} width`).toBeGreaterThanOrEqual(width);
      expect(b.height, `${name} height`).toBeGreaterThanOrEqual(height);
      expect(b.x + b.width, `${name} right edge`).toBeLessThanOrEqual(size.width);
      expect(b.y + b.height, `${name} bottom edge`).toBeLessThanOrEqual(size.height);
    }
    expect(overlap(boxes.canvas, boxes.lesson)).toBe(false);
    expect(overlap(boxes.lesson, boxes.panel)).toBe(false);
    expect(overlap(boxes.canvas, boxes.panel)).toBe(false);
    expect(overlap(boxes.canvas, boxes.shader)).toBe(false);
    expect(overlap(boxes.panel, boxes.shader)).toBe(false);

    // The GLSL wraps inside its box: nothing hidden sideways, even the longest line, which is wider than the box
    // unwrapped; the box scrolls down to every line.
    for (const stage of ['vertex', 'fragment']) {
      await page.getByRole('tab', { name: stage }).click();
      const text = page.getByLabel(`${stage} shader GLSL`);
      const fit = await text.evaluate((area: HTMLTextAreaElement) => {
        const longest = area.value.split('\n').reduce((a, b) => (b.length > a.length ? b : a), '');
        const probe = document.createElement('span');
        probe.style.cssText = `font: ${getComputedStyle(area).font}; white-space: pre; position: absolute;`;
        probe.textContent = longest;
        document.body.append(probe);
        const unwrapped = probe.getBoundingClientRect().width;
        probe.remove();
        area.scrollTop = area.scrollHeight;
        return {
          unwrapped,
          inner: area.clientWidth,
          scrollWidth: area.scrollWidth,
          bottom: area.scrollTop + area.clientHeight >= area.scrollHeight - 1,
        };
      });
      expect(fit.unwrapped, 'the longest line is wider than the box').toBeGreaterThan(fit.inner);
      expect(fit.scrollWidth, 'nothing hidden sideways').toBeLessThanOrEqual(fit.inner);
      expect(fit.bottom, 'the last line is reachable').toBe(true);
      await text.evaluate((area: HTMLTextAreaElement) => {
        area.scrollTop = 0;
      });
    }
    await page.getByRole('tab', { name: 'fragment' }).click();
    await page.addStyleTag({ content: `${HIDE_OVERLAYS} textarea { caret-color: transparent; }` });
    await expect(page).toHaveScreenshot(`layout-${size.width}x${size.height}.png`);
  });
}

test('the panel folders collapse and expand, and the page remembers them', async ({ page }) => {
  await page.setViewportSize({ width: 1280, height: 800 });
  await open(page);
  const folders = {
    View: true,
    Material: true,
    Lights: true,
    'Light 1': false,
    Sphere: false,
    Camera: false,
    Trackball: false,
  };
  for (const [name, open] of Object.entries(folders)) {
    expect(await isOpen(page, name), `${name} open by default`).toBe(open);
    await title(page, name).click();
    await expect.poll(() => isOpen(page, name), `${name} toggled`).toBe(!open);
    await panelAtRest(page);
  }
  await page.reload();
  for (const [name, open] of Object.entries(folders)) {
    expect(await isOpen(page, name), `${name} remembered`).toBe(!open);
    await title(page, name).click();
    await expect.poll(() => isOpen(page, name), `${name} toggled back`).toBe(open);
    await panelAtRest(page);
  }
});

test('the shader view collapses (the panel takes the column) and the page remembers it', async ({ page }) => {
  await page.setViewportSize({ width: 1280, height: 800 });
  await open(page);
  const panel = (await box(page, '.panel')).height;
  await page.getByRole('button', { name: 'GLSL' }).click();
  await expect(page.getByTestId('shader-text')).toBeHidden();
  expect((await box(page, '.panel')).height).toBeGreaterThan(panel + 300);
  await page.reload();
  await expect(page.getByRole('button', { name: 'GLSL' })).toHaveAttribute('aria-expanded', 'false');
  await page.getByRole('button', { name: 'GLSL' }).click();
  await expect(page.getByTestId('shader-text')).toBeVisible();
});

test('the splitter gives the panel more of the column (drag or keys), and the page remembers it', async ({
  page,
}) => {
  await page.setViewportSize({ width: 1280, height: 800 });
  await open(page);
  const splitter = page.getByRole('separator', { name: 'panel height' });
  await expect(splitter).toHaveAttribute('aria-valuenow', '55');
  const before = await box(page, '.panel');
  const handle = await splitter.boundingBox();
  const x = handle!.x + handle!.width / 2;
  const y = handle!.y + handle!.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x, y + 200, { steps: 5 });
  await page.mouse.up();
  const after = await box(page, '.panel');
  // The handle follows the pointer: the panel grows by the drag (to the pixel, less the rounding of the share).
  expect(Math.abs(after.height - before.height - 200)).toBeLessThanOrEqual(6);
  const dragged = Number(await splitter.getAttribute('aria-valuenow'));
  expect(dragged).toBeGreaterThan(75);
  await page.reload();
  await expect(splitter).toHaveAttribute('aria-valuenow', String(dragged));
  await splitter.focus();
  await page.keyboard.press('ArrowUp');
  await expect(splitter).toHaveAttribute('aria-valuenow', String(dragged - 5));
  await page.keyboard.press('End');
  await expect(splitter).toHaveAttribute('aria-valuenow', '85');
  await page.keyboard.press('Home');
  await expect(splitter).toHaveAttribute('aria-valuenow', '20');
  expect((await box(page, '.panel')).height).toBeLessThan(before.height / 2);
});
