/**
 * Deterministic Playwright runs for three.js scenes: the Chromium lookup, the software-rendering flags (SwiftShader,
 * or Mesa's llvmpipe on Xvfb) and a config preset that names baselines without the platform. The matchers are in
 * `@shadelab/playwright/test` (`toHaveRendered`, `toMatchScreenshotAcrossGpus`, `toMatchAcrossRenderers`,
 * `expectBackend`) and `@shadelab/playwright/reference` (`toMatchReference`); the page side of
 * `toMatchAcrossRenderers` is `@shadelab/playwright/page`.
 * @module @shadelab/playwright
 * @mergeModuleWith <project>
 */
export {
  type ChromiumChecks,
  type ChromiumLookup,
  chromiumArgs,
  chromiumExecutable,
  DEBIAN_CHROMIUM,
  describeBrowserSearch,
  lookupChromium,
  webgpuArgs,
} from './chromium.js';
export {
  type ShadelabPresetOptions,
  type ShadelabUse,
  SNAPSHOT_PATH_TEMPLATE,
  shadelabPreset,
  shadelabUse,
  XVFB_GLOBAL_SETUP,
} from './shadelabPreset.js';
export { findXvfb, startXvfb, type XvfbOptions, type XvfbServer } from './xvfb.js';
