import { expect, type Page } from '@playwright/test';
import type { SceneConfig, SceneStats, SceneSurface } from './harness/material';
import { openHarness, test } from './harness-helpers';

// ShadingMaterial's surface (issue 14): three's map, vertexColors, emissive/emissiveMap, opacity/transparent,
// alphaTest and alphaMap, by three's property names and chunks. Where and whether a pixel is drawn (alpha-tested
// holes, blended pixels) is judged against three's MeshPhongMaterial with the same textures; colours against
// shade() with tint = texel × vertex colour (ka and kd, never ks), emissive × its texel added, alpha blended
// over the clear colour, within 2/255 away from silhouettes, triangle edges (flat) and texel edges. Procedural
// 4 × 4 DataTextures (nearest), three's SphereGeometry (uvs, normals; convex, so nothing else shows through a hole
// or behind a blended pixel), on the material harness page.

async function open(page: Page): Promise<void> {
  await openHarness(page, 'material');
}

function scene(page: Page, config: SceneConfig): Promise<SceneStats> {
  return page.evaluate((c) => window.materialHarness.sceneCompare(c), config);
}

function expectSurface(stats: SceneStats, minCompared: number): void {
  const info = JSON.stringify(stats);
  expect(stats.covered, info).toBeGreaterThan(2500);
  expect(stats.coverageCompared, info).toBeGreaterThan(30000);
  expect(stats.coverageMismatches, info).toBe(0);
  expect(stats.compared, info).toBeGreaterThan(minCompared);
  expect(stats.maxError, info).toBeLessThanOrEqual(2);
  expect(stats.mismatches, info).toBe(0);
}

const SHADINGS = [
  ['phong', { shading: 'phong' }],
  ['gouraud', { shading: 'gouraud' }],
  ['flat (triangle soup)', { shading: 'flat' }],
  ['flat (plain indexed, derivative normals)', { shading: 'flat', indexedFlat: true }],
] as const;

const SURFACES: Array<[string, SceneSurface]> = [
  ['map: the texel multiplies ka and kd, not ks', { map: true }],
  ['vertexColors (RGB) multiply ka and kd', { vertexColors: 'rgb' }],
  ['map × vertexColors', { map: true, vertexColors: 'rgb' }],
  ['emissive is added outside the lighting', { emissive: [0.05, 0.1, 0.02] }],
  ['emissive × emissiveMap', { emissive: [0.1, 0.08, 0.05], emissiveMap: true }],
  ['opacity 0.6, transparent: blended as three blends', { opacity: 0.6, transparent: true }],
  [
    'map alpha × vertex alpha × alphaMap.g × opacity, transparent',
    { map: 'alpha', vertexColors: 'rgba', alphaMap: true, opacity: 0.9, transparent: true },
  ],
  [
    'alphaTest 0.5 with an alphaMap: holes where MeshPhongMaterial has them',
    { alphaMap: true, alphaTest: 0.5 },
  ],
  [
    'alphaTest on the map alpha, opaque (alpha written as 1)',
    { map: 'alpha', alphaTest: 0.6, emissive: [0.02, 0.02, 0.02] },
  ],
];

for (const [name, surface] of SURFACES) {
  test(`${name}: every shading, = shade() and MeshPhongMaterial's coverage`, async ({ harness }) => {
    const { page } = await harness('material');
    for (const [shadingName, variant] of SHADINGS) {
      const stats = await scene(page, { ...variant, object: 'uv-sphere', surface });
      expectSurface(stats, shadingName.startsWith('flat') ? 1000 : 2000);
    }
  });
}

test('the surface with three’s lights and fog', async ({ harness }) => {
  const { page } = await harness('material');
  for (const [, variant] of SHADINGS) {
    const stats = await scene(page, {
      ...variant,
      object: 'uv-sphere',
      surface: { map: true, vertexColors: 'rgb', emissive: [0.03, 0.02, 0.01] },
      threeLights: [
        { type: 'ambient', color: [0.1, 0.1, 0.1] },
        { type: 'point', color: [1, 0.8, 0.6], intensity: 3, position: [2, 1, 2], distance: 6, decay: 2 },
      ],
      fog: { near: 1.5, far: 4 },
    });
    expectSurface(stats, 1000);
  }
});

