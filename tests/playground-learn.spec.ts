import { gzipSync } from 'node:zlib';
import { expect, type Page } from '@playwright/test';
import {
  PLAYGROUND_AFTER_FIRST_FRAME,
  PLAYGROUND_FIRST_LOAD_BUDGET_GZIP,
  PLAYGROUND_LAZY_PARTS,
} from '../bench/lib/playground-budget.mjs';
import { STATE_MAX_CHARS } from '../playground/src/state/schema';
import { test } from './harness-helpers';
import { HIDE_OVERLAYS, open, picture, settle, stateUrl } from './playground-helpers';

// Issue 24 as a whole (the playground teaches the lecture): what ties its learning tools together.
// - The first load: the JavaScript index.html loads at start stays within its budget (gzip -9 bytes, counted from
//   what the page really requested), and each learning tool's code is a chunk of its own, requested only when the
//   tool is used (the tool's use is the proof that the chunk is its code).
// - A huge state in the URL is refused with a message naming the limit, and the state shown stays.
// - The visual baselines of the new views: the probe panel, a term view, the intensity profile, the attenuation
//   curve, the normal-matrix view, the compiled shader view and the copy-as-code dialog (?embed has its own in
//   playground-embed.spec.ts). Exact, as every playground baseline.

/** Paths of the JavaScript files the page requested so far, in order. */
function recordScripts(page: Page): string[] {
  const seen: string[] = [];
  page.on('request', (request) => {
    const path = new URL(request.url()).pathname;
    if (path.endsWith('.js')) seen.push(path);
  });
  return seen;
}

/** The chunk Vite names after a module: `/assets/<file name without extension>-<hash>.js`. */
const chunkOf = (module: string) => {
  const name = module
    .split('/')
    .at(-1)!
    .replace(/\.tsx?$/, '');
  return new RegExp(`^/assets/${name}-[\\w-]+\\.js$`);
};

/** Runs `use` and waits for the request of the chunk of `module` it must cause. */
async function loadsChunk(page: Page, module: string, use: () => Promise<void>): Promise<void> {
  const pattern = chunkOf(module);
  const requested = page.waitForRequest((r) => pattern.test(new URL(r.url()).pathname), { timeout: 20_000 });
  await use();
  await requested;
}

