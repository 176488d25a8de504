// Drop-in pixels (issue 22): ShadingMaterial({ ka: c, kd: c, ks: 0 }) renders the pixels of three's
// MeshPhongMaterial({ color: c, specular: 0 }) and MeshLambertMaterial({ color: c }) under three's lights, on
// WebGLRenderer and (ShadingNodeMaterial against MeshPhongNodeMaterial and MeshLambertNodeMaterial) on
// WebGPURenderer's WebGPU and WebGL2 backends. Cases: a sphere and a torus knot, under each of three's five light
// kinds alone and all five together, without fog, in Fog and in FogExp2, plain, with an sRGB map and with vertex
// colours (108 pictures per renderer, each against both of three's materials). Bound, in 8-bit sRGB, over the
// pixels whose 3 × 3 neighbourhood is drawn in both pictures: mean max|ΔRGB| ≤ 1/255, max ≤ 3/255; coverage
// equal everywhere. Gouraud and flat shading light a surface differently from three's per-fragment lighting, so
// for them only the brightness is checked (looser bound below). Harness: tests/harness/dropin.ts.
import { expect, type Page } from '@playwright/test';
import type { DropinCase, FogKind, GeometryKind, LightSet, RendererKind, RunResult } from './harness/dropin';
import { openHarness, webgpuTest as test } from './harness-helpers';

interface Harness {
  run(renderer: RendererKind, cases: DropinCase[]): Promise<RunResult>;
}

const GEOMETRIES: GeometryKind[] = ['sphere', 'torusKnot'];
const LIGHTS: LightSet[] = ['ambient', 'hemisphere', 'directional', 'point', 'spot', 'all'];
const FOGS: FogKind[] = ['none', 'fog', 'fogExp2'];

/** The bound of the phong-shaded cases (1/255 of 8-bit sRGB). */
const MEAN = 1;
const MAX = 3;
/**
 * The brightness bound of gouraud and flat shading against three's per-fragment lighting (1/255): `bias` bounds
 * the mean over the compared pixels and channels of ShadingMaterial − three's (as bright on average: a factor π
 * shows as tens), `mean` the mean of max|ΔRGB| (per-vertex and per-face lighting differ from per-fragment
 * lighting inside a triangle, most under a single directional light). Measured: |bias| ≤ 0.42, mean ≤ 1.44
 * (gouraud) and ≤ 4.6 (flat) on all three renderers.
 */
const BRIGHTNESS = { gouraud: { bias: 1, mean: 2 }, flat: { bias: 1, mean: 6 } } as const;

/** Opens the harness; returns the page errors and console errors seen (none are expected). */
const open = (page: Page): Promise<string[]> => openHarness(page, 'dropin');

const label = (c: DropinCase): string => `${c.geometry} ${c.lights} fog=${c.fog} ${c.surface} ${c.shading}`;

/** Runs `cases` on `renderer` in batches (one evaluate per geometry and surface) and returns every result. */
async function runAll(page: Page, renderer: RendererKind, cases: DropinCase[]): Promise<RunResult[]> {
  const runs: RunResult[] = [];
  const batches = new Map<string, DropinCase[]>();
  for (const c of cases) {
    const key = `${c.geometry} ${c.surface}`;
    batches.set(key, [...(batches.get(key) ?? []), c]);
  }
  for (const batch of batches.values()) {
    runs.push(
      await page.evaluate(([r, b]) => (window as never as { harness: Harness }).harness.run(r, b), [
        renderer,
        batch,
      ] as const),
    );
  }
  return runs;
}

/**
 * The phong-shaded cases, per model: every light set in no fog, Fog and FogExp2 (plain); every light set with the
 * map and with vertex colours (no fog); all lights with both the map and vertex colours in each fog. Fog and the
 * surface colour are applied after (fog) and before (surface) the lighting, apart from it, so every pair of
 * factors is drawn without drawing the whole product.
 */
