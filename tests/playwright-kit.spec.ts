// @shadelab/playwright's matchers on real canvases: toHaveRendered on a rendered, a blank, a context-less and a
// lost canvas (with and without the kit's `test`, which records contexts); waitForFirstFrame; toMatchReference
// on the lecture scene, passing and failing (with its attachments); toMatchScreenshotAcrossGpus against a
// committed baseline. The scene comes from tests/harness/kitScene.ts, which the harness page draws and this
// spec reads with referenceSceneOf, as a user's test reads the scene their app builds.
// expectBackend and toMatchAcrossRenderers in this browser, launched without the WebGPU flag, fail on the fallback.

import type { Page } from '@playwright/test';
import { test as plainTest } from '@playwright/test';
import { expect, referenceSceneOf, test } from '@shadelab/playwright/reference';
import { expectBackend, waitForFirstFrame } from '@shadelab/playwright/test';
import { buildKitScene, type KitSceneOptions } from './harness/kitScene';

/** Open the harness drawing `options`; resolves when it has drawn. */
async function openKit(page: Page, options: KitSceneOptions = {}) {
  await page.goto(`/harness/?page=kit&scene=${encodeURIComponent(JSON.stringify(options))}`);
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveRendered({ timeout: 30_000 }); // a loaded machine is slow to compile
  return canvas;
}

/**
 * A page of one 64 × 48 canvas whose script is `script` (`canvas` is the element), served at a URL so that
 * init scripts run as on any page.
 */
