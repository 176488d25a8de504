// @shadelab/react, rendered: pages bundled by one Vite build that resolves react, @react-three/fiber, three and
// @shadelab/* through the workspace's node_modules (the packages' built dist/, as an app resolves them), opened
// in Chromium.
// - guide: the R3F guide's complete example, verbatim: it draws the lecture's lit ellipsoid (picture-helpers.ts),
//   and a trackball drag turns it exactly as the vanilla Quick start (README.md, verbatim) is turned by the same
//   drag: the two canvases match before and after.
// - harness: the components and elements in one scene on an R3F root (frames drawn with `advance`), mounted
//   and unmounted 1,000 times: renderer.info (geometries, textures, programs) and the canvas's and document's
//   event listeners (counted by wrapping add/removeEventListener) are back at their baseline; and a hostile
//   colour prop written in place (ka={[NaN, -1, 0]}) gives one named error over 60 frames, not one per frame;
//   a <phongLight> element lights a <shadingMaterial> given no phongLights (the picture of the same light listed;
//   black without it); <AutoDetailSphere>'s detail follows LectureCamera's eye on the view axis, as the closed
//   forms of its radius and error scale and chooseSphereDetail say, up and back down.
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, type Page, test } from '@playwright/test';
import { chooseSphereDetail } from '@shadelab/sphere/detail';
import react from '@vitejs/plugin-react';
import { collectBlocks } from '../scripts/snippets.mjs';
import {
  buildAndServePages,
  canvasPixels,
  collectPageErrors,
  expectScenePicture,
  LECTURE_VIEW,
} from './picture-helpers';

const repo = fileURLToPath(new URL('..', import.meta.url));
const port = process.env.SHADELAB_E2E_PORT ?? '4173';
const out = join(repo, 'reports', `react-${port}`);
let origin = '';
let close: (() => Promise<void>) | undefined;

const blocks = collectBlocks();
/** The guide's complete app: its first tsx block that is neither partial nor a file of another app. */
const guideApp = blocks.find(
  (b) => b.file === 'packages/react/docs/guide.md' && b.ext === 'tsx' && !b.partial && !b.path,
);
const quickStart = blocks.find((b) => b.file === 'README.md' && b.run === 'lecture');

