// Copy as code (issue 24): for ten playground states (the defaults, a Gouraud material lit by two attenuated
// lights, orthographic, flat cel shading with the outline, a term view, each picked scene, the impostor) the
// "copy as code" buttons give a three.js program and an R3F app; each is pasted into a fresh app from the packed
// tarballs (tools/pack-apps/installed.mjs: one npm install, shared with the other specs that ask for the same
// and with later runs while the tarballs are unchanged), type-checked with the app's own TypeScript 5 (strict,
// skipLibCheck off), built with the app's Vite and run in Chromium. Each must draw exactly the playground canvas's
// pixels for its state (SwiftShader is deterministic; R3F's antialiasing is turned off in the page's WebGL
// contexts, the code itself is pasted as given). Two more states (a glTF model, whose URL is a placeholder;
// automatic detail with damping, a depth mode and a fixed orthographic box) are type-checked and built only.
// SHADELAB_PACK_KEEP=1 keeps the app folder.
import { mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, type Page } from '@playwright/test';
import { compareNeighbourhood, decodePng, type RgbaImage } from '@shadelab/playwright/test';
import { type CodeVariant, programOf } from '../playground/src/learn/copyCode';
import { validateState } from '../playground/src/state/schema';
import { packBuilt } from '../scripts/pack.mjs';
import { APP_DEPENDENCIES, installedApp, R3F_DEPENDENCIES, run } from '../tools/pack-apps/installed.mjs';
import { test } from './harness-helpers';
import { collectPageErrors, serveFiles } from './picture-helpers';
import { open } from './playground-helpers';

const repo = fileURLToPath(new URL('..', import.meta.url));
const template = join(repo, 'tools', 'pack-apps', 'copy-code');

/** The states compared: partial states, as a link gives them (the rest is the lecture's scene). */
const STATES = {
  defaults: {},
  // A non-default material lit by two attenuated lights (behind the eye: their markers are not in the picture).
  material: {
    material: {
      shading: 'gouraud',
      lighting: 'phong',
      ka: [0.1, 0.2, 0.3],
      kd: [0.3, 0.6, 0.9],
      ks: [0.9, 0.8, 0.2],
      shininess: 12,
    },
    lights: [
      {
        position: [3, 4, 5],
        ambient: [0.1, 0.1, 0.1],
        diffuse: [1, 0.8, 0.6],
        specular: [1, 1, 1],
        attenuation: { a: 0.5, b: 0.1, c: 0.02 },
      },
      {
        position: [-4, -2, 4],
        ambient: [0, 0, 0.05],
        diffuse: [0.3, 0.5, 1],
        specular: [0.5, 0.5, 0.5],
        attenuation: { a: 1, b: 0, c: 0.05 },
      },
    ],
  },
  // Orthographic, zoomed, another model scale and a turned trackball.
  orthographic: {
    camera: { projection: 'orthographic', zoom: 1.25 },
    model: { scale: [1.5, 1, 0.8] },
    trackball: { rotation: [0.2, 0.3, 0, Math.sqrt(1 - 0.13)] },
  },
  // Flat cel shading with the outline, on a coarser sphere.
  cel: {
    material: { shading: 'flat', celBands: 4, outline: true, outlineWidth: 0.05, outlineColor: '#ff8800' },
    sphere: { level: 3 },
  },
  // A picked scene: the instanced spheres.
  scene: { scene: 'instanced', material: { lighting: 'phong' } },
  // A term view (diffuse only) with the model matrix as the normal matrix, under a non-uniform scale.
  terms: { material: { output: 'diffuse', normalMatrix: 'model' }, model: { scale: [2, 0.6, 1.2] } },
  // The other scenes and the impostor.
  impostor: { sphere: { render: 'impostor', radius: 0.8 } },
  lights: { scene: 'lights' },
  skinned: { scene: 'skinned', material: { celBands: 3, outline: true } },
  textured: { scene: 'textured' },
} as const;
/**
 * States whose programs are only type-checked and built: a glTF model (its URL is a placeholder), automatic
 * detail with damping, a depth mode and an orthographic box that does not follow the aspect.
 */
