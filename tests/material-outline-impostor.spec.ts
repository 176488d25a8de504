import { expect, type Page } from '@playwright/test';
import type { ImpostorConfig, ImpostorStats, OutlineConfig, OutlineStats } from './harness/outline-impostor';
import { openHarness, test } from './harness-helpers';

// The outline and the impostor in any three.js scene (issue 14): createOutline on a SkinnedMesh with a moved
// bone, a mesh with morph targets at full influence and an InstancedMesh draws the hull around the deformed
// surface of each instance; judged against the hull built on the CPU from three's own deformation and drawn
// by three's MeshBasicMaterial. Runs in headless Chromium (SwiftShader) on the outline-impostor harness page.

async function open(page: Page): Promise<void> {
  await openHarness(page, 'outline-impostor');
}

function outline(page: Page, config: OutlineConfig): Promise<OutlineStats> {
  return page.evaluate((c) => window.outlineImpostorHarness.outlineCompare(c), config);
}

function impostors(page: Page, config: ImpostorConfig): Promise<ImpostorStats> {
  return page.evaluate((c) => window.outlineImpostorHarness.impostorCompare(c), config);
}

test.describe.configure({ mode: 'parallel' });

const INSTANCES: OutlineConfig['instances'] = [
  { position: [-2.2, 0.4, 0], scale: [0.7, 0.7, 0.7] },
  { position: [0, -0.5, -0.5], rotation: [0.3, 0.5, 0.2], scale: [1, 0.6, 0.8] },
  { position: [2.1, 0.6, 0.4], rotation: [0, 0, 0.6], scale: [0.5, 0.9, 0.5] },
];

for (const [name, config] of [
  ['a SkinnedMesh with a moved bone', { object: 'skinned' }],
  ['a mesh with a morph target at full influence', { object: 'morphed' }],
  [
    'an InstancedMesh (rotated, non-uniformly scaled instances)',
    { object: 'instanced', instances: INSTANCES },
  ],
  [
    'an InstancedMesh with per-instance morph weights',
    { object: 'instanced-morphed', instances: INSTANCES.map((i) => ({ ...i, scale: [0.6, 0.6, 0.6] })) },
  ],
  [
    'a skinned mesh with instances (a SkinnedMesh with an instanceMatrix: instancing × skinning)',
    {
      object: 'instanced-skinned',
      instances: [
        { position: [-1.6, 0.2, 0], scale: [0.7, 0.7, 0.7] },
        { position: [1.4, -0.3, -0.5], rotation: [0, 0.4, -0.3], scale: [0.6, 0.8, 0.6] },
      ],
    },
  ],
] as Array<[string, Omit<OutlineConfig, 'thickness'>]>) {
  test(`createOutline on ${name}: the hull of the deformed surface (= three's deformation, CPU hull)`, async ({
    page,
  }) => {
    await open(page);
    const stats = await outline(page, { ...config, thickness: 0.12 });
    const info = JSON.stringify(stats);
    expect(stats.compared, info).toBeGreaterThan(30000);
    expect(stats.ring, info).toBeGreaterThan(300);
    expect(stats.body, info).toBeGreaterThan(1500);
    expect(stats.mismatches, info).toBe(0);
    // Not vacuous: the hull of the raw geometry (the outline before this change) is far off.
    expect(stats.staleMismatches, info).toBeGreaterThan(200);
  });
}

test('createOutline on a plain mesh still matches the CPU hull (the control)', async ({ page }) => {
  await open(page);
  const stats = await outline(page, { object: 'mesh', thickness: 0.12 });
  const info = JSON.stringify(stats);
  expect(stats.compared, info).toBeGreaterThan(30000);
  expect(stats.ring, info).toBeGreaterThan(300);
  expect(stats.mismatches, info).toBe(0);
  expect(stats.staleMismatches, info).toBe(0);
});

/**
 * Five coloured instances: spheres of different radii, an ellipsoid (rotated, non-uniform scale), and a sphere
 * that intersects another.
 */
