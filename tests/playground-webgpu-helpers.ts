// Helpers of the renderer switch's specs (playground-webgpu.spec.ts, playground-webgpu-flags.spec.ts).
import { expect, type Page } from '@playwright/test';
import { decodePng, type RgbaImage } from '@shadelab/playwright/test';
import { HIDE_OVERLAYS, settle } from './playground-helpers';

/** The renderer select's WebGPU entry. */
export const WEBGPU = 'WebGPU (WebGL2 fallback)';

/**
 * What the page shows of the canvas area (overlays hidden): the WebGPU canvas when it lies over the WebGL one. The
 * page is brought to the front first: a page behind another of its context composites no frame until it is, so
 * its screenshot would wait seconds for one.
 */
export async function shot(page: Page): Promise<RgbaImage> {
  await page.addStyleTag({ content: HIDE_OVERLAYS });
  await page.bringToFront();
  return decodePng(await page.getByTestId('viewport').screenshot());
}

/** Lit (not background) pixels: any channel above 8. */
const lit = (img: RgbaImage, i: number) =>
  img.data[4 * i]! > 8 || img.data[4 * i + 1]! > 8 || img.data[4 * i + 2]! > 8;

/**
 * Two pictures of the same view: how many pixels are covered in one but not the other, and the largest channel
 * difference over the pixels whose 3 × 3 neighbourhood is covered in both (away from the silhouette's edge).
 */
export function difference(a: RgbaImage, b: RgbaImage) {
  expect([b.width, b.height]).toEqual([a.width, a.height]);
  const { width, height } = a;
  let coverage = 0;
  let covered = 0;
  let compared = 0;
  let maxDelta = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = y * width + x;
      if (lit(a, i) !== lit(b, i)) coverage++;
      if (lit(a, i)) covered++;
      let inside = x > 0 && y > 0 && x < width - 1 && y < height - 1;
      for (let dy = -1; inside && dy <= 1; dy++)
        for (let dx = -1; inside && dx <= 1; dx++) {
          const j = i + dy * width + dx;
          inside = lit(a, j) && lit(b, j);
        }
      if (!inside) continue;
      compared++;
      for (let k = 0; k < 3; k++)
        maxDelta = Math.max(maxDelta, Math.abs(a.data[4 * i + k]! - b.data[4 * i + k]!));
    }
  }
  return { coverage, covered, compared, maxDelta };
}

/** Switches the renderer in the panel and waits for WebGPU mode's label and its first frames to settle. */
export async function toWebGPU(page: Page) {
  await page.locator('[id="View.renderer"]').selectOption({ label: WEBGPU });
  await expect(page.getByTestId('renderer-backend')).toHaveText(/Renderer: (WebGPU|WebGL2)/, {
    timeout: 30_000,
  });
  await expect(page.getByTestId('viewport-webgpu')).toHaveAttribute('data-frames', /[1-9]/);
  await settle(page);
}

/** WebGL mode's and WebGPU mode's pictures of one state: the same coverage, within 2/255 away from edges. */
export function expectSamePicture(webgl: RgbaImage, gpu: RgbaImage) {
  const d = difference(webgl, gpu);
  expect(d.covered, 'the sphere is drawn').toBeGreaterThan(10_000);
  expect(d.coverage, 'pixels covered in one picture only').toBe(0);
  expect(d.compared, 'pixels compared away from the silhouette').toBeGreaterThan(0.9 * d.covered);
  expect(d.maxDelta, 'largest channel difference, 1/255').toBeLessThanOrEqual(2);
}

/** Page errors and console errors (none are expected: a lost device is reported on the page, not thrown). */
export function watchProblems(page: Page): string[] {
  const problems: string[] = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
  });
  return problems;
}

/**
 * Records, in order, every text the backend label and the shader panel's language line show from now on, the
 * latter with what the shader text is (` :: WGSL code`, ` :: GLSL code`): the WebGPU backend's life before a
 * device loss can be shorter than a poll.
 */
