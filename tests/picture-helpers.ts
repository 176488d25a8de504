// What a rendered picture of one shape must show, computed from the scene's camera and model parameters, and
// the means to look at a page's canvas: shared by smoke.spec.ts (the playground), snippets.spec.ts (the code
// blocks of the Markdown) and pack.spec.ts (apps installed from the tarballs).
//
// Every scene checked here is one origin-centred, axis-aligned shape (an ellipsoid or a box) seen by a
// perspective camera on the +z axis at distance `eye`, looking at the origin with up +y. A view ray
// d = (u, v, −1) (u, v in units of tan(fovy/2); NDC x = u / aspect, NDC y = v):
// - meets the ellipsoid (A = diag(1/a², 1/b², 1/c²), eye e = (0, 0, E)) when (dᵀAe)² ≥ (dᵀAd)(eᵀAe − 1), i.e.
//   u²/U² + v²/V² ≤ 1 with U = a / (t·c·√K), V = b / (t·c·√K), t = tan(fovy/2), K = E²/c² − 1 (the lecture's
//   (2, 1, 2) from E = 3 at 90°: U = √0.8, V = √0.2);
// - meets the box of half-sizes (hx, hy, hz) (E > hz) inside its front face's image: |u| ≤ hx/((E − hz)·t),
//   |v| ≤ hy/((E − hz)·t); the sides face away from an eye inside their extent.
// Samples lie at r times the silhouette's boundary in 36 directions: r < 1 inside, r > 1 outside, 10 % clear
// of the silhouette (a mesh lies inside its true surface by far less, and the edge pixels are antialiased).
import { expect, type Page } from '@playwright/test';
import { build, type PluginOption } from 'vite';
import { serveFolder } from '../scripts/serve.mjs';

export { serveFiles } from '../scripts/serve.mjs';

type Vec3 = readonly [number, number, number];

export interface SceneView {
  /** The shape at the origin: semi-axes of an ellipsoid, or half-sizes of a box (world units). */
  shape: { ellipsoid: Vec3 } | { box: Vec3 };
  /** Distance of the eye on +z (world units). */
  eye: number;
  /** Vertical field of view, degrees. */
  fovy: number;
  /** Position of the one point light for a lit picture (checked brighter towards it); none for unlit. */
  light?: Vec3;
  /** Unlit, coloured by the view-space normal (MeshNormalMaterial): the colour follows the normal. */
  normalColours?: boolean;
}

/** The lecture's demo scene: the (2, 1, 2) ellipsoid from (0, 0, 3), fovy 90°, one light at (−5, 10, 20). */
export const LECTURE_VIEW: SceneView = {
  shape: { ellipsoid: [2, 1, 2] },
  eye: 3,
  fovy: 90,
  light: [-5, 10, 20],
};

export interface Sample {
  /** Multiple of the silhouette's boundary: < 1 inside, > 1 outside. */
  r: number;
  /** Direction in the image, radians from +x towards +y. */
  angle: number;
  /** View ray (u, v, −1), u and v in units of tan(fovy/2). */
  u: number;
  v: number;
  /** Inside: the normal where the ray first meets the shape (world = view space: the camera is unturned). */
  normal?: Vec3;
}

export const SAMPLE_RADII = [0.15, 0.35, 0.55, 0.75, 0.9, 1.1, 1.2, 1.35, 1.5, 1.75, 2, 2.2] as const;

/** Samples at r times the silhouette's boundary (r in `radii`), `directions` directions each. */
export function silhouetteSamples(view: SceneView, radii = SAMPLE_RADII, directions = 36): Sample[] {
  const t = Math.tan((view.fovy * Math.PI) / 360);
  const E = view.eye;
  const samples: Sample[] = [];
  for (const r of radii) {
    for (let k = 0; k < directions; k++) {
      const angle = (2 * Math.PI * k) / directions;
      const [c, s] = [Math.cos(angle), Math.sin(angle)];
      if ('ellipsoid' in view.shape) {
        const [a, b, cz] = view.shape.ellipsoid;
        const scale = 1 / (t * cz * Math.sqrt((E * E) / (cz * cz) - 1));
        const [u, v] = [r * a * scale * c, r * b * scale * s];
        samples.push({
          r,
          angle,
          u,
          v,
          normal: r < 1 ? ellipsoidNormal([a, b, cz], E, u * t, v * t) : undefined,
        });
      } else {
        const [hx, hy, hz] = view.shape.box;
        const m = Math.max(Math.abs(c), Math.abs(s));
        const [u, v] = [(r * hx * c) / (m * (E - hz) * t), (r * hy * s) / (m * (E - hz) * t)];
        samples.push({ r, angle, u, v, normal: r < 1 ? [0, 0, 1] : undefined });
      }
    }
  }
  return samples;
}

