// The ray-cast impostor against the exact CPU reference (renderReference, computed in the page for the same
// view): colours within 1/255 over the interior (the bound is 2/255), the silhouette exact to half a
// pixel, depth exact.
import { expect, type Page } from '@playwright/test';
import type { TradeOption, TradeView } from '../playground/src/tradeoff/tradeoffScene';
import type { CompareResult } from './harness/tradeoff';
import { test } from './harness-helpers';

const impostor: TradeOption = { shading: 'impostor' };

async function compare(page: Page, view: TradeView, option: TradeOption = impostor): Promise<CompareResult> {
  return page.evaluate(([v, o]) => window.tradeoff.compare(v, o), [view, option] as const);
}

/**
 * The impostor's pixels against the reference: within 1/255 inside (the issue asks for 2/255; every view
 * measures at most 1, float32 against float64 rounding to the other side of an 8-bit code), the silhouette
 * within 0.5 px (no mismatched pixel farther from the exact edge), no NaN.
 */
function expectExact(r: CompareResult) {
  expect(r.interiorPixels).toBeGreaterThan(1000);
  expect(r.max).toBeLessThanOrEqual(1);
  expect(r.silhouettePx).toBeLessThanOrEqual(0.5);
  expect(r.mismatchedBeyondHalfPx).toBe(0);
  expect(r.blackPixels).toBe(0);
}

