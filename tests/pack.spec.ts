// Ready to `npm install`: the packed tarballs, installed into fresh apps made in a temporary folder (plain
// three.js on the newest and on the oldest supported three, a user's app whose main.ts is the README's Quick
// start, and a react-three-fiber app whose main.tsx is the R3F guide's example, both extracted verbatim at test
// time), type-check with the app's own TypeScript 5 in strict mode, build with Vite and render the lecture's
// scene in Chromium. Every app checks every declaration file too (skipLibCheck off: our .d.ts against
// @types/three old and new, and @shadelab/react's against R3F's and React's). The app sources are tools/pack-apps/<app>/ (kept out of the repo's own
// type check: the r3f app needs @react-three/fiber, which only the temporary app installs).
// SHADELAB_PACK_KEEP=1 keeps the temporary folder.
import { spawn } from 'node:child_process';
import {
  cpSync,
  existsSync,
  mkdirSync,
  mkdtempSync,
  readdirSync,
  readFileSync,
  realpathSync,
  rmSync,
  symlinkSync,
  writeFileSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, normalize, posix } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, type Page, test } from '@playwright/test';
import { markdownLinks } from '../scripts/check-links.mjs';
import { type PackedPackage, packBuilt } from '../scripts/pack.mjs';
import { collectBlocks } from '../scripts/snippets.mjs';
import { APP_DEPENDENCIES, installedApp, R3F_DEPENDENCIES, run } from '../tools/pack-apps/installed.mjs';
import { listening } from './net-helpers';
import {
  collectPageErrors,
  expectScenePicture,
  LECTURE_VIEW,
  canvasSamples as samples,
  serveFiles,
} from './picture-helpers';

const repo = fileURLToPath(new URL('..', import.meta.url));

/** What the lecture's scene needs; every other published package is installed too (scripts/pack.mjs PACKAGES). */
const LECTURE_PACKAGES = [
  '@shadelab/sphere',
  '@shadelab/camera',
  '@shadelab/trackball',
  '@shadelab/material',
];

/** The oldest three and @types/three we support, as pinned for scripts/three-compat.mjs. */
const oldest = (
  JSON.parse(readFileSync(join(repo, 'tools', 'three-compat', 'package.json'), 'utf8')) as {
    dependencies: { three: string; '@types/three': string };
  }
).dependencies;
/** The version range of a root devDependency (the repository's own Playwright, for the testing guide's app). */
function rootDevDependency(name: string): string {
  const pkg = JSON.parse(readFileSync(join(repo, 'package.json'), 'utf8')) as {
    devDependencies: Record<string, string>;
  };
  return pkg.devDependencies[name];
}
/** The README's Quick start, verbatim: the one code block under its "Quick start" heading. */
function quickStart(): string {
  const blocks = collectBlocks({ files: ['README.md'] }).filter((b) => /quick start/i.test(b.heading));
  if (blocks.length !== 1)
    throw new Error(`README.md: expected one code block under "Quick start", found ${blocks.length}`);
  return blocks[0].code;
}
/**
 * The app of docs/testing.md: each ```ts file=PATH block of the guide, verbatim, at PATH, and a test that must
 * fail (the exact image of a shininess the page does not draw).
 */
function testingGuideApp(): Record<string, string> {
  const blocks = collectBlocks({ files: ['docs/testing.md'] }).filter((b) => b.path !== undefined);
  const files = Object.fromEntries(blocks.map((b) => [b.path as string, b.code]));
  for (const path of ['src/scene.ts', 'src/main.ts', 'playwright.config.ts', 'tests/scene.spec.ts']) {
    if (!(path in files)) throw new Error(`docs/testing.md: no \`\`\`ts file=${path} block`);
  }
  files['tests/deliberately-failing.spec.ts'] =
    `// Deliberately failing: the page draws the material's shininess; this test's scene says 4.
import { expect, referenceSceneOf, test } from '@shadelab/playwright/reference';
import { buildScene } from '../src/scene';

test('deliberately failing: the exact image of another shininess', async ({ page }) => {
  await page.goto('/');
  const canvas = page.locator('canvas');
  await expect(canvas).toHaveRendered({ timeout: 30_000 });
  const { camera, sphere, material } = buildScene(400, 400);
  material.shininess = 4;
  await expect(canvas).toMatchReference(referenceSceneOf({ camera, sphere }), { rmse: 0.5, max: 4, silhouettePx: 1 });
});
`;
  return files;
}