test('the first load stays within its budget; each learning tool’s code loads only when it is used', async ({
  page,
}) => {
  const scripts = recordScripts(page);
  await open(page);
  // What index.html loads at start: its module script and the module preloads Vite lists for its static imports.
  const html = await (await page.request.get('/')).text();
  const entry = [...html.matchAll(/<script type="module"[^>]* src="([^"]+\.js)"/g)].map((m) => m[1]!);
  const preloads = [...html.matchAll(/<link rel="modulepreload"[^>]* href="([^"]+\.js)"/g)].map((m) => m[1]!);
  expect(entry).toHaveLength(1);
  const firstLoad = [...new Set([...entry, ...preloads])].sort();
  // At rest after the first frame the page has requested exactly those and the panels' chunk (loaded after the
  // first frame): nothing lazy came along.
  const afterFirstFrame = [...new Set(scripts)].filter((path) =>
    PLAYGROUND_AFTER_FIRST_FRAME.some(({ module }) => chunkOf(module).test(path)),
  );
  expect(afterFirstFrame).toHaveLength(PLAYGROUND_AFTER_FIRST_FRAME.length);
  expect(firstLoad.filter((path) => afterFirstFrame.includes(path))).toEqual([]);
  expect([...new Set(scripts)].sort()).toEqual([...firstLoad, ...afterFirstFrame].sort());
  let gzip = 0;
  for (const path of firstLoad) {
    const body = await (await page.request.get(path)).body();
    gzip += gzipSync(body, { level: 9 }).length;
  }
  console.log(
    `first load: ${firstLoad.length} scripts, ${gzip} B gzip -9 (budget ${PLAYGROUND_FIRST_LOAD_BUDGET_GZIP})`,
  );
  expect(gzip).toBeLessThanOrEqual(PLAYGROUND_FIRST_LOAD_BUDGET_GZIP);

  // None of the lazy parts is in the first load.
  for (const { module } of PLAYGROUND_LAZY_PARTS) {
    expect(
      firstLoad.filter((path) => chunkOf(module).test(path)),
      module,
    ).toEqual([]);
  }
  const uses: Record<string, () => Promise<void>> = {
    'playground/src/learn/probePanel.tsx': async () => {
      const canvas = page.getByTestId('viewport');
      const box = (await canvas.boundingBox())!;
      await canvas.click({ modifiers: ['Alt'], position: { x: box.width / 2, y: box.height / 2 } });
      await expect(page.getByTestId('probe-hit')).toBeVisible();
      await page.getByRole('button', { name: 'close the probe' }).click();
    },
    'playground/src/learn/profileMode.tsx': async () => {
      await page.getByRole('button', { name: 'intensity profile' }).click();
      await expect(page.getByTestId('profile-panel')).toBeVisible();
      await page.keyboard.press('Escape');
    },
    'playground/src/learn/attenuationPlot.tsx': async () => {
      const button = page.getByRole('button', { name: 'attenuation curve' });
      await button.click();
      await expect(page.getByTestId('attenuation-plot')).toBeVisible();
      await button.click();
    },
    'playground/src/learn/normalMatrixView.tsx': async () => {
      const button = page.getByRole('button', { name: 'normal matrix' });
      await button.click();
      await expect(page.getByTestId('normal-matrix-canvas')).toBeVisible();
      await button.click();
    },
    'playground/src/learn/copyCode.ts': async () => {
      await page.getByTestId('copy-code-three').click();
      const dialog = page.getByRole('dialog', { name: /^Copy as code/ });
      await expect(dialog.getByTestId('copy-code')).toHaveValue(/@shadelab\/material/);
      await dialog.getByRole('button', { name: 'close' }).click();
    },
    'playground/src/learn/adaptiveRun.ts': async () => {
      // Adaptive runs in the instanced spheres (the state through the hash: no reload).
      await page.evaluate(
        (hash) => {
          location.hash = hash;
        },
        stateUrl({ scene: 'instanced' }).slice(1),
      );
      await settle(page);
      await page.getByRole('button', { name: 'adaptive shading' }).click();
      await page.getByTestId('adaptive-toggle').check();
      await expect(page.getByTestId('adaptive-choices').locator('li').first()).toBeVisible();
      await page.getByTestId('adaptive-toggle').uncheck();
    },
  };
  expect(Object.keys(uses).sort()).toEqual(PLAYGROUND_LAZY_PARTS.map((p) => p.module).sort());
  for (const { module } of PLAYGROUND_LAZY_PARTS) {
    expect(
      scripts.filter((path) => chunkOf(module).test(path)),
      `${module} before its use`,
    ).toEqual([]);
    await loadsChunk(page, module, uses[module]!);
  }
});

test('a huge state in the URL is refused with a message naming the limit; the state shown stays', async ({
  page,
}) => {
  // Opened on a state of its own, which the page saves in this browser (after a short pause).
  const mine = { material: { shading: 'gouraud', shininess: 12 } };
  await open(page, mine);
  await expect.poll(() => page.evaluate(() => localStorage.getItem('shadelab.state'))).toContain('"gouraud"');
  const shown = await picture(page);
  const huge = `{"material":{"shading":"flat"},"pad":"${'x'.repeat(STATE_MAX_CHARS)}"}`;
  const limit = `more than the limit of ${STATE_MAX_CHARS}`;

  // A link pasted into this tab: refused, the state and the picture unchanged.
  await page.evaluate(
    (hash) => {
      location.hash = hash;
    },
    stateUrl(JSON.parse(huge)).slice(1),
  );
  const notice = page.getByTestId('notice').filter({ hasText: 'The state in the URL was refused' });
  await expect(notice).toContainText(`state: ${huge.length} characters is ${limit}`);
  await settle(page);
  expect(await picture(page)).toBe(shown);
  await expect(page.locator('[id="Material.shading"]')).toHaveValue('1');

  // The same link opened in a new load: refused, and the state this browser saved opens.
  await page.goto('about:blank');
  await page.goto(stateUrl(JSON.parse(huge)));
  await settle(page);
  await expect(notice).toContainText(limit);
  expect(await picture(page)).toBe(shown);
});