/** Normal at the first hit of the ray from (0, 0, E) along (x, y, −1) with the ellipsoid of semi-axes `axes`. */
function ellipsoidNormal(axes: Vec3, E: number, x: number, y: number): Vec3 {
  const [a2, b2, c2] = axes.map((s) => s * s);
  const qa = (x * x) / a2 + (y * y) / b2 + 1 / c2;
  const qb = (-2 * E) / c2;
  const qc = (E * E) / c2 - 1;
  const s = (-qb - Math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  const [px, py, pz] = [s * x, s * y, E - s];
  const n = [px / a2, py / b2, pz / c2];
  const len = Math.hypot(...n);
  return [n[0] / len, n[1] / len, n[2] / len];
}

/**
 * The pixel a sample falls on in a canvas of `width` × `height`: x right, y down (screenshots), yUp up
 * (gl.readPixels); null when off the canvas.
 */
export function samplePixel(
  sample: Sample,
  width: number,
  height: number,
): { x: number; y: number; yUp: number } | null {
  const x = Math.floor((((sample.u * height) / width + 1) / 2) * width);
  const yUp = Math.floor(((sample.v + 1) / 2) * height);
  if (x < 0 || yUp < 0 || x >= width || yUp >= height) return null;
  return { x, y: height - 1 - yUp, yUp };
}

const brightness = (rgb: readonly number[]) => rgb[0] + rgb[1] + rgb[2];

/**
 * Check a picture: every inside sample drawn (not the black background), every outside one exactly black;
 * lit: the side facing the light clearly brighter than the far side (ambient alone shades every sample alike);
 * normal colours: red grows with the normal's x, green with its y, and equal normals have equal colours.
 * `rgb[i]` is sample i's colour, null when it is off the canvas. Returns the brightness means it compared.
 */
export function expectPicture(
  view: SceneView,
  samples: readonly Sample[],
  rgb: readonly (number[] | null)[],
) {
  const inside: number[][] = [];
  const outside: number[][] = [];
  const towardsLight: number[] = [];
  const awayFromLight: number[] = [];
  // The light's direction seen from the eye; samples within 45° of it, and of its opposite, away from the centre.
  const light = view.light && Math.atan2(view.light[1], view.light[0]);
  samples.forEach(({ r, angle }, i) => {
    const px = rgb[i];
    if (px === null) return; // off the canvas (the shape is wider than a narrow canvas)
    (r < 1 ? inside : outside).push(px);
    if (light !== undefined && r >= 0.35 && r < 1) {
      const off = Math.abs(Math.atan2(Math.sin(angle - light), Math.cos(angle - light)));
      if (off <= Math.PI / 4) towardsLight.push(brightness(px));
      if (off >= (3 * Math.PI) / 4) awayFromLight.push(brightness(px));
    }
  });
  expect(inside.length).toBeGreaterThanOrEqual(150);
  expect(outside.length).toBeGreaterThanOrEqual(90);
  expect(inside.filter((px) => brightness(px) === 0)).toEqual([]);
  expect(outside.filter((px) => brightness(px) !== 0)).toEqual([]);
  const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;
  if (light !== undefined) {
    expect(towardsLight.length).toBeGreaterThanOrEqual(12);
    expect(awayFromLight.length).toBeGreaterThanOrEqual(12);
    // The lecture's light (−5, 10, 20) is mostly in front, so the far side still gets some diffuse light (and
    // sRGB output lifts dark tones).
    expect(mean(towardsLight)).toBeGreaterThan(1.25 * mean(awayFromLight));
    expect(Math.min(...towardsLight)).toBeGreaterThan(Math.max(...awayFromLight));
  }
  if (view.normalColours) {
    const drawn = samples.flatMap((s, i) => (s.normal && rgb[i] ? [{ n: s.normal, px: rgb[i] }] : []));
    const wrong: string[] = [];
    for (const p of drawn) {
      for (const q of drawn) {
        for (const c of [0, 1] as const) {
          if (p.n[c] - q.n[c] > 0.5 && !(p.px[c] > q.px[c]))
            wrong.push(`normal ${p.n} drawn ${p.px}, normal ${q.n} drawn ${q.px}: channel ${c}`);
        }
        if (p.n.every((x, k) => x === q.n[k]) && p.px.some((x, k) => Math.abs(x - q.px[k]) > 2))
          wrong.push(`the same normal ${p.n} drawn ${p.px} and ${q.px}`);
      }
    }
    expect(wrong.slice(0, 5)).toEqual([]);
  }
  return { towardsLight: mean(towardsLight), awayFromLight: mean(awayFromLight) };
}

/** RGB at pixels (x right, y down) of the page's one canvas, read from a screenshot: what is on screen. */
export async function canvasPixels(
  page: Page,
  pixels: readonly ({ x: number; y: number } | null)[],
): Promise<(number[] | null)[]> {
  const png = await page.locator('canvas').screenshot();
  return page.evaluate(
    async ({ b64, pixels }) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const canvas = document.createElement('canvas');
      canvas.width = img.width;
      canvas.height = img.height;
      const ctx = canvas.getContext('2d')!;
      ctx.drawImage(img, 0, 0);
      return pixels.map((p) => (p ? Array.from(ctx.getImageData(p.x, p.y, 1, 1).data.slice(0, 3)) : null));
    },
    { b64: png.toString('base64'), pixels },
  );
}