const SPHERES: ImpostorConfig['instances'] = [
  { position: [-2.2, 0.6, 0], scale: [0.8, 0.8, 0.8], color: [1, 0.5, 0.25] },
  { position: [0, 0, 0.5], scale: [1.1, 1.1, 1.1], color: [0.25, 1, 0.5] },
  { position: [2.2, -0.4, -0.5], rotation: [0.3, 0.2, 0.7], scale: [1.2, 0.6, 0.8], color: [0.5, 0.25, 1] },
  { position: [0.3, -1.9, 1], scale: [0.5, 0.5, 0.5], color: [1, 1, 1] },
  // Through the second sphere: where they intersect, the exact depth of each hit decides.
  { position: [0.9, 0.7, 0.9], scale: [0.6, 0.6, 0.6], color: [1, 1, 0.3] },
];

function expectImpostors(stats: ImpostorStats, minCovered: number, minCompared: number): void {
  const info = JSON.stringify(stats);
  // Where: every pixel away from the oracle's edges is drawn exactly where MeshPhongMaterial draws the spheres.
  expect(stats.covered, info).toBeGreaterThan(minCovered);
  expect(stats.coverageCompared, info).toBeGreaterThan(30000);
  expect(stats.coverageMismatches, info).toBe(0);
  // What colour: shade() at the exact hit with the instance colour as the tint, within 2/255, no NaN.
  expect(stats.compared, info).toBeGreaterThan(minCompared);
  expect(stats.maxError, info).toBeLessThanOrEqual(2);
  expect(stats.mismatches, info).toBe(0);
  expect(stats.darkPixels, info).toBe(0);
  // Each instance is one impostor at M × instance matrix: the same pixels as a SphereImpostor per sphere.
  expect(stats.objectsCovered, info).toBe(stats.covered);
  expect(stats.objectsMismatches, info).toBe(0);
}

test('SphereImpostorMaterial on an InstancedMesh: each instance a sphere (an ellipsoid under a non-uniform scale) where MeshPhongMaterial draws it, coloured as shade() × instanceColor', async ({
  page,
}) => {
  await open(page);
  const stats = await impostors(page, { instances: SPHERES });
  expectImpostors(stats, 5000, 4000);
  for (const n of stats.perInstance) expect(n, JSON.stringify(stats)).toBeGreaterThan(150);
});

test('the instanced impostor under the InstancedMesh’s own non-uniform scale: M × instance matrix', async ({
  page,
}) => {
  await open(page);
  const stats = await impostors(page, { instances: SPHERES, scale: [0.8, 1.3, 1] });
  expectImpostors(stats, 5000, 4000);
});

test('instanced impostor extremes: zero-scale and 1e±20-scale instances draw nothing wrong and leave the others exact', async ({
  page,
}) => {
  await open(page);
  const stats = await impostors(page, {
    instances: [
      ...SPHERES,
      { position: [0, 1.6, 0], scale: [0, 0, 0], color: [1, 0, 0] },
      { position: [1, 1.6, 0], scale: [1, 0, 1], color: [1, 0, 0] },
      { position: [-1, 1.8, 0], scale: [1e-20, 1e-20, 1e-20], color: [1, 0, 0] },
      // 1e20 behind the far plane (seen through it), and around the camera (the eye inside it).
      { position: [0, 0, -3e20], scale: [1e20, 1e20, 1e20], color: [1, 0, 0] },
      { position: [0, 0, 0], scale: [1e20, 1e20, 1e20], color: [1, 0, 0] },
    ],
  });
  expectImpostors(stats, 5000, 4000);
});

for (const [name, extra] of [
  ['fog', { fog: { near: 4, far: 8 } }],
  ['a clipping plane', { clip: [1, 0.3, 0, -0.2] }],
  ['a logarithmic depth buffer', { logarithmic: true }],
] as Array<[string, Partial<ImpostorConfig>]>) {
  test(`the instanced impostor with ${name}: the same pixels as one SphereImpostor per sphere, covered where MeshPhongMaterial draws`, async ({
    page,
  }) => {
    await open(page);
    const stats = await impostors(page, { instances: SPHERES, ...extra });
    const info = JSON.stringify(stats);
    expect(stats.covered, info).toBeGreaterThan(3000);
    expect(stats.coverageCompared, info).toBeGreaterThan(30000);
    expect(stats.coverageMismatches, info).toBe(0);
    expect(stats.darkPixels, info).toBe(0);
    expect(stats.objectsCovered, info).toBe(stats.covered);
    expect(stats.objectsMismatches, info).toBe(0);
    if (extra.logarithmic) {
      expect(stats.compared, info).toBeGreaterThan(4000);
      expect(stats.maxError, info).toBeLessThanOrEqual(2);
    }
  });
}
