/**
 * The test fixture: `test` (Playwright's, recording the context of every canvas its pages create) and
 * `expect` with `toHaveRendered()`, `toMatchScreenshotAcrossGpus()` and `toMatchAcrossRenderers()`;
 * `expectBackend`, `waitForFirstFrame`, `readCanvas` and the picture tools they use. The comparison with the exact reference is in `@shadelab/playwright/reference`.
 * @module @shadelab/playwright/test
 */
import {
  test as base,
  expect as baseExpect,
  type Expect,
  type PlaywrightTestArgs,
  type PlaywrightTestOptions,
  type PlaywrightWorkerArgs,
  type PlaywrightWorkerOptions,
  type TestType,
} from '@playwright/test';
import { recordCanvasContexts } from './canvasContexts.js';
import { toHaveRendered } from './toHaveRendered.js';
import { toMatchAcrossRenderers } from './toMatchAcrossRenderers.js';
import { toMatchScreenshotAcrossGpus } from './toMatchScreenshotAcrossGpus.js';

export type { CanvasState } from './canvasContexts.js';
export { recordCanvasContexts } from './canvasContexts.js';
export { compareNeighbourhood, type NeighbourhoodComparison } from './compareNeighbourhood.js';
export { type BackendInfo, type ExpectBackendOptions, expectBackend } from './expectBackend.js';
export {
  GPU_TOLERANCE,
  GPU_TOLERANCE_HARD_EDGES,
  type GpuTolerance,
  RENDERER_TOLERANCE,
} from './gpuTolerance.js';
export type { SceneContext, SceneFactory, SceneSetup } from './page.js';
export { type PictureSummary, summarisePicture } from './picture.js';
export { decodePng, encodePng, flipRows, type RgbaImage } from './png.js';
export {
  type BackendProof,
  type Rasteriser,
  RENDERER_NAMES,
  type RendererName,
  rasteriserOf,
} from './rendererNames.js';
export { type RenderedFrame, type RenderedOptions, readCanvas, waitForFirstFrame } from './toHaveRendered.js';
export type { AcrossRenderersOptions } from './toMatchAcrossRenderers.js';
export type { AcrossGpusOptions } from './toMatchScreenshotAcrossGpus.js';

/**
 * Playwright's `test`, with an automatic fixture that records the context of every canvas in every page of
 * the test (an init script), so that `toHaveRendered` can tell a canvas without a context, or with a lost
 * WebGPU device, from a blank one.
 */
export const test: TestType<
  PlaywrightTestArgs & PlaywrightTestOptions & { shadelabCanvasContexts: undefined },
  PlaywrightWorkerArgs & PlaywrightWorkerOptions
> = base.extend<{ shadelabCanvasContexts: undefined }>({
  shadelabCanvasContexts: [
    async ({ context }, use) => {
      await context.addInitScript(recordCanvasContexts);
      await use(undefined);
    },
    { auto: true },
  ],
});

/**
 * Playwright's `expect`, with two matchers for a canvas locator and one for a page:
 * - `await expect(canvas).toHaveRendered(options?)`: a live WebGL, WebGPU or 2D context and a picture that is
 *   not blank, waiting up to the timeout (see `RenderedOptions`);
 * - `await expect(canvas).toMatchScreenshotAcrossGpus(name, tolerance?)`: the screenshot against a baseline
 *   within the measured variation between rasterisers (`GPU_TOLERANCE`), for runs on real GPUs;
 * - `await expect(page).toMatchAcrossRenderers(scene, options?)`: the scene drawn by WebGLRenderer and by
 *   WebGPURenderer on both backends (the backend proven), the pictures within `RENDERER_TOLERANCE` of each
 *   other (see `AcrossRenderersOptions`; the page calls `exposeRenderers()` of `@shadelab/playwright/page`).
 */
export const expect: Expect<{
  toHaveRendered: typeof toHaveRendered;
  toMatchScreenshotAcrossGpus: typeof toMatchScreenshotAcrossGpus;
  toMatchAcrossRenderers: typeof toMatchAcrossRenderers;
}> = baseExpect.extend({ toHaveRendered, toMatchScreenshotAcrossGpus, toMatchAcrossRenderers });