const CHECKED_ONLY = {
  model: { scene: 'model', material: { celBands: 4, outline: true } },
  auto: {
    sphere: { auto: true, maxErrorPx: 1 },
    trackball: { damping: true, dampingFactor: 0.1, mapping: 'arcball' },
    camera: { depth: 'logarithmic', projection: 'orthographic', fitAspect: false },
  },
} as const;
type StateName = keyof typeof STATES;
const NAMES = Object.keys(STATES) as StateName[];
const VARIANTS: CodeVariant[] = ['three', 'r3f'];

/** The playground's viewport: its canvas (the stage beside the panel) sets the apps' window size. */
const PLAYGROUND_VIEWPORT = { width: 1000, height: 640 };

let app = '';
let origin = '';
let closeServer: (() => Promise<void>) | undefined;
const codes = new Map<string, string>();
const playground = new Map<StateName, RgbaImage>();

test.describe.configure({ mode: 'serial' });

test.beforeAll(async () => {
  // npm pack of six packages and, unless another spec or an earlier run installed the same, one npm install.
  test.setTimeout(420_000);
  const tarballs = packBuilt(mkdtempSync(join(tmpdir(), 'shadelab-copy-code-tgz-')), [
    'sphere',
    'camera',
    'trackball',
    'material',
    'reference',
    'react',
  ]);
  const shared = await installedApp({
    dependencies: { ...APP_DEPENDENCIES, ...R3F_DEPENDENCIES },
    tarballs,
  });
  for (const { tarball } of tarballs) rmSync(tarball, { force: true });
  app = mkdtempSync(join(tmpdir(), 'shadelab-copy-code-'));
  symlinkSync(join(shared, 'node_modules'), join(app, 'node_modules'), 'dir');
  writeFileSync(join(app, 'tsconfig.json'), readFileSync(join(template, 'tsconfig.json')));
});

test.afterAll(async () => {
  await closeServer?.();
  if (app && !process.env.SHADELAB_PACK_KEEP) rmSync(app, { recursive: true, force: true });
});

/** The canvas's own pixels (the playground keeps its drawing buffer): no overlay can be in them. */
async function playgroundPicture(page: Page): Promise<RgbaImage> {
  const url = await page
    .getByTestId('viewport')
    .evaluate((canvas: HTMLCanvasElement) => canvas.toDataURL('image/png'));
  return decodePng(Buffer.from(url.slice(url.indexOf(',') + 1), 'base64'));
}

/**
 * Clicks a copy button and reads the dialog's code, then closes it: the three.js dialog with its close button,
 * the R3F one with Escape (its close button has the focus), and the focus goes back to the copy button.
 */
async function copied(page: Page, variant: CodeVariant): Promise<string> {
  const button = page.getByTestId(`copy-code-${variant}`);
  await button.click();
  const dialog = page.getByRole('dialog', { name: /^Copy as code/ });
  const code = dialog.getByRole('textbox', { name: /: src\/main\.tsx?$/ });
  await expect(code).toHaveAttribute('data-variant', variant);
  const text = await code.inputValue();
  const close = dialog.getByRole('button', { name: 'close' });
  await expect(close).toBeFocused();
  if (variant === 'three') await close.click();
  else await page.keyboard.press('Escape');
  await expect(dialog).toHaveCount(0);
  await expect(button).toBeFocused();
  return text;
}

test('the copy buttons give the three.js program and the R3F app of the state shown', async ({
  page,
  context,
}) => {
  // Ten playground states opened and copied twice each, on a machine shared by many runs.
  test.setTimeout(180_000);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.setViewportSize(PLAYGROUND_VIEWPORT);
  for (const name of NAMES) {
    await open(page, STATES[name]);
    const checked = validateState(JSON.parse(JSON.stringify(STATES[name])));
    if (!checked.ok) throw new Error(checked.error);
    for (const variant of VARIANTS) {
      const code = await copied(page, variant);
      // What the generator gives for the state in the link: the button reads the state shown.
      expect(code, `${name} ${variant}`).toBe(programOf(variant, checked.state));
      // And the clipboard has it.
      expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(code);
      codes.set(`${name}-${variant}`, code);
    }
    playground.set(name, await playgroundPicture(page));
  }
  // Each state gives its own code and its own picture.
  for (const variant of VARIANTS) {
    expect(new Set(NAMES.map((n) => codes.get(`${n}-${variant}`))).size).toBe(NAMES.length);
  }
  expect(new Set(NAMES.map((n) => playground.get(n)!.data.join())).size).toBe(NAMES.length);
});

