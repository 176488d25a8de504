import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { HIDE_OVERLAYS, open } from './playground-helpers';

// Visual regression of the canvas (overlays hidden). Renders are pixel-deterministic under SwiftShader with the
// shared Playwright flags, so the tolerance is zero (playwright.config.ts: maxDiffPixels 0, threshold 0).
// The lecture scene's shots name their shading and lighting and set both; every other shot is the lecture
// scene's default (Phong shading, Blinn-Phong lighting) with only what its name says changed.
// Update the baselines after an intended change with:
//   SHADELAB_E2E_PORT=4105 npx playwright test tests/playground-visual.spec.ts --update-snapshots

async function shot(page: Page, name: string) {
  await page.addStyleTag({ content: HIDE_OVERLAYS });
  await expect(page.getByTestId('viewport')).toHaveScreenshot(name);
}

for (const shading of ['flat', 'gouraud', 'phong'] as const) {
  for (const lighting of ['phong', 'blinn-phong'] as const) {
    test(`lecture scene, ${shading} shading, ${lighting} lighting`, async ({ page }) => {
      await open(page, { material: { shading, lighting } });
      await shot(page, `lecture-${shading}-${lighting}.png`);
    });
  }
}

test('cel shading with 3 bands', async ({ page }) => {
  await open(page, { material: { celBands: 3 } });
  await shot(page, 'cel-3-bands.png');
});

test('cel shading with 3 bands and the outline', async ({ page }) => {
  await open(page, { material: { celBands: 3, outline: true }, model: { scale: [1.5, 1, 1.5] } });
  await shot(page, 'cel-3-bands-outline.png');
});

test('the ray-cast impostor (exact sphere on two triangles)', async ({ page }) => {
  await open(page, { sphere: { render: 'impostor' } });
  await shot(page, 'impostor.png');
});

test('orthographic camera', async ({ page }) => {
  await open(page, { camera: { projection: 'orthographic', top: 2.2, bottom: -2.2 } });
  await shot(page, 'orthographic.png');
});

test('two lights', async ({ page }) => {
  const light = (position: number[], diffuse: number[]) => ({
    position,
    ambient: [0.1, 0.1, 0.1],
    diffuse,
    specular: [0.8, 0.8, 0.8],
    attenuation: { a: 1, b: 0, c: 0 },
  });
  await open(page, { lights: [light([-5, 10, 20], [1, 1, 1]), light([6, -4, 8], [0.2, 0.4, 1])] });
  await shot(page, 'two-lights.png');
});

test('non-uniform scale, turned by the trackball', async ({ page }) => {
  await open(page, {
    model: { scale: [0.6, 1.6, 1.2] },
    trackball: { rotation: [0.25881904510252074, 0.2, 0, 0.9450287318402637] },
  });
  await shot(page, 'non-uniform-scale.png');
});

test('comparison view: flat | Gouraud | Phong | cel', async ({ page }) => {
  await open(page, {
    view: 'compare',
    sphere: { level: 3 },
    model: { scale: [1, 1, 1] },
    camera: { eye: [0, 0, 1.9] },
  });
  await shot(page, 'compare.png');
});

test('comparison view on a wide canvas: one row, as on the lecture slide', async ({ page }) => {
  // At 800 × 600 the canvas (460 × 600) is 2 × 2; from an aspect of 2 the cells line up in one row.
  await page.setViewportSize({ width: 1600, height: 500 });
  await open(page, {
    view: 'compare',
    sphere: { level: 3 },
    model: { scale: [1, 1, 1] },
    camera: { eye: [0, 0, 1.9] },
  });
  await shot(page, 'compare-wide.png');
});
