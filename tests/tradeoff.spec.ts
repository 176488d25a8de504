// The ray-cast impostor against the exact CPU reference (renderReference, computed in the page for the same
// view): colours within 2/255 over the interior, the silhouette exact to half a pixel, depth exact.
import { expect, type Page, test } from '@playwright/test';
import type { CompareResult } from '../playground/harness/tradeoff';
import type { TradeOption, TradeView } from '../playground/src/tradeoff/tradeoffScene';

async function open(page: Page) {
  await page.goto('/harness/tradeoff.html');
  await page.waitForFunction(() => document.body.dataset.ready === '1');
}

const impostor: TradeOption = { shading: 'impostor' };

async function compare(page: Page, view: TradeView, option: TradeOption = impostor): Promise<CompareResult> {
  return page.evaluate(([v, o]) => window.tradeoff.compare(v, o), [view, option] as const);
}

function expectExact(r: CompareResult) {
  expect(r.interiorPixels).toBeGreaterThan(1000);
  expect(r.max).toBeLessThanOrEqual(2);
  expect(r.silhouettePx).toBeLessThanOrEqual(0.5);
  expect(r.mismatchedBeyondHalfPx).toBe(0);
  expect(r.blackPixels).toBe(0);
}

test.describe('impostor vs reference', () => {
  test.beforeEach(async ({ page }) => open(page));

  test('the lecture scene at 1280×720: within 2/255 inside, silhouette within 0.5 px', async ({ page }) => {
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
    test(name, async ({ page }) => {
      const r = await compare(page, view);
      expectExact(r);
    });
  }

  test('cel bands: exact except where a band edge rounds differently in float32', async ({ page }) => {
    const r = await compare(page, { width: 320, height: 240, celBands: 4 });
    expect(r.silhouettePx).toBeLessThanOrEqual(0.5);
    expect(r.rmse).toBeLessThan(2);
    expect(r.blackPixels).toBe(0);
  });

  test('depth is exact: a plane through the ellipsoid hides exactly the part behind it', async ({ page }) => {
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
      page,
    }) => {
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

  test('eye inside the ellipsoid: nothing drawn (front surface clipped), no NaN', async ({ page }) => {
    const r = await compare(page, { width: 160, height: 120, eye: [0, 0, 0.5] });
    expect(r.blackPixels).toBe(0);
    expect(r.mismatchedPixels).toBe(0);
  });

  test('extreme model scales (1e-20, 1e20) and a huge far/near view stay finite and agree with the reference', async ({
    page,
  }) => {
    for (const scale of [1e-20, 1e20]) {
      const r = await compare(page, { width: 160, height: 120, scale: [scale, scale, scale] });
      expect(r.blackPixels).toBe(0);
      expect(r.mismatchedBeyondHalfPx).toBe(0);
    }
    const far = await compare(page, { width: 160, height: 120, eye: [0, 0, 40], fovy: 8 });
    expect(far.blackPixels).toBe(0);
    expect(far.silhouettePx).toBeLessThanOrEqual(0.5);
    expect(far.max).toBeLessThanOrEqual(2);
  });

  test('two impostors sharing one material: per-object uniforms are re-uploaded between draws', async ({
    page,
  }) => {
    const r = await page.evaluate(() => window.tradeoff.sharedMaterialCheck());
    expect(r.coveredA).toBeGreaterThan(500);
    expect(r.coveredB).toBeGreaterThan(500);
    expect(r.differing).toBe(0);
  });

  test('the meshes converge on the same reference (phong, icosahedron 5 vs 1)', async ({ page }) => {
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