/** The R3F guide's complete app (its one tsx block that is neither partial nor a file= block), verbatim. */
function r3fGuideApp(): string {
  const blocks = collectBlocks({ files: ['packages/react/docs/guide.md'] }).filter(
    (b) => b.ext === 'tsx' && !b.partial && b.path === undefined,
  );
  expect(blocks.length, 'the R3F guide has one complete app').toBe(1);
  return blocks[0].code;
}

/**
 * Each app: its source folder in tools/pack-apps, the dependencies it adds or overrides, and a src/main.ts
 * that replaces the folder's (or every file, for the testing guide's app).
 */
const apps = {
  vanilla: { template: 'vanilla', dependencies: {} },
  // A user's fresh app with the README's Quick start pasted in as its main.ts.
  quickstart: { template: 'vanilla', dependencies: {}, main: quickStart },
  oldest: {
    template: 'vanilla',
    dependencies: { three: oldest.three, '@types/three': oldest['@types/three'] },
  },
  // A user's R3F app whose src/main.tsx is the R3F guide's example, with @shadelab/react from its tarball.
  r3f: {
    template: 'r3f',
    main: r3fGuideApp,
    dependencies: R3F_DEPENDENCIES,
  },
  // docs/testing.md's app: its scene tested with @shadelab/playwright, from the tarball, with Playwright itself.
  playwright: {
    template: 'playwright',
    dependencies: { '@playwright/test': rootDevDependency('@playwright/test'), '@types/node': '^20.19.43' },
    files: testingGuideApp,
  },
} satisfies Record<
  string,
  {
    template: string;
    dependencies: Record<string, string>;
    main?: () => string;
    files?: () => Record<string, string>;
  }
>;
type App = keyof typeof apps;

let tmp = '';
let packed: PackedPackage[] = [];
let closeServer: (() => Promise<void>) | undefined;
let origin = '';
const timings: Record<string, number> = {};

async function timed<T>(label: string, work: () => Promise<T>): Promise<T> {
  const t0 = performance.now();
  const result = await work();
  timings[label] = Math.round(performance.now() - t0);
  return result;
}

/** Make the app folder, install it, type-check it and build it. */
async function makeApp(app: App): Promise<void> {
  const dir = join(tmp, app);
  cpSync(join(repo, 'tools', 'pack-apps', apps[app].template), dir, { recursive: true });
  const spec = apps[app];
  if ('main' in spec) {
    mkdirSync(join(dir, 'src'), { recursive: true });
    writeFileSync(join(dir, 'src', spec.template === 'r3f' ? 'main.tsx' : 'main.ts'), spec.main());
  }
  if ('files' in spec) {
    for (const [path, text] of Object.entries(spec.files())) {
      mkdirSync(dirname(join(dir, path)), { recursive: true });
      writeFileSync(join(dir, path), text);
    }
  }
  // The test kit only where it is used: the other apps are the three.js apps users ship.
  const installed = packed
    .filter((p) => app === 'playwright' || p.name !== '@shadelab/playwright')
    // @shadelab/react only in the R3F app (its peers, react and @react-three/fiber, are that app's).
    .filter((p) => app === 'r3f' || p.name !== '@shadelab/react');
  const dependencies = { ...APP_DEPENDENCIES, ...apps[app].dependencies };
  const pkg = {
    name: `shadelab-pack-${app}`,
    private: true,
    type: 'module',
    dependencies: {
      ...dependencies,
      ...Object.fromEntries(installed.map((p) => [p.name, `file:${p.tarball}`])),
    },
  };
  writeFileSync(join(dir, 'package.json'), `${JSON.stringify(pkg, null, 2)}\n`);
  if (app === 'playwright') {
    // The testing guide's app installs Playwright, which no other app has: an install of its own.
    await timed(`${app}: npm install`, () =>
      run('npm', ['install', '--no-audit', '--no-fund', '--prefer-offline', '--loglevel', 'error'], dir),
    );
  } else {
    // One install for the apps with the same tarballs and dependencies (the vanilla app and the Quick start's;
    // the R3F app and tests/playground-copy-code.spec.ts's), linked into each app folder.
    const shared = await timed(`${app}: npm install (shared)`, () =>
      installedApp({ dependencies, tarballs: installed }),
    );
    symlinkSync(join(shared, 'node_modules'), join(dir, 'node_modules'), 'dir');
  }
  await timed(`${app}: tsc --noEmit`, () => run('npx', ['--no-install', 'tsc', '--noEmit', '-p', '.'], dir));
  await timed(`${app}: vite build`, () =>
    run('npx', ['--no-install', 'vite', 'build', '--base', './', '--logLevel', 'warn'], dir),
  );
}

