// Size budget, minified and gzipped, without dependencies (three; @shadelab/material for @shadelab/reference,
// which has its own row; @playwright/test and Node's built-ins for @shadelab/playwright; react and
// @react-three/fiber for @shadelab/react, which wraps the other packages and counts only its own code), of every entry point of every package, read from the package.json `exports` maps so
// that a new entry is measured without editing this file:
// - a main entry (`@shadelab/x`): everything it exports, gated at the issue's targets (4 kB, material 8 kB,
//   playwright 10 kB);
// - a subpath (`@shadelab/x/y`): everything it exports, and what it adds to an app that already imports the
//   main entry (the bytes of main + subpath minus those of main), the latter gated at the same target;
// - the package total (all its entries together), reported so that growth is seen.
// `node scripts/size.mjs` checks the budgets; `--json PATH` also writes the numbers (with the run's meta block;
// `--json bench/results/size.json` is what BENCHMARKS.md shows).
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { writeJson } from '../bench/lib/meta.mjs';
import { root } from './setup.mjs';

const packages = ['sphere', 'camera', 'trackball', 'material', 'reference', 'playwright', 'react'];
/**
 * Target per entry, gzipped bytes. @shadelab/playwright runs in Node beside Playwright, never in an app's
 * bundle, and its failure messages are much of it: 10 kB. @shadelab/material ships the GLSL of every scene
 * feature three's chunks bring (instancing, batching, skinning, morphing, clipping, fog, tone mapping, three's
 * lights, both sides) and the CPU shade() of three's lights: a program compiles only what its scene uses, but the
 * text is in the entry (+3.5 kB over the lecture-only 8 kB): 12 kB; then the surface (three's map, vertex colours,
 * emissive, alpha and normal map chunks with their uniforms and validation, the split ka/kd and ks varyings of
 * textured gouraud and flat shading) and flat shading by derivatives, ≈ 1.6 kB more: 14 kB; then shadows (the
 * per-light shadow factors and recorded terms for each of three's shadow-casting light kinds) and view-space
 * lighting, ≈ 1.4 kB more: 16 kB; then flatShadingGeometry for either provoking vertex (WebGL's last, WebGPU's
 * first, and the material's warning for the wrong one) and the option definitions both materials share, ≈ 0.3 kB
 * more: 17 kB; then the swap into an existing scene (toShadingMaterial's mapping of three's six mesh materials,
 * the Material properties it copies, swapMaterials' traversal, skipped reasons, update and restore), ≈ 2.4 kB
 * more: 19.5 kB; then the debugging and teaching outputs (issue 24: the term views and the model normal matrix,
 * their defines and chunks, ≈ 0.8 kB) and one definition of both materials' options (issue 23, ≈ 0.2 kB), 20.7 kB
 * measured: 21 kB (`explainShade`, 1.5 kB, is the opt-in `@shadelab/material/explain`).
 */
const budgetOf = (/** @type {string} */ pkg) => ({ material: 22528, playwright: 10240 })[pkg] ?? 4096;
/**
 * Subpaths with a budget of their own (what they add to the main entry), gzipped bytes:
 * @shadelab/material/webgpu, the two node materials for WebGPURenderer (the shading: TSL lighting model,
 * PhongLight light node, face texture for exact flat shading, both sides in one pass; the ray-cast impostor:
 * bounds in the vertex stage, exact depth; three/webgpu excluded): 6 kB (4 kB held the shading alone); then the
 * surface and the node swap (7.3 kB measured before the parity work) and parity with ShadingMaterial (issue 23:
 * three's shadows recorded per light for vertex-lit shading, the normal map's tangent frame, exact flat shading of
 * skinned, morphed and instanced meshes with their morph, skin and instance reads), +1.8 kB: 9.1 kB measured,
 * 9.5 kB.
 * @shadelab/material/adaptive, AdaptiveShading with its CPU error model (a rasteriser and shade() over sampled
 * directions), the measured cost table, the allocation and the instance groups (@shadelab/sphere external):
 * 7.9 kB measured at its first commit: 8 kB; update()'s cache (per object and instance: the units kept with
 * the matrices they came from, the camera's key, the stats) +0.4 kB: 8.2 kB measured, 8.5 kB.
 */
const subpathBudgets = /** @type {Record<string, number>} */ ({
  '@shadelab/material/webgpu': 9728,
  '@shadelab/material/adaptive': 8704,
});

