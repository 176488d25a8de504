// How far pictures of one scene differ between rasterisers, the measurement behind @shadelab/playwright's
// GPU_TOLERANCE (toMatchScreenshotAcrossGpus). A real GPU cannot be measured on a machine without one, so the
// variation is measured where it can be, in headless Chromium (bench/harness/rasterisers.ts):
// - ShadingMaterial through WebGLRenderer (SwiftShader) with MSAA off and on: the edges blend;
// - the same with the camera shifted by 1/16 and 1/2 pixel: where another GPU's sub-pixel grid would put the
//   vertices (OpenGL ES asks for at least 4 bits, 1/16 px) and, at 1/2 px, farther than any would;
// - three's own MeshPhongNodeMaterial through WebGPURenderer on its WebGPU backend (Dawn on SwiftShader's
//   Vulkan) and on its WebGL2 backend (ANGLE on SwiftShader's GL ES): two APIs, two shader compilers;
// - a second rasteriser: Chromium headed on Xvfb without the SwiftShader flags (@shadelab/playwright's
//   rasteriser: 'llvmpipe'), where WebGL is Mesa's llvmpipe: each scene against SwiftShader's picture, and against
//   itself in a second browser (run-to-run determinism);
// - three's renderers, as toMatchAcrossRenderers draws them (@shadelab/playwright/page): MeshPhongMaterial on
//   WebGLRenderer against WebGPURenderer's WebGPU and WebGL2 backends, in both browsers (in the llvmpipe one
//   WebGL is llvmpipe and WebGPU SwiftShader's adapter, so that pair crosses rasterisers too).
// Each pair is scored by compareNeighbourhood: exact (radius 0: the largest channel difference and the pixels
// that differ) and within a neighbourhood (radius 1, 3 × 3, and radius 2, 5 × 5: how far a pixel lies outside
// the range its neighbourhood spans in the other picture). The tolerances are the largest 3 × 3 excess over the
// pairs that stand for another rasteriser with the app's settings (the 1/16 px shift and the two backends):
// one for smooth shading (Gouraud, Phong, the impostor, three's node material) and one for pictures with hard
// edges inside them (flat facets, cel bands), and one for toMatchAcrossRenderers (the renderer pairs). MSAA on
// against off and the 1/2 px shift are recorded to show what the tolerance does not cover.
// Deterministic (no timing).
//
// node bench/rasterisers.bench.mjs [--json PATH]
import { chromium } from '@playwright/test';
import { shadelabUse, startXvfb } from '@shadelab/playwright';
import { compareNeighbourhood, flipRows } from '@shadelab/playwright/test';
import { chromiumArgs, chromiumExecutable, webgpuArgs } from '../scripts/browser.mjs';
import { writeResults } from './lib/bench.mjs';
import { openPlayground } from './lib/browser.mjs';

const width = 320;
const height = 240;

/** @param {string} b64 @returns {import('@shadelab/playwright/test').RgbaImage} */
const image = (b64) => ({ width, height, data: new Uint8Array(Buffer.from(b64, 'base64')) });

/**
 * @param {import('@shadelab/playwright/test').RgbaImage} a
 * @param {import('@shadelab/playwright/test').RgbaImage} b
 */
function score(a, b) {
  const exact = compareNeighbourhood(a, b, { radiusPx: 0 });
  const near = compareNeighbourhood(a, b, { radiusPx: 1 });
  const wide = compareNeighbourhood(a, b, { radiusPx: 2 });
  return {
    maxChannelDiff: exact.maxExcess,
    differingPixels: exact.failingPixels,
    maxExcess3x3: near.maxExcess,
    pixelsBeyond3x3: near.failingPixels,
    maxExcess5x5: wide.maxExcess,
  };
}

/** The scenes: the kit's lecture scene (tests/harness/kitScene.ts) in each shading, at 320 × 240. */
/** @type {{ name: string, edges: 'smooth' | 'hard', options: import('../tests/harness/kitScene').KitSceneOptions }[]} */
const scenes = [
  { name: 'phong (icosahedron 6)', edges: 'smooth', options: { shading: 'phong' } },
  { name: 'gouraud (icosahedron 6)', edges: 'smooth', options: { shading: 'gouraud' } },
  { name: 'impostor', edges: 'smooth', options: { shading: 'impostor' } },
  { name: 'flat (icosahedron 3)', edges: 'hard', options: { shading: 'flat', level: 3 } },
  { name: 'cel, 4 bands (phong shading)', edges: 'hard', options: { shading: 'phong', celBands: 4 } },
];

