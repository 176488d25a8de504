import { expect, type Page } from '@playwright/test';
import type { CompareConfig, CompareStats } from './harness/material';
import { openHarness, test } from './harness-helpers';

// GPU against CPU, pixel by pixel: the lecture's scene (tetrahedron sphere level 6, scale (2, 1, 2), camera
// at (0, 0, 3) looking at the origin, fovy 90, light at (−5, 10, 20) with Ia 0.2, Id 1, Is 0.8) rendered
// with ShadingMaterial in headless Chromium (SwiftShader) and compared with shade() in the page.

async function open(page: Page): Promise<void> {
  await openHarness(page, 'material');
}

function compare(page: Page, config: CompareConfig): Promise<CompareStats> {
  return page.evaluate((c) => window.materialHarness.compare(c), config);
}

/** Within 2 of 255 per channel, on enough pixels that the test cannot pass vacuously. */
function expectMatch(stats: CompareStats, minCompared = 8000): void {
  expect(stats.compared, JSON.stringify(stats)).toBeGreaterThan(minCompared);
  expect(stats.maxError, JSON.stringify(stats)).toBeLessThanOrEqual(2);
  expect(stats.mismatches).toBe(0);
  expect(stats.darkPixels, 'no black (NaN) pixel on the mesh').toBe(0);
}

test.describe.configure({ mode: 'parallel' });

for (const shading of ['phong', 'gouraud', 'flat'] as const) {
  for (const lighting of ['phong', 'blinn-phong'] as const) {
    for (const celBands of [0, 3]) {
      test(`${shading} shading × ${lighting} lighting${celBands ? ` × ${celBands} cel bands` : ''} matches shade()`, async ({
        harness,
      }) => {
        const { page } = await harness('material');
        const stats = await compare(page, { shading, lighting, celBands });
        expectMatch(stats, shading === 'flat' ? 6000 : 8000);
        if (shading === 'flat') {
          // One colour per face: every pixel of a triangle (away from its edges) has the same colour.
          expect(stats.facesChecked).toBeGreaterThan(1000);
          expect(stats.facesMultiColour).toBe(0);
        }
        // Skipped: cel band and highlight edges, and for flat the pixels within 0.1 px of a triangle edge.
        if (celBands || shading === 'flat') expect(stats.boundarySkipped).toBeLessThan(stats.compared / 2);
      });
    }
  }
}

test('flat shading of a flatShadingGeometry (indexed, each face on its own last vertex) matches shade() too', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const lighting of ['phong', 'blinn-phong'] as const) {
    for (const celBands of [0, 3]) {
      const stats = await compare(page, { shading: 'flat', lighting, celBands, flatCorners: true });
      expectMatch(stats, 6000);
      expect(stats.facesChecked).toBeGreaterThan(1000);
      expect(stats.facesMultiColour).toBe(0);
    }
  }
  const mirrored = await compare(page, {
    shading: 'flat',
    lighting: 'phong',
    flatCorners: true,
    scale: [2, -1, 2],
    rotation: [0.3, -0.7, 0.2],
  });
  expectMatch(mirrored, 6000);
  expect(mirrored.facesMultiColour).toBe(0);
});

test('gouraud with analytic sphere normals (no normal attribute) and phong with a normal attribute', async ({
  harness,
}) => {
  const { page } = await harness('material');
  expectMatch(await compare(page, { shading: 'gouraud', lighting: 'phong', analytic: true }));
  expectMatch(await compare(page, { shading: 'phong', lighting: 'blinn-phong', analytic: false }));
});

test('an orthographic camera uses the constant view direction', async ({ harness }) => {
  const { page } = await harness('material');
  expectMatch(await compare(page, { shading: 'phong', lighting: 'phong', orthographic: true }), 5000);
  expectMatch(await compare(page, { shading: 'gouraud', lighting: 'blinn-phong', orthographic: true }), 5000);
});

test('a rotated, mirrored model (negative determinant) keeps outward normals', async ({ harness }) => {
  const { page } = await harness('material');
  const rotation: [number, number, number] = [0.4, -0.9, 0.3];
  expectMatch(await compare(page, { shading: 'phong', lighting: 'phong', scale: [-2, 1, 2], rotation }));
  expectMatch(await compare(page, { shading: 'flat', lighting: 'phong', scale: [2, -1, 2], rotation }), 6000);
});