test.describe('impostor vs reference', () => {
  test('the lecture scene at 1280×720: within 1/255 inside, silhouette within 0.5 px', async ({
    harness,
  }) => {
    const { page } = await harness('tradeoff');
    const r = await compare(page, { width: 1280, height: 720 });
    test.info().annotations.push({ type: 'impostor', description: JSON.stringify(r) });
    expectExact(r);
  });

  const views: Array<[string, TradeView]> = [
    ['blinn-phong', { width: 320, height: 240, lighting: 'blinn-phong', shininess: 80 }],
    ['orthographic', { width: 320, height: 240, projection: 'orthographic' }],
    [
      'rotated ellipsoid, off-centre eye',
      { width: 320, height: 240, rotation: [0.4, -0.7, 0.2], eye: [0.8, -0.5, 3.2] },
    ],
    ['mirrored (negative determinant)', { width: 320, height: 240, scale: [-2, 1, 2] }],
    ['light behind and to the side', { width: 320, height: 240, light: [6, -2, -3] }],
    ['small and far (30 px)', { width: 320, height: 240, eye: [0, 0, 9.5], fovy: 20 }],
  ];
  for (const [name, view] of views) {
    test(name, async ({ harness }) => {
      const { page } = await harness('tradeoff');
      const r = await compare(page, view);
      expectExact(r);
    });
  }

  // The docs/design.md extremes rows that apply to the impostor, each within 1/255 inside and 0.5 px at the edge.
  const extremes: Array<[string, TradeView]> = [
    [
      'two lights, each with its own intensities',
      {
        width: 320,
        height: 240,
        lights: [
          { position: [-5, 10, 20] },
          {
            position: [4, -3, 6],
            ambient: [0.05, 0.1, 0.05],
            diffuse: [0.5, 0.3, 0.2],
            specular: [0.3, 0.3, 0.6],
          },
        ],
      },
    ],
    [
      'attenuation a + b·t + c·t²',
      {
        width: 320,
        height: 240,
        lights: [{ position: [-2, 3, 4], attenuation: { a: 0.5, b: 0.1, c: 0.02 } }],
      },
    ],
    ['ks = 0 (no specular)', { width: 320, height: 240, ks: [0, 0, 0] }],
    ['kd = 0 (no diffuse)', { width: 320, height: 240, kd: [0, 0, 0] }],
    ['shininess 0 (0⁰ = 1: the highlight covers the lit side)', { width: 320, height: 240, shininess: 0 }],
    ['shininess 1e4 (a pinpoint highlight)', { width: 320, height: 240, shininess: 1e4, light: [0, 0, 20] }],
    [
      // On a convex surface a light at a surface point lights only that point (l·n ≤ 0 elsewhere): the
      // lecture light keeps the rest of the picture lit.
      'a light at the surface (t = 0 at the front pole), beside the lecture light',
      { width: 320, height: 240, lights: [{ position: [0, 0, 2] }, { position: [-5, 10, 20] }] },
    ],
    [
      'a light at the surface with attenuation 1/t² (a = b = 0: clamped at 10⁶), beside the lecture light',
      {
        width: 320,
        height: 240,
        lights: [
          { position: [0, 0, 2], attenuation: { a: 0, b: 0, c: 1 }, diffuse: [0.2, 0.2, 0.2] },
          { position: [-5, 10, 20] },
        ],
      },
    ],
  ];
  for (const [name, view] of extremes) {
    test(`extremes: ${name}`, async ({ harness }) => {
      const { page } = await harness('tradeoff');
      const r = await compare(page, view);
      test.info().annotations.push({ type: 'impostor', description: JSON.stringify(r) });
      expectExact(r);
    });
  }

  // far/near = 1e9 in every depth mode. (The far end of the pixel's ray, unprojected in float32, goes to
  // infinity beyond 1e7, where P's −(f + n)/(f − n) rounds to −1: the shader never divides by its w.)
  const farViews = [
    { width: 320, height: 240, near: 1e-3, far: 1e6 },
    { width: 320, height: 240, near: 0.1, far: 1e8 },
  ];
  for (const [depth, views] of [
    ['reversed', farViews],
    ['standard', [{ width: 320, height: 240, near: 1e-3, far: 1e4 }, ...farViews]],
    ['logarithmic', [{ width: 320, height: 240, near: 1e-3, far: 1e4 }, ...farViews]],
  ] as const) {
    test(`extremes: far/near up to 1e9 with a ${depth} depth buffer`, async ({ harness }) => {
      const { page } = await harness('tradeoff');
      for (const view of views) {
        const r = await page.evaluate(([v, o, d]) => window.tradeoff.compare(v, o, d), [
          view,
          impostor,
          depth,
        ] as const);
        test
          .info()
          .annotations.push({ type: `far/near ${view.far / view.near}`, description: JSON.stringify(r) });
        expectExact(r);
      }
    });
  }

  test('cel bands: exact except where a band edge rounds differently in float32', async ({ harness }) => {
    const { page } = await harness('tradeoff');
    const r = await compare(page, { width: 320, height: 240, celBands: 4 });
    expect(r.silhouettePx).toBeLessThanOrEqual(0.5);
    expect(r.rmse).toBeLessThan(2);
    expect(r.blackPixels).toBe(0);
  });

  test('depth is exact: a plane through the ellipsoid hides exactly the part behind it', async ({
    harness,
  }) => {
    const { page } = await harness('tradeoff');
    for (const planeZ of [1.6, 1.8, 1.9]) {
      const r = await page.evaluate(
        ([o, z]) => window.tradeoff.depthCheck({ width: 320, height: 240 }, o, z),
        [impostor, planeZ] as const,
      );
      expect(r.sphere).toBeGreaterThan(100);
      expect(r.plane).toBeGreaterThan(100);
      expect(r.wrong).toBe(0);
    }
  });

  for (const depth of ['logarithmic', 'reversed'] as const) {
    test(`a ${depth} depth buffer: the same exact pixels, and exact depth against a mesh plane`, async ({
      harness,
    }) => {
      const { page } = await harness('tradeoff');
      for (const view of [
        { width: 320, height: 240 },
        { width: 320, height: 240, projection: 'orthographic' },
        { width: 320, height: 240, rotation: [0.4, -0.7, 0.2], eye: [0.8, -0.5, 3.2] },
      ] satisfies TradeView[]) {
        const r = await page.evaluate(([v, o, d]) => window.tradeoff.compare(v, o, d), [
          view,
          impostor,
          depth,
        ] as const);
        expectExact(r);
      }
      for (const planeZ of [1.6, 1.8, 1.9]) {
        const r = await page.evaluate(
          ([o, z, d]) => window.tradeoff.depthCheck({ width: 320, height: 240 }, o, z, 1e-5, d),
          [impostor, planeZ, depth] as const,
        );
        expect(r.sphere).toBeGreaterThan(100);
        expect(r.plane).toBeGreaterThan(100);
        expect(r.wrong, `plane at z = ${planeZ}`).toBe(0);
      }
    });
  }

  test('eye inside the ellipsoid: nothing drawn (front surface clipped), no NaN', async ({ harness }) => {
    const { page } = await harness('tradeoff');
    const r = await compare(page, { width: 160, height: 120, eye: [0, 0, 0.5] });
    expect(r.blackPixels).toBe(0);
    expect(r.mismatchedPixels).toBe(0);
  });

  test('extreme model scales (1e-20, 1e20) and a huge far/near view stay finite and agree with the reference', async ({
    harness,
  }) => {
    const { page } = await harness('tradeoff');
    for (const scale of [1e-20, 1e20]) {
      const r = await compare(page, { width: 160, height: 120, scale: [scale, scale, scale] });
      expect(r.blackPixels).toBe(0);
      expect(r.mismatchedBeyondHalfPx).toBe(0);
    }
    const far = await compare(page, { width: 160, height: 120, eye: [0, 0, 40], fovy: 8 });
    expect(far.blackPixels).toBe(0);
    expect(far.silhouettePx).toBeLessThanOrEqual(0.5);
    expect(far.max).toBeLessThanOrEqual(1);
  });

  test('two impostors sharing one material: per-object uniforms are re-uploaded between draws', async ({
    harness,
  }) => {
    const { page } = await harness('tradeoff');
    const r = await page.evaluate(() => window.tradeoff.sharedMaterialCheck());
    expect(r.coveredA).toBeGreaterThan(500);
    expect(r.coveredB).toBeGreaterThan(500);
    expect(r.differing).toBe(0);
  });

  test('a zero scale: every mesh shading draws the flattened disc as the reference does (normal towards the viewer)', async ({
    harness,
  }) => {
    const { page } = await harness('tradeoff');
    // The docs/design.md row "model matrix with a zero scale": face on, and rotated in an oblique view. (The
    // impostor draws nothing at a zero scale: its quad's inverse matrix is singular; see the material README.)
    for (const view of [
      { width: 320, height: 240, scale: [2, 1, 0] },
      { width: 320, height: 240, scale: [2, 0, 1], rotation: [0.9, 0.3, 0], eye: [0.5, 1, 3] },
    ] satisfies TradeView[]) {
      for (const shading of ['flat', 'gouraud', 'phong'] as const) {
        const r = await compare(page, view, { shading, base: 'icosahedron', level: 6 });
        test.info().annotations.push({ type: `${shading} ${view.scale}`, description: JSON.stringify(r) });
        expect(r.interiorPixels).toBeGreaterThan(5000);
        expect(r.max).toBeLessThanOrEqual(2);
        expect(r.rmse).toBeLessThan(0.5);
        expect(r.silhouettePx).toBeLessThanOrEqual(0.5);
        expect(r.mismatchedBeyondHalfPx).toBe(0);
        expect(r.blackPixels).toBe(0);
      }
    }
  });

  test('the meshes converge on the same reference (phong, icosahedron 5 vs 1)', async ({ harness }) => {
    const { page } = await harness('tradeoff');
    const fine = await compare(
      page,
      { width: 320, height: 240 },
      { shading: 'phong', base: 'icosahedron', level: 5 },
    );
    const coarse = await compare(
      page,
      { width: 320, height: 240 },
      { shading: 'phong', base: 'icosahedron', level: 1 },
    );
    expect(fine.silhouettePx).toBeLessThan(coarse.silhouettePx);
    expect(fine.silhouettePx).toBeLessThanOrEqual(1);
    expect(coarse.silhouettePx).toBeGreaterThan(2);
  });
});
