// The material options `output` (term views) and `normalMatrix` (issue 24) on WebGLRenderer + ShadingMaterial and
// on WebGPURenderer + ShadingNodeMaterial (its WebGPU backend, proven, and its WebGL2 backend): each term view is
// shade() with the other terms zeroed, the attenuation view its formula, the terms add up to the colour, the
// normal view is three's MeshNormalMaterial's, and 'model' normals are M·n (the lecture's wrong way) exactly as
// the CPU computes them. Harness: tests/harness/material-output.ts (one page and one renderer per kind per test).
import { expect, type Page } from '@playwright/test';
import { openHarness, webgpuTest as test } from './harness-helpers';

type RendererKind = 'gl' | 'webgpu' | 'webgl2';
type Shading = 'flat' | 'gouraud' | 'phong';
type LightingCase = 'phong' | 'blinn-phong' | 'cel';
type Lights = 'phong' | 'three';
type Output = 'color' | 'ambient' | 'diffuse' | 'specular' | 'attenuation' | 'normal';
interface Case {
  renderer: RendererKind;
  shading: Shading;
  lighting: LightingCase;
  lights: Lights;
  output: Output;
  normalMatrix?: 'inverse-transpose' | 'model';
  scale?: readonly [number, number, number];
}
interface Stats {
  covered: number;
  compared: number;
  max: number;
  over2: number;
  worst: unknown;
}
interface Harness {
  backendInfo(b: 'webgpu' | 'webgl2'): Promise<{ isWebGPUBackend: boolean; isWebGLBackend: boolean }>;
  check(c: Case): Promise<Stats>;
  terms(
    r: RendererKind,
    s: Shading,
    l: LightingCase,
    lights: Lights,
  ): Promise<{ sum: { compared: number; max: number }; checks: Record<string, Stats> }>;
  normalOracle(
    r: RendererKind,
    s: Shading,
    scale: readonly [number, number, number],
  ): Promise<{ compared: number; max: number; coverageDiffers: number }>;
  modelAgainstInverse(
    r: RendererKind,
    s: Shading,
    o: Output,
    scale: readonly [number, number, number],
  ): Promise<{ compared: number; differing: number; max: number }>;
}

const RENDERERS: readonly RendererKind[] = ['gl', 'webgpu', 'webgl2'];
const SHADINGS: readonly Shading[] = ['flat', 'gouraud', 'phong'];
const LIGHTINGS: readonly LightingCase[] = ['phong', 'blinn-phong', 'cel'];
const STRETCHED = [1.3, 0.45, 1] as const;

let page: Page;
let problems: string[];
test.describe.configure({ mode: 'serial' });
test.beforeAll(async ({ browser }) => {
  page = await browser.newPage();
  problems = await openHarness(page, 'material-output');
});
test.afterAll(async () => {
  await page.close();
});
test.afterEach(() => {
  expect(problems).toEqual([]);
});

test('WebGPURenderer runs its WebGPU backend (not a silent fallback) and its WebGL2 backend', async () => {
  const webgpu = await page.evaluate(() =>
    (window as never as { harness: Harness }).harness.backendInfo('webgpu'),
  );
  expect(webgpu).toEqual({ isWebGPUBackend: true, isWebGLBackend: false });
  const webgl2 = await page.evaluate(() =>
    (window as never as { harness: Harness }).harness.backendInfo('webgl2'),
  );
  expect(webgl2).toEqual({ isWebGPUBackend: false, isWebGLBackend: true });
});

