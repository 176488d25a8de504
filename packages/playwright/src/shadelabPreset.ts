import { fileURLToPath } from 'node:url';
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

/** The flags that select SwiftShader, left out with `gpu: true` and with the llvmpipe rasteriser. */
const SWIFTSHADER_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

/**
 * The path of the kit's Playwright global setup for the llvmpipe rasteriser: it starts one Xvfb for the run
 * when a project uses `rasteriser: 'llvmpipe'` and stops it at the end. `shadelabPreset({ rasteriser:
 * 'llvmpipe' })` sets it; a config that puts the llvmpipe mode in one project sets `globalSetup:
 * XVFB_GLOBAL_SETUP` itself.
 */
export const XVFB_GLOBAL_SETUP: string = fileURLToPath(new URL('./xvfbGlobalSetup.js', import.meta.url));

/** What the browser of the llvmpipe mode keeps of the environment (nothing else, so no secret is copied). */
const KEPT_ENV = ['PATH', 'HOME', 'TMPDIR', 'LANG', 'XDG_RUNTIME_DIR', 'FONTCONFIG_PATH'];

/**
 * The launch environment of the llvmpipe mode: the display of the kit's Xvfb (`SHADELAB_XVFB_DISPLAY`, set by
 * the global setup before the workers start) or else `DISPLAY`, and Mesa told to draw in software with llvmpipe.
 */
function llvmpipeEnv(env: Record<string, string | undefined>): Record<string, string> {
  const out: Record<string, string> = {};
  for (const k of KEPT_ENV) if (env[k] !== undefined) out[k] = env[k] as string;
  const display = env.SHADELAB_XVFB_DISPLAY ?? env.DISPLAY;
  if (display !== undefined) out.DISPLAY = display;
  out.LIBGL_ALWAYS_SOFTWARE = '1';
  out.GALLIUM_DRIVER = 'llvmpipe';
  out.SHADELAB_RASTERISER = 'llvmpipe';
  return out;
}

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
  /**
   * The software rasteriser of WebGL: `'swiftshader'` (headless; the same pixels on every machine) or
   * `'llvmpipe'`: Chromium headed on a virtual X server (Xvfb, which the kit's global setup starts, see
   * {@link XVFB_GLOBAL_SETUP}), without the SwiftShader flags and with `--ignore-gpu-blocklist`, so that WebGL
   * is drawn by Mesa's llvmpipe (OpenGL 4.5 through ANGLE): deterministic run to run, and a second rasteriser
   * to check cross-GPU tolerances against. With `webgpu: true` its WebGPU adapter stays SwiftShader's, and a
   * WebGPU canvas presents. Not with `gpu: true`. @default 'swiftshader'
   */
  rasteriser?: 'swiftshader' | 'llvmpipe';
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
  /** False in the llvmpipe mode (Chromium headed, on Xvfb); not set otherwise (Playwright's default, true). */
  headless?: boolean;
}

/**
 * The `use` block for deterministic pictures: Chromium found as {@link lookupChromium} finds it
 * (`$SHADELAB_CHROMIUM`, then `/usr/bin/chromium`, then Playwright's own browser), launched with
 * {@link chromiumArgs} (WebGL on SwiftShader; `rasteriser: 'llvmpipe'` for Mesa's llvmpipe on Xvfb; `gpu:
 * true` for the machine's GPU), one device pixel per CSS pixel.
 *
 * @throws Error when `$SHADELAB_CHROMIUM` names a missing file, or when no Chromium is found (the message
 * lists what was searched and how to install one); TypeError for an unknown `rasteriser` or one given with
 * `gpu: true`.
 */
export function shadelabUse({
  gpu = false,
  webgpu = false,
  rasteriser = 'swiftshader',
  args = [],
  checks,
}: ShadelabPresetOptions = {}): ShadelabUse {
  if (rasteriser !== 'swiftshader' && rasteriser !== 'llvmpipe') {
    throw new TypeError(
      `shadelabUse: rasteriser must be 'swiftshader' or 'llvmpipe', got ${String(rasteriser)}`,
    );
  }
  if (gpu && rasteriser === 'llvmpipe') {
    throw new TypeError(
      "shadelabUse: rasteriser 'llvmpipe' is a software rasteriser: it cannot go with gpu: true",
    );
  }
  const browser = lookupChromium(checks);
  if (browser.problem !== undefined) throw new Error(browser.problem);
  if (browser.executable === null) {
    throw new Error(`no Chromium for Playwright. ${describeBrowserSearch(browser)}`);
  }
  const llvmpipe = rasteriser === 'llvmpipe';
  const base =
    gpu || llvmpipe
      ? [...chromiumArgs.filter((a) => !SWIFTSHADER_ARGS.includes(a)), '--ignore-gpu-blocklist']
      : chromiumArgs;
  const launchOptions: LaunchOptions = { args: [...base, ...(webgpu ? webgpuArgs : []), ...args] };
  // undefined: Playwright's own browser, which Playwright finds by itself.
  if (browser.executable !== undefined) launchOptions.executablePath = browser.executable;
  if (!llvmpipe) return { browserName: 'chromium', launchOptions, deviceScaleFactor: 1 };
  // Playwright's own --enable-unsafe-swiftshader stays: WebGPU's adapter needs it, and WebGL still takes Mesa
  // (expectBackend(page, 'webgl2', { rasteriser: 'llvmpipe' }) proves it).
  launchOptions.headless = false;
  launchOptions.env = llvmpipeEnv(checks?.env ?? process.env);
  return { browserName: 'chromium', launchOptions, deviceScaleFactor: 1, headless: false };
}

/**
 * A Playwright config for deterministic pictures, to merge with your own:
 * `export default defineConfig(shadelabPreset(), { testDir: 'tests', webServer: … })`. It sets
 * {@link shadelabUse} as `use`, baselines named without the platform ({@link SNAPSHOT_PATH_TEMPLATE}) and
 * exact screenshot comparisons (`toHaveScreenshot` with `maxDiffPixels: 0, threshold: 0`: SwiftShader renders
 * the same pixels everywhere). With `rasteriser: 'llvmpipe'` it also sets `globalSetup` to
 * {@link XVFB_GLOBAL_SETUP}, which starts the Xvfb the headed Chromium draws on.
 *
 * @throws Error as {@link shadelabUse} does when no Chromium is found.
 */
export function shadelabPreset(options: ShadelabPresetOptions = {}): PlaywrightTestConfig {
  return {
    snapshotPathTemplate: SNAPSHOT_PATH_TEMPLATE,
    expect: { toHaveScreenshot: { maxDiffPixels: 0, threshold: 0 } },
    use: shadelabUse(options),
    ...(options.rasteriser === 'llvmpipe' ? { globalSetup: XVFB_GLOBAL_SETUP } : {}),
  };
}
