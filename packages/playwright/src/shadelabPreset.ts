import type { LaunchOptions, PlaywrightTestConfig } from '@playwright/test';
import {
  type ChromiumChecks,
  chromiumArgs,
  describeBrowserSearch,
  lookupChromium,
  webgpuArgs,
} from './chromium.js';

/**
 * Baselines named without the platform or the project (`lecture.png`, not `lecture-chromium-linux.png`): the
 * flags make every machine render the same pixels, so one baseline serves them all. Folders follow the test
 * files: `<testDir>/__screenshots__/<test file path>/<name><ext>`.
 */
export const SNAPSHOT_PATH_TEMPLATE = '{testDir}/__screenshots__/{testFilePath}/{arg}{ext}';

/** The flags that select SwiftShader, left out with `gpu: true`. */
const SWIFTSHADER_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

/** Options of {@link shadelabUse} and {@link shadelabPreset}. */
export interface ShadelabPresetOptions {
  /**
   * Render on the machine's GPU instead of SwiftShader: the two SwiftShader flags are left out and
   * `--ignore-gpu-blocklist` is added. Pictures then vary by GPU: compare them with
   * `toMatchScreenshotAcrossGpus`. @default false
   */
  gpu?: boolean;
  /**
   * Also launch Chromium with WebGPU ({@link webgpuArgs}): a WebGPU adapter (SwiftShader's on a machine
   * without a GPU). @default false
   */
  webgpu?: boolean;
  /** More launch flags, after the deterministic ones. @default [] */
  args?: readonly string[];
  /** The checks of the Chromium lookup (tests fake them). @default the real environment and file system */
  checks?: ChromiumChecks;
}

/** What {@link shadelabUse} returns: the `use` block of a Playwright config or project. */
export interface ShadelabUse {
  /** The browser: Chromium. */
  browserName: 'chromium';
  /** Chromium from the lookup, launched with the deterministic flags. */
  launchOptions: LaunchOptions;
  /** One device pixel per CSS pixel, so a canvas screenshot is its drawing buffer. */
  deviceScaleFactor: number;
}

/**
 * The `use` block for deterministic pictures: Chromium found as {@link lookupChromium} finds it
 * (`$SHADELAB_CHROMIUM`, then `/usr/bin/chromium`, then Playwright's own browser), launched with
 * {@link chromiumArgs} (WebGL on SwiftShader; `gpu: true` for the machine's GPU), one device pixel per CSS
 * pixel.
 *
 * @throws Error when `$SHADELAB_CHROMIUM` names a missing file, or when no Chromium is found (the message
 * lists what was searched and how to install one).
 */
export function shadelabUse({
  gpu = false,
  webgpu = false,
  args = [],
  checks,
}: ShadelabPresetOptions = {}): ShadelabUse {
  const browser = lookupChromium(checks);
  if (browser.problem !== undefined) throw new Error(browser.problem);
  if (browser.executable === null) {
    throw new Error(`no Chromium for Playwright. ${describeBrowserSearch(browser)}`);
  }
  const base = gpu
    ? [...chromiumArgs.filter((a) => !SWIFTSHADER_ARGS.includes(a)), '--ignore-gpu-blocklist']
    : chromiumArgs;
  const launchOptions: LaunchOptions = { args: [...base, ...(webgpu ? webgpuArgs : []), ...args] };
  // undefined: Playwright's own browser, which Playwright finds by itself.
  if (browser.executable !== undefined) launchOptions.executablePath = browser.executable;
  return { browserName: 'chromium', launchOptions, deviceScaleFactor: 1 };
}

/**
 * A Playwright config for deterministic pictures, to merge with your own:
 * `export default defineConfig(shadelabPreset(), { testDir: 'tests', webServer: … })`. It sets
 * {@link shadelabUse} as `use`, baselines named without the platform ({@link SNAPSHOT_PATH_TEMPLATE}) and
 * exact screenshot comparisons (`toHaveScreenshot` with `maxDiffPixels: 0, threshold: 0`: SwiftShader renders
 * the same pixels everywhere).
 *
 * @throws Error as {@link shadelabUse} does when no Chromium is found.
 */
export function shadelabPreset(options: ShadelabPresetOptions = {}): PlaywrightTestConfig {
  return {
    snapshotPathTemplate: SNAPSHOT_PATH_TEMPLATE,
    expect: { toHaveScreenshot: { maxDiffPixels: 0, threshold: 0 } },
    use: shadelabUse(options),
  };
}