/** The harness page: one scene with every component and element, and the hooks the tests drive. */
const HARNESS = `
import { advance, createRoot, events, extend } from '@react-three/fiber';
import { PhongLight } from '@shadelab/material';
import { AutoDetailSphere, LectureCamera, Trackball } from '@shadelab/react';
import type { AutoDetailSphere as DetailMesh } from '@shadelab/sphere/detail';
import { useEffect, useMemo } from 'react';
import * as THREE from 'three';

// <Canvas> registers three's classes; a bare root does not.
extend(THREE as never);

// Listeners alive on the canvas and the document: each (type, listener, capture) once, as the DOM keeps them.
type Entry = { target: string; type: string; listener: unknown; capture: boolean };
const live: Entry[] = [];
function watch(target: EventTarget, name: string) {
  const add = target.addEventListener.bind(target);
  const remove = target.removeEventListener.bind(target);
  const captureOf = (o: unknown) => (typeof o === 'boolean' ? o : !!(o as { capture?: boolean } | undefined)?.capture);
  const find = (type: string, listener: unknown, capture: boolean) =>
    live.findIndex((e) => e.target === name && e.type === type && e.listener === listener && e.capture === capture);
  target.addEventListener = (type: string, listener: never, options?: never) => {
    if (listener && find(type, listener, captureOf(options)) < 0) live.push({ target: name, type, listener, capture: captureOf(options) });
    add(type, listener, options);
  };
  target.removeEventListener = (type: string, listener: never, options?: never) => {
    const i = find(type, listener, captureOf(options));
    if (i >= 0) live.splice(i, 1);
    remove(type, listener, options);
  };
}

const canvas = document.createElement('canvas');
canvas.style.width = '400px';
canvas.style.height = '400px';
watch(canvas, 'canvas');
watch(document, 'document');
document.body.append(canvas);

function Scene({ ka, onMounted }: { ka?: [number, number, number]; onMounted: () => void }) {
  const light = useMemo(() => new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 }), []);
  useEffect(onMounted, []);
  return (
    <>
      <LectureCamera makeDefault eye={[0, 0, 3]} fovy={90} near={0.1} far={10} />
      <primitive object={light} position={[-5, 10, 20]} />
      <Trackball makeDefault>
        <mesh scale={[2, 1, 2]}>
          <subdivisionSphereGeometry args={[{ level: 4, normals: 'none' }]} />
          <shadingMaterial shading="phong" lighting="blinn-phong" phongLights={[light]} ka={ka ?? [1, 1, 1]} />
        </mesh>
      </Trackball>
      <AutoDetailSphere maxErrorPx={1} position={[0, 0.8, 1]} scale={0.2}>
        <shadingMaterial shading="gouraud" phongLights={[light]} />
      </AutoDetailSphere>
      <mesh position={[0, -0.8, 1]} scale={0.2}>
        <subdivisionSphereGeometry args={[{ level: 2 }]} />
        <outlineMaterial thickness={0.05} color="#102030" />
      </mesh>
    </>
  );
}
// One light three ways: a <phongLight> element the material finds in the scene (no phongLights), the same light
// listed in phongLights, or no light at all.
function Lit({ mode, onMounted }: { mode: 'scene' | 'listed' | 'none'; onMounted: () => void }) {
  const listed = useMemo(() => new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 }), []);
  useEffect(onMounted, []);
  return (
    <>
      <LectureCamera makeDefault eye={[0, 0, 3]} fovy={90} near={0.1} far={10} />
      {mode === 'scene' && <phongLight args={[{ ambient: 0.2, diffuse: 1, specular: 0.8 }]} position={[-5, 10, 20]} />}
      {mode === 'listed' && <primitive object={listed} position={[-5, 10, 20]} />}
      <mesh scale={[2, 1, 2]}>
        <subdivisionSphereGeometry args={[{ level: 4, normals: 'none' }]} />
        {mode === 'listed' ? (
          <shadingMaterial shading="phong" phongLights={[listed]} />
        ) : (
          <shadingMaterial shading="phong" />
        )}
      </mesh>
    </>
  );
}
// An AutoDetailSphere (radius 0.5, at the origin) seen from [0, 0, eye]; onRendered after every commit.
let detailSphere: DetailMesh | null = null;
function Detail({ eye, onRendered }: { eye: number; onRendered: () => void }) {
  useEffect(onRendered);
  return (
    <>
      <LectureCamera makeDefault eye={[0, 0, eye]} fovy={90} near={0.01} far={100} />
      <AutoDetailSphere ref={(s) => { detailSphere = s; }} maxErrorPx={0.5} scale={0.5}>
        <shadingMaterial />
      </AutoDetailSphere>
    </>
  );
}
function Empty({ onMounted }: { onMounted: () => void }) {
  useEffect(onMounted, []);
  return null;
}

const root = createRoot(canvas);
let gl: THREE.WebGLRenderer | undefined;
const ready = root
  .configure({ events, frameloop: 'never', dpr: 1, flat: true, size: { width: 400, height: 400, top: 0, left: 0 } })
  .then((r) => {
    gl = r.render(null).getState().gl as THREE.WebGLRenderer;
  });
const frame = () => advance(performance.now());
const stats = () => ({
  geometries: gl!.info.memory.geometries,
  textures: gl!.info.memory.textures,
  programs: gl!.info.programs?.length ?? 0,
  listeners: live.map((e) => e.target + ':' + e.type).sort(),
});
const mount = (ka?: [number, number, number]) =>
  new Promise<void>((resolve) => root.render(<Scene ka={ka} onMounted={resolve} />));
const unmount = () => new Promise<void>((resolve) => root.render(<Empty onMounted={resolve} />));

Object.assign(window, {
  harness: {
    ready: () => ready,
    stats,
    frame,
    async cycles(n: number) {
      let mounted = stats();
      for (let i = 0; i < n; i++) {
        await mount();
        frame();
        if (i === 0) mounted = stats();
        await unmount();
        frame();
      }
      return mounted;
    },
    async lit(mode: 'scene' | 'listed' | 'none') {
      await new Promise<void>((resolve) => root.render(<Lit key={mode} mode={mode} onMounted={resolve} />));
      frame();
    },
    async detailAt(eye: number) {
      await new Promise<void>((resolve) => root.render(<Detail eye={eye} onRendered={resolve} />));
      frame();
      const { base, level, triangles, radiusPx, errorScalePx } = detailSphere!.detail;
      const g = detailSphere!.geometry;
      return {
        base, level, triangles, radiusPx, errorScalePx,
        drawn: (g.index ? g.index.count : g.attributes.position.count) / 3,
        rendered: gl!.info.render.triangles,
      };
    },
    async hostile(frames: number) {
      await mount([Number.NaN, -1, 0]);
      for (let i = 0; i < frames; i++) frame();
    },
  },
});
`;