/** Serve `<tmp>/<app>/dist` at `/<app>/`. */
async function serve(): Promise<string> {
  const served = await serveFiles((path) => {
    const [, app, ...rest] = normalize(path).split('/');
    const file = join(tmp, app ?? '', 'dist', rest.join('/') || 'index.html');
    return app in apps && file.startsWith(tmp) ? file : undefined;
  });
  closeServer = served.close;
  return served.origin;
}

const brightness = (rgb: number[]) => rgb[0] + rgb[1] + rgb[2];

// The lecture's view: the (2, 1, 2) ellipsoid seen from z = 3 with fovy 90° covers x within ±0.894 and
// y within ±0.447 of the half-size (tangents from the eye: 2/√5 and 1/√5), so these points are background.
const BACKGROUND = [
  [0.01, 0.01],
  [0.99, 0.01],
  [0.01, 0.99],
  [0.99, 0.99],
  [0.5, 0.1],
  [0.5, 0.9],
  [0.01, 0.5],
  [0.99, 0.5],
] as const;
const CENTRE = [0.5, 0.5] as const;
const TOWARDS_LIGHT = [0.35, 0.42] as const; // the light is at (−5, 10, 20): up, left, in front
const AWAY_FROM_LIGHT = [0.65, 0.58] as const;
const RIM = [
  [0.1, 0.5],
  [0.9, 0.5],
] as const;
const ABOVE = [0.5, 0.2] as const; // background until a vertical drag tilts the long z axis up

async function checkLectureScene(page: Page, app: App): Promise<void> {
  const errors = collectPageErrors(page);
  await page.setViewportSize({ width: 400, height: 400 });
  await page.goto(`${origin}/${app}/`);
  const canvas = page.locator('canvas');
  await expect(canvas).toHaveCount(1);
  await expect(canvas).toHaveJSProperty('width', 400);
  await expect
    .poll(async () => brightness((await samples(page, [CENTRE]))[0]), { timeout: 30_000 })
    .toBeGreaterThan(120);

  const before = await samples(page, [CENTRE, TOWARDS_LIGHT, AWAY_FROM_LIGHT, ...RIM, ABOVE, ...BACKGROUND]);
  const [centre, lit, dim, rimLeft, rimRight, above, ...background] = before;
  // The material's default colour is orange (kd = (0.6, 0.35, 0.2)): red > green > blue where it is lit.
  expect(centre[0]).toBeGreaterThan(centre[1]);
  expect(centre[1]).toBeGreaterThan(centre[2]);
  // Diffuse lighting from the upper left: brighter towards the light than away from it.
  expect(brightness(lit)).toBeGreaterThan(brightness(dim));
  // Ambient light reaches the rim on both sides; outside the silhouette is the black background.
  expect(brightness(rimLeft)).toBeGreaterThan(15);
  expect(brightness(rimRight)).toBeGreaterThan(15);
  expect(brightness(above)).toBeLessThanOrEqual(6);
  for (const px of background) expect(brightness(px)).toBeLessThanOrEqual(6);

  // The trackball: a vertical drag from the centre turns the sphere about the camera's u axis, tilting its long
  // z semi-axis towards the viewer's vertical, so the silhouette grows above the centre.
  const box = (await canvas.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++)
    await page.mouse.move(box.x + box.width / 2, box.y + box.height * (0.5 - 0.025 * i));
  await page.mouse.up();
  await expect.poll(async () => brightness((await samples(page, [ABOVE]))[0])).toBeGreaterThan(15);
  const after = await samples(page, BACKGROUND.slice(0, 4));
  for (const px of after) expect(brightness(px)).toBeLessThanOrEqual(6);

  expect(errors).toEqual([]);
}

test.describe.configure({ mode: 'serial' });

