// The parity view (issue 23): WebGL mode's and WebGPU mode's pictures of the same state side by side, with the
// heat map of their difference and its numbers, in Chromium with the kit's WebGPU flags. WebGPU's picture is
// drawn offscreen (never presented: headless Chromium loses a WebGPU device that presents a canvas) by the same
// code that draws WebGPU mode, on WebGPURenderer's WebGPU backend, which the page names and the test checks.
// Every scene of the picker (the user's model too) and the impostor are drawn within a stated bound of WebGL
// mode's picture away from edges, and the numbers shown equal a recomputation from the two read-backs.
import { expect, type Page } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import { test } from './harness-helpers';
import { open, settle, urlState } from './playground-helpers';
import { awayFromEdges, parityNumbers, readParity, watchProblems } from './playground-webgpu-helpers';

test.use(shadelabUse({ webgpu: true, args: ['--shadelab-own-browser=playground-webgpu-parity'] }));

/** A model's GLB made by three's GLTFExporter in the harness page (as tests/playground-model.spec.ts makes it). */
async function texturedModel(page: Page): Promise<Buffer> {
  const maker = await page.context().newPage();
  await maker.goto('/harness/?page=gltf-maker');
  await maker.waitForFunction(
    () => typeof (window as unknown as { makeModel?: unknown }).makeModel === 'function',
  );
  const bytes = await maker.evaluate(() =>
    (window as unknown as { makeModel(k: string): Promise<number[]> }).makeModel('textured'),
  );
  await maker.close();
  return Buffer.from(bytes);
}

/**
 * The states compared: every scene of the picker with the default panel (the user's model below), and the
 * sphere's impostor, cel bands with the outline, and flat shading.
 */
const SCENES: { name: string; state: object }[] = [
  { name: 'the lecture’s sphere', state: {} },
  { name: 'the impostor', state: { sphere: { render: 'impostor' } } },
  { name: 'cel bands and the outline', state: { material: { celBands: 4, outline: true } } },
  { name: 'flat shading', state: { material: { shading: 'flat' } } },
  { name: 'instanced spheres', state: { scene: 'instanced' } },
  { name: 'skinned + morphing mesh', state: { scene: 'skinned' } },
  { name: 'textured, normal map (phong)', state: { scene: 'textured' } },
  { name: 'textured (gouraud)', state: { scene: 'textured', material: { shading: 'gouraud' } } },
  { name: 'three’s lights, fog, clipping', state: { scene: 'lights' } },
];

/**
 * Reads the parity view, checks that WebGPU's half ran on the WebGPU backend and that the numbers shown are the
 * ones recomputed from the two read-backs, and returns the comparison away from edges (logged).
 */
async function compared(page: Page, name: string) {
  // Proof of the backend: the page names it from three's `backend.isWebGPUBackend` (never the WebGL2 fallback).
  await expect(page.getByTestId('parity-backend')).toHaveText(/\(WebGPU\)$/, { timeout: 60_000 });
  const { w, h, webgl, webgpu, numbers } = await readParity(page);
  await expect(page.getByTestId('parity-backend')).toHaveText(/\(WebGPU\)$/);
  const { coverage, ...shown } = numbers;
  expect(shown).toEqual(parityNumbers(webgl, webgpu, w, h));
  const away = awayFromEdges(webgl, webgpu, w, h);
  const timestamps = await page.evaluate(async () => {
    const gpu = (
      navigator as unknown as { gpu: { requestAdapter(): Promise<{ features: Set<string> } | null> } }
    ).gpu;
    return (await gpu.requestAdapter())?.features.has('timestamp-query') ?? false;
  });
  console.log(`parity, ${name}: ${JSON.stringify({ w, h, numbers, away, timestamps })}`);
  expect(away.lit, 'something is drawn').toBeGreaterThan(0.05 * w * h);
  expect(away.compared, 'pixels compared away from edges').toBeGreaterThan(0.6 * w * h);
  return { w, h, webgl, webgpu, numbers, away };
}

/**
 * The bound (measured: max 1–2 away from edges, mean ≤ 0.03; coverage equal but for 12 pixels on the impostor's
 * silhouette): within 2/255 away from edges, mean ≤ 0.05/255, coverage differing on at most 0.1 % of the lit
 * pixels.
 */
function withinBound({ away }: Awaited<ReturnType<typeof compared>>) {
  expect(away.max, 'largest channel difference away from edges, 1/255').toBeLessThanOrEqual(2);
  expect(away.mean, 'mean channel difference away from edges, 1/255').toBeLessThanOrEqual(0.05);
  expect(away.coverage, 'pixels lit in one picture only').toBeLessThanOrEqual(0.001 * away.lit);
}

test.describe('the parity view on the WebGPU backend (offscreen)', () => {
  for (const { name, state } of SCENES) {
    test(`${name}: WebGPU mode draws WebGL mode’s picture; the numbers are the read-backs’`, async ({
      page,
    }) => {
      test.setTimeout(120_000);
      const problems = watchProblems(page);
      await open(page, { view: 'parity', ...state });
      const result = await compared(page, name);
      if ((state as { scene?: string }).scene === 'lights') {
        // three's node fog blends in linear before the output conversion, WebGL's fog_fragment after it (the
        // material's WebGPU guide): the fogged far part differs, as it does for three's own materials (measured
        // max 61 away from edges, mean 0.9). Nearer than the fog (the lower 30 % of this portrait picture: the
        // ground in front, the box, the clipped sphere's cut) the bound holds.
        const { w, h, webgl, webgpu } = result;
        const rows = Math.floor(0.3 * h);
        const near = awayFromEdges(
          webgl.subarray(0, 4 * w * rows),
          webgpu.subarray(0, 4 * w * rows),
          w,
          rows,
        );
        expect(near.max, 'nearer than the fog, away from edges').toBeLessThanOrEqual(2);
        expect(result.away.max, 'in the fog, away from edges').toBeLessThanOrEqual(96);
        expect(result.away.mean).toBeLessThanOrEqual(1.5);
      } else {
        withinBound(result);
      }
      expect(problems).toEqual([]);
    });
  }

  test('your model (a textured glTF, swapped with swapNodeMaterials): WebGPU mode draws WebGL mode’s picture', async ({
    page,
  }) => {
    test.setTimeout(120_000);
    const problems = watchProblems(page);
    const glb = await texturedModel(page);
    await open(page, { view: 'parity' });
    await page
      .getByTestId('model-file')
      .setInputFiles({ name: 'textured.glb', mimeType: 'model/gltf-binary', buffer: glb });
    await expect(page.getByTestId('model-note')).toContainText('“textured.glb”', { timeout: 20_000 });
    await settle(page);
    expect((await urlState(page))['scene']).toBe('model');
    withinBound(await compared(page, 'your model'));
    expect(problems).toEqual([]);
  });
});