test('each program type-checks in the fresh app (TypeScript 5, strict, skipLibCheck off) and builds with Vite', async () => {
  test.setTimeout(300_000);
  const input: Record<string, string> = {};
  mkdirSync(join(app, 'src'), { recursive: true });
  for (const [name, partial] of Object.entries(CHECKED_ONLY)) {
    const checked = validateState(JSON.parse(JSON.stringify(partial)));
    if (!checked.ok) throw new Error(checked.error);
    for (const variant of VARIANTS) codes.set(`${name}-${variant}`, programOf(variant, checked.state));
  }
  for (const name of [...NAMES, ...(Object.keys(CHECKED_ONLY) as (keyof typeof CHECKED_ONLY)[])]) {
    for (const variant of VARIANTS) {
      const entry = `src/${name}-${variant}.${variant === 'three' ? 'ts' : 'tsx'}`;
      writeFileSync(join(app, entry), codes.get(`${name}-${variant}`)!);
      const html = readFileSync(join(template, `${variant}.html`), 'utf8').replace('%ENTRY%', `/${entry}`);
      mkdirSync(join(app, name, variant), { recursive: true });
      writeFileSync(join(app, name, variant, 'index.html'), html);
      input[`${name}-${variant}`] = join(app, name, variant, 'index.html');
    }
  }
  const typecheck = await run('npx', ['--no-install', 'tsc', '--noEmit', '-p', '.'], app).catch(
    (e: Error) => e.message,
  );
  expect(typecheck, 'tsc --noEmit').toBe('');
  writeFileSync(
    join(app, 'vite.config.mjs'),
    `export default { base: './', logLevel: 'warn', build: { chunkSizeWarningLimit: 4096, rollupOptions: { input: ${JSON.stringify(input)} } } };\n`,
  );
  await run('npx', ['--no-install', 'vite', 'build'], app);
  const dist = join(app, 'dist');
  const served = await serveFiles((path) => {
    const file = normalize(join(dist, path.endsWith('/') ? `${path}index.html` : path));
    return file.startsWith(dist) ? file : undefined;
  });
  closeServer = served.close;
  origin = served.origin;
});

/** Opens a built program at the playground canvas's size and waits until its picture rests (two equal shots). */
async function programPicture(page: Page, name: StateName, variant: CodeVariant): Promise<RgbaImage> {
  const { width, height } = playground.get(name)!;
  const errors = collectPageErrors(page);
  // R3F's <Canvas> asks for an antialiased context (three's WebGLRenderer does not): every WebGL context of the
  // page is made without, so that both programs must draw the playground's pixels themselves.
  await page.addInitScript(() => {
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (
      this: HTMLCanvasElement,
      type: string,
      attributes?: object,
    ) {
      const plain = type.startsWith('webgl') ? { ...attributes, antialias: false } : attributes;
      return getContext.call(this, type as '2d', plain as CanvasRenderingContext2DSettings);
    } as typeof getContext;
  });
  await page.setViewportSize({ width, height });
  await page.goto(`${origin}/${name}/${variant}/`);
  const canvas = page.locator('canvas');
  await expect(canvas).toHaveCount(1);
  let last = '';
  let shot: RgbaImage | null = null;
  await expect
    .poll(
      async () => {
        if (errors.length) return `errors: ${errors.join('\n')}`;
        shot = decodePng(await canvas.screenshot());
        const key = shot.data.join();
        const lit = shot.data.some((v, i) => i % 4 !== 3 && v > 40);
        const rests = lit && key === last;
        last = key;
        return rests ? 'drawn' : 'waiting';
      },
      { timeout: 40_000, intervals: [300] },
    )
    .toBe('drawn');
  expect(errors).toEqual([]);
  return shot!;
}

for (const name of NAMES) {
  test(`${name}: the pasted three.js program and R3F app draw the playground's picture`, async ({ page }) => {
    const reference = playground.get(name)!;
    for (const variant of VARIANTS) {
      const picture = await programPicture(page, name, variant);
      expect([picture.width, picture.height], variant).toEqual([reference.width, reference.height]);
      const result = compareNeighbourhood(reference, picture, { radiusPx: 0, maxChannelDiff: 0 });
      expect(
        { failingPixels: result.failingPixels, worst: result.worst, maxExcess: result.maxExcess },
        `${name}, ${variant}: pixels off the playground's picture`,
      ).toEqual({ failingPixels: 0, worst: null, maxExcess: 0 });
    }
  });
}
