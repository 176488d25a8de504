// @shadelab/playwright across renderers: expectBackend and toMatchAcrossRenderers in Chromium launched by the
// kit's preset with WebGPU (SwiftShader's adapter). One harness page (tests/harness/kit-renderers.ts, which calls
// exposeRenderers) serves every test of a worker, its renderers made once and shared. A scene that matches
// passes; one whose colour differs per backend fails with the pictures and diffs attached; WebGPU that is not
// there (navigator.gpu stubbed away) fails expectBackend and the matcher, which never passes on a silent
// fallback to WebGL2, not even negated. tests/playwright-kit.spec.ts checks a browser launched without the flag.
import type { Browser, Page, TestInfo } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import { expect, expectBackend, type SceneFactory, test } from '@shadelab/playwright/test';

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

let shared: Page | undefined;
/** The worker's one page of the harness (its renderers are made on the first scene and kept). */
async function harness(browser: Browser, baseURL: string | undefined): Promise<Page> {
  if (shared === undefined || shared.isClosed()) {
    shared = await browser.newPage({ baseURL });
    await shared.goto('/harness/?page=kit-renderers');
  }
  return shared;
}
test.afterAll(async () => {
  await shared?.close();
});

/**
 * three's MeshPhongMaterial on a sphere under a point and an ambient light, with the colour `arg.color` on
 * WebGLRenderer and `arg.gpuColor` (default the same) on WebGPURenderer: three converts it to its node material.
 */
const phongSphere: SceneFactory = ({ THREE, kind, arg, width, height }) => {
  const { color, gpuColor = color } = arg as { color: number; gpuColor?: number };
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x000033);
  const material = new THREE.MeshPhongMaterial({
    color: kind === 'webgl' ? color : gpuColor,
    specular: 0x444444,
    shininess: 30,
  });
  scene.add(new THREE.Mesh(new THREE.SphereGeometry(1, 48, 24), material));
  const light = new THREE.PointLight(0xffffff, 3 * Math.PI, 0, 0);
  light.position.set(-3, 4, 5);
  scene.add(light, new THREE.AmbientLight(0xffffff, 0.5));
  const camera = new THREE.PerspectiveCamera(45, width / height, 0.1, 10);
  camera.position.set(0, 0, 3.2);
  return { scene, camera };
};

const attachmentNames = (info: TestInfo) => info.attachments.map((a) => a.name);

test('expectBackend finds WebGPU (a device on SwiftShader’s adapter) and WebGL2 (SwiftShader)', async ({
  browser,
  baseURL,
}) => {
  const page = await harness(browser, baseURL);
  const gpu = await expectBackend(page, 'webgpu', { rasteriser: 'swiftshader' });
  expect(gpu).toMatchObject({ backend: 'webgpu', rasteriser: 'swiftshader' });
  const gl = await expectBackend(page, 'webgl2');
  expect(gl.rasteriser).toBe('swiftshader');
  expect(gl.description).toContain('SwiftShader');
  expect(await failure(expectBackend(page, 'webgl2', { rasteriser: 'llvmpipe' }))).toMatch(
    /^expectBackend\(page, 'webgl2'\): webgl2 is drawn by swiftshader \(.*SwiftShader.*\), not llvmpipe\.$/,
  );
});

test('three’s MeshPhongMaterial matches across WebGLRenderer and both WebGPURenderer backends, nothing attached', async ({
  browser,
  baseURL,
}, info) => {
  const page = await harness(browser, baseURL);
  await expect(page).toMatchAcrossRenderers(phongSphere, {
    arg: { color: 0xc08040 },
    width: 128,
    height: 96,
  });
  expect(info.attachments).toEqual([]);
});

test('the repository’s ShadingMaterial / ShadingNodeMaterial ellipsoid, registered by the page, matches by name', async ({
  browser,
  baseURL,
}) => {
  const page = await harness(browser, baseURL);
  await expect(page).toMatchAcrossRenderers('lecture', { width: 128, height: 96 });
});