test.describe.configure({ mode: 'default' });

test.beforeAll(async () => {
  test.setTimeout(180_000);
  if (!guideApp || !quickStart) throw new Error('the R3F guide’s app or the README’s Quick start is missing');
  rmSync(out, { recursive: true, force: true });
  const pages: Record<string, { file: string; code: string; root?: boolean }> = {
    guide: { file: 'main.tsx', code: guideApp.code, root: true },
    quickstart: { file: 'main.ts', code: quickStart.code },
    harness: { file: 'main.tsx', code: HARNESS },
  };
  const input: Record<string, string> = {};
  for (const [name, page] of Object.entries(pages)) {
    const dir = join(out, 'src', name);
    mkdirSync(dir, { recursive: true });
    writeFileSync(join(dir, page.file), page.code);
    writeFileSync(
      join(dir, 'index.html'),
      `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8" />
    <link rel="icon" href="data:," />
    <title>${name}</title>
    <style>html, body { margin: 0; } canvas { display: block; } #root { width: 800px; height: 800px; }</style>
  </head>
  <body>
    ${page.root ? '<div id="root"></div>' : ''}
    <script type="module" src="./${page.file}"></script>
  </body>
</html>
`,
    );
    input[name] = join(dir, 'index.html');
  }
  ({ origin, close } = await buildAndServePages({
    root: join(out, 'src'),
    outDir: join(out, 'dist'),
    input,
    plugins: [react()],
  }));
});

test.afterAll(async () => {
  await close?.();
});

/** A 40 × 40 grid of the square canvas's pixels (the guide's 800 × 800, or the harness's 400 × 400). */
const grid = async (page: Page, size = 800) =>
  (await canvasPixels(
    page,
    Array.from({ length: 1600 }, (_, i) => ({
      x: size / 80 + (size / 40) * (i % 40),
      y: size / 80 + (size / 40) * Math.floor(i / 40),
    })),
  )) as number[][];
const maxDifference = (a: number[][], b: number[][]) =>
  Math.max(...a.flatMap((p, i) => p.map((c, j) => Math.abs(c - b[i][j]))));
const changed = (a: number[][], b: number[][]) => a.filter((p, i) => p.some((c, j) => c !== b[i][j])).length;

/** A drag straight down from the centre: a turn about the camera's x axis, which tilts the ellipsoid. */
async function drag(page: Page) {
  await page.mouse.move(400, 400);
  await page.mouse.down();
  await page.mouse.move(400, 600, { steps: 10 });
  await page.mouse.up();
}

