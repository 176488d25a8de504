// The code blocks of the Markdown marked ```ts run=SCENE (the README's Quick start, each package README's
// first example, a guide's example that loads a model) run as a user would run them: each block, verbatim, is
// the main.ts of a page (a generated index.html), all bundled by one Vite build that resolves `three` and
// `@shadelab/*` through the workspace's node_modules (the packages' built dist/, through their `exports`), and
// opened in Chromium. A page error or console error fails the test (an option that throws shows as one), and the
// picture must be SCENE's: drawn inside the silhouette computed from the scene's camera and model, the
// background outside, brighter towards the light when lit (picture-helpers.ts); what a page fetches is served
// by the test (PAGE_SETUP). scripts/snippets.mjs type-checks the same blocks; see DEVELOPERS.md, "Code in docs".
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, type Page, test } from '@playwright/test';
import { SphereGeometry } from 'three';
import { type Block, collectBlocks } from '../scripts/snippets.mjs';
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
const runs = blocks.filter((b) => b.run);
const port = process.env.SHADELAB_E2E_PORT ?? '4173';
const out = join(repo, 'reports', `snippets-run-${port}`);
/** The page of each runnable block: a folder named after its Markdown file and line. */
const pageOf = (b: Block) => `${b.file.replace(/[^\w.-]+/g, '_')}-${b.line}`;
let origin = '';
let close: (() => Promise<void>) | undefined;

// In order, in one worker (one build); a failed test does not skip the others.
test.describe.configure({ mode: 'default' });

test.beforeAll(async () => {
  test.setTimeout(180_000);
  rmSync(out, { recursive: true, force: true });
  const input: Record<string, string> = {};
  for (const b of runs) {
    const dir = join(out, 'src', pageOf(b));
    mkdirSync(dir, { recursive: true });
    writeFileSync(join(dir, 'main.ts'), b.code);
    // The block runs first; the mark says it ran to its end (a module that throws stops before it).
    writeFileSync(
      join(dir, 'entry.ts'),
      "import './main.ts';\ndocument.documentElement.dataset.ran = 'true';\n",
    );
    writeFileSync(
      join(dir, 'index.html'),
      `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8" />
    <link rel="icon" href="data:," />
    <title>${b.file}:${b.line}</title>
    <style>html, body { margin: 0; } canvas { display: block; }</style>
  </head>
  <body>
    <script type="module" src="./entry.ts"></script>
  </body>
</html>
`,
    );
    input[pageOf(b)] = join(dir, 'index.html');
  }
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
  const quickStart = blocks.filter((b) => b.file === 'README.md' && /quick start/i.test(b.heading));
  expect(quickStart.map((b) => b.run)).toEqual(['lecture']);
  const marked = [
    'README.md (Quick start)',
    ...[...first.values()].filter((b) => b.run).map((b) => b.file),
  ].sort();
  expect(marked).toEqual([...MUST_RUN].sort());
  for (const file of Object.keys(NOT_RUN)) expect(first.get(file)?.partial, file).toBeTruthy();
  expect([...first.keys()].sort()).toEqual([...MUST_RUN.slice(1), ...Object.keys(NOT_RUN)].sort());
  for (const b of runs) expect(Object.keys(SCENES), `${b.file}:${b.line} run=${b.run}`).toContain(b.run);
});

for (const b of runs) {
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
