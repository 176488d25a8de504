import { expect, type Page } from '@playwright/test';
import type { ShadowConfig, ShadowStats } from './harness/material-shadow';
import { openHarness, test } from './harness-helpers';

// ShadingMaterial receiving three's shadows (issue 14): a ground plane in the shadow of an occluder, lit by one of
// three's shadow-casting lights and an AmbientLight. Where the shadow falls is three's own MeshPhongMaterial's
// shadow (same shadow map, same chunks); colours are shade() with the light's colour times three's shadow factor.

async function open(page: Page): Promise<void> {
  await openHarness(page, 'material-shadow');
}

function compare(page: Page, config: ShadowConfig): Promise<ShadowStats> {
  return page.evaluate((c) => window.shadowHarness.shadowCompare(c), config);
}

function expectOracleShadow(stats: ShadowStats): void {
  const info = JSON.stringify(stats);
  expect(stats.oracleShadowed, info).toBeGreaterThan(800);
  expect(stats.maskCompared, info).toBeGreaterThan(20000);
  expect(stats.maskMismatches, info).toBe(0);
}

function expectShade(stats: ShadowStats): void {
  const info = JSON.stringify(stats);
  expect(stats.compared, info).toBeGreaterThan(20000);
  expect(stats.shadowCompared, info).toBeGreaterThan(800);
  expect(stats.maxError, info).toBeLessThanOrEqual(2);
  expect(stats.mismatches, info).toBe(0);
}

for (const shading of ['flat', 'gouraud', 'phong'] as const) {
  test(`receiveShadow, DirectionalLight, ${shading}: shadowed where MeshPhongMaterial is, colours = shade() with the light × shadow factor`, async ({
    harness,
  }) => {
    const { page } = await harness('material-shadow');
    const stats = await compare(page, { shading, light: 'directional' });
    expectOracleShadow(stats);
    expectShade(stats);
  });
}

for (const light of ['spot', 'point'] as const) {
  test(`receiveShadow, ${light === 'spot' ? 'SpotLight' : 'PointLight (cube shadow map)'}, phong: where MeshPhongMaterial is shadowed, = shade()`, async ({
    harness,
  }) => {
    const { page } = await harness('material-shadow');
    const stats = await compare(page, { shading: 'phong', light, ks: 0.5 });
    expectOracleShadow(stats);
    expectShade(stats);
  });
}

test('gouraud and flat with a SpotLight and a PointLight: the shadow falls where MeshPhongMaterial has it', async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  for (const shading of ['flat', 'gouraud'] as const) {
    for (const light of ['spot', 'point'] as const) {
      expectOracleShadow(await compare(page, { shading, light }));
    }
  }
});

test("shadow.intensity 0.5: half of the light is kept in the shadow (three's 1 − intensity), = shade()", async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  for (const shading of ['gouraud', 'phong'] as const) {
    const stats = await compare(page, { shading, light: 'directional', intensity: 0.5 });
    expectOracleShadow(stats);
    expectShade(stats);
  }
});

test('PCF shadow maps: the soft shadow falls where MeshPhongMaterial has it; cel bands keep the shadow', async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  expectOracleShadow(await compare(page, { shading: 'phong', light: 'directional', mapType: 'pcf' }));
  const cel = await compare(page, { shading: 'phong', light: 'directional', celBands: 3 });
  expectOracleShadow(cel);
  expectShade(cel);
});

test('receiveShadow false: no shadow on ShadingMaterial (the light is kept everywhere, = shade())', async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  const stats = await compare(page, { shading: 'phong', light: 'directional', receive: false });
  expect(stats.shadowed, JSON.stringify(stats)).toBe(0);
  expect(stats.compared).toBeGreaterThan(20000);
  expect(stats.maxError, JSON.stringify(stats)).toBeLessThanOrEqual(2);
});

test('flipping receiveShadow and castShadow 1,000 times keeps programs bounded', async ({ page }) => {
  await open(page);
  const { before, after } = await page.evaluate(() => window.shadowHarness.flipShadows(1000));
  expect(after).toBeLessThanOrEqual(before + 2);
});

test('a texture on gouraud and flat shading (the ka/kd part × texel and the ks part shadowed apart), DoubleSide: = shade()', async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  for (const shading of ['flat', 'gouraud'] as const) {
    // Shininess 0: the highlight is uniform, so per-vertex and per-face colours are exact on the plane.
    const stats = await compare(page, {
      shading,
      light: 'directional',
      map: true,
      ks: 0.5,
      shininess: 0,
      doubleSide: true,
    });
    expectOracleShadow(stats);
    expectShade(stats);
  }
  const phong = await compare(page, {
    shading: 'phong',
    light: 'spot',
    map: true,
    ks: 0.5,
    doubleSide: true,
  });
  expectOracleShadow(phong);
  expectShade(phong);
});

test('the impostor and the outline in a scene with a shadow-casting light draw as without it', async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  const { drawn, differing } = await page.evaluate(() => window.shadowHarness.othersWithShadows());
  expect(drawn).toBeGreaterThan(1000);
  expect(differing).toBe(0);
});

test("three's lights with an attenuated PhongLight, lit per fragment in view space (perspective, orthographic) or in world space (a scaled camera): = shade()", async ({
  harness,
}) => {
  const { page } = await harness('material-shadow');
  for (const camera of ['perspective', 'orthographic', 'scaled'] as const) {
    for (const shading of ['phong', 'gouraud'] as const) {
      const stats = await compare(page, {
        shading,
        light: 'directional',
        phongLight: true,
        camera,
        ks: 0.5,
        shininess: 0,
      });
      expectOracleShadow(stats);
      expectShade(stats);
      expect(stats.viewSpace).toBe(shading === 'phong' && camera !== 'scaled');
    }
  }
  // The same in phong shading with the highlight (shininess 16), which varies over the plane.
  for (const camera of ['perspective', 'orthographic', 'scaled'] as const) {
    const stats = await compare(page, {
      shading: 'phong',
      light: 'directional',
      phongLight: true,
      camera,
      ks: 0.5,
    });
    expectShade(stats);
  }
});