const tmp = join(root, 'node_modules', '.shadelab-size');
mkdirSync(tmp, { recursive: true });

/** Bundle `export * from` each source file, minified; returns the bytes. */
async function measure(/** @type {string} */ name, /** @type {string[]} */ sources) {
  const entry = join(tmp, `${name.replaceAll(/[^a-z]+/g, '-')}.ts`);
  writeFileSync(entry, sources.map((s) => `export * from ${JSON.stringify(s)};\n`).join(''));
  const result = await build({
    configFile: false,
    logLevel: 'silent',
    root,
    build: {
      write: false,
      minify: true,
      lib: { entry, formats: ['es'], fileName: 'size' },
      // Dependencies are not counted: three (a peer), @shadelab/material in @shadelab/reference (its own row),
      // @playwright/test and Node's built-ins in @shadelab/playwright (it runs in Node, beside Playwright), and
      // react and @react-three/fiber in @shadelab/react (peers, as three).
      rollupOptions: {
        external: (id) =>
          id === 'three' ||
          id.startsWith('three/') ||
          id.startsWith('@shadelab/') ||
          id.startsWith('@playwright/') ||
          id === 'react' ||
          id.startsWith('react/') ||
          id.startsWith('@react-three/') ||
          id.startsWith('node:'),
      },
    },
  });
  const outputs = (Array.isArray(result) ? result : [result]).flatMap((r) => ('output' in r ? r.output : []));
  let minified = 0;
  let gzipped = 0;
  for (const chunk of outputs) {
    if (chunk.type !== 'chunk') continue;
    minified += Buffer.byteLength(chunk.code);
    gzipped += gzipSync(chunk.code, { level: 9 }).length;
  }
  return { minified, gzipped };
}

/** @type {{ package: string, entry: string, measure: string, minified: number, gzipped: number, budget: number | null, ok: boolean }[]} */
const rows = [];
for (const pkg of packages) {
  const manifest = JSON.parse(readFileSync(join(root, 'packages', pkg, 'package.json'), 'utf8'));
  // './impostor' → packages/material/src/impostor.ts ('.' → src/index.ts), as the dist layout mirrors src.
  const entries = Object.keys(manifest.exports)
    .filter((k) => k !== './package.json')
    .map((k) => ({
      name: k === '.' ? manifest.name : `${manifest.name}/${k.slice(2)}`,
      source: join(root, 'packages', pkg, 'src', `${k === '.' ? 'index' : k.slice(2)}.ts`),
    }));
  const budget = budgetOf(pkg);
  const main = await measure(entries[0].name, [entries[0].source]);
  rows.push({
    package: manifest.name,
    entry: entries[0].name,
    measure: 'whole entry',
    ...main,
    budget,
    ok: main.gzipped <= budget,
  });
  for (const sub of entries.slice(1)) {
    const whole = await measure(sub.name, [sub.source]);
    rows.push({
      package: manifest.name,
      entry: sub.name,
      measure: 'whole entry',
      ...whole,
      budget: null,
      ok: true,
    });
    const both = await measure(`${sub.name}+main`, [entries[0].source, sub.source]);
    const added = { minified: both.minified - main.minified, gzipped: both.gzipped - main.gzipped };
    rows.push({
      package: manifest.name,
      entry: sub.name,
      measure: 'added to main',
      ...added,
      budget: subpathBudgets[sub.name] ?? budget,
      ok: added.gzipped <= (subpathBudgets[sub.name] ?? budget),
    });
  }
  if (entries.length > 1) {
    const total = await measure(
      `${manifest.name} total`,
      entries.map((e) => e.source),
    );
    rows.push({
      package: manifest.name,
      entry: `${manifest.name} (all entries)`,
      measure: 'total',
      ...total,
      budget: null,
      ok: true,
    });
  }
}
rmSync(tmp, { recursive: true, force: true });

for (const r of rows) {
  console.log(
    `${r.ok ? 'ok  ' : 'OVER'} ${`${r.entry} (${r.measure})`.padEnd(52)} ${String(r.minified).padStart(7)} B min  ${String(r.gzipped).padStart(6)} B gzip${r.budget === null ? '' : `  (budget ${r.budget} B)`}`,
  );
}
const i = process.argv.indexOf('--json');
// { meta, rows }: bench/results/size.json is what BENCHMARKS.md shows (npm run benchmarks).
if (i >= 0) writeJson(process.argv[i + 1], rows);
process.exit(rows.every((r) => r.ok) ? 0 : 1);
