// The code blocks of the Markdown marked ```ts run=SCENE (the README's Quick start, each package README's
// first example, a guide's example that loads a model) run as a user would run them: each block, verbatim, is
// the main.ts of a page (a generated index.html), all bundled by one Vite build that resolves `three` and
// `@shadelab/*` through the workspace's node_modules (the packages' built dist/, through their `exports`), and
// opened in Chromium. A page error or console error fails the test (an option that throws shows as one), and the
// picture must be SCENE's: drawn inside the silhouette computed from the scene's camera and model, the
// background outside, brighter towards the light when lit (picture-helpers.ts); what a page fetches is served
// by the test (PAGE_SETUP). The blocks marked ```ts picture=NAME (the pictures of the docs) are built and opened
// the same way, and their canvas must equal, pixel for pixel, images/NAME.png beside their Markdown, the image
// the Markdown shows (SwiftShader's renders are deterministic); --update-snapshots writes it instead.
// scripts/snippets.mjs type-checks the same blocks; see DEVELOPERS.md, "Code in docs".
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, type Page, test } from '@playwright/test';
import { SphereGeometry } from 'three';
import {
  type Block,
  collectBlocks,
  pictureFile,
  quickStartBlock,
  runPageName,
  writeRunPages,
} from '../scripts/snippets.mjs';
import { glbOf } from './glb';
import {
  buildAndServePages,
  collectPageErrors,
  expectScenePicture,
  LECTURE_VIEW,
  type SceneView,
} from './picture-helpers';

const repo = fileURLToPath(new URL('..', import.meta.url));

/** What each `run=SCENE` block draws: its camera and model, as the block sets them. */
const SCENES: Record<string, SceneView> = {
  // README Quick start, material README: the (2, 1, 2) ellipsoid from (0, 0, 3), fovy 90°, light (−5, 10, 20).
  lecture: LECTURE_VIEW,
  // Camera README: the unit cube with MeshNormalMaterial, eye (0, 0, 3), fovy 90°.
  'camera-cube': { shape: { box: [0.5, 0.5, 0.5] }, eye: 3, fovy: 90, normalColours: true },
  // Trackball README: the unit cube with MeshNormalMaterial, eye (0, 0, 4), fovy 45°.
  'trackball-cube': { shape: { box: [0.5, 0.5, 0.5] }, eye: 4, fovy: 45, normalColours: true },
  // Sphere README: the unit sphere with MeshNormalMaterial, eye (0, 0, 4), fovy 50°.
  'sphere-normals': { shape: { ellipsoid: [1, 1, 1] }, eye: 4, fovy: 50, normalColours: true },
  // The existing-scene guide: the model it loads is served as the unit sphere (below), eye (0, 0, 4), fovy 50°,
  // three's DirectionalLight at (−5, 10, 20) and an AmbientLight.
  'gltf-sphere': { shape: { ellipsoid: [1, 1, 1] }, eye: 4, fovy: 50, light: [-5, 10, 20] },
};

/**
 * What a scene's page fetches, served by the test, and what else its page must show; returns the check to run
 * after the picture's. The existing-scene guide loads `/models/model.glb`, here the unit sphere (three's
 * SphereGeometry, 64 × 32, inside the true sphere by far less than the samples' 10 %) with a dielectric glTF
 * material, which GLTFLoader makes a MeshStandardMaterial: the block's log must say swapMaterials converted it.
 */
const PAGE_SETUP: Partial<Record<string, (page: Page) => Promise<() => void>>> = {
  'gltf-sphere': async (page) => {
    const body = glbOf(new SphereGeometry(1, 64, 32), {
      baseColorFactor: [0.8, 0.45, 0.2, 1],
      metallicFactor: 0,
      roughnessFactor: 0.5,
    });
    await page.route('**/models/model.glb', (route) =>
      route.fulfill({ status: 200, contentType: 'model/gltf-binary', body }),
    );
    // The block's log, and swapMaterials' warning of what it skipped (there must be none).
    const logs: string[] = [];
    page.on('console', (m) => {
      if (m.type() === 'log' || m.text().startsWith('swapMaterials')) logs.push(m.text());
    });
    return () => expect(logs).toEqual(['1 materials swapped, 0 left in place']);
  },
};

