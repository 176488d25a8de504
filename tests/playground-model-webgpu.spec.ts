// A KTX2-textured model (KHR_texture_basisu) on the WebGPU backend: the playground transcodes its Basis texture
// once, for the viewer's WebGL renderer, and WebGPU mode draws that same compressed texture, so the format
// chosen must be one the WebGPU device samples too. The parity view draws WebGPU mode offscreen (presenting a
// WebGPU canvas headless loses the device: playground-webgpu-flags.spec.ts) beside WebGL mode, on SwiftShader's
// WebGPU adapter, and the two pictures must agree as they do for the uncompressed model
// (playground-webgpu-parity.spec.ts).
import { expect, type Page } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import { ktx2Glb } from './glb-compress';
import { test } from './harness-helpers';
import { open, settle } from './playground-helpers';
import { awayFromEdges, readParity, watchProblems } from './playground-webgpu-helpers';

// WebGPU's device can restart Chromium's GPU process: a browser of its own (the switch is the file's name).
test.use(shadelabUse({ webgpu: true, args: ['--shadelab-own-browser=playground-model-webgpu'] }));

/** The textured box GLB made by three's GLTFExporter in the harness page (as playground-model.spec.ts does). */
async function texturedModel(page: Page): Promise<Buffer> {
  const maker = await page.context().newPage();
  await maker.goto('/harness/?page=gltf-maker');
  await maker.waitForFunction(() => typeof window.makeModel === 'function');
  const bytes = await maker.evaluate(() => window.makeModel('textured'));
  await maker.close();
  return Buffer.from(bytes);
}

test('a KTX2-textured model: WebGPU mode draws the transcoded texture as WebGL mode does (parity view)', async ({
  page,
}) => {
  test.setTimeout(120_000);
  const problems = watchProblems(page);
  const glb = await ktx2Glb(await texturedModel(page));
  await open(page, { view: 'parity' });
  await page
    .getByTestId('model-file')
    .setInputFiles({ name: 'box-ktx2.glb', mimeType: 'model/gltf-binary', buffer: glb });
  await expect(page.getByTestId('model-note')).toContainText('“box-ktx2.glb”', { timeout: 20_000 });
  await settle(page);
  await expect(page.getByTestId('parity-backend')).toHaveText(/\(WebGPU\)$/, { timeout: 60_000 });
  const { w, h, webgl, webgpu } = await readParity(page);
  await expect(page.getByTestId('parity-backend')).toHaveText(/\(WebGPU\)$/);
  const away = awayFromEdges(webgl, webgpu, w, h);
  console.log(`parity, KTX2 model: ${JSON.stringify({ w, h, away })}`);
  expect(away.lit, 'something is drawn').toBeGreaterThan(0.05 * w * h);
  // The uncompressed model's bound (playground-webgpu-parity.spec.ts).
  expect(away.max, 'largest channel difference away from edges, 1/255').toBeLessThanOrEqual(2);
  expect(away.mean, 'mean channel difference away from edges, 1/255').toBeLessThanOrEqual(0.05);
  expect(away.coverage, 'pixels lit in one picture only').toBeLessThanOrEqual(0.001 * away.lit);
  expect(problems).toEqual([]);
});
