// toHaveRendered on WebGPU canvases: Chromium launched by the kit's preset with webgpu: true (a WebGPU adapter,
// SwiftShader's). A context never configured and a device that is lost fail, each with its own message.
import type { Page } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import { expect, test } from '@shadelab/playwright/test';

test.use(shadelabUse({ webgpu: true }));

/** The message of a failing assertion. */
async function failure(assertion: Promise<unknown>): Promise<string> {
  const error = await assertion.then(
    () => undefined,
    (e: unknown) => e,
  );
  if (!(error instanceof Error)) throw new Error('the assertion passed; it should have failed');
  return error.message;
}

/** A page (a secure origin: WebGPU needs one) whose module script gets a device and a WebGPU context. */
async function openGpuCanvas(page: Page, script: string) {
  await page.route('https://kit.test/', (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><body style="margin:0"><canvas width="64" height="48" style="display:block"></canvas><script type="module">const canvas = document.querySelector('canvas'); const adapter = await navigator.gpu.requestAdapter(); const device = await adapter.requestDevice(); const context = canvas.getContext('webgpu'); ${script} document.body.dataset.ready = '1';</script></body>`,
    }),
  );
  await page.goto('https://kit.test/');
  await page.waitForFunction(() => document.body.dataset.ready === '1');
  return page.locator('canvas');
}

test('fails on a context never configured with a device, and on a lost device, saying which', async ({
  page,
}) => {
  const unconfigured = await openGpuCanvas(page, '');
  expect(await failure(expect(unconfigured).toHaveRendered({ timeout: 5_000 }))).toContain(
    'its WebGPU context was never configured with a device (context.configure)',
  );
  const lost = await openGpuCanvas(
    page,
    'context.configure({ device, format: navigator.gpu.getPreferredCanvasFormat() }); device.destroy(); await device.lost;',
  );
  expect(await failure(expect(lost).toHaveRendered({ timeout: 5_000 }))).toContain(
    'its WebGPU device is lost (device.lost has resolved)',
  );
});