/** The examples that must run: the README's Quick start and each package README's first code block. */
const MUST_RUN = [
  'README.md (Quick start)',
  'packages/camera/README.md',
  'packages/material/README.md',
  'packages/sphere/README.md',
  'packages/trackball/README.md',
];
/** First examples that draw nothing: type-checked only (scripts/snippets.mjs), with the reason. */
const NOT_RUN: Record<string, string> = {
  'packages/reference/README.md':
    'scores a GPU render it does not make (partial: `pixels` is its context); the renderer is tested in tests/',
  'packages/playwright/README.md':
    "a Playwright test, run in Node (partial: the app's buildScene is its context); docs/testing.md's app, which tests/pack.spec.ts runs, is the whole of it",
  'packages/react/README.md':
    "JSX elements (partial: the light is its context); the guide's complete app is what tests/react.spec.ts and tests/pack.spec.ts render",
};

const blocks = collectBlocks();
/** The blocks run in Chromium: `run=SCENE` and `picture=NAME`. */
const runs = blocks.filter((b) => b.run || b.picture);
const pictures = blocks.filter((b): b is Block & { picture: string } => b.picture !== undefined);
const port = process.env.SHADELAB_E2E_PORT ?? '4173';
const out = join(repo, 'reports', `snippets-run-${port}`);
/** The page of each runnable block: a folder named after its Markdown file and line. */
const pageOf = runPageName;
let origin = '';
let close: (() => Promise<void>) | undefined;

// In order, in one worker (one build); a failed test does not skip the others.
test.describe.configure({ mode: 'default' });

test.beforeAll(async () => {
  test.setTimeout(180_000);
  rmSync(out, { recursive: true, force: true });
  const input = writeRunPages(runs, join(out, 'src'));
  ({ origin, close } = await buildAndServePages({
    root: join(out, 'src'),
    outDir: join(out, 'dist'),
    input,
  }));
});

test.afterAll(async () => {
  await close?.();
});

test('the Quick start and each package README’s first example are marked to run, with a known scene', () => {
  const first = new Map<string, Block>();
  for (const b of blocks) {
    // Each package README's (the guides in packages/<name>/docs/ are not front doors).
    if (/^packages\/[^/]+\/README\.md$/.test(b.file) && !first.has(b.file)) first.set(b.file, b);
  }
  // The one block under the README's Quick start (bench/first-frame.bench.mjs times its page too).
  expect(quickStartBlock(blocks).run).toBe('lecture');
  const marked = [
    'README.md (Quick start)',
    ...[...first.values()].filter((b) => b.run).map((b) => b.file),
  ].sort();
  expect(marked).toEqual([...MUST_RUN].sort());
  for (const file of Object.keys(NOT_RUN)) expect(first.get(file)?.partial, file).toBeTruthy();
  expect([...first.keys()].sort()).toEqual([...MUST_RUN.slice(1), ...Object.keys(NOT_RUN)].sort());
  for (const b of runs.filter((b) => b.run))
    expect(Object.keys(SCENES), `${b.file}:${b.line} run=${b.run}`).toContain(b.run);
});

for (const b of runs.filter((b) => b.run)) {
  test(`${b.file}:${b.line} (${b.heading}) runs and draws the ${b.run} scene`, async ({ page }) => {
    const errors = collectPageErrors(page);
    // Larger than any canvas the examples make; a block sized to the window fills it.
    await page.setViewportSize({ width: 900, height: 900 });
    const check = await PAGE_SETUP[b.run!]?.(page);
    await page.goto(`${origin}/${pageOf(b)}/`);
    await expectScenePicture(page, SCENES[b.run!], errors);
    await expect(page.locator('html')).toHaveAttribute('data-ran', 'true');
    check?.();
  });
}

test('each picture block is shown by its Markdown, and each image of those images/ folders is a block’s', () => {
  const seen = new Map<string, Block>();
  for (const b of pictures) {
    const image = pictureFile(b);
    const other = seen.get(image);
    expect(other, `${b.file}:${b.line} and ${other?.file}:${other?.line} both draw ${image}`).toBeUndefined();
    seen.set(image, b);
    const markdown = readFileSync(join(repo, b.file), 'utf8');
    expect(
      markdown,
      `${b.file} shows ![…](images/${b.picture}.png), the picture of its block at line ${b.line}`,
    ).toContain(`](images/${b.picture}.png)`);
  }
  // No stale image: every PNG of a folder the pictures are written to is the picture of a block.
  for (const folder of new Set([...seen.keys()].map((f) => dirname(f)))) {
    if (!existsSync(join(repo, folder))) continue; // the pictures' tests say the images are missing
    for (const f of readdirSync(join(repo, folder)).filter((f) => f.endsWith('.png')))
      expect([...seen.keys()], `${folder}/${f} is drawn by no picture= block`).toContain(`${folder}/${f}`);
  }
});