const PHONG_CASES: DropinCase[] = GEOMETRIES.flatMap((geometry) => [
  ...LIGHTS.flatMap((lights) => FOGS.map((fog) => ({ geometry, lights, fog, surface: 'plain' as const }))),
  ...(['map', 'vertexColors'] as const).flatMap((surface) =>
    LIGHTS.map((lights) => ({ geometry, lights, fog: 'none' as const, surface })),
  ),
  ...FOGS.map((fog) => ({ geometry, lights: 'all' as const, fog, surface: 'both' as const })),
]).map((c) => ({ ...c, shading: 'phong' as const }));
/** Gouraud and flat: every light set on each model, plain, no fog (three's pictures are the phong cases'). */
const BRIGHTNESS_CASES: DropinCase[] = GEOMETRIES.flatMap((geometry) =>
  (['gouraud', 'flat'] as const).flatMap((shading) =>
    LIGHTS.map((lights) => ({ geometry, lights, fog: 'none' as const, surface: 'plain' as const, shading })),
  ),
);

/**
 * The measurements by class of case, for the report: phong-shaded by lights, fog, surface and model; gouraud and
 * flat by lights. Each: the worst mean, the worst max and the largest |signed mean| over the class's cases and
 * both references (1/255 of 8-bit sRGB).
 */
function summary(renderer: RendererKind, runs: RunResult[]): string {
  const classes = new Map<string, { mean: number; max: number; bias: number; n: number }>();
  for (const run of runs) {
    for (const r of run.results) {
      const c = r.case;
      const keys =
        c.shading === 'phong'
          ? [`lights=${c.lights}`, `fog=${c.fog}`, `surface=${c.surface}`, `model=${c.geometry}`]
          : [`lights=${c.lights}`];
      for (const key of keys.map((k) => `${c.shading} ${k}`)) {
        const s = classes.get(key) ?? { mean: 0, max: 0, bias: 0, n: 0 };
        for (const cmp of r.comparisons) {
          s.mean = Math.max(s.mean, cmp.mean);
          s.max = Math.max(s.max, cmp.max);
          s.bias = Math.max(s.bias, Math.abs(cmp.signedMean));
        }
        s.n++;
        classes.set(key, s);
      }
    }
  }
  const ms = runs.reduce((s, r) => s + r.ms, 0);
  return [
    `${renderer}: ${runs.reduce((s, r) => s + r.results.length, 0)} cases in ${(ms / 1000).toFixed(1)} s`,
    ...[...classes].map(
      ([k, s]) =>
        `  ${k.padEnd(26)} mean ≤ ${s.mean.toFixed(3)}, max ≤ ${s.max}, |signed mean| ≤ ${s.bias.toFixed(3)} (${s.n} cases)`,
    ),
  ].join('\n');
}

/** Every failure of the phong-shaded cases against the bound, one line per case. */
function phongFailures(runs: RunResult[]): string[] {
  const failures: string[] = [];
  for (const run of runs) {
    for (const r of run.results) {
      const problems: string[] = [];
      const { surface } = r.case;
      if ((surface === 'map' || surface === 'both') && !r.carried.map)
        problems.push('the material did not keep `map`');
      if ((surface === 'vertexColors' || surface === 'both') && !r.carried.vertexColors)
        problems.push('the material did not keep `vertexColors`');
      for (const cmp of r.comparisons) {
        if (cmp.coverageMismatch !== 0) problems.push(`coverage differs on ${cmp.coverageMismatch} px`);
        if (cmp.mean > MEAN || cmp.max > MAX)
          problems.push(
            `vs ${cmp.reference}: mean ${cmp.mean.toFixed(3)}, max ${cmp.max} (signed mean ${cmp.signedMean.toFixed(2)}) worst ${JSON.stringify(cmp.worst)}`,
          );
      }
      if (problems.length > 0) failures.push(`${label(r.case)}: ${problems.join('; ')}`);
    }
  }
  return failures;
}

