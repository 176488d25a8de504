/**
 * The comparison with the exact reference: `expect` (everything of `@shadelab/playwright/test`, and
 * `toMatchReference(scene, budget)`) and `referenceSceneOf`, which reads the scene from the app's own three.js
 * objects. Needs `@shadelab/reference` (and `@shadelab/material`, which it depends on) installed.
 * @module @shadelab/playwright/reference
 */
import type { Expect } from '@playwright/test';
import { expect as testExpect } from './test.js';
import type { toHaveRendered } from './toHaveRendered.js';
import type { toMatchAcrossRenderers } from './toMatchAcrossRenderers.js';
import { toMatchReference } from './toMatchReference.js';
import type { toMatchScreenshotAcrossGpus } from './toMatchScreenshotAcrossGpus.js';

export {
  type ReferenceMaterialLike,
  type ReferenceScene,
  referenceSceneOf,
  type SceneObjects,
} from './referenceSceneOf.js';
export { test } from './test.js';
export type { ReferenceBudget, ReferenceOptions } from './toMatchReference.js';

/**
 * The `expect` of `@shadelab/playwright/test` (`toHaveRendered`, `toMatchScreenshotAcrossGpus`,
 * `toMatchAcrossRenderers`) with
 * `await expect(canvas).toMatchReference(scene, budget)`: the canvas against `renderReference` of the same
 * scene, within a budget of RMSE, max (8-bit sRGB codes) and silhouette error (px).
 */
export const expect: Expect<{
  toHaveRendered: typeof toHaveRendered;
  toMatchScreenshotAcrossGpus: typeof toMatchScreenshotAcrossGpus;
  toMatchAcrossRenderers: typeof toMatchAcrossRenderers;
  toMatchReference: typeof toMatchReference;
}> = testExpect.extend({ toMatchReference });
