// Term views on WebGPURenderer's WebGPU backend (issue 24): the parity view draws WebGPU mode's picture offscreen
// (never presented: headless Chromium loses a WebGPU device that presents), on the WebGPU backend with the kit's
// WebGPU flags, which the page names and the test checks. The colour and term pictures of both halves: see
// playground-term-views.spec.ts for what is checked.
import { expect } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import { test } from './harness-helpers';
import { choose, open } from './playground-helpers';
import { expectSum, TERMS, TWO_LIGHTS } from './playground-term-views-helpers';
import { readParity } from './playground-webgpu-helpers';

test.use(shadelabUse({ webgpu: true, args: ['--shadelab-own-browser=playground-term-views'] }));

test('the parity view’s WebGPU picture: ambient + diffuse + specular = colour', async ({ page }) => {
  test.setTimeout(120_000);
  await open(page, { ...TWO_LIGHTS, view: 'parity' });
  await expect(page.getByTestId('parity-backend')).toHaveText(/\(WebGPU\)$/, { timeout: 60_000 });
  const read = async (output: string) => {
    if (output !== 'color') await choose(page, 'Material.output', output);
    return readParity(page);
  };
  const color = await read('color');
  const terms = [];
  for (const term of TERMS) terms.push(await read(term));
  expectSum(
    color.webgpu,
    terms.map((t) => t.webgpu),
    10_000,
  );
  // And the WebGL half of the same view, for good measure.
  expectSum(
    color.webgl,
    terms.map((t) => t.webgl),
    10_000,
  );
  await expect(page.getByTestId('parity-backend')).toHaveText(/\(WebGPU\)$/);
});