const playground = await openPlayground();
/** @typedef {{ scene: string, edges: 'smooth' | 'hard', pair: string, sameSettings: boolean, renderers?: boolean, maxChannelDiff: number, differingPixels: number, maxExcess3x3: number, pixelsBeyond3x3: number, maxExcess5x5: number }} Pair */
/** @type {Pair[]} */
const pairs = [];
/** @type {Record<string, unknown>} */
const notes = {};
try {
  const page = await playground.browser.newPage();
  await page.goto(playground.url('harness/rasterisers.html'));
  await page.waitForFunction(() => document.body.dataset.ready === '1');
  /** @type {Map<string, import('@shadelab/playwright/test').RgbaImage>} SwiftShader's picture of each scene */
  const swiftshader = new Map();
  for (const { name, edges, options } of scenes) {
    /** @param {import('../tests/harness/kitScene').KitSceneOptions} extra */
    const draw = async (extra) =>
      image(await page.evaluate((o) => window.rasterisers.renderShading(o), { ...options, ...extra }));
    const base = await draw({});
    swiftshader.set(name, base);
    /** @type {[string, boolean, import('../tests/harness/kitScene').KitSceneOptions][]} */
    const variants = [
      ['picture shifted 1/16 px (x and y)', true, { shiftPx: [1 / 16, 1 / 16] }],
      ['picture shifted 1/2 px (x and y)', false, { shiftPx: [0.5, 0.5] }],
      ['MSAA off / on (WebGLRenderer antialias)', false, { antialias: true }],
    ];
    for (const [pair, sameSettings, extra] of variants) {
      pairs.push({ scene: name, edges, pair, sameSettings, ...score(base, await draw(extra)) });
    }
    console.log(`${name}: done`);
  }

  // WebGPU: its own browser, with the WebGPU flag (the WebGL2 backend is drawn in the same page).
  const gpuBrowser = await chromium.launch({
    executablePath: chromiumExecutable() ?? undefined,
    args: [...chromiumArgs, ...webgpuArgs],
  });
  try {
    const gpuPage = await gpuBrowser.newPage();
    await gpuPage.goto(playground.url('harness/rasterisers.html'));
    await gpuPage.waitForFunction(() => document.body.dataset.ready === '1');
    const node = (/** @type {boolean} */ forceWebGL) =>
      gpuPage.evaluate(
        ([w, h, f]) => window.rasterisers.renderNode(w, h, f),
        /** @type {const} */ ([width, height, forceWebGL]),
      );
    const gpu = await node(false);
    const gl = await node(true);
    notes.backends = [gpu.backend, gl.backend];
    if (gpu.backend !== 'webgpu' || gl.backend !== 'webgl2') {
      throw new Error(`expected the WebGPU and WebGL2 backends, got ${gpu.backend} and ${gl.backend}`);
    }
    // The two backends may return the rows in opposite orders: score the orientation that lines up.
    const a = image(gpu.pixels);
    const b = image(gl.pixels);
    const straight = score(a, b);
    const flipped = score(flipRows(a), b);
    const lined = flipped.differingPixels < straight.differingPixels ? flipped : straight;
    notes.webgpuRows = lined === flipped ? 'opposite order to WebGL2 (flipped)' : 'same order as WebGL2';
    pairs.push({
      scene: "three's MeshPhongNodeMaterial (icosahedron 6)",
      edges: 'smooth',
      pair: 'WebGPURenderer: WebGPU backend / WebGL2 backend',
      sameSettings: true,
      ...lined,
    });
    pairs.push(...(await rendererPairs(gpuPage, 'SwiftShader')));
  } finally {
    await gpuBrowser.close();
  }

  // llvmpipe: headed Chromium on the kit's Xvfb, launched as shadelabPreset({ rasteriser: 'llvmpipe' }) does.
  const xvfb = await startXvfb();
  try {
    const { launchOptions } = shadelabUse({
      rasteriser: 'llvmpipe',
      webgpu: true,
      checks: { env: { ...process.env, SHADELAB_XVFB_DISPLAY: xvfb.display } },
    });
    /** Each scene drawn in a new llvmpipe browser, and what draws WebGL and WebGPU there. */
    const llvmpipeRun = async (/** @type {boolean} */ withRenderers) => {
      const browser = await chromium.launch(launchOptions);
      try {
        const p = await browser.newPage();
        await p.goto(playground.url('harness/rasterisers.html'));
        await p.waitForFunction(() => document.body.dataset.ready === '1');
        const backends = await p.evaluate(async () => {
          const gl = /** @type {WebGL2RenderingContext} */ (
            document.createElement('canvas').getContext('webgl2')
          );
          const info = gl.getExtension('WEBGL_debug_renderer_info');
          const gpu = /** @type {any} */ (navigator).gpu;
          const adapter = gpu ? await gpu.requestAdapter() : null;
          return {
            webgl: String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)),
            webgpu: adapter ? `${adapter.info.vendor} ${adapter.info.architecture}`.trim() : 'none',
          };
        });
        /** @type {Map<string, import('@shadelab/playwright/test').RgbaImage>} */
        const pictures = new Map();
        for (const { name, options } of scenes) {
          pictures.set(name, image(await p.evaluate((o) => window.rasterisers.renderShading(o), options)));
        }
        return { backends, pictures, renderers: withRenderers ? await rendererPairs(p, 'llvmpipe') : [] };
      } finally {
        await browser.close();
      }
    };
    const first = await llvmpipeRun(true);
    const second = await llvmpipeRun(false);
    if (!first.backends.webgl.includes('llvmpipe')) {
      throw new Error(`expected WebGL on llvmpipe in the headed browser, got ${first.backends.webgl}`);
    }
    notes.llvmpipe = first.backends;
    notes.llvmpipeRunToRun = scenes.map(({ name }) => ({
      scene: name,
      differingPixels: score(
        /** @type {any} */ (first.pictures.get(name)),
        /** @type {any} */ (second.pictures.get(name)),
      ).differingPixels,
    }));
    for (const { name, edges } of scenes) {
      pairs.push({
        scene: name,
        edges,
        pair: 'llvmpipe / SwiftShader (WebGLRenderer)',
        sameSettings: true,
        ...score(/** @type {any} */ (first.pictures.get(name)), /** @type {any} */ (swiftshader.get(name))),
      });
    }
    pairs.push(...first.renderers);
    console.log('llvmpipe: done');
  } finally {
    await xvfb.stop();
  }
} finally {
  await playground.close();
}

