import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { open, picture, settle, stateUrl } from './playground-helpers';

// Issue 24's pixel probe: Alt+click on the object opens a panel with the lecture's equation at that pixel
// (explainShade, as the shading evaluates it) beside the GPU's pixel read back from the canvas. The probe's 8-bit
// colour must agree with the GPU's within 1/255 for every shading × lighting, on the sphere and on picked scenes.
// One page for the whole file (each state is loaded through the URL's hash, without a reload), many probes.

test.describe.configure({ mode: 'serial' });

const SHADINGS = ['flat', 'gouraud', 'phong'] as const;
/** The lightings: Phong, Blinn-Phong and cel (4 bands, on Blinn-Phong). */
const LIGHTINGS = [
  { name: 'phong', material: { lighting: 'phong' } },
  { name: 'blinn-phong', material: { lighting: 'blinn-phong' } },
  { name: 'cel', material: { lighting: 'blinn-phong', celBands: 4 } },
] as const;

let page: Page;
let clicks = 0;

test.beforeAll(async ({ browser }) => {
  page = await browser.newPage({ viewport: { width: 800, height: 600 } });
  await open(page);
});
test.afterAll(async () => {
  await page.close();
});

/** Loads a state through the hash (the app takes it without a reload) and waits until the page rests. */
async function show(state: object): Promise<void> {
  await page.evaluate((hash) => {
    location.hash = hash;
  }, stateUrl(state).slice(1));
  await settle(page, 250);
}

interface Probed {
  cpu: number[] | null;
  gpu: number[] | null;
  miss: string | null;
  unreproduced: string | null;
  text: string;
}

/**
 * A pixel the GPU may draw either way, as the panel says: a flat face's edge, a cel band's edge, a texel
 * boundary under nearest filtering, a switch between two filters (the rasteriser's, the sampler's and float
 * precision decide).
 */
const tie = (probed: Probed) =>
  /on an edge|cel band’s edge/.test(probed.text) ||
  /texel boundary|switch between/.test(probed.unreproduced ?? '');

/** Alt+clicks the canvas at (fx, fy) (fractions of its size) and reads the probe panel once it has probed. */
async function probeAt(fx: number, fy: number): Promise<Probed> {
  const canvas = page.getByTestId('viewport');
  const box = (await canvas.boundingBox())!;
  const position = { x: Math.floor(box.width * fx) + 0.5, y: Math.floor(box.height * fy) + 0.5 };
  await canvas.click({ modifiers: ['Alt'], position });
  clicks++;
  const panel = page.getByTestId('probe-panel');
  await expect(panel).toHaveAttribute('data-probed', String(clicks));
  return panel.evaluate((element) => {
    const rgb = (id: string) =>
      element.querySelector(`[data-testid="${id}"]`)?.getAttribute('data-rgb')?.split(',').map(Number) ??
      null;
    return {
      cpu: rgb('probe-cpu'),
      gpu: rgb('probe-gpu'),
      miss: element.querySelector('[data-testid="probe-miss"]')?.textContent ?? null,
      unreproduced: element.querySelector('[data-testid="probe-unreproduced"]')?.textContent ?? null,
      text: element.textContent ?? '',
    };
  });
}

/** The probe hit, and its colour is the GPU's within 1/255 on every channel. */
function expectAgrees(probed: Probed, where: string): void {
  expect(probed.miss, `${where}: a hit`).toBeNull();
  expect(probed.cpu, `${where}: the probe's colour`).not.toBeNull();
  expect(probed.gpu, `${where}: the GPU's pixel`).not.toBeNull();
  const delta = Math.max(...probed.cpu!.map((c, i) => Math.abs(c - probed.gpu![i]!)));
  expect(delta, `${where}: probe ${probed.cpu} vs GPU ${probed.gpu}`).toBeLessThanOrEqual(1);
}

/**
 * Probes each point of the state shown; every probe that hits (off the object and ties are passed over) agrees
 * with the GPU. Returns how many hit, for the caller to require some.
 */
async function agreeingHits(points: readonly (readonly [number, number])[], where: string): Promise<number> {
  let hits = 0;
  for (const [fx, fy] of points) {
    const probed = await probeAt(fx, fy);
    if (probed.miss || tie(probed)) continue;
    hits++;
    expectAgrees(probed, `${where} at (${fx}, ${fy})`);
  }
  return hits;
}

/** Points on the default sphere (scale 2, 1, 2 from (0, 0, 3)): centre, highlight side, rim, lower left. */
const SPHERE_POINTS = [
  [0.5, 0.5],
  [0.42, 0.38],
  [0.8, 0.52],
  [0.3, 0.55],
] as const;

