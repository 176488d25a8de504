// @shadelab/playwright on two software rasterisers: this spec runs in the default project (headless Chromium,
// WebGL on SwiftShader) and in the `llvmpipe` project (the kit's rasteriser: 'llvmpipe', headed Chromium on the
// Xvfb that the kit's global setup starts, WebGL on Mesa's llvmpipe). The baselines are SwiftShader's: on
// llvmpipe the kit's lecture scene must match them within the kit's GPU tolerances (measured in
// bench/rasterisers.bench.mjs) while differing from them exactly, which validates the tolerances on a second
// rasteriser, not only on shifted pictures. toMatchAcrossRenderers runs on both (on llvmpipe WebGL is llvmpipe
// and WebGPU SwiftShader's adapter), and a WebGPU canvas is presented.
import { type ShadelabUse, shadelabUse } from '@shadelab/playwright';
import {
  expect,
  expectBackend,
  GPU_TOLERANCE,
  GPU_TOLERANCE_HARD_EDGES,
  type Rasteriser,
  test,
  waitForFirstFrame,
} from '@shadelab/playwright/test';
import type { KitSceneOptions } from './harness/kitScene';

/** The project's rasteriser, read from its launch environment (the preset marks the llvmpipe mode). */
const rasteriserOf = (use: unknown): Exclude<Rasteriser, 'gpu'> =>
  (use as Partial<ShadelabUse>).launchOptions?.env?.SHADELAB_RASTERISER === 'llvmpipe'
    ? 'llvmpipe'
    : 'swiftshader';

// The project's Chromium, with WebGPU as well (shadelabUse({ webgpu: true }) of its own rasteriser).
test.use({
  launchOptions: [
    // biome-ignore lint/correctness/noEmptyPattern: Playwright reads a fixture's dependencies from this pattern: none
    async ({}, use, { project }) =>
      use(shadelabUse({ webgpu: true, rasteriser: rasteriserOf(project.use) }).launchOptions),
    { scope: 'worker' },
  ],
});

test('the browser draws WebGL with the project’s rasteriser, and gives WebGPU', async ({ page }, info) => {
  await page.goto('/harness/?page=kit-renderers');
  const rasteriser = rasteriserOf(info.project.use);
  const gl = await expectBackend(page, 'webgl2', { rasteriser });
  if (rasteriser === 'llvmpipe') expect(gl.description).toMatch(/llvmpipe .*OpenGL 4\.5/);
  await expectBackend(page, 'webgpu', { rasteriser: 'swiftshader' });
});

const scenes: { name: string; options: KitSceneOptions; hardEdges: boolean }[] = [
  { name: 'phong', options: { shading: 'phong' }, hardEdges: false },
  { name: 'gouraud', options: { shading: 'gouraud' }, hardEdges: false },
  { name: 'impostor', options: { shading: 'impostor' }, hardEdges: false },
  { name: 'flat', options: { shading: 'flat', level: 3 }, hardEdges: true },
  { name: 'cel', options: { shading: 'phong', celBands: 4 }, hardEdges: true },
];

test('the lecture scene in each shading matches SwiftShader’s baseline within the GPU tolerance, and on llvmpipe differs from it exactly', async ({
  page,
}, info) => {
  const llvmpipe = rasteriserOf(info.project.use) === 'llvmpipe';
  for (const { name, options, hardEdges } of scenes) {
    await page.goto(`/harness/?page=kit&scene=${encodeURIComponent(JSON.stringify(options))}`);
    const canvas = page.getByTestId('viewport');
    await expect(canvas).toHaveRendered({ timeout: 30_000 });
    const file = `rasteriser-${name}.png`;
    await expect(canvas, name).toMatchScreenshotAcrossGpus(
      file,
      hardEdges ? GPU_TOLERANCE_HARD_EDGES : GPU_TOLERANCE,
    );
    // SwiftShader draws its baseline exactly; llvmpipe does not (so the tolerance above was needed).
    const exactly = { maxChannelDiff: 0, radiusPx: 0, maxDiffPixels: 0 };
    if (llvmpipe) await expect(canvas, name).not.toMatchScreenshotAcrossGpus(file, exactly);
    else await expect(canvas, name).toMatchScreenshotAcrossGpus(file, exactly);
  }
});