test('flipping each surface feature (and flat shading of a plain indexed geometry) 1,000 times keeps renderer.info.programs bounded', async ({
  page,
}) => {
  await open(page);
  const result = await page.evaluate(() => window.materialHarness.flipSurface(1000));
  // None, each of the 9 features alone, and the flat soup: 11 variants, each compiled once.
  expect(result.variants).toBe(11);
  expect(result.max).toBeLessThanOrEqual(result.before + result.variants);
  expect(result.after).toBeLessThanOrEqual(result.before + result.variants);
});

/** A 3 × 3 plane turned towards the light, so that a perturbed normal changes the diffuse and the highlight. */
const PLANE = {
  shading: 'phong',
  object: 'plane',
  instances: [{ position: [0, 0, 0], rotation: [-0.5, 0.35, 0.1], scale: [1.2, 0.9, 1] }],
} as const;

for (const [name, surface] of [
  ['tangent space', { normalMap: 'tangent' }],
  ['tangent space, normalScale (−0.5, 1.8)', { normalMap: 'tangent', normalScale: [-0.5, 1.8] }],
  ['tangent space with a map', { normalMap: 'tangent', map: true }],
  ['object space (normalMapType)', { normalMap: 'object' }],
] as Array<[string, SceneSurface]>) {
  test(`normalMap, ${name}: the normal through three's tangent frame in world space, = shade() with that normal`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { ...PLANE, surface });
    expectSurface(stats, 3000);
    // The map matters: shade() with the unperturbed normal is far from what is drawn.
    const plain = await scene(page, { ...PLANE, surface: { ...surface, unperturbed: true } });
    expect(plain.maxError, JSON.stringify(plain)).toBeGreaterThan(20);
  });
}

test('normalMap with gouraud or flat shading: ignored (no per-fragment normal), one console warning', async ({
  page,
}) => {
  await open(page);
  const warnings: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'warning' && m.text().includes('ShadingMaterial')) warnings.push(m.text());
  });
  for (const shading of ['gouraud', 'flat'] as const) {
    const stats = await scene(page, { ...PLANE, shading, surface: { normalMap: 'tangent' } });
    // Drawn as without the map: shade() with the geometry's normals.
    expectSurface(stats, 1500);
  }
  expect(warnings).toEqual([
    "ShadingMaterial: normalMap needs a per-fragment normal (shading 'phong'); gouraud shading ignores it",
    "ShadingMaterial: normalMap needs a per-fragment normal (shading 'phong'); flat shading ignores it",
  ]);
});

for (const side of ['double', 'back'] as const)
  test(`normalMap on a back face (${side === 'double' ? 'DoubleSide' : 'BackSide'}): lit with the flipped perturbed normal, = shade()`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    // The plane turned away: its back face looks at the camera and the light.
    const config = {
      ...PLANE,
      instances: [{ position: [0, 0, 0], rotation: [0.5, Math.PI - 0.35, 0.1], scale: [1.2, 0.9, 1] }],
    } as const;
    const stats = await scene(page, { ...config, surface: { normalMap: 'tangent', side } });
    expectSurface(stats, 3000);
    const plain = await scene(page, {
      ...config,
      surface: { normalMap: 'tangent', side, unperturbed: true },
    });
    expect(plain.maxError, JSON.stringify(plain)).toBeGreaterThan(20);
  });

for (const side of ['double', 'back'] as const)
  test(`a textured, vertex-coloured back face (${side === 'double' ? 'DoubleSide' : 'BackSide'}), every shading: the ka/kd and ks parts of each side, = shade() with the flipped normal`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    for (const [rotation, minCompared] of [
      [[-0.5, 0.35, 0.1], 3000], // front faces (DoubleSide only)
      [[0.5, Math.PI - 0.35, 0.1], 3000], // back faces
    ] as const) {
      if (side === 'back' && rotation[1] < 1) continue;
      for (const [shadingName, variant] of SHADINGS) {
        const stats = await scene(page, {
          ...variant,
          object: 'plane',
          instances: [{ position: [0, 0, 0], rotation, scale: [1.2, 0.9, 1] }],
          surface: { map: true, vertexColors: 'rgb', emissive: [0.02, 0.01, 0], side },
        });
        expectSurface(stats, shadingName.startsWith('flat') ? minCompared / 2 : minCompared);
      }
    }
  });
