/*
 * Playwright global setup for the llvmpipe rasteriser: when a project of the config runs Chromium with
 * `rasteriser: 'llvmpipe'`, start one Xvfb for the run and hand its display to the workers (the environment
 * variable `SHADELAB_XVFB_DISPLAY`, which the preset's launch options read); stop it when the run ends. Named
 * in a config by its path, XVFB_GLOBAL_SETUP; `shadelabPreset({ rasteriser: 'llvmpipe' })` sets it.
 */
import type { FullConfig } from '@playwright/test';
import { startXvfb } from './xvfb.js';

/** The environment variable that carries the display of the kit's Xvfb to the workers. */
export const XVFB_DISPLAY_ENV = 'SHADELAB_XVFB_DISPLAY';

/** Whether any project launches Chromium in the llvmpipe mode (the preset marks its launch environment). */
export function usesLlvmpipe(config: Pick<FullConfig, 'projects'>): boolean {
  return config.projects.some((p) => {
    const env = (p.use as { launchOptions?: { env?: Record<string, unknown> } } | undefined)?.launchOptions
      ?.env;
    return env?.SHADELAB_RASTERISER === 'llvmpipe';
  });
}

/** The global setup: see the module's description. Returns the teardown (stops Xvfb), or nothing when not needed. */
export default async function xvfbGlobalSetup(
  config: FullConfig,
): Promise<(() => Promise<void>) | undefined> {
  if (process.env[XVFB_DISPLAY_ENV] !== undefined || !usesLlvmpipe(config)) return undefined;
  let server: Awaited<ReturnType<typeof startXvfb>>;
  try {
    server = await startXvfb();
  } catch (error) {
    // The other projects still run; the llvmpipe project's browsers then fail to launch, saying there is no X
    // server (unless DISPLAY names one).
    console.warn(`shadelab: the llvmpipe rasteriser has no X server: ${(error as Error).message}`);
    return undefined;
  }
  process.env[XVFB_DISPLAY_ENV] = server.display;
  return async () => {
    delete process.env[XVFB_DISPLAY_ENV];
    await server.stop();
  };
}