test('toMatchAcrossRenderers: three’s MeshPhongMaterial and the lecture’s ShadingMaterial match on every renderer', async ({
  page,
}) => {
  await page.goto('/harness/?page=kit-renderers');
  await expect(page).toMatchAcrossRenderers(
    ({ THREE, width, height }) => {
      const scene = new THREE.Scene();
      scene.background = new THREE.Color(0x000033);
      const material = new THREE.MeshPhongMaterial({ color: 0xc08040, specular: 0x444444, shininess: 30 });
      scene.add(new THREE.Mesh(new THREE.SphereGeometry(1, 48, 24), material));
      const light = new THREE.PointLight(0xffffff, 3 * Math.PI, 0, 0);
      light.position.set(-3, 4, 5);
      scene.add(light, new THREE.AmbientLight(0xffffff, 0.5));
      const camera = new THREE.PerspectiveCamera(45, width / height, 0.1, 10);
      camera.position.set(0, 0, 3.2);
      return { scene, camera };
    },
    { width: 128, height: 96 },
  );
  await expect(page).toMatchAcrossRenderers('lecture', { width: 128, height: 96 });
});

test('a WebGPU canvas that presents keeps its device on llvmpipe’s display (headless, it is lost, and the kit says so)', async ({
  page,
}, info) => {
  await page.route('https://kit.test/', (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><body style="margin:0"><canvas width="64" height="48" style="display:block"></canvas><script type="module">
        const canvas = document.querySelector('canvas');
        const device = await (await navigator.gpu.requestAdapter()).requestDevice();
        const context = canvas.getContext('webgpu');
        context.configure({ device, format: navigator.gpu.getPreferredCanvasFormat(), alphaMode: 'opaque' });
        const encoder = device.createCommandEncoder();
        encoder.beginRenderPass({ colorAttachments: [{ view: context.getCurrentTexture().createView(), loadOp: 'clear', storeOp: 'store', clearValue: { r: 1, g: 0.5, b: 0, a: 1 } }] }).end();
        device.queue.submit([encoder.finish()]);
      </script></body>`,
    }),
  );
  await page.goto('https://kit.test/');
  const canvas = page.locator('canvas');
  if (rasteriserOf(info.project.use) === 'llvmpipe') {
    // One frame cleared to orange: drawn against black.
    const frame = await waitForFirstFrame(canvas, { timeout: 30_000, background: [0, 0, 0] });
    expect(frame.picture.drawnPixels).toBe(64 * 48);
    expect(Array.from(frame.image.data.subarray(0, 4))).toEqual([255, 128, 0, 255]);
    expect(frame.canvas).toMatchObject({ context: 'webgpu', configured: true, lost: false });
    // Still presenting, with the same device, 30 frames later.
    await page.evaluate(
      () =>
        new Promise((resolve) => {
          let n = 0;
          const tick = () => (++n === 30 ? resolve(undefined) : requestAnimationFrame(tick));
          requestAnimationFrame(tick);
        }),
    );
    await expect(canvas).toHaveRendered({ background: [0, 0, 0] });
  } else {
    // Headless Chromium loses the device of a WebGPU canvas that presents (hence the kit's offscreen renders).
    await expect(canvas).not.toHaveRendered({ timeout: 30_000 });
    const error = await expect(canvas)
      .toHaveRendered({ timeout: 5_000 })
      .then(
        () => null,
        (e: Error) => e.message,
      );
    expect(error).toContain('its WebGPU device is lost (device.lost has resolved)');
  }
});
