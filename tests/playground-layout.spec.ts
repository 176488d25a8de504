import { expect, type Page } from '@playwright/test';
import { decodePng } from '@shadelab/playwright/test';
import { test } from './harness-helpers';
import { HIDE_OVERLAYS, open, panelAtRest, settle, stateUrl } from './playground-helpers';

// The playground's layout at the two common desktop sizes: canvas on the left, the side column (the Learn panel's
// button, the tools, the dock of the learning tools' panels, the leva panel, the notes and statistics, the shader
// view at the bottom) on the right; nothing wider than the window, no part overlapping another, each at least the
// size below (measured from the layout: index.html's CSS gives the side column 340 px, 520 px from 1800 px up, and
// splits what the tools and notes leave 55 : 45 between the panel and the shader view); with every panel open, no
// panel meets what the view draws. Whole-page screenshots (maxDiffPixels 0 as everywhere) with what changes every
// frame (the statistics) hidden. Update the baselines after an intended change with:
//   SHADELAB_E2E_PORT=4316 npx playwright test tests/playground-layout.spec.ts --update-snapshots

const SIZES = [
  { width: 1280, height: 800, canvas: [935, 800], lesson: [320, 24], panel: [340, 310], shader: [340, 250] },
  {
    width: 1920,
    height: 1080,
    canvas: [1395, 1080],
    lesson: [500, 24],
    panel: [520, 480],
    shader: [520, 390],
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
  const shader = (await box(page, '.shader-view')).height;
  await page.getByRole('button', { name: 'GLSL' }).click();
  await expect(page.getByTestId('shader-text')).toBeHidden();
  // The panel takes the shader view's height but for its title (and the splitter, gone with it).
  const title = (await box(page, '.shader-view')).height;
  expect((await box(page, '.panel')).height).toBeGreaterThanOrEqual(panel + shader - title - 1);
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
  await page.mouse.move(x, y + 100, { steps: 5 });
  await page.mouse.up();
  const after = await box(page, '.panel');
  // The handle follows the pointer: the panel grows by the drag (to the pixel, less the rounding of the share).
  expect(Math.abs(after.height - before.height - 100)).toBeLessThanOrEqual(6);
  const dragged = Number(await splitter.getAttribute('aria-valuenow'));
  expect(dragged).toBeGreaterThan(65);
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

/** The panels a student opens: the lesson, every learning tool, the probe at the view's centre, all statistics. */
async function openEveryPanel(page: Page) {
  await page.getByTestId('lesson-open').click();
  for (const name of ['intensity profile', 'attenuation curve', 'normal matrix', 'adaptive shading']) {
    await page.getByRole('navigation', { name: 'tools' }).getByRole('button', { name, exact: false }).click();
  }
  await page.getByTestId('stats-summary').click();
  const canvas = page.getByTestId('viewport');
  const c = (await canvas.boundingBox())!;
  await canvas.click({ modifiers: ['Alt'], position: { x: c.width / 2, y: c.height / 2 } });
  await expect(page.getByTestId('probe-panel')).toHaveAttribute('data-probed', /[1-9]/);
  for (const id of ['profile-panel', 'attenuation-panel', 'normal-matrix-panel', 'adaptive-panel']) {
    await expect(page.getByTestId(id)).toBeVisible();
  }
}

/**
 * The drawn objects' boxes in page pixels: in each cell of the view (the canvas, the compare view's cells, the
 * parity view's pictures), the box of the pixels brighter than 8 in any channel, from a screenshot of the stage with
 * what is drawn over the view hidden.
 */
async function objectBoxes(page: Page, cells: Box[]): Promise<Box[]> {
  const style = await page.addStyleTag({ content: `${HIDE_OVERLAYS} .parity-label { visibility: hidden; }` });
  const stage = (await page.locator('main.stage').boundingBox())!;
  const shot = decodePng(await page.locator('main.stage').screenshot());
  await style.evaluate((element) => (element as Element).remove());
  const scale = shot.width / stage.width;
  const boxes: Box[] = [];
  for (const cell of cells) {
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    const left = Math.round((cell.x - stage.x) * scale);
    const top = Math.round((cell.y - stage.y) * scale);
    const right = Math.min(shot.width, Math.round((cell.x - stage.x + cell.width) * scale));
    const bottom = Math.min(shot.height, Math.round((cell.y - stage.y + cell.height) * scale));
    for (let y = top; y < bottom; y++) {
      for (let x = left; x < right; x++) {
        const i = 4 * (y * shot.width + x);
        if (shot.data[i]! > 8 || shot.data[i + 1]! > 8 || shot.data[i + 2]! > 8) {
          [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x), Math.max(y1, y)];
        }
      }
    }
    if (x1 < x0) continue;
    boxes.push({
      x: stage.x + x0 / scale,
      y: stage.y + y0 / scale,
      width: (x1 - x0 + 1) / scale,
      height: (y1 - y0 + 1) / scale,
    });
  }
  return boxes;
}

/** Every visible box of what is not the view: the side column's parts and the docked panels, and the messages. */
async function panelBoxes(page: Page): Promise<{ name: string; box: Box }[]> {
  return page.evaluate(() => {
    const parts = [
      ...document.querySelectorAll('.side > *, .dock > *, .messages .message, .stats-box, .tools'),
    ] as HTMLElement[];
    return parts
      .map((element) => {
        const r = element.getBoundingClientRect();
        const name = element.dataset['testid'] ?? element.getAttribute('aria-label') ?? element.className;
        return { name, box: { x: r.x, y: r.y, width: r.width, height: r.height } };
      })
      .filter(({ box }) => box.width > 0 && box.height > 0);
  });
}

const VIEWS = {
  single: { cells: '[data-testid="viewport"]' },
  compare: { cells: '.compare-labels li' },
  parity: { cells: '.parity > div:not(.parity-numbers)' },
} as const;

test('with every panel open, no panel meets a drawn object, in every view, at 1280 × 800 and 1920 × 1080', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await page.setViewportSize({ width: SIZES[0].width, height: SIZES[0].height });
  await open(page);
  await openEveryPanel(page);
  for (const size of SIZES) {
    await page.setViewportSize({ width: size.width, height: size.height });
    for (const [view, { cells }] of Object.entries(VIEWS)) {
      await page.evaluate((hash) => {
        window.location.hash = hash;
      }, stateUrl({ view }).slice(2));
      await settle(page);
      if (view === 'parity')
        await expect(page.getByTestId('parity-numbers')).toBeVisible({ timeout: 30_000 });
      const cellBoxes = await page.locator(cells).evaluateAll((elements) =>
        elements.map((e) => {
          const r = e.getBoundingClientRect();
          return { x: r.x, y: r.y, width: r.width, height: r.height };
        }),
      );
      expect(cellBoxes.length, `${view}: cells`).toBeGreaterThan(0);
      const objects = await objectBoxes(page, cellBoxes);
      expect(objects.length, `${view}: objects drawn`).toBeGreaterThan(0);
      const panels = await panelBoxes(page);
      expect(panels.map((p) => p.name)).toEqual(
        expect.arrayContaining([
          'lesson',
          'tools',
          'probe-panel',
          'profile-panel',
          'attenuation-panel',
          'normal-matrix-panel',
          'adaptive-panel',
          'stats-box',
        ]),
      );
      for (const object of objects) {
        for (const panel of panels) {
          expect(
            overlap(object, panel.box),
            `${size.width} × ${size.height}, ${view} view: ${panel.name}`,
          ).toBe(false);
        }
      }
    }
  }
});
