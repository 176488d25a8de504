// OutlineNodeMaterial (createOutlineNode, @shadelab/material/webgpu) under WebGPURenderer, on its WebGPU backend
// and its WebGL2 backend (forceWebGL), rendered offscreen into a RenderTarget and read back. Each picture is judged
// against the hull built on the CPU from three's own deformation (drawn by three's MeshBasicNodeMaterial on the
// same renderer: where the outline is) and against WebGLRenderer + createOutline's OutlineMaterial in the same
// scene (the same coverage). Harness: tests/harness/webgpu-outline.ts.
import { expect, type Page } from '@playwright/test';
import type { Backend, Instance, OutlineConfig, WebGPUOutlineHarness } from './harness/webgpu-outline';
import { webgpuTest as test } from './harness-helpers';

/** Opens the harness; returns the page errors and console errors seen (none are expected). */

function outline(page: Page, backend: Backend, config: OutlineConfig) {
  return page.evaluate(
    ([b, c]) => (window as never as { harness: WebGPUOutlineHarness }).harness.outlineCompare(b, c),
    [backend, config] as const,
  );
}

const INSTANCES: Instance[] = [
  { position: [-2.2, 0.4, 0], scale: [0.7, 0.7, 0.7] },
  { position: [0, -0.5, -0.5], rotation: [0.3, 0.5, 0.2], scale: [1, 0.6, 0.8] },
  { position: [2.1, 0.6, 0.4], rotation: [0, 0, 0.6], scale: [0.5, 0.9, 0.5] },
];

/** The extremes of the instance matrix: a mirrored instance (det < 0), one flattened to a disc, zero, 1e20. */
const EXTREME_INSTANCES: Instance[] = [
  { position: [-2, 0.6, 0], scale: [-0.7, 0.7, 0.7] },
  { position: [0, -0.9, 0], rotation: [0.5, 0.3, 0], scale: [0.9, 0.9, 0] },
  { position: [2, 0.6, 0], scale: [0, 0, 0] },
  // Far beyond the far plane (and, seen from the eye, around nothing): draws nothing.
  { position: [0, 0, -3e20], scale: [1e20, 1e20, 1e20] },
  { position: [1.9, -1.1, 0], scale: [0.6, 0.6, 0.6] },
];

// Not here: an InstancedMesh with per-instance morph weights (setMorphAt). three 0.187's morph node throws on it
// under any node material, its own MeshBasicNodeMaterial included ("Cannot set properties of null" in
// UniformArrayNode.updateBuffer: the influences array it updates was never set up, the weights being read from
// morphTexture). The WebGL outline is tested on it (tests/material-outline-impostor.spec.ts).
const CASES: Array<[string, Omit<OutlineConfig, 'thickness'>, boolean]> = [
  ['a plain mesh (non-uniform scale)', { object: 'mesh' }, false],
  ['a sphere without normals (userData.isSphere: normal = position)', { object: 'sphere' }, false],
  ['a mesh with a morph target at full influence', { object: 'morphed' }, true],
  ['a SkinnedMesh with a moved bone', { object: 'skinned' }, true],
  [
    'an InstancedMesh (rotated, non-uniformly scaled instances)',
    { object: 'instanced', instances: INSTANCES },
    true,
  ],
  [
    'a SkinnedMesh with instances (instancing × skinning)',
    {
      object: 'instanced-skinned',
      instances: [
        { position: [-1.6, 0.2, 0], scale: [0.7, 0.7, 0.7] },
        { position: [1.4, -0.3, -0.5], rotation: [0, 0.4, -0.3], scale: [0.6, 0.8, 0.6] },
      ],
    },
    true,
  ],
];

for (const backend of ['webgpu', 'webgl2'] as const) {
  for (const [group, cases] of [
    ['a mesh, a sphere without normals, morph targets, skinning', CASES.slice(0, 4)],
    ['instanced, instanced × skinning', CASES.slice(4)],
  ] as const) {
    test(`${backend} backend: createOutlineNode on ${group}: the hull of the deformed surface, where the CPU hull of three's deformation is and where WebGLRenderer + OutlineMaterial draws it`, async ({
      harness,
    }) => {
      const { page, problems } = await harness('webgpu-outline');
      for (const [name, config, moved] of cases) {
        const stats = await outline(page, backend, { ...config, thickness: 0.12 });
        const info = `${backend} ${name}: ${JSON.stringify(stats)}`;
        // Proof of the backend that ran (no silent fallback to WebGL2).
        expect(stats.backend, info).toEqual({
          isWebGPUBackend: backend === 'webgpu',
          isWebGLBackend: backend === 'webgl2',
        });
        expect(stats.compared, info).toBeGreaterThan(30000);
        expect(stats.ring, info).toBeGreaterThan(300);
        expect(stats.body, info).toBeGreaterThan(1500);
        expect(stats.stray, info).toBe(0);
        // Where the CPU hull is (away from its edges), and the GLSL outline's coverage.
        expect(stats.mismatches, info).toBe(0);
        expect(stats.glCompared, info).toBeGreaterThan(30000);
        expect(stats.glMismatches, info).toBe(0);
        // Not vacuous: the hull of the raw geometry is far off (the mesh itself: the same).
        if (moved) expect(stats.staleMismatches, info).toBeGreaterThan(200);
        else expect(stats.staleMismatches, info).toBe(0);
      }
      expect(problems).toEqual([]);
    });
  }

  test(`${backend} backend: the outline of instances with a negative determinant, a zero and a 1e20 scale: finite (no stray pixel), the same coverage as WebGLRenderer + OutlineMaterial (the robust normal sign(det)·cof)`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-outline');
    const stats = await outline(page, backend, {
      object: 'instanced',
      instances: EXTREME_INSTANCES,
      thickness: 0.12,
    });
    const info = JSON.stringify(stats);
    expect(stats.backend.isWebGPUBackend, info).toBe(backend === 'webgpu');
    expect(stats.stray, info).toBe(0);
    expect(stats.ring, info).toBeGreaterThan(300);
    expect(stats.glCompared, info).toBeGreaterThan(30000);
    expect(stats.glMismatches, info).toBe(0);
    expect(problems).toEqual([]);
  });
}

test("OutlineNodeMaterial's options: OutlineMaterial's defaults, and its errors for bad input (same class, same message but for the material's name)", async ({
  harness,
}) => {
  const { page } = await harness('webgpu-outline');
  const { rows, defaults } = await page.evaluate(() =>
    (window as never as { harness: WebGPUOutlineHarness }).harness.errors(),
  );
  for (const row of rows) {
    expect(row.webgl, row.options).toMatch(/^(TypeError|RangeError): OutlineMaterial\./);
    expect(row.node, row.options).toBe(row.webgl.replace('OutlineMaterial.', 'OutlineNodeMaterial.'));
  }
  // thickness, colour, side (BackSide = 1) and fog: the same.
  expect(defaults[0]).toBe('0.03 0,0,0 1 true');
  expect(defaults[1]).toBe(defaults[0]);
  expect(defaults[2]).toBe('RangeError: OutlineNodeMaterial.thickness must be a finite number ≥ 0, got -2');
  expect(defaults[3]).toBe('0.03 ff0000');
});