test('a material whose colour differs per backend fails, with every picture, the diff and the backends attached', async ({
  browser,
  baseURL,
}, info) => {
  const page = await harness(browser, baseURL);
  // 0xc08040 against 0xc08840: the green channel 8 codes apart, twice the tolerance.
  const message = await failure(
    expect(page).toMatchAcrossRenderers(phongSphere, {
      arg: { color: 0xc08040, gpuColor: 0xc08840 },
      width: 128,
      height: 96,
      name: 'tint',
    }),
  );
  expect(message).toContain('expect(page).toMatchAcrossRenderers(scene)');
  expect(message).toMatch(
    /webgpu and webgpu-webgl2 differ from webgl beyond the tolerance \(each pixel within \d+ codes/,
  );
  expect(message).toMatch(/webgpu +\d+ pixels beyond/);
  expect(message).toMatch(/webgpu +WebGPURenderer, WebGPU backend \(GPUDevice; google swiftshader/);
  expect(message).toMatch(/webgpu-webgl2 +WebGPURenderer, WebGL2 backend: ANGLE/);
  expect(attachmentNames(info)).toEqual([
    'tint-webgl.png',
    'tint-webgpu.png',
    'tint-webgpu-webgl2.png',
    'tint-webgpu-diff.png',
    'tint-webgpu-webgl2-diff.png',
    'tint-backends.json',
  ]);
  const backends = JSON.parse(String(info.attachments[5].body));
  expect(backends.map((b: { proof: { api: string } }) => b.proof.api)).toEqual([
    'webgl2',
    'webgpu',
    'webgl2',
  ]);
  expect(backends[1].proof).toMatchObject({ isWebGPUBackend: true, gpuDevice: true });
  // Negated, the same difference passes.
  await expect(page).not.toMatchAcrossRenderers(phongSphere, {
    arg: { color: 0xc08040, gpuColor: 0xc08840 },
    width: 128,
    height: 96,
  });
});

test('WebGPU stubbed away: expectBackend fails, and the matcher fails on the fallback to WebGL2, negated too', async ({
  browser,
  baseURL,
}, info) => {
  const context = await browser.newContext({ baseURL });
  try {
    await context.addInitScript(() =>
      Object.defineProperty(Navigator.prototype, 'gpu', { get: () => undefined }),
    );
    const page = await context.newPage();
    await page.goto('/harness/?page=kit-renderers');
    expect(await failure(expectBackend(page, 'webgpu'))).toContain(
      "expectBackend(page, 'webgpu'): the browser cannot give webgpu: navigator.gpu is undefined",
    );
    await expectBackend(page, 'webgl2');
    const scene = { arg: { color: 0xc08040 }, width: 64, height: 48, name: 'fallback' } as const;
    const message = await failure(expect(page).toMatchAcrossRenderers(phongSphere, scene));
    expect(message).toContain(
      'webgpu: WebGPU was asked for, but WebGPURenderer fell back to its WebGL2 backend: navigator.gpu is undefined',
    );
    expect(message).toMatch(/webgpu +WebGPURenderer, WebGL2 backend: ANGLE/);
    expect(attachmentNames(info)).toContain('fallback-backends.json');
    expect(await failure(expect(page).not.toMatchAcrossRenderers(phongSphere, scene))).toContain('fell back');
    // Without WebGPU in the list, the two WebGL2 renderers still compare.
    await expect(page).toMatchAcrossRenderers(phongSphere, {
      ...scene,
      renderers: ['webgl', 'webgpu-webgl2'],
    });
  } finally {
    await context.close();
  }
});

test('says what is missing: a page without exposeRenderers, a blank scene, a factory that throws, an unknown name, bad options', async ({
  browser,
  baseURL,
}) => {
  const page = await harness(browser, baseURL);
  const blank: SceneFactory = ({ THREE }) => ({
    scene: new THREE.Scene(),
    camera: new THREE.PerspectiveCamera(),
  });
  expect(await failure(expect(page).toMatchAcrossRenderers(blank, { width: 16, height: 16 }))).toContain(
    "Nothing to compare: webgl's picture is blank (all 16×16 pixels are rgb(0, 0, 0))",
  );
  const throwing: SceneFactory = ({ renderer }) => {
    throw new RangeError(`no scene for ${renderer}`);
  };
  const thrown = await failure(expect(page).toMatchAcrossRenderers(throwing, { width: 16, height: 16 }));
  expect(thrown).toContain('Renderers could not draw the scene:\n  webgl: RangeError: no scene for webgl\n');
  expect(thrown).toContain('  webgpu-webgl2: RangeError: no scene for webgpu-webgl2');
  expect(await failure(expect(page).toMatchAcrossRenderers('nope'))).toContain(
    'no scene registered as "nope" (registered: "lecture")',
  );
  expect(await failure(expect(page).toMatchAcrossRenderers('lecture', { renderers: ['webgl'] }))).toContain(
    'toMatchAcrossRenderers: renderers must list at least two of webgl, webgpu, webgpu-webgl2, got ["webgl"]',
  );
  expect(await failure(expect(page).toMatchAcrossRenderers('lecture', { width: 0 }))).toContain(
    'toMatchAcrossRenderers: width must be an integer 1 … 4096 pixels, got 0',
  );
  const bare = await browser.newPage();
  try {
    await bare.route('http://kit.test/', (route) =>
      route.fulfill({ contentType: 'text/html', body: '<p>app</p>' }),
    );
    await bare.goto('http://kit.test/');
    expect(await failure(expect(bare).toMatchAcrossRenderers('lecture', { timeout: 5_000 }))).toContain(
      "The page (http://kit.test/) has no renderers for the kit after 5000 ms: a script of the page must import { exposeRenderers } from '@shadelab/playwright/page'",
    );
  } finally {
    await bare.close();
  }
});
