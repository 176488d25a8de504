// Term views (issue 24): the panel's `output` (Material folder, `material.output` in the URL) draws the colour or
// one term of the lecture's equation alone. The material's contract (@shadelab/material's ShadingOutput): with
// no emissive and three's default NoToneMapping, the ambient, diffuse and specular pictures decoded to linear
// add up to the colour's where it is not clamped. Checked on every pixel of the view, within the rounding of the
// four 8-bit sRGB pictures, in WebGL mode (single and compare view) and WebGPU mode's WebGL2 backend here; the
// WebGPU backend in playground-term-views-webgpu.spec.ts.
import { expect } from '@playwright/test';
import { test } from './harness-helpers';
import { choose, open, urlState } from './playground-helpers';
import { expectSum, pictures, screen, TWO_LIGHTS } from './playground-term-views-helpers';
import { toWebGPU } from './playground-webgpu-helpers';

test.describe('term views add up to the colour (linear, within rounding)', () => {
  test('WebGL mode, the lecture’s sphere; the output is in the URL and a bad one is refused', async ({
    page,
  }) => {
    await open(page);
    const { color, terms } = await pictures(page, screen(page));
    expectSum(color, terms, 20_000);
    await choose(page, 'Material.output', 'specular');
    expect((await urlState(page)).material).toMatchObject({ output: 'specular' });
    // The baselines of two term views (overlays hidden, as in playground-visual.spec.ts).
    await page.addStyleTag({ content: 'main.stage > :not(canvas) { visibility: hidden !important; }' });
    await choose(page, 'Material.output', 'diffuse');
    await expect(page.getByTestId('viewport')).toHaveScreenshot('term-diffuse.png');
    await choose(page, 'Material.output', 'normal');
    await expect(page.getByTestId('viewport')).toHaveScreenshot('term-normal.png');
    await page.goto('about:blank');
    await open(page, { material: { output: 'everything' } });
    await expect(page.getByTestId('notice')).toContainText(
      'state.material.output: "everything" is not one of',
    );
  });

  test('WebGL mode, Gouraud with Phong lighting and two lights, one attenuated', async ({ page }) => {
    await open(page, TWO_LIGHTS);
    const { color, terms } = await pictures(page, screen(page));
    expectSum(color, terms, 20_000);
  });

  test('WebGL mode, the compare view (flat | Gouraud | Phong | cel): every cell', async ({ page }) => {
    await open(page, { view: 'compare' });
    const { color, terms } = await pictures(page, screen(page));
    expectSum(color, terms, 4 * 3_000);
  });

  test('WebGPU mode (WebGPURenderer’s WebGL2 backend here), single and compare view', async ({ page }) => {
    test.setTimeout(120_000);
    await open(page, TWO_LIGHTS);
    await toWebGPU(page);
    await expect(page.getByTestId('renderer-backend')).toHaveText(/^Renderer: WebGL2/);
    let { color, terms } = await pictures(page, screen(page));
    expectSum(color, terms, 20_000);
    await choose(page, 'View.view', 'flat | Gouraud | Phong | cel');
    ({ color, terms } = await pictures(page, screen(page)));
    expectSum(color, terms, 4 * 3_000);
  });
});