async function openCanvas(page: Page, script: string) {
  await page.route('http://kit.test/', (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><body style="margin:0;background:#000"><canvas width="64" height="48" style="display:block"></canvas><script>const canvas = document.querySelector('canvas');${script}</script></body>`,
    }),
  );
  await page.goto('http://kit.test/');
  return page.locator('canvas');
}

/** A WebGL2 clear of the whole canvas to one colour, and a scissored clear of a 10 × 10 square in another. */
const CLEAR_BLUE = `const gl = canvas.getContext('webgl2'); gl.clearColor(0, 0, 1, 1); gl.clear(gl.COLOR_BUFFER_BIT);`;
const DRAW_SQUARE = `${CLEAR_BLUE} gl.enable(gl.SCISSOR_TEST); gl.scissor(20, 20, 10, 10); gl.clearColor(1, 0, 0, 1); gl.clear(gl.COLOR_BUFFER_BIT);`;

/** The message of a failing assertion. */
async function failure(assertion: Promise<unknown>): Promise<string> {
  const error = await assertion.then(
    () => undefined,
    (e: unknown) => e,
  );
  if (!(error instanceof Error)) throw new Error('the assertion passed; it should have failed');
  return error.message;
}

test.describe('toHaveRendered', () => {
  test('passes on the lecture scene, and waitForFirstFrame reports its WebGL2 context and picture', async ({
    page,
  }) => {
    const canvas = await openKit(page);
    const frame = await waitForFirstFrame(canvas);
    expect(frame.canvas).toMatchObject({
      context: 'webgl2',
      lost: false,
      recorded: true,
      width: 320,
      height: 240,
    });
    expect(frame.picture.background).toEqual([0, 0, 255, 255]);
    // The ellipsoid covers the ellipse u²/0.8 + v²/0.2 < 1 (u, v in units of tan 45°): π·0.4 of the canvas's
    // (2·4/3) × 2, that is 18,096 of its 76,800 pixels.
    const covered = ((Math.PI * 0.4) / (16 / 3)) * 320 * 240;
    expect(Math.abs(frame.picture.drawnPixels - covered)).toBeLessThan(0.005 * covered);
    await expect(canvas).toHaveRendered({ background: [0, 0, 255], minDrawnPixels: 18_000 });
  });

  test('fails on a blank canvas, saying it is flat and its colour', async ({ page }) => {
    const canvas = await openCanvas(page, CLEAR_BLUE);
    const message = await failure(expect(canvas).toHaveRendered({ timeout: 5_000 }));
    expect(message).toContain('expect(canvas).toHaveRendered()');
    expect(message).toContain('the picture is blank: all 64×48 pixels are rgb(0, 0, 255)');
    expect(message).toContain('WebGL2 context');
    expect(test.info().attachments.map((a) => a.name)).toContain('toHaveRendered-actual.png');
    await expect(canvas).not.toHaveRendered({ timeout: 5_000 });
  });

  test('fails on a lost context (WEBGL_lose_context), even with its last picture on screen', async ({
    page,
  }) => {
    const canvas = await openCanvas(page, DRAW_SQUARE);
    await expect(canvas).toHaveRendered();
    await canvas.evaluate((c: HTMLCanvasElement) =>
      c.getContext('webgl2')!.getExtension('WEBGL_lose_context')!.loseContext(),
    );
    const message = await failure(expect(canvas).toHaveRendered({ timeout: 5_000 }));
    expect(message).toContain('its WebGL2 context is lost (isContextLost() is true)');
  });

  test('fails on a canvas without a context, and on an element that is not a canvas', async ({ page }) => {
    const canvas = await openCanvas(page, '');
    expect(await failure(expect(canvas).toHaveRendered({ timeout: 5_000 }))).toContain(
      'the canvas has no context: the page never called getContext on it',
    );
    expect(await failure(expect(page.locator('body')).toHaveRendered({ timeout: 5_000 }))).toContain(
      'the element is a <body>, not a <canvas>',
    );
  });

  test('a picture whose drawn pixels fall short of minDrawnPixels, or that is all background, fails', async ({
    page,
  }) => {
    const canvas = await openCanvas(page, DRAW_SQUARE);
    await expect(canvas).toHaveRendered({ minDrawnPixels: 100 });
    expect(await failure(expect(canvas).toHaveRendered({ minDrawnPixels: 101, timeout: 5_000 }))).toContain(
      'only 100 pixels differ from the background rgb(0, 0, 255), 101 needed',
    );
    // With the red square's colour as the background, the blue rest is what is drawn.
    await expect(canvas).toHaveRendered({ background: [255, 0, 0], minDrawnPixels: 64 * 48 - 100 });
    expect(await failure(expect(canvas).toHaveRendered({ minDrawnPixels: 0 }))).toContain(
      'toHaveRendered: minDrawnPixels must be an integer ≥ 1, got 0',
    );
  });

  test('waitForFirstFrame waits for a frame drawn later, and throws with the reason when none comes', async ({
    page,
  }) => {
    const canvas = await openCanvas(page, `setTimeout(() => { ${DRAW_SQUARE} }, 400);`);
    const frame = await waitForFirstFrame(canvas, { timeout: 30_000 });
    expect(frame.picture.drawnPixels).toBe(100);
    const blank = await openCanvas(page, CLEAR_BLUE);
    expect(await failure(waitForFirstFrame(blank, { timeout: 5_000 }))).toMatch(
      /^waitForFirstFrame: the canvas did not render within \d+ ms: the picture is blank/,
    );
  });
});

plainTest.describe("toHaveRendered with Playwright's own test (contexts not recorded)", () => {
  plainTest(
    'passes on a drawn canvas, finding its context; fails on a blank or lost one',
    async ({ page }) => {
      const canvas = await openCanvas(page, DRAW_SQUARE);
      await expect(canvas).toHaveRendered();
      const lost = await openCanvas(page, DRAW_SQUARE);
      await lost.evaluate((c: HTMLCanvasElement) =>
        c.getContext('webgl2')!.getExtension('WEBGL_lose_context')!.loseContext(),
      );
      // Without the recorder the context is asked for once the canvas shows a picture: the lost one still does.
      expect(await failure(expect(lost).toHaveRendered({ timeout: 5_000 }))).toContain(
        'its WebGL2 context is lost (isContextLost() is true)',
      );
      const blank = await openCanvas(page, CLEAR_BLUE);
      expect(await failure(expect(blank).toHaveRendered({ timeout: 5_000 }))).toContain(
        'the picture is blank',
      );
    },
  );
});

test.describe('toMatchReference', () => {
  const budget = { rmse: 1, max: 2, silhouettePx: 1 };

  for (const options of [
    { shading: 'impostor' },
    { shading: 'phong', level: 6 },
  ] satisfies KitSceneOptions[]) {
    test(`the lecture scene drawn by ${options.shading} matches the exact reference within ${JSON.stringify(budget)}`, async ({
      page,
    }) => {
      const canvas = await openKit(page, options);
      const kit = buildKitScene(options);
      await expect(canvas).toMatchReference(
        referenceSceneOf({ camera: kit.camera, sphere: kit.sphere, background: kit.background }),
        budget,
      );
      expect(test.info().attachments).toEqual([]);
    });
  }

  test('fails when the scene has another shininess than the page drew, with the numbers and the diff attached', async ({
    page,
  }) => {
    const canvas = await openKit(page, { shininess: 8 });
    const kit = buildKitScene({ shininess: 32 });
    const scene = referenceSceneOf({ camera: kit.camera, sphere: kit.sphere, background: kit.background });
    const message = await failure(expect(canvas).toMatchReference(scene, budget));
    expect(message).toContain('expect(canvas).toMatchReference(scene, {rmse:1,max:2,silhouettePx:1})');
    expect(message).toContain('The canvas differs from the exact reference beyond the budget (rmse, max)');
    expect(message).toMatch(/silhouette px +0(\.00)? ≤ 1/);
    expect(message).toContain('Attached: reference-expected.png');
    const attachments = test.info().attachments;
    expect(attachments.map((a) => a.name)).toEqual([
      'reference-expected.png',
      'reference-actual.png',
      'reference-diff.png',
      'reference-error.json',
    ]);
    const numbers = JSON.parse(attachments[3].body!.toString());
    expect(numbers.budget).toEqual(budget);
    expect(numbers.measured.max).toBeGreaterThan(2);
  });

  test('fails when the ellipsoid is off by 10 % in height: the silhouette, in pixels', async ({ page }) => {
    const canvas = await openKit(page, { scale: [2, 1.1, 2] });
    const kit = buildKitScene();
    const scene = referenceSceneOf({ camera: kit.camera, sphere: kit.sphere, background: kit.background });
    const message = await failure(expect(canvas).toMatchReference(scene, { silhouettePx: 1 }));
    expect(message).toContain('beyond the budget (silhouettePx)');
    expect(message).toMatch(/RMSE .*\(not checked\)/);
  });

  test('says so when the camera does not fit the canvas, or the budget is empty or negative', async ({
    page,
  }) => {
    const canvas = await openKit(page);
    const kit = buildKitScene({ width: 320, height: 320 });
    const square = referenceSceneOf({ camera: kit.camera, sphere: kit.sphere, background: kit.background });
    expect(await failure(expect(canvas).toMatchReference(square, budget))).toContain(
      "the camera's projection has aspect 1.00000 but the canvas is 320×240 (aspect 1.33333)",
    );
    expect(await failure(expect(canvas).toMatchReference(square, {}))).toContain(
      'toMatchReference: the budget needs at least one of rmse, max and silhouettePx',
    );
    expect(await failure(expect(canvas).toMatchReference(square, { rmse: -1 }))).toContain(
      'toMatchReference: rmse must be a finite number ≥ 0, got -1',
    );
  });
});

test.describe('toMatchScreenshotAcrossGpus', () => {
  // GPU_TOLERANCE (4 codes beyond a 3 × 3 neighbourhood's range) is the variation measured in
  // bench/results/rasterisers.json for a picture moved by 1/16 px, as another GPU's sub-pixel grid moves it.
  test('the lecture scene matches its baseline, and so does the picture moved by 1/16 px', async ({
    page,
  }) => {
    for (const options of [{}, { shiftPx: [1 / 16, 1 / 16] }] satisfies KitSceneOptions[]) {
      const canvas = await openKit(page, options);
      await expect(canvas, JSON.stringify(options)).toMatchScreenshotAcrossGpus('kit-lecture.png');
    }
  });

  test('fails on another shininess, with the expected, actual and diff pictures attached', async ({
    page,
  }) => {
    const canvas = await openKit(page, { shininess: 8 });
    const message = await failure(expect(canvas).toMatchScreenshotAcrossGpus('kit-lecture.png'));
    expect(message).toMatch(/The canvas differs from .*kit-lecture\.png beyond the tolerance/);
    expect(message).toContain("each pixel within 4 codes of its 3×3 neighbourhood's range, at most 0 beyond");
    expect(test.info().attachments.map((a) => a.name)).toEqual([
      'kit-lecture-expected.png',
      'kit-lecture-actual.png',
      'kit-lecture-diff.png',
    ]);
  });

  test('what it does not cover: MSAA against a baseline drawn without, and a move of 1/2 px', async ({
    page,
  }) => {
    for (const options of [{ antialias: true }, { shiftPx: [0.5, 0.5] }] satisfies KitSceneOptions[]) {
      const canvas = await openKit(page, options);
      expect(await failure(expect(canvas).toMatchScreenshotAcrossGpus('kit-lecture.png'))).toContain(
        'beyond the tolerance',
      );
    }
  });

  test('a bad tolerance is refused, naming it', async ({ page }) => {
    const canvas = await openKit(page);
    expect(
      await failure(expect(canvas).toMatchScreenshotAcrossGpus('kit-lecture.png', { radiusPx: 0.5 })),
    ).toContain('toMatchScreenshotAcrossGpus: radiusPx must be an integer 0 … 8, got 0.5');
  });
});

test.describe('expectBackend and toMatchAcrossRenderers without the WebGPU flag', () => {
  // This spec's browser is the preset's default: no --enable-unsafe-webgpu, so WebGPURenderer falls back to WebGL2.
  test('expectBackend(page, "webgpu") fails saying which flag is missing; the matcher fails on the fallback', async ({
    page,
  }) => {
    await page.goto('/harness/?page=kit-renderers');
    expect(await failure(expectBackend(page, 'webgpu'))).toMatch(
      /^expectBackend\(page, 'webgpu'\): the browser cannot give webgpu: (navigator\.gpu is undefined|navigator\.gpu\.requestAdapter\(\) returned null).*--enable-unsafe-webgpu/,
    );
    expect((await expectBackend(page, 'webgl2', { rasteriser: 'swiftshader' })).description).toContain(
      'SwiftShader',
    );
    const message = await failure(
      expect(page).toMatchAcrossRenderers('lecture', {
        renderers: ['webgl', 'webgpu'],
        width: 32,
        height: 24,
      }),
    );
    expect(message).toMatch(
      /webgpu: WebGPU was asked for, but WebGPURenderer fell back to its WebGL2 backend: /,
    );
    expect(message).toMatch(/webgpu +WebGPURenderer, WebGL2 backend: ANGLE/);
  });
});