test.beforeAll(async () => {
  // npm install of five apps, five strict type checks and five Vite builds on a 2-core machine.
  test.setTimeout(720_000);
  tmp = mkdtempSync(join(tmpdir(), 'shadelab-pack-'));
  packed = await timed('npm pack', async () => packBuilt(join(tmp, 'tarballs')));
  await Promise.all((Object.keys(apps) as App[]).map(makeApp));
  origin = await serve();
});

test.afterAll(async () => {
  await closeServer?.();
  if (tmp && !process.env.SHADELAB_PACK_KEEP) rmSync(tmp, { recursive: true, force: true });
  console.log(`pack test timings (ms): ${JSON.stringify(timings)}`);
});

test('each tarball holds its ESM build, declarations, README and package.json, and nothing else', () => {
  expect(packed.map((p) => p.name)).toEqual(expect.arrayContaining(LECTURE_PACKAGES));
  for (const p of packed) {
    expect(p.files, p.name).toEqual(
      expect.arrayContaining(['package.json', 'dist/index.js', 'dist/index.d.ts']),
    );
    for (const f of p.files) {
      expect(f, p.name).toMatch(
        /^(package\.json|README\.md|LICENSE|CHANGELOG\.md|dist\/[\w.-]+\.(js|d\.ts)(\.map)?|src\/[\w.-]+\.(ts|tsx|js)|docs\/(api\/)?[\w.@-]+\.md|docs\/images\/[\w-]+\.png)$/,
      );
      // (Not a test: docs/api/@shadelab.playwright.test.md, the reference of the @shadelab/playwright/test entry.)
      expect(f, p.name).not.toMatch(/\.test\.(ts|js|d\.ts)(\.map)?$|test-util|tsbuildinfo/);
    }
    // The guide and the generated API reference ship in the package, and every link the README and the guide
    // make inside the package resolves in the tarball (links out of it, such as BENCHMARKS.md, are the
    // repository's: scripts/check-links.mjs checks those).
    expect(p.files, p.name).toEqual(expect.arrayContaining(['docs/guide.md', 'docs/api/README.md']));
    for (const page of p.files.filter((f) => f === 'README.md' || f.startsWith('docs/'))) {
      const folder = posix.dirname(page);
      const text = readFileSync(join(repo, 'packages', p.name.split('/')[1], page), 'utf8');
      for (const { target } of markdownLinks(text)) {
        if (/^[a-z][a-z\d+.-]*:/i.test(target) || target.startsWith('#')) continue;
        const path = posix.normalize(posix.join(folder, decodeURI(target.replace(/[#?].*$/, ''))));
        if (path.startsWith('../')) continue;
        expect(
          p.files.some((f) => f === path || f.startsWith(`${path.replace(/\/$/, '')}/`)),
          `${p.name}: ${page} → ${target}`,
        ).toBe(true);
      }
    }
    // Dependencies between our packages are plain ranges that the sibling being released satisfies.
    const manifest = JSON.parse(
      readFileSync(join(repo, 'packages', p.name.split('/')[1], 'package.json'), 'utf8'),
    );
    for (const [dep, range] of Object.entries<string>(manifest.dependencies ?? {})) {
      const sibling = packed.find((q) => q.name === dep);
      if (sibling) expect(range, `${p.name} → ${dep}`).toBe(`^${sibling.version}`);
    }
    // Every module has its declaration beside it, and its source: no stale build of a removed module ships.
    // (A source may be JavaScript: @shadelab/playwright's Chromium lookup, which set-up scripts import unbuilt.)
    for (const js of p.files.filter((f) => f.startsWith('dist/') && f.endsWith('.js'))) {
      expect(p.files, `${p.name}: ${js}`).toContain(js.replace(/\.js$/, '.d.ts'));
      const source = js.replace(/^dist\/(.*)\.js$/, 'src/$1');
      expect(
        ['ts', 'tsx', 'js'].some((ext) => p.files.includes(`${source}.${ext}`)),
        `${p.name}: ${js} has no source (left by a removed or renamed file? \`npm run pack\` builds from scratch)`,
      ).toBe(true);
    }
  }
});

test('each package.json is ready to publish: types-first exports, files, no side effects, peers, metadata', () => {
  for (const p of packed) {
    const folder = p.name.split('/')[1];
    const manifest = JSON.parse(readFileSync(join(repo, 'packages', folder, 'package.json'), 'utf8'));
    const where = `packages/${folder}/package.json`;
    expect(manifest.private, where).toBeUndefined();
    expect(manifest.type, where).toBe('module');
    // @shadelab/react's one job on import is registering its JSX elements with R3F's extend: a side effect.
    expect(manifest.sideEffects, where).toBe(folder === 'react');
    expect(Object.keys(manifest.exports ?? {}), `${where}: exports`).toContain('.');
    // Every entry point (the main one and subpaths such as './impostor') lists "types" first, and both files
    // are in the tarball.
    for (const [path, entry] of Object.entries(
      manifest.exports as Record<string, string | Record<string, string>>,
    )) {
      if (path === './package.json') continue;
      if (typeof entry === 'string')
        throw new Error(`${where}: exports['${path}'] must be a conditions object`);
      expect(Object.keys(entry)[0], `${where}: exports['${path}'] lists "types" first`).toBe('types');
      expect(p.files, `${where}: exports['${path}']`).toContain(entry.types.replace(/^\.\//, ''));
      expect(p.files, `${where}: exports['${path}']`).toContain(entry.import.replace(/^\.\//, ''));
    }
    expect(Array.isArray(manifest.files) && manifest.files.length > 0, `${where}: files`).toBe(true);
    expect(manifest.engines?.node, where).toMatch(/^>=\d+/);
    expect(manifest.repository?.url, where).toMatch(/^git\+https:\/\//);
    expect(manifest.repository?.directory, where).toBe(`packages/${folder}`);
    expect(manifest.license, where).toBe('MIT');
    expect(manifest.keywords?.length, `${where}: keywords`).toBeGreaterThan(0);
    expect(manifest.description, where).toBeTruthy();
    // A package whose build imports three declares it as a peer with a lower bound only; none bundles it.
    const importsThree = p.files
      .filter((f) => f.endsWith('.js'))
      .some((f) => /from ['"]three['"]/.test(readFileSync(join(repo, 'packages', folder, f), 'utf8')));
    if (importsThree)
      expect(manifest.peerDependencies?.three, `${where}: peer three`).toMatch(/^>=\d+\.\d+\.\d+$/);
    expect(manifest.dependencies?.three, `${where}: three must not be a dependency`).toBeUndefined();
  }
});

test("a fresh three.js app renders the lecture's scene from the tarballs and the trackball turns it", async ({
  page,
}) => {
  await checkLectureScene(page, 'vanilla');
});

test(`the same app on the oldest supported three (${oldest.three}, @types/three ${oldest['@types/three']})`, async ({
  page,
}) => {
  await checkLectureScene(page, 'oldest');
});

test("the README's Quick start, pasted into a fresh Vite app from the tarballs, renders the lit ellipsoid", async ({
  page,
}) => {
  const errors = collectPageErrors(page);
  await page.setViewportSize({ width: 900, height: 900 }); // the Quick start's canvas is 800 × 800
  await page.goto(`${origin}/quickstart/`);
  await expectScenePicture(page, LECTURE_VIEW, errors);
});

test('the packages import and work in Node (server-side code, tests): no DOM touched at import', async () => {
  const script = `
    import { Camera } from '@shadelab/camera';
    import { PhongLight, ShadingMaterial, shade } from '@shadelab/material';
    import { sphereCounts, subdivideSphere, SubdivisionSphereGeometry } from '@shadelab/sphere';
    import { chooseSphereDetail } from '@shadelab/sphere/detail';
    import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
    import { OutlineMaterial } from '@shadelab/material/outline';
    import { flatShadingGeometry } from '@shadelab/material';
    import { intersectSphere } from '@shadelab/reference';
    import { Trackball } from '@shadelab/trackball';
    const hit = intersectSphere([0, 0, 3], [0, 0, -1]);
    const mesh = subdivideSphere({ level: 2 });
    const geometry = new SubdivisionSphereGeometry({ level: 2 });
    const camera = new Camera();
    camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
    camera.setPerspective(90, 1, 0.1, 10);
    const light = new PhongLight();
    const material = new ShadingMaterial({ lights: [light] });
    const trackball = new Trackball(null, null, { camera });
    const detail = chooseSphereDetail({ radiusPx: 300, maxErrorPx: 0.5 });
    const impostor = new SphereImpostor(new SphereImpostorMaterial({ lights: [light] }));
    const lit = shade(
      { position: [0, 0, 1], normal: [0, 0, 1], eye: [0, 0, 3, 1] },
      { ka: [0, 0, 0], kd: [1, 1, 1], ks: [0, 0, 0], shininess: 1, lighting: 'phong', celBands: 0 },
      [{ position: [0, 0, 10], ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [0, 0, 0], attenuation: { a: 1, b: 0, c: 0 } }],
    );
    console.log(JSON.stringify({
      triangles: (mesh.indices ? mesh.indices.length : mesh.positions.length / 3) / 3,
      expected: sphereCounts('tetrahedron', 2).triangles,
      geometryTriangles: (geometry.index ? geometry.index.count : geometry.attributes.position.count) / 3,
      w: camera.getFrame().w.toArray(),
      shading: material.shading,
      matrix: trackball.getMatrix().toArray(),
      lit: Array.from(lit),
      hit: hit && [hit.t0, hit.t1],
      detail: [detail.errorPx <= 0.5, detail.triangles === sphereCounts(detail.base, detail.level).triangles],
      impostorShading: impostor.material.shading,
      outlineThickness: new OutlineMaterial({ thickness: 0.05 }).thickness,
      flatVertices: flatShadingGeometry(geometry).attributes.position.count,
    }));
  `;
  const out = await run('node', ['--input-type=module', '-e', script], join(tmp, 'vanilla'));
  const result = JSON.parse(out.trim().split('\n').at(-1)!);
  expect(result.triangles).toBe(4 * 4 ** 2);
  expect(result.expected).toBe(64);
  expect(result.geometryTriangles).toBe(64);
  expect(result.w[0]).toBeCloseTo(0, 12);
  expect(result.w[1]).toBeCloseTo(0, 12);
  expect(result.w[2]).toBeCloseTo(1, 12);
  expect(result.shading).toBe('phong');
  expect(result.matrix).toEqual([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
  // Head-on light, kd = 1, unattenuated: l·n = 1.
  for (const c of result.lit) expect(c).toBeCloseTo(1, 12);
  // The CPU reference: a ray from z = 3 down the axis enters the unit sphere at t = 2 and leaves at t = 4.
  expect(result.hit[0]).toBeCloseTo(2, 12);
  expect(result.hit[1]).toBeCloseTo(4, 12);
  // The subpath entries resolve from the tarballs too.
  expect(result.detail).toEqual([true, true]);
  expect(result.impostorShading).toBe('phong');
  expect(result.outlineThickness).toBe(0.05);
  expect(result.flatVertices).toBe(64); // level 2: one vertex per face
});

test("a fresh react-three-fiber app renders the lecture's scene from the tarballs and the trackball turns it", async ({
  page,
}) => {
  await checkLectureScene(page, 'r3f');
});

/**
 * Run the app's own Playwright in `dir`: not inside this run (the variables Playwright gives its workers are
 * left out), with no browser of Playwright's own (PLAYWRIGHT_BROWSERS_PATH names an empty folder), so that
 * only the kit's lookup can find one. Resolves with the exit code and the output.
 */
function runAppPlaywright(dir: string, args: string[], env: Record<string, string> = {}) {
  const clean = Object.fromEntries(
    Object.entries(process.env).filter(([k]) => !/^(PW_|PLAYWRIGHT_|TEST_|NODE_OPTIONS$)/.test(k)),
  );
  const noBrowsers = join(tmp, 'no-playwright-browsers');
  mkdirSync(noBrowsers, { recursive: true });
  return new Promise<{ code: number | null; out: string }>((resolve, reject) => {
    const child = spawn('npx', ['--no-install', 'playwright', 'test', ...args], {
      cwd: dir,
      env: { ...clean, CI: '1', PLAYWRIGHT_BROWSERS_PATH: noBrowsers, ...env },
    });
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
    });
    child.stderr.on('data', (d) => {
      out += d;
    });
    child.on('error', reject);
    child.on('close', (code) => resolve({ code, out }));
  });
}

/**
 * The process ids of the dev servers Vite's lock files (`node_modules/.vite/lock`) say still run for the app in
 * `dir`. A killed server that its parent has not reaped yet (a zombie) has exited: its lock file is removed, as
 * Vite removes those of processes that are gone.
 */
function viteServersRunning(dir: string): number[] {
  const locks = join(dir, 'node_modules', '.vite', 'lock');
  if (!existsSync(locks)) return [];
  const running: number[] = [];
  for (const name of readdirSync(locks).filter((n) => n.endsWith('.json'))) {
    const file = join(locks, name);
    let record: { pid?: number; root?: string };
    try {
      record = JSON.parse(readFileSync(file, 'utf8'));
    } catch {
      continue; // being written or removed
    }
    if (record.root !== realpathSync(dir) || typeof record.pid !== 'number') continue;
    if (processRuns(record.pid)) running.push(record.pid);
    else rmSync(file, { force: true });
  }
  return running;
}

/** Whether process `pid` exists and has not exited (on Linux a zombie, state Z in /proc, has exited). */
function processRuns(pid: number): boolean {
  try {
    process.kill(pid, 0);
  } catch (error) {
    return (error as NodeJS.ErrnoException).code === 'EPERM';
  }
  try {
    return !/\) Z /.test(readFileSync(`/proc/${pid}/stat`, 'utf8'));
  } catch {
    return process.platform !== 'linux';
  }
}

interface ReportTest {
  title: string;
  status: string;
  results: { status: string; attachments: { name: string }[]; errors: { message?: string }[] }[];
}

/** Every test of a Playwright JSON report, with its spec file. */
function reportTests(report: { suites: unknown[] }): (ReportTest & { file: string })[] {
  const out: (ReportTest & { file: string })[] = [];
  const walk = (suite: {
    file?: string;
    specs?: { title: string; tests: ReportTest[] }[];
    suites?: unknown[];
  }) => {
    for (const spec of suite.specs ?? []) {
      for (const t of spec.tests) out.push({ ...t, title: spec.title, file: suite.file ?? '' });
    }
    for (const child of suite.suites ?? []) walk(child as typeof suite);
  };
  for (const suite of report.suites) walk(suite as Parameters<typeof walk>[0]);
  return out;
}

test("docs/testing.md's app, from the tarballs, runs its visual tests with its own Playwright: the guide's passes, a deliberately failing one fails with the diff attached", async () => {
  test.setTimeout(300_000);
  const dir = join(tmp, 'playwright');
  // The guide's first run writes the baseline of toMatchScreenshotAcrossGpus (and passes).
  const first = await timed('playwright app: first run', () =>
    runAppPlaywright(dir, ['tests/scene.spec.ts', '--update-snapshots=missing', '--reporter=line']),
  );
  expect(first.code, first.out).toBe(0);
  expect(
    readFileSync(join(dir, 'tests', '__screenshots__', 'scene.spec.ts', 'lecture.png')).length,
  ).toBeGreaterThan(0);
  // Then every test, as CI runs them: the failing one fails the run. Its web server takes the same port, once the
  // first run's has let it go.
  const port = Number(
    /const port = (\d+)/.exec(readFileSync(join(dir, 'playwright.config.ts'), 'utf8'))?.[1],
  );
  await expect.poll(() => listening(port), { timeout: 30_000, message: `port ${port} freed` }).toBe(false);
  // Vite refuses to start beside a dev server of the same app that still runs, which it reads from its lock files:
  // the first run's server must be gone, not only its port.
  await expect
    .poll(() => viteServersRunning(dir), { timeout: 30_000, message: "the first run's Vite server gone" })
    .toEqual([]);
  const report = join(dir, 'report.json');
  const all = await timed('playwright app: second run', () =>
    runAppPlaywright(dir, ['--reporter=json'], { PLAYWRIGHT_JSON_OUTPUT_NAME: report }),
  );
  expect(all.code, all.out).toBe(1);
  const tests = reportTests(JSON.parse(readFileSync(report, 'utf8')));
  const guide = tests.find((t) => t.file === 'scene.spec.ts');
  const failing = tests.find((t) => t.file === 'deliberately-failing.spec.ts');
  expect(guide?.status, all.out + JSON.stringify(guide?.results[0]?.errors)).toBe('expected');
  expect(failing?.status).toBe('unexpected');
  const result = failing!.results[0];
  expect(result.errors[0].message).toContain('The canvas differs from the exact reference beyond the budget');
  expect(result.attachments.map((a) => a.name)).toEqual(
    expect.arrayContaining([
      'reference-expected.png',
      'reference-actual.png',
      'reference-diff.png',
      'reference-error.json',
    ]),
  );
});
