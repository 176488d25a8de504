// Issue 23's "the lighting itself", on WebGLRenderer in headless Chromium (SwiftShader): the vertex-heavy variant of
// the realistic scene (bench/harness/realistic-scene.ts with the level-3 icosahedron sphere: 1,280 triangles a
// sphere, 1,000 instances, three's three PointLights and DirectionalLight, linear fog, 1280×720) wearing
// MeshBasicMaterial (the unlit floor: the same vertices, instancing, fog and output, no lighting),
// MeshPhongMaterial and ShadingMaterial (phong shading with Phong and with Blinn-Phong lighting; gouraud), the
// variants interleaved frame by frame (bench/harness/lighting-bench.ts), so that load from
// other processes hits all of them alike.
// - frame time / MeshPhongMaterial's, the median of the ratios of frames from the same cycle;
// - the lighting above the floor, (frame − MeshBasic's) / (MeshPhong's − MeshBasic's), frames of one cycle, the
//   median over the cycles (and the same of the medians). Target: ShadingMaterial phong ≤ 0.9.
// Only this bench's own page is built (not the playground): vite builds bench/harness/lighting-bench.html.
//
//   node bench/lighting.bench.mjs [--json PATH] [--frames 40]
// The smallest run: --frames 2.
import { createReadStream, existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { build } from 'vite';
import { chromiumArgs, chromiumExecutable } from '../scripts/browser.mjs';
import { arg, summarize, writeResults } from './lib/bench.mjs';
import { recordBrowser } from './lib/meta.mjs';

const frames = Number(arg('--frames', '40'));
/** Clock ticks per second of /proc's CPU times (USER_HZ, 100 on Linux). */
const TICKS_PER_SECOND = 100;
const root = fileURLToPath(new URL('..', import.meta.url));

/** @typedef {import('./harness/lighting-bench').LightingVariant} LightingVariant */
const FLOOR = 'MeshBasicMaterial (unlit floor)';
const PHONG = 'MeshPhongMaterial';
/** @type {Array<[string, LightingVariant]>} */
const variants = [
  [FLOOR, { kind: 'three-basic' }],
  [PHONG, { kind: 'three-phong' }],
  ['ShadingMaterial phong, Phong lighting', { kind: 'shadelab', shading: 'phong', lighting: 'phong' }],
  [
    'ShadingMaterial phong, Blinn-Phong lighting',
    { kind: 'shadelab', shading: 'phong', lighting: 'blinn-phong' },
  ],
  ['ShadingMaterial gouraud, Phong lighting', { kind: 'shadelab', shading: 'gouraud', lighting: 'phong' }],
];
const TARGET = 'ShadingMaterial phong, Phong lighting';

// Build this bench's page alone, as bench/harness/vite.config.ts builds the pages (the packages' sources).
const outDir = mkdtempSync(join(tmpdir(), 'shadelab-lighting-'));
const packages = ['sphere', 'camera', 'trackball', 'material', 'reference'];
await build({
  configFile: false,
  root: join(root, 'bench'),
  publicDir: false,
  logLevel: 'warn',
  resolve: {
    alias: Object.fromEntries(
      packages.map((name) => [`@shadelab/${name}`, join(root, 'packages', name, 'src')]),
    ),
    dedupe: ['three'],
  },
  build: {
    target: 'es2022',
    outDir,
    emptyOutDir: true,
    chunkSizeWarningLimit: 2000,
    rollupOptions: { input: { 'harness/lighting-bench': join(root, 'bench/harness/lighting-bench.html') } },
  },
});
const server = createServer((req, res) => {
  const path = new URL(req.url ?? '/', 'http://x').pathname;
  const file = join(outDir, path);
  if (path.includes('..') || !existsSync(file)) {
    res.writeHead(404).end();
    return;
  }
  res.writeHead(200, { 'content-type': path.endsWith('.html') ? 'text/html' : 'text/javascript' });
  createReadStream(file).pipe(res);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(undefined)));
const address = server.address();
const port = typeof address === 'object' && address ? address.port : 0;
const browser = await chromium.launch({
  executablePath: chromiumExecutable() ?? undefined,
  args: chromiumArgs,
});
recordBrowser(`Chromium ${browser.version()}`);
const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
await page.goto(`http://127.0.0.1:${port}/harness/lighting-bench.html`);
await page.waitForFunction(() => document.body.dataset.ready === '1');

/**
 * CPU seconds used so far by this script's child processes (the browser, its GPU process where SwiftShader draws,
 * its renderer): utime + stime of every live descendant, from /proc. What a frame costs in CPU time does not
 * depend on how much of the machine other work takes, where its wall time does.
 */
function cpuSeconds() {
  /** @type {Map<number, number[]>} */
  const children = new Map();
  /** @type {Map<number, number>} */
  const ticks = new Map();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    let stat;
    try {
      stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
    } catch {
      continue; // ended meanwhile
    }
    const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    const pid = Number(entry);
    const parent = Number(fields[1]);
    children.set(parent, [...(children.get(parent) ?? []), pid]);
    ticks.set(pid, Number(fields[11]) + Number(fields[12]));
  }
  let total = 0;
  const stack = [...(children.get(process.pid) ?? [])];
  while (stack.length > 0) {
    const pid = /** @type {number} */ (stack.pop());
    total += ticks.get(pid) ?? 0;
    stack.push(...(children.get(pid) ?? []));
  }
  return total / TICKS_PER_SECOND;
}

