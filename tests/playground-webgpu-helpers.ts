// Helpers of the renderer switch's specs (playground-webgpu.spec.ts, playground-webgpu-flags.spec.ts).
import { expect, type Page } from '@playwright/test';
import { decodePng, type RgbaImage } from '@shadelab/playwright/test';
import { HIDE_OVERLAYS, settle } from './playground-helpers';

/** The renderer select's WebGPU entry. */
export const WEBGPU = 'WebGPU (WebGL2 fallback)';

/** What the page shows of the canvas area (overlays hidden): the WebGPU canvas when it lies over the WebGL one. */
export async function shot(page: Page): Promise<RgbaImage> {
  await page.addStyleTag({ content: HIDE_OVERLAYS });
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