export async function recordReports(page: Page): Promise<() => Promise<string[]>> {
  await page.evaluate(() => {
    const seen: string[] = [];
    (window as unknown as { seen: string[] }).seen = seen;
    const note = () => {
      const code = (document.querySelector('[data-testid="shader-text"]') as HTMLTextAreaElement | null)
        ?.value;
      // What the shader text is: WGSL has `@fragment`/`@vertex` entry points, three's GLSL starts `#version 300 es`.
      const kind = /@(fragment|vertex)\s+fn\s+main\(/.test(code ?? '')
        ? 'WGSL code'
        : /^#version 300 es/.test(code ?? '')
          ? 'GLSL code'
          : 'no code';
      for (const id of ['renderer-backend', 'shader-language']) {
        const label = document.querySelector(`[data-testid="${id}"]`)?.textContent ?? null;
        const text = label !== null && id === 'shader-language' ? `${label} :: ${kind}` : label;
        if (text !== null && seen[seen.length - 1] !== text && !seen.includes(text)) seen.push(text);
      }
    };
    new MutationObserver(note).observe(document.body, {
      subtree: true,
      childList: true,
      characterData: true,
    });
  });
  return () => page.evaluate(() => (window as unknown as { seen: string[] }).seen);
}

/** The parity view's two read-backs (RGBA, rows bottom-up) and the numbers it shows. */
export interface ParityRead {
  w: number;
  h: number;
  webgl: Uint8Array;
  webgpu: Uint8Array;
  numbers: { pixels: number; max: number; mean: number; over1: number; over3: number; coverage: number };
  seq: number;
}

/**
 * Waits until the parity view rests with a comparison of the last frame, then reads WebGL's cell back from the
 * viewer's canvas (gl.readPixels) and WebGPU's picture from its canvas (getImageData), and the numbers shown.
 */
export async function readParity(page: Page): Promise<ParityRead> {
  await expect(page.getByTestId('parity-numbers')).toBeVisible({ timeout: 60_000 });
  await settle(page);
  // The comparison of the last frame has arrived when the sequence stops moving.
  let seq = -1;
  for (let i = 0; i < 40; i++) {
    const now = Number(await page.getByTestId('parity').getAttribute('data-seq'));
    if (now === seq && now > 0) break;
    seq = now;
    await page.waitForTimeout(300);
  }
  const read = await page.evaluate(() => {
    const panel = document.querySelector<HTMLElement>('[data-testid="parity"]')!;
    const [x, y, w, h] = panel.dataset['cell']!.split(',').map(Number) as [number, number, number, number];
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="viewport"]')!;
    const gl = canvas.getContext('webgl2')!;
    const webgl = new Uint8Array(4 * w * h);
    gl.readPixels(x, y, w, h, gl.RGBA, gl.UNSIGNED_BYTE, webgl);
    const gpu = document.querySelector<HTMLCanvasElement>('[data-testid="parity-webgpu"]')!;
    const top = gpu.getContext('2d')!.getImageData(0, 0, w, h).data;
    const webgpu = new Uint8Array(4 * w * h);
    for (let r = 0; r < h; r++) webgpu.set(top.subarray((h - 1 - r) * 4 * w, (h - r) * 4 * w), r * 4 * w);
    const b64 = (a: Uint8Array) => {
      let s = '';
      for (let i = 0; i < a.length; i += 0x8000) s += String.fromCharCode(...a.subarray(i, i + 0x8000));
      return btoa(s);
    };
    const d = document.querySelector<HTMLElement>('[data-testid="parity-numbers"]')!.dataset;
    const numbers = Object.fromEntries(
      ['pixels', 'max', 'mean', 'over1', 'over3', 'coverage'].map((k) => [k, Number(d[k])]),
    );
    return { w, h, webgl: b64(webgl), webgpu: b64(webgpu), numbers, seq: Number(panel.dataset['seq']) };
  });
  return {
    ...read,
    webgl: new Uint8Array(Buffer.from(read.webgl, 'base64')),
    webgpu: new Uint8Array(Buffer.from(read.webgpu, 'base64')),
    numbers: read.numbers as ParityRead['numbers'],
  };
}

/** The parity numbers recomputed from two read-backs: largest channel difference per pixel, over every pixel. */
export function parityNumbers(a: Uint8Array, b: Uint8Array, w: number, h: number) {
  let max = 0;
  let sum = 0;
  let over1 = 0;
  let over3 = 0;
  for (let k = 0; k < w * h; k++) {
    let d = 0;
    for (let c = 0; c < 3; c++) d = Math.max(d, Math.abs(a[4 * k + c]! - b[4 * k + c]!));
    max = Math.max(max, d);
    sum += d;
    if (d > 1) over1++;
    if (d > 3) over3++;
  }
  return { pixels: w * h, max, mean: sum / (w * h), over1, over3 };
}

/** Whether pixel (x, y) of `p` is on an edge: a channel spans more than 24 codes over its 3 × 3 neighbourhood. */
function onEdge(p: Uint8Array, w: number, h: number, x: number, y: number): boolean {
  if (x === 0 || y === 0 || x === w - 1 || y === h - 1) return true;
  for (let c = 0; c < 3; c++) {
    let lo = 255;
    let hi = 0;
    for (let dy = -1; dy <= 1; dy++)
      for (let dx = -1; dx <= 1; dx++) {
        const v = p[4 * ((y + dy) * w + x + dx) + c]!;
        lo = Math.min(lo, v);
        hi = Math.max(hi, v);
      }
    if (hi - lo > 24) return true;
  }
  return false;
}

/**
 * Two pictures of one view compared away from edges (silhouettes, cel and texture edges: see `onEdge`, in either
 * picture): pixels compared, the largest and the mean channel difference there, and pixels lit in one only.
 */
export function awayFromEdges(a: Uint8Array, b: Uint8Array, w: number, h: number) {
  let compared = 0;
  let max = 0;
  let sum = 0;
  let litA = 0;
  let coverage = 0;
  const lit = (p: Uint8Array, k: number) => p[4 * k]! > 8 || p[4 * k + 1]! > 8 || p[4 * k + 2]! > 8;
  for (let y = 0; y < h; y++)
    for (let x = 0; x < w; x++) {
      const k = y * w + x;
      if (lit(a, k)) litA++;
      if (lit(a, k) !== lit(b, k)) coverage++;
      if (onEdge(a, w, h, x, y) || onEdge(b, w, h, x, y)) continue;
      compared++;
      let d = 0;
      for (let c = 0; c < 3; c++) d = Math.max(d, Math.abs(a[4 * k + c]! - b[4 * k + c]!));
      max = Math.max(max, d);
      sum += d;
    }
  return { lit: litA, compared, max, mean: compared ? sum / compared : 0, coverage };
}
