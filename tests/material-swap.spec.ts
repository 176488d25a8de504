import { expect, type Page } from '@playwright/test';
import type { Shading } from '@shadelab/material';
import type { CaseReport, MaterialMode, SwapRun } from './harness/swap';
import { test, timedLoad } from './harness-helpers';

// Issue 22: swapMaterials on glTF models built in code (three's GLTFExporter, binary GLB) and loaded back with
// GLTFLoader, nothing downloaded: a textured mesh, a vertex-coloured mesh, a skinned mesh posed by its clip
// (AnimationMixer at a fixed time), instances (EXT_mesh_gpu_instancing), a multi-material box as glTF gives it (a
// Group, one Mesh per primitive) and merged back into one mesh with groups and a material array, two meshes
// sharing one material, a ShaderMaterial mesh added after loading, an unlit mesh (KHR_materials_unlit) and a
// clearcoat one (KHR_materials_clearcoat). One 800 × 320 render shows every model in its own 160 px cell, lit by
// three's Hemisphere, Ambient, Directional, Point and Spot lights. three's own pictures are the oracle
// (tests/harness/swap.ts).

/** Opens the page and collects page errors and console errors for the whole test. */
async function open(page: Page): Promise<string[]> {
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await timedLoad(async () => {
    await page.goto('/harness/?page=swap');
    await page.waitForFunction(() => document.body.dataset.ready === '1');
  });
  return errors;
}

/** The swap options these tests vary (a plain type: Playwright's argument types cannot walk the whole options). */
interface Options {
  shading?: Shading;
  celBands?: number;
}

const run = (page: Page, mode: MaterialMode, options: Options = {}): Promise<SwapRun> =>
  page.evaluate((a) => window.swapHarness.run(a.mode, a.options), { mode, options });

/** Logs the case numbers, and attaches both pictures of `mode` (default options) to the report, to look at. */
async function attach(page: Page, r: SwapRun): Promise<void> {
  const shots: Record<string, string> = Object.keys(r.options).length
    ? {}
    : await page.evaluate((m) => window.swapHarness.pictures(m), r.mode);
  for (const [name, url] of Object.entries(shots)) {
    await test.info().attach(`${r.mode}-${name}.png`, {
      body: Buffer.from(url.slice(url.indexOf(',') + 1), 'base64'),
      contentType: 'image/png',
    });
  }
  const rows = r.cases.map(
    (c) =>
      `${c.name}: covered ${c.swap.covered}, compared ${c.swap.compared}, mean ${c.swap.mean.toFixed(3)}, max ${c.swap.max}, changed ${c.swap.diffPixels}`,
  );
  console.log(`[${r.mode} ${JSON.stringify(r.options)}] ${rows.join('; ')}`);
}

/** What every swap must do, whatever the originals: the objects, skipped, warnings, coverage and restore(). */
function expectSwapAndRestore(r: SwapRun): void {
  const at = `[${r.mode}${Object.keys(r.options).length ? ` ${JSON.stringify(r.options)}` : ''}]`;
  expect(r.borderCovered, `${at} the models stay inside their cells`).toBe(0);
  expect.soft(r.failures, `${at} references, sharing, order and disposal`).toEqual([]);
  expect.soft(r.made, `${at} one ShadingMaterial per distinct original material`).toBe(r.distinctOriginals);
  expect
    .soft(r.skipped, `${at} skipped: the ShaderMaterial mesh only, with its reason`)
    .toEqual([
      { object: 'shaderMesh', material: 'ShaderMaterial', reason: expect.stringContaining('ShaderMaterial') },
    ]);
  expect
    .soft(r.swapWarnings.length, `${at} one console.warn for the swap: ${r.swapWarnings.join(' | ')}`)
    .toBe(1);
  expect
    .soft(r.swapWarnings.join(''), `${at} the warning names what was skipped`)
    .toContain('ShaderMaterial');
  expect.soft(r.restoreWarnings, `${at} restore() warns about nothing`).toEqual([]);
  for (const c of r.cases) {
    const info = `${at} ${c.name}: ${JSON.stringify(c)}`;
    expect.soft(c.swap.covered, `${info}\n(enough pixels drawn)`).toBeGreaterThan(1500);
    expect
      .soft(c.swap.coverageMismatches, `${c.name} ${at}: coverage after swap equals three's\n${info}`)
      .toBe(0);
    expect
      .soft(c.restore.diffPixels, `${c.name} ${at}: restore() gives the original picture\n${info}`)
      .toBe(0);
  }
  expect.soft(r.restoreDiffPixels, `${at} the whole picture after restore()`).toBe(0);
  expect.soft(r.restoreMaxDiff, `${at} the whole picture after restore()`).toBe(0);
  // Unlit: the ShadingMaterial draws colour × texel through its emissive, as three's MeshBasicMaterial does.
  const unlit = r.cases.find((c) => c.name === 'unlit') as CaseReport;
  const unlitInfo = `unlit ${at}: ${JSON.stringify(unlit.swap)}`;
  expect.soft(unlit.swap.mean, `unlit ${at}: mean max|Δ| ≤ 1/255\n${unlitInfo}`).toBeLessThanOrEqual(1);
  expect.soft(unlit.swap.max, `unlit ${at}: max|Δ| ≤ 3/255\n${unlitInfo}`).toBeLessThanOrEqual(3);
  const shader = r.cases.find((c) => c.name === 'shader') as CaseReport;
  expect.soft(shader.swap.diffPixels, `${at} the skipped ShaderMaterial mesh is drawn as before`).toBe(0);
}