test('the R3F guide’s app draws the lecture’s lit ellipsoid, and a trackball drag turns it as the vanilla trackball does', async ({
  page,
}) => {
  await page.setViewportSize({ width: 900, height: 900 });
  const errors = collectPageErrors(page);
  await page.goto(`${origin}/quickstart/`);
  await expectScenePicture(page, LECTURE_VIEW, errors);
  const vanilla = await grid(page);
  await drag(page);
  await expect.poll(async () => changed(vanilla, await grid(page))).toBeGreaterThan(100);
  const vanillaTurned = await grid(page);

  await page.goto(`${origin}/guide/`);
  // R3F's canvas starts at the DOM default 300 × 150 and takes its container's size once measured: wait for
  // that, or the picture check reads the first size and samples the wrong pixels.
  await expect
    .poll(() => page.locator('canvas').evaluate((c: HTMLCanvasElement) => [c.width, c.height]))
    .toEqual([800, 800]);
  await expectScenePicture(page, LECTURE_VIEW, errors);
  const before = await grid(page);
  // The same picture as the vanilla Quick start (flat: no tone mapping), within rasteriser rounding.
  expect(maxDifference(before, vanilla)).toBeLessThanOrEqual(2);
  await drag(page);
  // frameloop="demand": the drag invalidated the frame; the ellipsoid tilted as the vanilla one did.
  await expect.poll(async () => maxDifference(await grid(page), vanillaTurned)).toBeLessThanOrEqual(2);
  expect(changed(before, await grid(page))).toBeGreaterThan(100);
  expect(errors).toEqual([]);
});

test('mounting and unmounting the scene 1,000 times leaves renderer.info and the listeners at their baseline', async ({
  page,
}) => {
  test.setTimeout(600_000);
  const errors = collectPageErrors(page);
  await page.goto(`${origin}/harness/`);
  type Stats = { geometries: number; textures: number; programs: number; listeners: string[] };
  type Harness = { ready(): Promise<void>; stats(): Stats; cycles(n: number): Promise<Stats> };
  const baseline = await page.evaluate(async () => {
    const h = (window as unknown as { harness: Harness }).harness;
    await h.ready();
    return h.stats();
  });
  // R3F's own pointer listeners on the canvas are the baseline; nothing of the scene's is.
  expect(baseline.listeners.length).toBeGreaterThan(0);
  expect(baseline.geometries).toBe(0);
  const mounted = await page.evaluate(() => (window as unknown as { harness: Harness }).harness.cycles(1000));
  // While mounted, the scene's resources and the trackball's listeners were there (the check is not vacuous).
  expect(mounted.geometries).toBeGreaterThanOrEqual(3);
  expect(mounted.programs).toBeGreaterThan(baseline.programs);
  expect(mounted.listeners).toEqual([...baseline.listeners, 'canvas:pointerdown', 'canvas:wheel'].sort());
  // R3F disposes what it created at idle priority: wait for it, then compare.
  await expect
    .poll(() => page.evaluate(() => (window as unknown as { harness: Harness }).harness.stats()), {
      timeout: 30_000,
    })
    .toEqual(baseline);
  expect(errors).toEqual([]);
});

test('a hostile colour prop written in place (ka={[NaN, -1, 0]}) gives one error naming it, not one per frame', async ({
  page,
}) => {
  const errors = collectPageErrors(page);
  await page.goto(`${origin}/harness/`);
  await page.evaluate(async () => {
    const h = (
      window as unknown as { harness: { ready(): Promise<void>; hostile(n: number): Promise<void> } }
    ).harness;
    await h.ready();
    await h.hostile(60);
  });
  expect(errors).toHaveLength(1);
  expect(errors[0]).toContain('ShadingMaterial.ka');
  expect(errors[0]).toContain('NaN');
});

type LitMode = 'scene' | 'listed' | 'none';
type DetailSeen = {
  base: string;
  level: number;
  triangles: number;
  radiusPx: number;
  errorScalePx: number;
  drawn: number;
  rendered: number;
};
type SceneHarness = {
  ready(): Promise<void>;
  lit(mode: LitMode): Promise<void>;
  detailAt(eye: number): Promise<DetailSeen>;
};