for (const b of pictures) {
  const image = pictureFile(b);
  test(`${b.file}:${b.line} (${b.heading}) draws ${image}`, async ({ page }, testInfo) => {
    const errors = collectPageErrors(page);
    await page.setViewportSize({ width: 900, height: 900 });
    await page.goto(`${origin}/${pageOf(b)}/`);
    await expect(page.locator('html')).toHaveAttribute('data-ran', 'true', { timeout: 30_000 });
    const canvas = page.locator('canvas');
    await expect(canvas).toHaveCount(1);
    const size = await canvas.evaluate((c: HTMLCanvasElement) => [c.width, c.height]);
    const box = (await canvas.boundingBox())!;
    // The screenshot of the canvas's CSS box is its drawing buffer, 1:1.
    expect([Math.round(box.width), Math.round(box.height)], 'canvas CSS size = drawing buffer').toEqual(size);
    // The picture is drawn once: wait until two screenshots in a row agree (the frame is on screen).
    let shot = await canvas.screenshot();
    for (let i = 0; i < 20; i++) {
      const next = await canvas.screenshot();
      if (next.equals(shot)) break;
      shot = next;
    }
    expect(errors, 'page errors').toEqual([]);
    const path = join(repo, image);
    const mode = testInfo.config.updateSnapshots;
    const update = `SHADELAB_E2E_PORT=<port> CI=1 npx playwright test tests/snippets.spec.ts --workers=1 --project=swiftshader --update-snapshots, then look at ${image}`;
    if (!existsSync(path)) {
      if (mode === 'all' || mode === 'changed' || mode === 'missing') {
        mkdirSync(dirname(path), { recursive: true });
        writeFileSync(path, shot);
        console.log(`${image}: written (${shot.length} bytes)`);
        return;
      }
      await testInfo.attach(`${b.picture}-actual.png`, { body: shot, contentType: 'image/png' });
      throw new Error(`${image} is missing (the picture of ${b.file}:${b.line}); to write it: ${update}`);
    }
    const committed = readFileSync(path);
    const diff = await comparePictures(page, shot, committed);
    if (diff === null) return;
    if (mode === 'all' || mode === 'changed') {
      writeFileSync(path, shot);
      console.log(`${image}: rewritten (${diff}; ${shot.length} bytes)`);
      return;
    }
    await testInfo.attach(`${b.picture}-actual.png`, { body: shot, contentType: 'image/png' });
    await testInfo.attach(`${b.picture}-expected.png`, { body: committed, contentType: 'image/png' });
    throw new Error(
      `${image} is not what ${b.file}:${b.line} draws: ${diff}. After an intended change: ${update}`,
    );
  });
}

/**
 * Compare two PNGs pixel for pixel (RGBA, decoded in the page without colour conversion): null when equal,
 * else what differs (the sizes, or how many pixels and the first one).
 */
async function comparePictures(page: Page, drawn: Buffer, committed: Buffer): Promise<string | null> {
  return page.evaluate(
    async ({ a, b }) => {
      const decode = async (b64: string) => {
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }), {
          colorSpaceConversion: 'none',
          premultiplyAlpha: 'none',
        });
        const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
        const ctx = canvas.getContext('2d')!;
        ctx.drawImage(bitmap, 0, 0);
        return ctx.getImageData(0, 0, bitmap.width, bitmap.height);
      };
      const [x, y] = [await decode(a), await decode(b)];
      if (x.width !== y.width || x.height !== y.height)
        return `drawn ${x.width} × ${x.height}, the image is ${y.width} × ${y.height}`;
      let count = 0;
      let first = '';
      for (let i = 0; i < x.data.length; i += 4) {
        const p = [...x.data.subarray(i, i + 4)];
        const q = [...y.data.subarray(i, i + 4)];
        if (p.every((v, k) => v === q[k])) continue;
        if (count++ === 0)
          first = `first at (${(i / 4) % x.width}, ${Math.floor(i / 4 / x.width)}): drawn ${p}, image ${q}`;
      }
      return count === 0 ? null : `${count} of ${x.width} × ${x.height} pixels differ, ${first}`;
    },
    { a: drawn.toString('base64'), b: committed.toString('base64') },
  );
}