test.describe('the learning views’ baselines', () => {
  let page: Page;
  test.beforeAll(async ({ browser }) => {
    page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    // The copy dialog then says "copied to the clipboard" on every run.
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
  });
  test.afterAll(async () => {
    await page.close();
  });

  /**
   * The view and what is drawn over it (the messages hidden), and, when a tool's panel is open, the dock that holds
   * it (`<name>-dock.png`).
   */
  async function stageShot(name: string): Promise<void> {
    // Removed after the shot: `open` on the same page only changes the hash (no reload).
    const style = await page.addStyleTag({ content: HIDE_OVERLAYS });
    await expect(page.locator('main.stage')).toHaveScreenshot(name);
    if (await page.getByTestId('dock').locator('> *').count()) {
      await expect(page.getByTestId('dock')).toHaveScreenshot(name.replace(/\.png$/, '-dock.png'));
    }
    await style.evaluate((element) => (element as Element).remove());
  }

  test('the probe panel (Gouraud, Phong lighting: the vertices and weights) and a term view', async () => {
    await open(page, { material: { shading: 'gouraud', lighting: 'phong' } });
    const canvas = page.getByTestId('viewport');
    const box = (await canvas.boundingBox())!;
    await canvas.click({
      modifiers: ['Alt'],
      position: { x: Math.floor(box.width * 0.42) + 0.5, y: Math.floor(box.height * 0.4) + 0.5 },
    });
    await expect(page.getByTestId('probe-gouraud')).toBeVisible();
    await expect(page.getByTestId('probe-gpu')).toBeVisible();
    await settle(page);
    await stageShot('learn-probe-gouraud.png');
    await page.getByRole('button', { name: 'close the probe' }).click();

    // The diffuse term alone, in the compare view (flat | Gouraud | Phong | cel), on a coarse sphere.
    await open(page, { view: 'compare', material: { output: 'diffuse' }, sphere: { level: 3 } });
    await stageShot('learn-term-diffuse-compare.png');
  });

  test('the intensity profile and the attenuation curve', async () => {
    await open(page, { sphere: { level: 3 }, model: { scale: [1, 1, 1] }, camera: { eye: [0, 0, 2.2] } });
    await page.getByRole('button', { name: 'intensity profile' }).click();
    await expect(page.getByTestId('profile-overlay')).toBeVisible();
    const box = (await page.getByTestId('viewport').boundingBox())!;
    await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.55);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.7, box.y + box.height * 0.55, { steps: 8 });
    await page.mouse.up();
    await expect(page.getByTestId('profile-plot')).toBeVisible({ timeout: 15_000 });
    await settle(page);
    await stageShot('learn-profile.png');
    await page.keyboard.press('Escape');

    const lights = [
      { position: [-5, 10, 20], attenuation: { a: 1, b: 0.05, c: 0.002 } },
      { position: [3, -1, 4], diffuse: [0.2, 0.4, 1], attenuation: { a: 0.5, b: 0.2, c: 0.05 } },
    ];
    await open(page, { lights });
    await page.getByRole('button', { name: 'attenuation curve' }).click();
    await expect(page.getByTestId('attenuation-plot')).toBeVisible();
    await settle(page);
    await stageShot('learn-attenuation.png');
    await page.getByRole('button', { name: 'attenuation curve' }).click();
    await expect(page.getByTestId('attenuation-panel')).toHaveCount(0);
  });

  test('the normal-matrix view, the compiled shader view and the copy-as-code dialog', async () => {
    await open(page, { model: { scale: [2, 0.6, 1.2] } });
    const canvas = page.getByTestId('viewport');
    const box = (await canvas.boundingBox())!;
    await canvas.click({
      modifiers: ['Alt'],
      position: { x: Math.floor(box.width * 0.45) + 0.5, y: Math.floor(box.height * 0.42) + 0.5 },
    });
    await expect(page.getByTestId('probe-hit')).toBeVisible();
    // The figure takes the probed point (the probe stays open: closing it clears the probe).
    await page.getByRole('button', { name: 'normal matrix' }).click();
    await expect(page.getByTestId('normal-matrix-canvas')).toBeVisible();
    await settle(page);
    await stageShot('learn-normal-matrix.png');
    await page.getByRole('button', { name: 'normal matrix' }).click();
    await page.getByRole('button', { name: 'close the probe' }).click();

    // The GLSL view as compiled for this scene (flat shading, cel bands), fragment stage, from its start.
    await open(page, { material: { shading: 'flat', celBands: 3 } });
    await page.getByRole('tab', { name: 'fragment' }).click();
    const text = page.getByTestId('shader-text');
    await text.evaluate((t: HTMLTextAreaElement) => {
      t.scrollTop = 0;
    });
    await page.addStyleTag({ content: 'textarea { caret-color: transparent; }' });
    await expect(page.locator('.shader-view')).toHaveScreenshot('learn-shader-compiled.png');

    await page.getByTestId('copy-code-r3f').click();
    const dialog = page.getByRole('dialog', { name: /^Copy as code/ });
    await expect(dialog).not.toContainText('copying…');
    // The dialog alone: its rounded corners show the page behind it, which is hidden here.
    await page.addStyleTag({ content: '.side { visibility: hidden !important; }' });
    await expect(dialog).toHaveScreenshot('learn-copy-code-r3f.png');
  });
});