for (const shading of SHADINGS) {
  test(`the sphere, ${shading} shading: the probe agrees with the GPU pixel for every lighting`, async () => {
    for (const lighting of LIGHTINGS) {
      await show({ material: { shading, ...lighting.material } });
      for (const [fx, fy] of SPHERE_POINTS) {
        const probed = await probeAt(fx, fy);
        expectAgrees(probed, `sphere ${shading} × ${lighting.name} at (${fx}, ${fy})`);
        if (shading === 'gouraud') expect(probed.text).toContain('weight');
        if (shading === 'flat') expect(probed.text).toContain('centroid');
        if (lighting.name === 'cel') expect(probed.text).toContain('cel band');
        expect(probed.text).toContain(lighting.name === 'phong' ? 'v·r' : 'n·h');
      }
    }
  });
}

/**
 * Picked scenes: instanced spheres (instance colours), three's lights with fog and clipping, a skinned and
 * morphed mesh, a textured one with a normal map.
 */
const SCENES = [
  {
    scene: 'instanced',
    points: [
      [0.5, 0.5],
      [0.3, 0.4],
      [0.62, 0.55],
    ],
  },
  {
    // Off the canvas's middle column: there a pixel's centre lies on the floor's edge at x = 0, a tie that the
    // GPU's fill rule breaks (the panel says so) and a flat-shaded probe may not.
    scene: 'lights',
    points: [
      [0.3, 0.5],
      [0.7, 0.6],
      [0.53, 0.55],
    ],
  },
  {
    scene: 'skinned',
    points: [
      [0.5, 0.5],
      [0.4, 0.4],
      [0.6, 0.45],
    ],
  },
  {
    scene: 'textured',
    points: [
      [0.5, 0.5],
      [0.4, 0.4],
      [0.6, 0.45],
    ],
  },
] as const;

for (const { scene, points } of SCENES) {
  for (const shading of SHADINGS) {
    test(`the ${scene} scene, ${shading} shading: the probe agrees with the GPU pixel for every lighting`, async () => {
      for (const lighting of LIGHTINGS) {
        await show({ scene, material: { shading, ...lighting.material } });
        const where = `${scene} ${shading} × ${lighting.name}`;
        expect(await agreeingHits(points, where), `${where}: probes that hit`).toBeGreaterThan(0);
      }
    });
  }
}

/** A model's GLB, made by three's GLTFExporter in the harness page (tests/harness/gltf-maker.ts). */
async function madeModel(kind: string): Promise<Buffer> {
  const maker = await page.context().browser()!.newPage();
  await maker.goto('/harness/?page=gltf-maker');
  await maker.waitForFunction(() => typeof (window as { makeModel?: unknown }).makeModel === 'function');
  const bytes = await maker.evaluate(
    (k) => (window as unknown as { makeModel(k: string): Promise<number[]> }).makeModel(k),
    kind,
  );
  await maker.close();
  await page.bringToFront();
  return Buffer.from(bytes);
}

/**
 * Loaded models, as a user opens them: plain colours (one emissive) in every shading × lighting; vertex colours
 * and a texture in every shading, each with one of the lightings. (A skin is probed in the skinned scene: a
 * model's clip plays from the load, so where a pause lands its pose is not the same from run to run.)
 */
const MODELS = ['coloured', 'vertexColours', 'textured'] as const;
/** A row of points across the middle of the view, and one above it (the panel opens below the middle). */
const MODEL_POINTS: (readonly [number, number])[] = [
  ...[0.25, 0.4, 0.55, 0.7].map((fx) => [fx, 0.5] as const),
  [0.45, 0.4],
];

for (const kind of MODELS) {
  test(`a loaded model (${kind}): the probe agrees with the GPU pixel in every shading`, async () => {
    test.setTimeout(240_000);
    await show({});
    const name = `${kind}.glb`;
    await page.getByTestId('model-file').setInputFiles({
      name,
      mimeType: 'model/gltf-binary',
      buffer: await madeModel(kind),
    });
    await expect(page.getByTestId('model-note')).toContainText(`“${name}”`, { timeout: 20_000 });
    for (const [i, shading] of SHADINGS.entries()) {
      for (const lighting of kind === 'coloured' ? LIGHTINGS : [LIGHTINGS[i]!]) {
        await show({ scene: 'model', material: { shading, ...lighting.material } });
        const where = `${kind} ${shading} × ${lighting.name}`;
        expect(await agreeingHits(MODEL_POINTS, where), `${where}: probes that hit`).toBeGreaterThan(1);
      }
    }
  });
}

/** Two lights, one attenuated, so that the attenuation view is not a constant. */
const TWO_LIGHTS = [
  { position: [-5, 10, 20] },
  { position: [2.5, 0.5, 1.5], diffuse: [0.4, 0.6, 1], attenuation: { a: 0.5, b: 0.3, c: 0.2 } },
];

