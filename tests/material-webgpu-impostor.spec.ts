// SphereImpostorNodeMaterial (@shadelab/material/webgpu) under WebGPURenderer, on its WebGPU backend and its WebGL2
// backend (forceWebGL), rendered offscreen into a RenderTarget and read back: against WebGLRenderer +
// SphereImpostorMaterial in the same scene (coverage and colours), its depth against a mesh box and a subdivided
// mesh sphere, and its bad-input errors against SphereImpostorMaterial's. Harness: tests/harness/webgpu-impostor.ts.
import { expect } from '@playwright/test';
import { webgpuTest as test } from './harness-helpers';

type Backend = 'webgpu' | 'webgl2';
type Scenario =
  | 'ellipsoid'
  | 'sphere'
  | 'instanced'
  | 'mirrored'
  | 'orthographic'
  | 'inside'
  | 'fog'
  | 'clipped'
  | 'clip-intersection'
  | 'extreme'
  | 'box';
interface Variant {
  lighting: 'phong' | 'blinn-phong';
  celBands: number;
}
interface Counts {
  boxPixels: number;
  spherePixels: number;
}
interface Harness {
  backendInfo(b: Backend): Promise<{ isWebGPUBackend: boolean; isWebGLBackend: boolean }>;
  crossRenderer(
    b: Backend,
    v: Variant,
    scenario: Scenario,
  ): Promise<{
    covered: number;
    coverageMismatch: number;
    coverageMismatchOffEdge: number;
    compared: number;
    maxDelta: number;
    differing: number;
    worst: unknown;
  }>;
  occlusion(
    b: Backend,
    v: Variant,
    mode?: 'standard' | 'logarithmic' | 'reversed',
  ): Promise<{
    logarithmic: boolean;
    reversed: boolean;
    impostor: Counts;
    mesh: Counts;
    boxAlone: Counts;
    sphereAlone: Counts;
    disagree: number;
    disagreeOffEdge: number;
  }>;
  scaleInvariance(
    on: Backend | 'webgl',
    v: Variant,
    scenario: 'huge' | 'tiny',
  ): Promise<{
    covered: number;
    coverageMismatch: number;
    coverageMismatchOffEdge: number;
    maxDelta: number;
  }>;
  errors(): {
    rows: { options: string; webgl: string; node: string }[];
    setters: string[];
    valid: string;
  };
}

/** Opens the harness; returns the page errors and console errors seen (none are expected). */

const VARIANTS: Variant[] = (['phong', 'blinn-phong'] as const).flatMap((lighting) =>
  [0, 4].map((celBands) => ({ lighting, celBands })),
);

test('WebGLRenderer + SphereImpostorMaterial: the whole scene scaled by 1e15 and by 1e-18 = the scene unscaled (same coverage but for silhouette pixels, colours within 2/255 away from edges); neither did before its inverse matrix was scaled by a power of two (1e15: the coverage wrong off the silhouette; 1e-18: nothing drawn)', async ({
  harness,
}) => {
  const { page, problems } = await harness('webgpu-impostor');
  for (const variant of VARIANTS) {
    for (const scenario of ['huge', 'tiny'] as const) {
      const stats = await page.evaluate(
        ([v, sc]) => (window as never as { harness: Harness }).harness.scaleInvariance('webgl', v, sc),
        [variant, scenario] as const,
      );
      const label = `${scenario} ${JSON.stringify(variant)} ${JSON.stringify(stats)}`;
      expect(stats.covered, label).toBeGreaterThan(2000);
      expect(stats.coverageMismatchOffEdge, label).toBe(0);
      expect(stats.coverageMismatch, label).toBeLessThanOrEqual(stats.covered * 0.01);
      expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
    }
  }
  expect(problems).toEqual([]);
});

