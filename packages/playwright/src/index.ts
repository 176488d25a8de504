/**
 * Deterministic Playwright runs for three.js scenes: the Chromium lookup, the software-rendering flags and a
 * config preset that names baselines without the platform. The matchers are in `@shadelab/playwright/test`
 * (`toHaveRendered`, `toMatchScreenshotAcrossGpus`) and `@shadelab/playwright/reference` (`toMatchReference`).
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
} from './shadelabPreset.js';