test('swapMaterials on the loaded glTF models (the Standard, Physical and Basic materials GLTFLoader makes; default, flat and Gouraud cel shading): coverage, skipped, restore()', async ({
  page,
}) => {
  const errors = await open(page);
  const loaded = await page.evaluate(() => window.swapHarness.loaded);
  // What the round trip gave: the test is about these objects, so check they are what the test says they are.
  expect(loaded).toEqual({
    instanced: true,
    instanceColors: true,
    skinned: true,
    animations: 1,
    multiPrimitivesChildren: 6,
    sharedLoadedShared: true,
    unlitType: 'MeshBasicMaterial',
    physicalType: 'MeshPhysicalMaterial',
    extensionsUsed: expect.arrayContaining([
      'EXT_mesh_gpu_instancing',
      'KHR_materials_unlit',
      'KHR_materials_clearcoat',
    ]),
  });
  const r = await run(page, 'standard');
  await attach(page, r);
  console.log(`skipped: ${JSON.stringify(r.skipped)}; warned: ${JSON.stringify(r.swapWarnings)}`);
  expectSwapAndRestore(r);
  // The other shadings draw the same pixels' coverage too (flat shading reads each face's corners its own way).
  for (const options of [{ shading: 'flat' }, { shading: 'gouraud', celBands: 3 }] as const) {
    const other = await run(page, 'standard', options);
    await attach(page, other);
    expectSwapAndRestore(other);
  }
  expect(errors).toEqual([]);
});

test('swapMaterials on MeshLambert and MeshPhong (specular 0) originals: diffuse pixels within 1/255 mean, 3/255 max away from silhouettes', async ({
  page,
}) => {
  const errors = await open(page);
  for (const mode of ['lambert', 'phong'] as const) {
    const r = await run(page, mode);
    await attach(page, r);
    expectSwapAndRestore(r);
    for (const c of r.cases) {
      if (c.name === 'shader') continue;
      const info = `${c.name} [${mode}]: ${JSON.stringify(c.swap)}`;
      expect.soft(c.swap.compared, `${info}\n(enough pixels compared)`).toBeGreaterThan(1000);
      expect.soft(c.swap.mean, `${c.name} [${mode}]: mean max|Δ| ≤ 1/255\n${info}`).toBeLessThanOrEqual(1);
      expect.soft(c.swap.max, `${c.name} [${mode}]: max|Δ| ≤ 3/255\n${info}`).toBeLessThanOrEqual(3);
    }
  }
  expect(errors).toEqual([]);
});

// A rendered cycle compiles the swapped scene's six programs again (restore() disposed the materials, so three
// released them): 0.45 … 0.75 s under SwiftShader on this shared 2-core machine, so rendering every cycle would
// take 8 … 12 minutes. A render every 50 cycles (20 compile and release rounds, 41 frames) keeps a run at 10 … 40 s;
// every cycle checks that what it made was disposed once and nothing else was.
const CYCLES = 1000;
const EVERY = 50;

for (const [label, options] of [
  ['default options', {}],
  ["shading 'flat'", { shading: 'flat' }],
] as const) {
  test(`1,000 swap/restore cycles (${label}) on the loaded models end at the renderer.info baseline`, async ({
    page,
  }) => {
    test.setTimeout(180_000);
    const errors = await open(page);
    let residual = 0;
    if (options.shading === 'flat') {
      // Flat shading of a non-indexed geometry (the icosahedron of the instances) reads a face texture that
      // ShadingMaterial caches per geometry and frees when the geometry is disposed, not when the material is:
      // the first swap leaves it behind, bounded (one per non-indexed geometry), and no cycle after adds to it.
      const warm = await page.evaluate((o) => window.swapHarness.cycles(1, 1, o), options);
      residual = warm.after.textures - warm.before.textures;
      console.log(
        `flat warm-up cycle: before ${JSON.stringify(warm.before)}, after ${JSON.stringify(warm.after)}`,
      );
      expect(
        residual,
        "at most the one non-indexed geometry's face texture is left by a flat swap",
      ).toBeLessThanOrEqual(1);
    }
    const start = Date.now();
    const r = await page.evaluate((a) => window.swapHarness.cycles(a.n, a.every, a.options), {
      n: CYCLES,
      every: EVERY,
      options,
    });
    const line = `${label}, ${CYCLES} cycles, a render every ${EVERY}: ${r.frames} frames in ${Date.now() - start} ms (the loop's own JS ${Math.round(r.ms)} ms, the GPU work finishing at the last read-back); before ${JSON.stringify(r.before)}, peak ${JSON.stringify(r.peak)}, after ${JSON.stringify(r.after)}${residual ? ` (the warm-up left ${residual} texture)` : ''}`;
    console.log(line);
    test.info().annotations.push({ type: 'swap cycles', description: line });
    expect(r.failures).toEqual([]);
    expect(r.after, line).toEqual(r.before);
    // Not vacuous: the swapped scene compiled programs of its own, all released by restore().
    expect(r.peak.programs, line).toBeGreaterThan(r.before.programs);
    expect(r.frames, line).toBeGreaterThan((2 * CYCLES) / EVERY);
    expect(r.distinctOriginals, '13 materials: 1 a model, 3 a box, 1 for the shared pair').toBe(13);
    expect(r.made, 'one made material per distinct original, every swap').toBe(r.distinctOriginals * CYCLES);
    expect(r.disposedOnce, 'every made material disposed exactly once by its restore()').toBe(r.made);
    expect(r.userDisposals, 'nothing the user owns disposed').toBe(0);
    expect(r.warnings, 'one console.warn a swap (the ShaderMaterial mesh), none from restore()').toBe(CYCLES);
    expect(errors).toEqual([]);
  });
}
