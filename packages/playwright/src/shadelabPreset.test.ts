import { existsSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { chromiumArgs, DEBIAN_CHROMIUM, webgpuArgs } from './chromium.js';
import { SNAPSHOT_PATH_TEMPLATE, shadelabPreset, shadelabUse, XVFB_GLOBAL_SETUP } from './shadelabPreset.js';
import { usesLlvmpipe } from './xvfbGlobalSetup.js';

const OWN = '/home/u/.cache/ms-playwright/chromium-1/chrome-linux/chrome';

/** The lookup's checks with a fake file system: `present` files exist. */
const checks = (env: Record<string, string | undefined>, present: string[]) => ({
  env,
  exists: (path: string) => present.includes(path),
  playwrightPath: () => OWN,
});

describe('shadelabUse', () => {
  it("launches Debian's Chromium with the deterministic flags, one device pixel per CSS pixel", () => {
    expect(shadelabUse({ checks: checks({}, [DEBIAN_CHROMIUM, OWN]) })).toEqual({
      browserName: 'chromium',
      launchOptions: { executablePath: DEBIAN_CHROMIUM, args: chromiumArgs },
      deviceScaleFactor: 1,
    });
    expect(chromiumArgs).toContain('--use-angle=swiftshader');
    expect(chromiumArgs).toContain('--enable-unsafe-swiftshader');
  });

  it("SHADELAB_CHROMIUM first; Playwright's own browser (no executablePath: Playwright finds it) last", () => {
    const named = shadelabUse({
      checks: checks({ SHADELAB_CHROMIUM: '/opt/chrome' }, ['/opt/chrome', DEBIAN_CHROMIUM]),
    });
    expect(named.launchOptions.executablePath).toBe('/opt/chrome');
    const own = shadelabUse({ checks: checks({}, [OWN]) });
    expect(own.launchOptions).toEqual({ args: chromiumArgs });
  });

  it('adds the WebGPU flag and the flags given, after the deterministic ones', () => {
    const use = shadelabUse({ webgpu: true, args: ['--lang=fr'], checks: checks({}, [DEBIAN_CHROMIUM]) });
    expect(use.launchOptions.args).toEqual([...chromiumArgs, ...webgpuArgs, '--lang=fr']);
    expect(webgpuArgs).toEqual(['--enable-unsafe-webgpu']);
  });

  it('gpu: true leaves SwiftShader out and the GPU block list off, keeping the other flags', () => {
    const use = shadelabUse({ gpu: true, checks: checks({}, [DEBIAN_CHROMIUM]) });
    expect(use.launchOptions.args).toEqual([
      '--disable-background-networking',
      '--disable-component-update',
      '--no-first-run',
      '--ignore-gpu-blocklist',
    ]);
  });

  it("throws the lookup's messages: a SHADELAB_CHROMIUM that does not exist, or no Chromium anywhere", () => {
    expect(() =>
      shadelabUse({ checks: checks({ SHADELAB_CHROMIUM: '/opt/missing' }, [DEBIAN_CHROMIUM]) }),
    ).toThrow('SHADELAB_CHROMIUM is set to /opt/missing, which does not exist');
    expect(() => shadelabUse({ checks: checks({}, []) })).toThrow(
      `no Chromium for Playwright. Looked at $SHADELAB_CHROMIUM (not set), ${DEBIAN_CHROMIUM}, Playwright's own browser (${OWN}). Install one (apt-get install chromium, or npx playwright install chromium) or set SHADELAB_CHROMIUM to a Chromium binary.`,
    );
  });
});

describe("shadelabUse({ rasteriser: 'llvmpipe' })", () => {
  const env = {
    PATH: '/usr/bin',
    HOME: '/home/u',
    SECRET_TOKEN: 'x',
    DISPLAY: ':0',
    SHADELAB_XVFB_DISPLAY: ':42',
  };
  it('launches headed, without the SwiftShader flags, on the display of the kit’s Xvfb, with Mesa in software', () => {
    const use = shadelabUse({ rasteriser: 'llvmpipe', checks: checks(env, [DEBIAN_CHROMIUM]) });
    expect(use.headless).toBe(false);
    expect(use.launchOptions.headless).toBe(false);
    expect(use.launchOptions.args).toEqual([
      '--disable-background-networking',
      '--disable-component-update',
      '--no-first-run',
      '--ignore-gpu-blocklist',
    ]);
    // Only what the browser needs is copied from the environment (no secret reaches the config or a report).
    expect(use.launchOptions.env).toEqual({
      PATH: '/usr/bin',
      HOME: '/home/u',
      DISPLAY: ':42',
      LIBGL_ALWAYS_SOFTWARE: '1',
      GALLIUM_DRIVER: 'llvmpipe',
      SHADELAB_RASTERISER: 'llvmpipe',
    });
    expect(usesLlvmpipe({ projects: [{ use: {} }, { use }] } as never)).toBe(true);
    expect(
      usesLlvmpipe({ projects: [{ use: shadelabUse({ checks: checks(env, [DEBIAN_CHROMIUM]) }) }] } as never),
    ).toBe(false);
  });

  it('takes DISPLAY when the kit’s Xvfb is not running (xvfb-run), and the WebGPU flag when asked', () => {
    const use = shadelabUse({
      rasteriser: 'llvmpipe',
      webgpu: true,
      checks: checks({ DISPLAY: ':99' }, [DEBIAN_CHROMIUM]),
    });
    expect(use.launchOptions.env?.DISPLAY).toBe(':99');
    expect(use.launchOptions.args).toContain('--enable-unsafe-webgpu');
  });

  it('refuses an unknown rasteriser, and llvmpipe with gpu: true', () => {
    expect(() =>
      shadelabUse({ rasteriser: 'angle' as never, checks: checks({}, [DEBIAN_CHROMIUM]) }),
    ).toThrow(new TypeError("shadelabUse: rasteriser must be 'swiftshader' or 'llvmpipe', got angle"));
    expect(() =>
      shadelabUse({ rasteriser: 'llvmpipe', gpu: true, checks: checks({}, [DEBIAN_CHROMIUM]) }),
    ).toThrow("shadelabUse: rasteriser 'llvmpipe' is a software rasteriser: it cannot go with gpu: true");
  });

  it('the preset adds the global setup that starts Xvfb, a file that exists once built', () => {
    const config = shadelabPreset({ rasteriser: 'llvmpipe', checks: checks(env, [DEBIAN_CHROMIUM]) });
    expect(config.globalSetup).toBe(XVFB_GLOBAL_SETUP);
    expect(XVFB_GLOBAL_SETUP).toMatch(/xvfbGlobalSetup\.js$/);
    expect(existsSync(XVFB_GLOBAL_SETUP.replace(/\.js$/, '.ts'))).toBe(true);
    expect(shadelabPreset({ checks: checks(env, [DEBIAN_CHROMIUM]) }).globalSetup).toBeUndefined();
  });
});

describe('shadelabPreset', () => {
  it('names baselines without the platform, compares screenshots exactly and uses shadelabUse', () => {
    const config = shadelabPreset({ checks: checks({}, [DEBIAN_CHROMIUM]) });
    expect(config.snapshotPathTemplate).toBe('{testDir}/__screenshots__/{testFilePath}/{arg}{ext}');
    expect(SNAPSHOT_PATH_TEMPLATE).not.toMatch(/platform|projectName/);
    expect(config.expect).toEqual({ toHaveScreenshot: { maxDiffPixels: 0, threshold: 0 } });
    expect(config.use).toEqual(shadelabUse({ checks: checks({}, [DEBIAN_CHROMIUM]) }));
  });
});