for (const renderer of RENDERERS) {
  for (const lights of ['phong', 'three'] as const) {
    for (const shading of SHADINGS) {
      test(`${renderer}, ${lights === 'phong' ? 'two attenuated PhongLights' : "three's five lights"}, ${shading}: each term view = shade() with the other terms zeroed, attenuation = the mean falloff, ambient + diffuse + specular = colour`, async () => {
        for (const lighting of LIGHTINGS) {
          const r = await page.evaluate(
            ([a, b, c, d]) => (window as never as { harness: Harness }).harness.terms(a, b, c, d),
            [renderer, shading, lighting, lights] as const,
          );
          for (const [output, stats] of Object.entries(r.checks)) {
            const label = `${lighting} ${output}: ${JSON.stringify(stats)}`;
            expect(stats.covered, label).toBeGreaterThan(1000);
            expect(stats.compared, label).toBeGreaterThan(250);
            expect(stats.max, label).toBeLessThanOrEqual(2);
          }
          // Three 8-bit values each rounded once: their sum is within 1.5/255 of the colour's (in linear).
          expect(r.sum.compared, lighting).toBeGreaterThan(300);
          expect(r.sum.max, `${lighting} sum: ${JSON.stringify(r.sum)}`).toBeLessThanOrEqual(2);
          const worst = Object.entries(r.checks).map(([o, c]) => `${o} ${c.max.toFixed(2)}`);
          console.log(
            `${renderer} ${lights} ${shading} ${lighting}: max |GPU − CPU| ${worst.join(', ')}; sum ${r.sum.max}`,
          );
        }
      });
    }
  }

  test(`${renderer}: the normal view is three's MeshNormalMaterial's (phong, flat) and the CPU's view-space normal (every shading), under a non-uniform scale`, async () => {
    for (const shading of SHADINGS) {
      const cpu = await page.evaluate(
        ([r, s, scale]) =>
          (window as never as { harness: Harness }).harness.check({
            renderer: r,
            shading: s,
            lighting: 'phong',
            lights: 'phong',
            output: 'normal',
            scale,
          }),
        [renderer, shading, STRETCHED] as const,
      );
      expect(cpu.compared, `${shading}: ${JSON.stringify(cpu)}`).toBeGreaterThan(300);
      expect(cpu.max, `${shading}: ${JSON.stringify(cpu)}`).toBeLessThanOrEqual(2);
      if (shading === 'gouraud') continue; // packed per vertex and interpolated: not three's per-pixel normal
      const three = await page.evaluate(
        ([r, s, scale]) => (window as never as { harness: Harness }).harness.normalOracle(r, s, scale),
        [renderer, shading, STRETCHED] as const,
      );
      expect(three.compared, `${shading}: ${JSON.stringify(three)}`).toBeGreaterThan(1000);
      expect(three.coverageDiffers, `${shading}: ${JSON.stringify(three)}`).toBe(0);
      expect(three.max, `${shading}: ${JSON.stringify(three)}`).toBeLessThanOrEqual(2);
    }
  });

  test(`${renderer}: normalMatrix 'model' draws M·n as the CPU computes it, unlike the inverse transpose under a non-uniform scale, and the same under a uniform one`, async () => {
    for (const shading of SHADINGS) {
      for (const output of ['normal', 'color'] as const) {
        const label = `${shading} ${output}`;
        const cpu = await page.evaluate(
          ([r, s, o, scale]) =>
            (window as never as { harness: Harness }).harness.check({
              renderer: r,
              shading: s,
              lighting: 'phong',
              lights: 'phong',
              output: o,
              normalMatrix: 'model',
              scale,
            }),
          [renderer, shading, output, STRETCHED] as const,
        );
        expect(cpu.compared, `${label}: ${JSON.stringify(cpu)}`).toBeGreaterThan(300);
        expect(cpu.max, `${label}: ${JSON.stringify(cpu)}`).toBeLessThanOrEqual(2);
        const stretched = await page.evaluate(
          ([r, s, o, scale]) =>
            (window as never as { harness: Harness }).harness.modelAgainstInverse(r, s, o, scale),
          [renderer, shading, output, STRETCHED] as const,
        );
        // Most of the surface leans: the two pictures differ by far more than rounding.
        expect(stretched.differing, `${label}: ${JSON.stringify(stretched)}`).toBeGreaterThan(
          stretched.compared / 3,
        );
        expect(stretched.max, label).toBeGreaterThan(20);
        const uniform = await page.evaluate(
          ([r, s, o]) =>
            (window as never as { harness: Harness }).harness.modelAgainstInverse(r, s, o, [0.8, 0.8, 0.8]),
          [renderer, shading, output] as const,
        );
        expect(uniform.max, `${label} uniform: ${JSON.stringify(uniform)}`).toBeLessThanOrEqual(1);
      }
    }
  });
}
