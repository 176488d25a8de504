// The playground's renderer switch with the kit's WebGPU flags (Chromium exposes SwiftShader's WebGPU adapter).
// What happens on this machine, every run: WebGPU mode opens WebGPURenderer's WebGPU backend and says "WebGPU",
// with the WGSL of the node material in the shader panel; presenting its canvas headless then loses the device
// (Chromium drops the WebGPU instance), which the page reports and survives: the WebGL2 backend takes over on a
// new canvas, says why, and draws WebGL mode's picture within 2/255 away from edges, with the GLSL in the panel.
// No uncaught error on the way. Without the flags: playground-webgpu.spec.ts.
import { expect } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import { test } from './harness-helpers';
import { choose, open, settle, urlState } from './playground-helpers';
import { expectSamePicture, recordReports, shot, toWebGPU, watchProblems } from './playground-webgpu-helpers';

// The lost device restarts Chromium's GPU process: a switch no other spec passes (Chromium ignores it) gives this
// file a browser of its own, so the restart never reaches another spec's pages.
test.use(shadelabUse({ webgpu: true, args: ['--shadelab-own-browser=playground-webgpu-flags'] }));

const LOST = /^Renderer: WebGL2 \(WebGPU's fallback: the WebGPU device was lost: .+\)$/;

test.describe('the renderer switch, with the WebGPU flags', () => {
  test('WebGPU runs (WGSL shown), its presented canvas loses the device, the WebGL2 backend takes over and says so', async ({
    page,
  }) => {
    test.setTimeout(120_000);
    const problems = watchProblems(page);
    await open(page);
    const settings = await urlState(page);
    const webgl = await shot(page);
    const reports = await recordReports(page);
    await toWebGPU(page);
    await expect(page.getByTestId('renderer-backend')).toHaveText(LOST, { timeout: 30_000 });
    await expect(page.getByTestId('shader-language')).toHaveText(/^GLSL generated/, { timeout: 30_000 });
    // The GPU process restarts: the WebGL canvas's context is lost and restored too (the viewer says so), and
    // the WebGL2 backend opens again on a fresh canvas.
    await expect(page.getByTestId('context-message')).toHaveText(/restored/, { timeout: 30_000 });
    await expect(page.getByTestId('viewport-webgpu')).toHaveAttribute('data-frames', /[1-9]/);
    await settle(page);
    const seen = await reports();
    // In order: WebGPU ran, and its shader panel showed WGSL; then the loss and the fallback with GLSL.
    expect(seen.indexOf('Renderer: WebGPU')).toBeGreaterThanOrEqual(0);
    const ran = seen.indexOf('Renderer: WebGPU');
    const wgsl = seen.findIndex((t) => /^WGSL generated .* :: WGSL code$/.test(t));
    const lost = seen.findIndex((t) => LOST.test(t));
    const glsl = seen.findIndex((t) => /^GLSL generated .* :: GLSL code$/.test(t));
    expect(ran, seen.join('\n')).toBeGreaterThanOrEqual(0);
    expect(wgsl, seen.join('\n')).toBeGreaterThan(ran);
    expect(lost, seen.join('\n')).toBeGreaterThan(wgsl);
    expect(glsl, seen.join('\n')).toBeGreaterThan(lost);
    expect(
      await page
        .getByTestId('viewport-webgpu')
        .evaluate((c: HTMLCanvasElement) => c.getContext('webgl2') !== null),
    ).toBe(true);
    expectSamePicture(webgl, await shot(page));
    expect(problems).toEqual([]);

    await choose(page, 'View.renderer', 'WebGL');
    await expect(page.getByTestId('viewport-webgpu')).toHaveCount(0);
    // The screen shows WebGL mode's picture exactly. (Not read with toDataURL: after the GPU process restarted,
    // Chromium gives an empty image of a WebGL canvas that still shows, and reads back, its picture.)
    expect(Buffer.from((await shot(page)).data).equals(Buffer.from(webgl.data))).toBe(true);
    expect(await urlState(page)).toEqual(settings);
  });
});