/** Every failure of the gouraud and flat cases against the brightness bound. */
function brightnessFailures(runs: RunResult[]): string[] {
  const failures: string[] = [];
  for (const run of runs) {
    for (const r of run.results) {
      for (const cmp of r.comparisons) {
        const problems: string[] = [];
        if (cmp.coverageMismatch !== 0) problems.push(`coverage differs on ${cmp.coverageMismatch} px`);
        const bound = BRIGHTNESS[r.case.shading as 'gouraud' | 'flat'];
        if (Math.abs(cmp.signedMean) > bound.bias || cmp.mean > bound.mean)
          problems.push(`signed mean ${cmp.signedMean.toFixed(2)}, mean ${cmp.mean.toFixed(2)}`);
        if (problems.length > 0)
          failures.push(`${label(r.case)} vs ${cmp.reference}: ${problems.join('; ')}`);
      }
    }
  }
  return failures;
}

/**
 * What makes the comparison mean something: every case draws enough pixels, nothing saturates (three's picture
 * stays below 255), three's two materials draw the same pixels, and fog, map and vertex colours
 * each change three's picture (so ShadingMaterial had to apply them to match).
 */
function sanity(runs: RunResult[]): string[] {
  const failures: string[] = [];
  const byLabel = new Map(runs.flatMap((run) => run.results.map((r) => [label(r.case), r] as const)));
  for (const r of byLabel.values()) {
    const [phong, lambert] = r.comparisons;
    if (phong.compared < 2500) failures.push(`${label(r.case)}: only ${phong.compared} px compared`);
    if (phong.covered !== lambert.covered)
      failures.push(`${label(r.case)}: three's materials' coverage differs`);
    if (r.referenceMax >= 255) failures.push(`${label(r.case)}: three's picture saturates`);
    if (r.referenceMean < 25) failures.push(`${label(r.case)}: three's picture is nearly black`);
    const plainCase = r.case.fog === 'none' && r.case.surface === 'plain';
    if (!plainCase && (r.changeFromPlain === null || r.changeFromPlain < 4))
      failures.push(
        `${label(r.case)}: three's picture differs from the plain unfogged one by ${r.changeFromPlain}/255 only`,
      );
  }
  return failures;
}

for (const renderer of ['webgl', 'webgpu', 'webgl2'] as const) {
  const who =
    renderer === 'webgl'
      ? 'WebGLRenderer: ShadingMaterial = MeshPhongMaterial({ specular: 0 }) and MeshLambertMaterial'
      : `WebGPURenderer's ${renderer === 'webgpu' ? 'WebGPU' : 'WebGL2'} backend: ShadingNodeMaterial = MeshPhongNodeMaterial({ specular: 0 }) and MeshLambertNodeMaterial`;
  test(`${who} under three's five lights alone and together, in no fog, Fog and FogExp2, plain, mapped and vertex-coloured, on a sphere and a torus knot: mean ≤ 1/255, max ≤ 3/255 (sRGB) away from silhouettes, same coverage; gouraud and flat as bright`, async ({
    page,
  }) => {
    test.setTimeout(180_000);
    const problems = await open(page);
    const runs = await runAll(page, renderer, PHONG_CASES);
    const brightness = await runAll(page, renderer, BRIGHTNESS_CASES);
    console.log(summary(renderer, [...runs, ...brightness]));
    for (const run of [...runs, ...brightness]) {
      if (renderer === 'webgpu')
        expect(run.backend).toEqual({ isWebGPUBackend: true, isWebGLBackend: false, device: true });
      if (renderer === 'webgl2')
        expect(run.backend).toMatchObject({ isWebGPUBackend: false, isWebGLBackend: true });
    }
    expect(sanity(runs), 'the cases mean something').toEqual([]);
    expect(phongFailures(runs), 'phong-shaded cases beyond the bound').toEqual([]);
    expect(brightnessFailures(brightness), 'gouraud and flat brightness').toEqual([]);
    expect(problems).toEqual([]);
  });
}