for (const backend of ['webgpu', 'webgl2'] as const) {
  test(`${backend} backend: the impostor (an ellipsoid 2, 1, 2 and a unit sphere, one mesh each and two instances of an InstancedMesh; mirrored; orthographic; in three's Fog; cut by clipping planes; spheres scaled by 1e±20 that draw nothing; the eye inside) = WebGLRenderer + SphereImpostorMaterial; the scene scaled by 1e15 and 1e-18 = the scene unscaled: same coverage but for silhouette pixels, colours within 2/255 away from edges`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-impostor');
    const info = await page.evaluate(
      (b) => (window as never as { harness: Harness }).harness.backendInfo(b),
      backend,
    );
    expect(info.isWebGPUBackend).toBe(backend === 'webgpu');
    expect(info.isWebGLBackend).toBe(backend === 'webgl2');
    const scenarios = [
      'ellipsoid',
      'sphere',
      'instanced',
      'mirrored',
      'orthographic',
      'fog',
      'clipped',
      'clip-intersection',
      'extreme',
    ] as const;
    for (const scenario of scenarios) {
      // Fog softens the cel edges that the comparison leaves out: cel 0 there.
      const all = scenario === 'ellipsoid' || scenario === 'sphere' || scenario === 'instanced';
      for (const variant of all ? VARIANTS : VARIANTS.filter((v) => v.celBands === 0)) {
        const stats = await page.evaluate(
          ([b, v, sc]) => (window as never as { harness: Harness }).harness.crossRenderer(b, v, sc),
          [backend, variant, scenario] as const,
        );
        const label = `${backend} ${scenario} ${JSON.stringify(variant)} ${JSON.stringify(stats)}`;
        expect(stats.covered, label).toBeGreaterThan(scenario === 'sphere' ? 500 : 1000);
        // Coverage differs only on the silhouette (the two ray casts round differently there), and rarely.
        expect(stats.coverageMismatchOffEdge, label).toBe(0);
        expect(stats.coverageMismatch, label).toBeLessThanOrEqual(stats.covered * 0.01);
        // Cel band edges are left out too.
        expect(stats.compared, label).toBeGreaterThan(stats.covered * (variant.celBands > 0 ? 0.5 : 0.75));
        expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
      }
    }
    // The whole scene scaled by 1e15 and by 1e-18 (the cofactors of the model-view matrix would overflow or
    // underflow in 32-bit floats unscaled): the picture of the unscaled scene.
    for (const scenario of ['huge', 'tiny'] as const) {
      const stats = await page.evaluate(
        ([b, v, sc]) => (window as never as { harness: Harness }).harness.scaleInvariance(b, v, sc),
        [backend, VARIANTS[0], scenario] as const,
      );
      const label = `${backend} ${scenario} ${JSON.stringify(stats)}`;
      expect(stats.covered, label).toBeGreaterThan(2000);
      expect(stats.coverageMismatchOffEdge, label).toBe(0);
      expect(stats.coverageMismatch, label).toBeLessThanOrEqual(stats.covered * 0.01);
      expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
    }
    // A perspective eye inside the ellipsoid: its front surface is behind the eye, nothing is drawn by either.
    const inside = await page.evaluate(
      ([b, v]) => (window as never as { harness: Harness }).harness.crossRenderer(b, v, 'inside'),
      [backend, VARIANTS[0]] as const,
    );
    expect(inside.covered, JSON.stringify(inside)).toBe(0);
    expect(inside.coverageMismatch, JSON.stringify(inside)).toBe(0);
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: the impostor writes its exact depth: a mesh box through it is hidden where it is behind, as with WebGLRenderer + SphereImpostorMaterial and as with a subdivided mesh sphere`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-impostor');
    for (const variant of [VARIANTS[0], VARIANTS[3]]) {
      const stats = await page.evaluate(
        ([b, v]) => (window as never as { harness: Harness }).harness.crossRenderer(b, v, 'box'),
        [backend, variant] as const,
      );
      const label = `${backend} box ${JSON.stringify(variant)} ${JSON.stringify(stats)}`;
      expect(stats.coverageMismatchOffEdge, label).toBe(0);
      expect(stats.coverageMismatch, label).toBeLessThanOrEqual(stats.covered * 0.01);
      expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
      const o = await page.evaluate(
        ([b, v]) => (window as never as { harness: Harness }).harness.occlusion(b, v),
        [backend, variant] as const,
      );
      const olabel = `${backend} ${JSON.stringify(variant)} ${JSON.stringify(o)}`;
      // Each hides part of the other.
      expect(o.impostor.boxPixels, olabel).toBeGreaterThan(200);
      expect(o.impostor.boxPixels, olabel).toBeLessThan(o.boxAlone.boxPixels - 150);
      expect(o.impostor.spherePixels, olabel).toBeLessThan(o.sphereAlone.spherePixels - 150);
      // As with the mesh sphere, but for the mesh's facets along the boundary.
      expect(o.disagreeOffEdge, olabel).toBe(0);
      expect(Math.abs(o.impostor.boxPixels - o.mesh.boxPixels), olabel).toBeLessThanOrEqual(
        o.mesh.boxPixels * 0.03,
      );
    }
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: the impostor's depth in a logarithmic and in a reversed-Z depth buffer hides the box as a subdivided mesh sphere does`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-impostor');
    for (const mode of ['logarithmic', 'reversed'] as const) {
      const o = await page.evaluate(
        ([b, v, m]) => (window as never as { harness: Harness }).harness.occlusion(b, v, m),
        [backend, VARIANTS[0], mode] as const,
      );
      const label = `${backend} ${mode} ${JSON.stringify(o)}`;
      expect(mode === 'logarithmic' ? o.logarithmic : o.reversed, label).toBe(true);
      expect(o.impostor.boxPixels, label).toBeGreaterThan(200);
      expect(o.impostor.boxPixels, label).toBeLessThan(o.boxAlone.boxPixels - 150);
      expect(o.impostor.spherePixels, label).toBeLessThan(o.sphereAlone.spherePixels - 150);
      expect(o.disagreeOffEdge, label).toBe(0);
      expect(Math.abs(o.impostor.boxPixels - o.mesh.boxPixels), label).toBeLessThanOrEqual(
        o.mesh.boxPixels * 0.03,
      );
    }
    expect(problems).toEqual([]);
  });
}

test("bad input throws SphereImpostorMaterial's errors (same class, same message but for the material's name)", async ({
  harness,
}) => {
  const { page } = await harness('webgpu-impostor');
  const { rows, setters, valid } = await page.evaluate(() =>
    (window as never as { harness: Harness }).harness.errors(),
  );
  expect(rows.length).toBeGreaterThan(10);
  for (const row of rows) {
    expect(row.webgl, row.options).toMatch(
      /^(TypeError|RangeError): (ShadingMaterial|SphereImpostorMaterial)\./,
    );
    expect(row.node, row.options).toMatch(/^(TypeError|RangeError): SphereImpostorNodeMaterial\./);
    const strip = (s: string) => s.replace(/^(\w+): \w+\./, '$1: M.');
    expect(strip(row.node), row.options).toBe(strip(row.webgl));
  }
  expect(setters).toEqual([
    "TypeError: SphereImpostorNodeMaterial.shading must be 'phong' (a ray-cast sphere is shaded per fragment), got gouraud",
    expect.stringMatching(/^TypeError: SphereImpostorNodeMaterial\.lighting must be/),
  ]);
  expect(valid).toBe('no error');
});