for (const output of ['ambient', 'diffuse', 'specular', 'attenuation', 'normal'] as const) {
  test(`the ${output} term view: the probe shows the term the GPU draws, within 1/255`, async () => {
    for (const shading of SHADINGS) {
      await show({ material: { shading, output }, lights: TWO_LIGHTS });
      for (const [fx, fy] of SPHERE_POINTS.slice(0, 2)) {
        const probed = await probeAt(fx, fy);
        expectAgrees(probed, `sphere ${shading}, output ${output} at (${fx}, ${fy})`);
        expect(probed.text).toContain(`the ${output} view`);
      }
    }
  });
}

test("normalMatrix 'model' (the lecture's wrong normals under the (2, 1, 2) scale): the probe uses M as the GPU does", async () => {
  for (const shading of SHADINGS) {
    await show({ material: { shading, normalMatrix: 'model' } });
    for (const [fx, fy] of SPHERE_POINTS) {
      expectAgrees(await probeAt(fx, fy), `sphere ${shading}, normalMatrix model at (${fx}, ${fy})`);
    }
  }
  await show({ scene: 'instanced', material: { shading: 'phong', normalMatrix: 'model' } });
  expect(await agreeingHits(SCENES[0].points, 'instanced, normalMatrix model')).toBeGreaterThan(0);
});

test('a probe off the object says so; the arrows toggle', async () => {
  const close = page.getByRole('button', { name: 'close the probe' });
  if (await close.count()) await close.click(); // the panel of the tests before, with its arrows
  await expect(page.getByTestId('probe-panel')).toHaveCount(0);
  await show({});
  const before = await picture(page);
  const same = async (expected: string, what: string) =>
    expect((await picture(page)) === expected, what).toBe(true);
  const off = await probeAt(0.02, 0.03);
  expect(off.miss).toMatch(/off the object/);
  expect(off.cpu).toBeNull();
  await same(before, 'a probe off the object draws no arrows');

  const probed = await probeAt(0.45, 0.45);
  expectAgrees(probed, 'sphere, default state');
  const withArrows = await picture(page);
  expect(withArrows === before, 'the arrows are drawn').toBe(false);
  await page.getByTestId('probe-arrows').uncheck();
  await settle(page, 250);
  await same(before, 'arrows off: the picture without the probe');
  await page.getByTestId('probe-arrows').check();
  await settle(page, 250);
  await same(withArrows, 'arrows on again');
});

test('the probe follows the trackball while the panel is open, and still agrees with the GPU', async () => {
  await show({ material: { shading: 'gouraud' } });
  const first = await probeAt(0.5, 0.45);
  expectAgrees(first, 'before the drag');
  const pixel = await page.getByTestId('probe-pixel').textContent();
  const canvas = page.getByTestId('viewport');
  const box = (await canvas.boundingBox())!;
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.56, box.y + box.height * 0.5, { steps: 4 });
  await page.mouse.up();
  await settle(page, 250);
  await expect(page.getByTestId('probe-pixel')).not.toHaveText(pixel ?? '');
  const after = await page.getByTestId('probe-panel').evaluate((element) => ({
    cpu: element.querySelector('[data-testid="probe-cpu"]')?.getAttribute('data-rgb'),
    gpu: element.querySelector('[data-testid="probe-gpu"]')?.getAttribute('data-rgb'),
  }));
  const [cpu, gpu] = [after.cpu!.split(',').map(Number), after.gpu!.split(',').map(Number)];
  expect(Math.max(...cpu.map((c, i) => Math.abs(c - gpu[i]!)))).toBeLessThanOrEqual(1);
  await page.getByRole('button', { name: 'close the probe' }).click();
  await expect(page.getByTestId('probe-panel')).toHaveCount(0);
});

test('the open panel docks beside the view at 1280 × 800 and 1920 × 1080, in the side column', async () => {
  for (const [width, height] of [
    [1280, 800],
    [1920, 1080],
  ] as const) {
    await page.setViewportSize({ width, height });
    await show({ material: { shading: 'gouraud', celBands: 3 } });
    const probed = await probeAt(0.5, 0.45);
    expectAgrees(probed, `${width} × ${height}`);
    const canvas = (await page.getByTestId('viewport').boundingBox())!;
    const panel = (await page.getByTestId('probe-panel').boundingBox())!;
    const side = (await page.locator('.side').boundingBox())!;
    expect(panel.x, 'the panel lies beside the view').toBeGreaterThanOrEqual(canvas.x + canvas.width);
    expect(panel.x).toBeGreaterThanOrEqual(side.x);
    expect(panel.x + panel.width).toBeLessThanOrEqual(side.x + side.width + 0.5);
    expect(panel.y).toBeGreaterThanOrEqual(side.y);
    const page_ = await page.evaluate(() => ({
      overflowX: document.documentElement.scrollWidth > window.innerWidth,
      overflowY: document.documentElement.scrollHeight > window.innerHeight,
    }));
    expect(page_).toEqual({ overflowX: false, overflowY: false });
  }
  await page.setViewportSize({ width: 800, height: 600 });
});