test('a <phongLight> in the scene lights a <shadingMaterial> given no phongLights, as listing it does', async ({
  page,
}) => {
  const errors = collectPageErrors(page);
  await page.goto(`${origin}/harness/`);
  const draw = async (mode: LitMode) => {
    await page.evaluate(async (m) => {
      const h = (window as unknown as { harness: SceneHarness }).harness;
      await h.ready();
      await h.lit(m);
    }, mode);
    return grid(page, 400);
  };
  const found = await draw('scene');
  const listed = await draw('listed');
  const unlit = await draw('none');
  // The material found the element in the scene: the picture of the same light listed, within rounding.
  expect(maxDifference(found, listed)).toBeLessThanOrEqual(1);
  // And it is lit: without any light there is no ambient term either, so the ellipsoid is drawn black (on the
  // page's white through the transparent canvas); with the light found, every one of those pixels has colour.
  const black = (p: number[]) => p.every((c) => c === 0);
  const ellipsoid = unlit.flatMap((p, i) => (black(p) ? [i] : []));
  expect(ellipsoid.length).toBeGreaterThan(400);
  expect(ellipsoid.filter((i) => black(found[i]))).toEqual([]);
  expect(errors).toEqual([]);
});

test('<AutoDetailSphere> follows the R3F camera: moving the eye closer raises the detail, moving back restores it', async ({
  page,
}) => {
  const errors = collectPageErrors(page);
  await page.goto(`${origin}/harness/`);
  const eyes = [6, 1.5, 0.8, 6];
  const seen = await page.evaluate(async (eyes) => {
    const h = (window as unknown as { harness: SceneHarness }).harness;
    await h.ready();
    const out: DetailSeen[] = [];
    for (const eye of eyes) out.push(await h.detailAt(eye));
    return out;
  }, eyes);
  // The sphere (R = 0.5 at the origin) seen on the view axis with fovy 90° (P₁₁ = 1) in 400 pixels: its radius on
  // screen R·(H/2)/√(d² − R²) and its error scale (H/2)·R·d²/(d² − R²)^{3/2}, exact there; the detail is
  // chooseSphereDetail's for that scale within the harness's budget (0.5 px, levels up to 8).
  const [R, halfH] = [0.5, 200];
  const expected = eyes.map((d) => {
    const q = d * d - R * R;
    const errorScalePx = (halfH * R * d * d) / q ** 1.5;
    const { base, level, triangles } = chooseSphereDetail({
      radiusPx: errorScalePx,
      maxErrorPx: 0.5,
      maxLevel: 8,
    });
    return { radiusPx: (halfH * R) / Math.sqrt(q), errorScalePx, base, level, triangles };
  });
  seen.forEach((s, i) => {
    const e = expected[i];
    expect(Math.abs(s.radiusPx / e.radiusPx - 1), `radius at eye ${eyes[i]}`).toBeLessThan(1e-6);
    expect(Math.abs(s.errorScalePx / e.errorScalePx - 1), `error scale at eye ${eyes[i]}`).toBeLessThan(1e-6);
    expect({ base: s.base, level: s.level, triangles: s.triangles }).toEqual({
      base: e.base,
      level: e.level,
      triangles: e.triangles,
    });
    // The frame drew that detail: the mesh's geometry, and the renderer's count for the frame (the only mesh).
    expect([s.drawn, s.rendered]).toEqual([e.triangles, e.triangles]);
  });
  // Closer, finer; back where it was, the detail it had.
  expect(seen[1].triangles).toBeGreaterThan(seen[0].triangles);
  expect(seen[2].triangles).toBeGreaterThan(seen[1].triangles);
  expect(seen[3]).toEqual(seen[0]);
  expect(errors).toEqual([]);
});