/** Every timed frame of each variant, in cycle order (frame i of every variant comes from cycle i): wall ms, CPU ms. */
const wall = variants.map(() => /** @type {number[]} */ ([]));
const cpu = variants.map(() => /** @type {number[]} */ ([]));
const triangles = await page.evaluate((a) => window.lightingBench.prepare(a.variants, a.warmup), {
  variants: variants.map(([, v]) => v),
  warmup: 3,
});
for (let i = 0; i < frames; i++) {
  for (let k = 0; k < variants.length; k++) {
    const c0 = cpuSeconds();
    wall[k].push(await page.evaluate((n) => window.lightingBench.frame(n), k));
    cpu[k].push((cpuSeconds() - c0) * 1000);
  }
  if ((i + 1) % 10 === 0) console.log(`${i + 1}/${frames} cycles`);
}
await browser.close();
server.close();
rmSync(outDir, { recursive: true, force: true });

const median = (/** @type {number[]} */ xs) => summarize(xs).median;
const at = (/** @type {string} */ name) => variants.findIndex(([n]) => n === name);
/**
 * Each variant's frames against MeshPhongMaterial's: the median of the same-cycle ratios (and the ratio of the
 * medians), of the frame and of the lighting above the floor. @param {number[][]} times
 */
function ratios(times) {
  const floor = times[at(FLOOR)];
  const phong = times[at(PHONG)];
  return variants.map(([name], k) => {
    const f = times[k];
    return {
      frame: { paired: median(f.map((t, i) => t / phong[i])), median: median(f) / median(phong) },
      lighting:
        name === FLOOR
          ? null
          : {
              paired: median(f.map((t, i) => (t - floor[i]) / (phong[i] - floor[i]))),
              median: (median(f) - median(floor)) / (median(phong) - median(floor)),
            },
    };
  });
}
const wallRatios = ratios(wall);
const cpuRatios = ratios(cpu);
/** @type {Record<string, any>} */
const rows = {};
variants.forEach(([name], k) => {
  rows[name] = {
    frameMs: summarize(wall[k]),
    cpuMs: summarize(cpu[k]),
    trianglesPerFrame: triangles[k],
    vsMeshPhong: wallRatios[k].frame,
    lightingVsMeshPhong: wallRatios[k].lighting,
    cpuVsMeshPhong: cpuRatios[k].frame,
    cpuLightingVsMeshPhong: cpuRatios[k].lighting,
  };
});
const target = rows[TARGET].lightingVsMeshPhong;
const cpuTarget = rows[TARGET].cpuLightingVsMeshPhong;
const results = {
  scene:
    '1,000 instances (10 × 10 × 10, spacing 3) of the level-3 icosahedron sphere (1,280 triangles, 642 vertices, indexed, smooth normals), instanceColor, three PointLights (decay 2) and a DirectionalLight, linear Fog, perspective camera 50°, 1280×720; every material grey 0.6 (ka = kd = colour), specular ks 0.5, shininess 32',
  note: 'The machine was shared with other work during the run (2 cores; load average in meta): the same-cycle ratios are the result, the absolute milliseconds are not.',
  width: 1280,
  height: 720,
  frames,
  floor: FLOOR,
  rows,
  target: {
    variant: TARGET,
    measure: 'lighting above the unlit floor / MeshPhongMaterial’s, median over the cycles',
    ratio: target.paired,
    cpuRatio: cpuTarget.paired,
    target: '≤ 0.9',
    met: target.paired <= 0.9,
  },
};
const cell = (/** @type {{ paired: number, median: number } | null} */ x) =>
  x ? `${x.paired.toFixed(3)} (${x.median.toFixed(3)})` : '—';
console.log(
  '| variant | wall ms | CPU ms | / MeshPhong (wall; CPU) | lighting above the floor / MeshPhong’s (wall; CPU) |',
);
console.log('| --- | ---: | ---: | ---: | ---: |');
for (const [name, row] of Object.entries(rows)) {
  console.log(
    `| ${name} | ${row.frameMs.median.toFixed(1)} | ${row.cpuMs.median.toFixed(1)} | ${cell(row.vsMeshPhong)}; ${cell(row.cpuVsMeshPhong)} | ${cell(row.lightingVsMeshPhong)}; ${cell(row.cpuLightingVsMeshPhong)} |`,
  );
}
writeResults(results);
