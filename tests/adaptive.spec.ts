// AdaptiveShading (issue 25) in Chromium: the adaptive picture against the full-detail Phong picture of the same
// scene (honesty: at most the budget at the 99th percentile of the drawn pixels, at most 0.5% of them over it; a
// field of spheres, of torus knots and of a glTF model exported and loaded back in the page), and
// 1,000 instances moving for 600 frames with a bounded number of draw calls and uploads.
import { expect } from '@playwright/test';
import type { CameraKind, Field } from './harness/adaptive';
import { test } from './harness-helpers';

for (const field of ['spheres', 'knots', 'model'] as Field[]) {
  for (const camera of ['perspective', 'orthographic'] as CameraKind[]) {
    test(`honesty: a ${field} field, ${camera} camera, budgets 2, 8 and 32`, async ({ harness }) => {
      const { page } = await harness('adaptive');
      for (const budget of [2, 8, 32]) {
        // The model's orthographic view zoomed in (2.5×): there some of its meshes take a cheaper shading.
        const zoom = field === 'model' ? 2.5 : 1;
        const r = await page.evaluate(
          ([f, c, b, z]) =>
            window.adaptiveHarness.honesty(f as Field, c as CameraKind, b as number, z as number),
          [field, camera, budget, zoom] as const,
        );
        test.info().annotations.push({
          type: `budget ${budget}`,
          description: `drawn ${r.drawn}, p99 ${r.p99}, over ${(100 * r.over).toFixed(3)}%, max ${r.max}, choices ${JSON.stringify(r.choices)}`,
        });
        expect(r.drawn).toBeGreaterThan(2000);
        expect(r.p99).toBeLessThanOrEqual(budget);
        expect(r.over).toBeLessThanOrEqual(0.005);
      }
    });
  }
}

test('the loaded model is what GLTFLoader gave back: three meshes, swapped to ShadingMaterial per field slot', async ({
  harness,
}) => {
  const { page } = await harness('adaptive');
  const meshes = await page.evaluate(() => window.adaptiveHarness.loadedModel());
  expect(meshes.map((m) => m.name).sort()).toEqual(['ring', 'rock', 'vase']);
  for (const m of meshes) {
    expect(m.material).toBe('MeshStandardMaterial');
    expect(m.vertices).toBeGreaterThan(300);
  }
});

test('1,000 instances moving for 600 frames: bounded draw calls and uploads', async ({ harness }) => {
  const { page } = await harness('adaptive');
  const r = await page.evaluate(() => window.adaptiveHarness.instances(600));
  test.info().annotations.push({ type: 'instances', description: JSON.stringify(r) });
  expect(r.instances).toBe(1000);
  // One draw per group in use (the original InstancedMesh draws nothing), never one per instance.
  expect(r.maxCalls).toBeLessThanOrEqual(r.maxGroups);
  expect(r.maxGroups).toBeLessThanOrEqual(13);
  // Every instance moves every frame: each group's matrices are uploaded once a frame, as one range.
  expect(r.maxUploads).toBeLessThanOrEqual(r.maxGroups);
});
