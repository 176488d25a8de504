// Helpers of the term-view specs (playground-term-views.spec.ts, playground-term-views-webgpu.spec.ts): the
// pictures of the colour and of each term, and the check that the terms add up to the colour (linear).
import { expect, type Page } from '@playwright/test';
import type { RgbaImage } from '@shadelab/playwright/test';
import { choose } from './playground-helpers';
import { shot } from './playground-webgpu-helpers';

/** The terms whose pictures add up to the colour. */
export const TERMS = ['ambient', 'diffuse', 'specular'] as const;

/** sRGB 8-bit code (may be fractional) to linear. */
const linear = (code: number) => {
  const c = Math.min(Math.max(code, 0), 255) / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
};

/**
 * Compares the colour picture with the three terms' on every pixel the colour does not clamp: each 8-bit value
 * stands for the interval of linear values that round to it (± `slack` codes); the terms' intervals must add
 * up to an interval that meets the colour's. Returns how many pixels were compared and the worst miss, in codes
 * of the colour at that pixel (0 = within rounding).
 */
export function termsSum(color: Uint8Array, terms: Uint8Array[], slack = 0.5) {
  let compared = 0;
  let lit = 0;
  let worst = 0;
  let where = '';
  for (let i = 0; i < color.length; i += 4) {
    const rgb = [color[i]!, color[i + 1]!, color[i + 2]!];
    if (rgb.some((c) => c === 255)) continue;
    compared++;
    if (rgb.some((c) => c > 8)) lit++;
    for (let k = 0; k < 3; k++) {
      const lo = terms.reduce((s, t) => s + linear(t[i + k]! - slack), 0);
      const hi = terms.reduce((s, t) => s + linear(t[i + k]! + slack), 0);
      const c = rgb[k]!;
      const [clo, chi] = [linear(c - slack), linear(c + slack)];
      const miss = lo > chi ? lo - chi : clo > hi ? clo - hi : 0;
      if (miss === 0) continue;
      // In codes: the miss over the local slope of the sRGB curve at the colour.
      const codes = miss / Math.max(linear(c + 1) - linear(c), 1e-9);
      if (codes > worst) {
        worst = codes;
        where = `pixel ${i / 4} channel ${k}: colour ${c}, terms ${terms.map((t) => t[i + k]).join(' + ')}`;
      }
    }
  }
  return { compared, lit, worst, where };
}

/** The pictures of the colour and of each term, by the panel's output select, read by `read`. */
export async function pictures(page: Page, read: () => Promise<Uint8Array>) {
  const color = await read();
  const terms: Uint8Array[] = [];
  for (const term of TERMS) {
    await choose(page, 'Material.output', term);
    terms.push(await read());
  }
  await choose(page, 'Material.output', 'color');
  return { color, terms };
}

/** Reads what the page shows of the canvas area (WebGL's canvas, or WebGPU mode's over it), RGBA. */
export const screen = (page: Page) => async () => {
  // The learning tools' buttons and panels over the canvas are not the picture.
  await page.addStyleTag({ content: 'main.stage > :not(canvas) { visibility: hidden !important; }' });
  const image: RgbaImage = await shot(page);
  return new Uint8Array(image.data);
};

/** The terms add up to the colour within rounding on every unclamped pixel, over at least `minLit` lit ones. */
export function expectSum(color: Uint8Array, terms: Uint8Array[], minLit: number) {
  const result = termsSum(color, terms);
  expect(result.lit, 'lit pixels compared').toBeGreaterThan(minLit);
  expect(result.worst, result.where).toBe(0);
  // The terms are not all the same picture: each adds its share somewhere.
  for (const t of terms) expect(t.some((v, i) => i % 4 !== 3 && v > 8)).toBe(true);
  // The check sees a missing term: without the specular picture the sum falls short by many codes.
  expect(termsSum(color, terms.slice(0, 2)).worst, 'ambient + diffuse alone').toBeGreaterThan(5);
}

/** Gouraud shading, Phong lighting, two lights (one attenuated, one blue). */
export const TWO_LIGHTS = {
  material: { shading: 'gouraud', lighting: 'phong', shininess: 12 },
  lights: [
    { position: [-5, 10, 20], attenuation: { a: 1, b: 0.02, c: 0.001 } },
    { position: [4, -2, 6], diffuse: [0.2, 0.4, 1], specular: [0.5, 0.5, 0.5] },
  ],
};