const extremes: Array<[string, CompareConfig]> = [
  ['shininess 0', { shading: 'phong', lighting: 'phong', shininess: 0 }],
  ['shininess 10⁴', { shading: 'phong', lighting: 'blinn-phong', shininess: 1e4 }],
  ['ks = 0', { shading: 'gouraud', lighting: 'phong', ks: [0, 0, 0] }],
  ['kd = 0', { shading: 'phong', lighting: 'phong', kd: [0, 0, 0] }],
  [
    'attenuation',
    { shading: 'phong', lighting: 'phong', light: [1, 2, 4], attenuation: { a: 1, b: 0.2, c: 0.05 } },
  ],
];
for (const [name, config] of extremes) {
  test(`extremes: ${name} matches shade()`, async ({ harness }) => {
    const { page } = await harness('material');
    expectMatch(await compare(page, config));
  });
}

test('extremes: a light at the surface (t = 0, a = 0) stays finite: no black (NaN) pixel', async ({
  harness,
}) => {
  const { page } = await harness('material');
  // The light sits on the sphere's front vertex (0, 0, 2) with a = 0: attenuation up to 10⁶. The colour
  // there is ill-conditioned (l is tangent to the surface, scaled by 1/t), so only finiteness is checked.
  for (const shading of ['phong', 'gouraud', 'flat'] as const) {
    const stats = await compare(page, {
      shading,
      lighting: 'phong',
      light: [0, 0, 2],
      attenuation: { a: 0, b: 1 },
    });
    expect(stats.covered).toBeGreaterThan(10000);
    expect(stats.darkPixels, JSON.stringify(stats)).toBe(0);
  }
});

test('extremes: zero, 1e-20 and 1e20 scales render without NaN (no black pixel)', async ({ harness }) => {
  const { page } = await harness('material');
  for (const scale of [
    [2, 1, 0],
    [2, 1, 1e-20],
    [1e20, 1, 2],
    [1e-20, 1e-20, 1e-20],
  ] as Array<[number, number, number]>) {
    for (const shading of ['phong', 'gouraud', 'flat'] as const) {
      // Known limit: gouraud at a 1e20 axis scale shows black pixels where SwiftShader clips the 1e20-long
      // slivers and interpolates colours across them (see the package README); phong and flat stay clean.
      // Gouraud at a 1e20 axis scale: SwiftShader clips the 1e20-long triangles and interpolates (and
      // extrapolates) the vertex colours across them, which gives black where lit and unlit vertex colours
      // meet. With kd = ks = 0 every vertex colour is ka·Ia, yet a NaN anywhere in the lighting would still
      // give NaN (NaN·0 = NaN): no black pixel then means the per-vertex lighting is finite.
      const constant = shading === 'gouraud' && scale[0] === 1e20;
      const black: [number, number, number] = [0, 0, 0];
      const stats = await compare(page, {
        shading,
        lighting: 'blinn-phong',
        scale,
        ...(constant ? { kd: black, ks: black } : {}),
      });
      expect(stats.darkPixels, `${shading} ${scale}: ${JSON.stringify(stats)}`).toBe(0);
      if (scale[2] !== 1e-20 && scale[0] !== 1e-20)
        expect(stats.covered, `${shading} ${scale}`).toBeGreaterThan(1000);
    }
  }
  // The flattened disc (scale z = 0) faces the camera: its pixels match shade() with the plane normal.
  expectMatch(await compare(page, { shading: 'phong', lighting: 'phong', scale: [2, 1, 0] }));
});

test('1,000 option flips keep renderer.info.programs bounded by the variants used', async ({ page }) => {
  await open(page);
  const result = await page.evaluate(() => window.materialHarness.flipPrograms(1000));
  expect(result.variants).toBe(12);
  expect(result.after).toBeLessThanOrEqual(result.before + 12);
  expect(result.max).toBeLessThanOrEqual(result.before + 12);
});

test('one material drawing two differently transformed objects in a row renders each correctly', async ({
  harness,
}) => {
  const { page } = await harness('material');
  const result = await page.evaluate(() => window.materialHarness.sharedMaterial());
  expect(result.covered).toBeGreaterThan(2000);
  expect(result.differing).toBe(0);
});

test('createOutline draws a black inverted-hull ring around a cel sphere and leaves the sphere unchanged', async ({
  harness,
}) => {
  const { page } = await harness('material');
  const result = await page.evaluate(() => window.materialHarness.outline(0.08));
  expect(result.covered).toBeGreaterThan(3000);
  expect(result.insideChanged).toBe(0);
  // A ring of about 0.08 world units ≈ 1.7 px around a ~90 × 45 px ellipse: hundreds of pixels, all black.
  expect(result.ring).toBeGreaterThan(200);
  expect(result.ringBlack).toBe(result.ring);
});