/**
 * three's MeshPhongMaterial drawn by the kit's renderers (the 'three-phong' scene of the harness page): WebGLRenderer
 * against WebGPURenderer's WebGPU and WebGL2 backends, each backend proven.
 * @param {import('@playwright/test').Page} p @param {string} rasteriser what draws WebGL in this browser
 * @returns {Promise<Pair[]>}
 */
async function rendererPairs(p, rasteriser) {
  const pictures = await p.evaluate(
    ([w, h]) =>
      /** @type {any} */ (globalThis)[Symbol.for('shadelab.renderers')].render('three-phong', {
        renderers: ['webgl', 'webgpu', 'webgpu-webgl2'],
        width: w,
        height: h,
      }),
    [width, height],
  );
  for (const picture of pictures) {
    if (!picture.ok) throw new Error(`${picture.renderer} could not draw: ${picture.error}`);
  }
  if (pictures[1].proof.api !== 'webgpu') throw new Error('the WebGPU backend did not run');
  /** @type {import('@shadelab/playwright/test').RgbaImage[]} */
  const [gl, ...gpu] = pictures.map((/** @type {{ pixels: string }} */ x) => image(x.pixels));
  const names = ['WebGPU backend', 'WebGL2 backend'];
  return gpu.map((picture, i) => ({
    scene: "three's MeshPhongMaterial (icosahedron 6)",
    edges: /** @type {const} */ ('smooth'),
    pair: `WebGLRenderer / WebGPURenderer ${names[i]} (${rasteriser}${rasteriser === 'llvmpipe' && i === 0 ? '; WebGPU on SwiftShader' : ''})`,
    sameSettings: true,
    renderers: true,
    ...score(picture, gl),
  }));
}

for (const p of pairs) {
  console.log(
    `${p.scene.padEnd(46)} ${p.pair.padEnd(50)} exact: max ${String(p.maxChannelDiff).padStart(3)}, ${String(p.differingPixels).padStart(6)} px differ; 3×3: max excess ${p.maxExcess3x3}; 5×5: ${p.maxExcess5x5}`,
  );
}
/** The tolerance of the scenes with `edges`: the largest 3 × 3 excess over their same-settings pairs. @param {'smooth' | 'hard'} edges */
const tolerance = (edges) => ({
  maxChannelDiff: Math.max(
    ...pairs
      .filter((p) => p.sameSettings && (edges === 'hard' || p.edges === 'smooth'))
      .map((p) => p.maxExcess3x3),
  ),
  radiusPx: 1,
  maxDiffPixels: 0,
});
const derived = {
  smooth: tolerance('smooth'),
  hardEdges: tolerance('hard'),
  renderers: {
    maxChannelDiff: Math.max(...pairs.filter((p) => p.renderers).map((p) => p.maxExcess3x3)),
    radiusPx: 1,
    maxDiffPixels: 0,
  },
};
console.log(`derived tolerances: ${JSON.stringify(derived)}`);
writeResults({
  note: "Headless Chromium, SwiftShader (WebGL2 through ANGLE; WebGPU through Dawn on its Vulkan), and headed Chromium on Xvfb with @shadelab/playwright's llvmpipe mode (WebGL2 through ANGLE on Mesa's llvmpipe; WebGPU still SwiftShader's adapter). 320 × 240, the lecture scene of tests/harness/kitScene.ts. A real GPU is not measured: the pairs are the variation that can be produced here.",
  size: { width, height },
  ...notes,
  pairs,
  tolerance: derived,
});
