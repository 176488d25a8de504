import { defineConfig } from '@playwright/test';
import { chromiumArgs, lookupChromium } from './scripts/browser.mjs';

const port = Number(process.env.SHADELAB_E2E_PORT ?? 4173);
const browser = lookupChromium();
// A SHADELAB_CHROMIUM that names no file stops the run, as `npm test` does, rather than testing another browser.
if (browser.problem) throw new Error(browser.problem);
const executablePath = browser.executable ?? undefined;

export default defineConfig({
  testDir: 'tests',
  // Renders are pixel-deterministic under SwiftShader with these flags: one baseline for every platform.
  snapshotPathTemplate: '{testDir}/__screenshots__/{testFilePath}/{arg}{ext}',
  fullyParallel: true,
  workers: 2,
  retries: 0,
  timeout: 60_000,
  reporter: [['list'], ['json', { outputFile: 'reports/playwright.json' }]],
  expect: { toHaveScreenshot: { maxDiffPixels: 0, threshold: 0 } },
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    viewport: { width: 800, height: 600 },
    deviceScaleFactor: 1,
    launchOptions: { executablePath, args: chromiumArgs },
  },
  webServer: {
    // Each port builds into its own folder, so parallel runs (and `npm start`) never share an output.
    command: `npx vite build playground --outDir dist-e2e-${port} --emptyOutDir --logLevel warn && npx vite preview playground --outDir dist-e2e-${port} --host 127.0.0.1 --port ${port} --strictPort`,
    url: `http://127.0.0.1:${port}`,
    reuseExistingServer: !process.env.CI,
    timeout: 180_000,
  },
});
