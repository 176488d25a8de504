import { defineConfig } from '@playwright/test';
import { shadelabPreset, shadelabUse, XVFB_GLOBAL_SETUP } from '@shadelab/playwright';

const port = Number(process.env.SHADELAB_E2E_PORT ?? 4173);

// @shadelab/playwright's preset, as users get it: Chromium from $SHADELAB_CHROMIUM, /usr/bin/chromium or
// Playwright's own browser (a SHADELAB_CHROMIUM that names no file stops the run, as `npm test` does, rather than
// testing another browser), launched with the SwiftShader flags, whose renders are pixel-deterministic: one
// baseline for every platform (named without it) and exact screenshot comparisons.
export default defineConfig(shadelabPreset(), {
  testDir: 'tests',
  fullyParallel: true,
  // Three workers on two cores: a test waits on its page (a settle, a readback, an install) for part of its time,
  // and a third worker's browser draws then; the gate keeps both cores busy.
  workers: 3,
  retries: 0,
  // A margin, not a guess: under the gate's own load (three workers on two cores, or `npm run test:loaded`) every
  // test stays under a quarter of its timeout; `npm test` prints the ten nearest theirs.
  timeout: 120_000,
  // A wait on the page that fails within 5 s under load is a flake, not a finding: assertions wait up to 10 s.
  expect: { timeout: 10_000 },
  reporter: [['list'], ['json', { outputFile: 'reports/playwright.json' }]],
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    viewport: { width: 800, height: 600 },
  },
  // The second rasteriser: the kit's llvmpipe mode (headed Chromium on an Xvfb that XVFB_GLOBAL_SETUP starts for
  // the run, WebGL drawn by Mesa's llvmpipe) runs the kit's cross-rasteriser spec against SwiftShader's baselines.
  globalSetup: XVFB_GLOBAL_SETUP,
  projects: [
    { name: 'swiftshader' },
    {
      name: 'llvmpipe',
      testMatch: 'playwright-kit-rasterisers.spec.ts',
      use: shadelabUse({ rasteriser: 'llvmpipe' }),
    },
  ],
  webServer: {
    // Each port builds into its own folder, so parallel runs (and `npm start`) never share an output: the
    // playground, then the tests' harness pages (tests/harness/, at /harness/?page=<name>) beside it, one server
    // (scripts/e2e-build.mjs); with SHADELAB_E2E_BUILT set (`npm test` builds in a stage of its own) it serves
    // that build as it is.
    command: [
      ...(process.env.SHADELAB_E2E_BUILT ? [] : [`node scripts/e2e-build.mjs --port ${port}`]),
      `npx vite preview playground --outDir dist-e2e-${port} --host 127.0.0.1 --port ${port} --strictPort`,
    ].join(' && '),
    url: `http://127.0.0.1:${port}`,
    reuseExistingServer: !process.env.CI,
    timeout: 180_000,
  },
});