/** RGB at fractions (x right, y down) of the page's one canvas, read from a screenshot. */
export async function canvasSamples(page: Page, points: readonly (readonly [number, number])[]) {
  const box = (await page.locator('canvas').boundingBox())!;
  const [w, h] = [Math.round(box.width), Math.round(box.height)];
  const rgb = await canvasPixels(
    page,
    points.map(([fx, fy]) => ({ x: Math.round(fx * (w - 1)), y: Math.round(fy * (h - 1)) })),
  );
  return rgb as number[][];
}

/**
 * Wait until the page's one canvas shows the scene (its centre drawn; failing at once with the page's errors,
 * such as an option that throws), then check its picture against `view` with `expectPicture`. `errors` collects
 * the page's errors and console errors (see `collectPageErrors`); any at the end fails too.
 */
export async function expectScenePicture(page: Page, view: SceneView, errors: string[]) {
  const canvas = page.locator('canvas');
  await expect(canvas).toHaveCount(1);
  const size = await canvas.evaluate((c: HTMLCanvasElement) => [c.width, c.height]);
  const [width, height] = size;
  const box = (await canvas.boundingBox())!;
  // Pixels are read from a screenshot of the canvas's CSS box: it must be the drawing buffer, 1:1.
  expect([Math.round(box.width), Math.round(box.height)]).toEqual(size);
  const centre = { x: Math.floor(width / 2), y: Math.floor(height / 2) };
  const state = async () => {
    if (errors.length) return 'error';
    const [px] = await canvasPixels(page, [centre]);
    return px && brightness(px) > 0 ? 'drawn' : 'blank';
  };
  // A loaded machine is slow to compile the first program; a page error ends the wait at once.
  await expect.poll(state, { timeout: 30_000 }).not.toBe('blank');
  expect(errors, 'page errors').toEqual([]);
  const samples = silhouetteSamples(view);
  const rgb = await canvasPixels(
    page,
    samples.map((s) => samplePixel(s, width, height)),
  );
  const means = expectPicture(view, samples, rgb);
  expect(errors).toEqual([]);
  return means;
}

/** Collect the page's uncaught errors and console errors (a thrown RangeError shows as one) into a list. */
export function collectPageErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(e.stack ?? e.message));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  return errors;
}

/**
 * Build the pages `input` (name → index.html under `root`) with Vite into `outDir` and serve them: resolves with
 * the origin and a `close()`. Shared by the specs that bundle pages of their own (snippets, react).
 */
export async function buildAndServePages({
  root,
  outDir,
  input,
  plugins = [],
}: {
  root: string;
  outDir: string;
  input: Record<string, string>;
  plugins?: PluginOption[];
}): Promise<{ origin: string; close: () => Promise<void> }> {
  await build({
    configFile: false,
    root,
    base: './',
    logLevel: 'warn',
    plugins,
    build: { outDir, emptyOutDir: true, chunkSizeWarningLimit: 4096, rollupOptions: { input } },
  });
  return serveFolder(outDir);
}
