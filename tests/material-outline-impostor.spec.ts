import { expect, type Page, test } from '@playwright/test';
import type { OutlineConfig, OutlineStats } from '../playground/harness/outline-impostor';

// The outline and the impostor in any three.js scene (issue 14): createOutline on a SkinnedMesh with a moved
// bone, a mesh with morph targets at full influence and an InstancedMesh draws the hull around the deformed
// surface of each instance; judged against the hull built on the CPU from three's own deformation and drawn
// by three's MeshBasicMaterial. Runs in headless Chromium (SwiftShader) on the outline-impostor harness page.

async function open(page: Page): Promise<void> {
  await page.goto('/harness/outline-impostor.html');
  await expect(page.locator('body')).toHaveAttribute('data-ready', '1');
}

function outline(page: Page, config: OutlineConfig): Promise<OutlineStats> {
  return page.evaluate((c) => window.outlineImpostorHarness.outlineCompare(c), config);
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
