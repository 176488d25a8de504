import { describe, expect, it } from 'vitest';
import { int, renderBenchmarks, table } from '../../scripts/benchmarks.mjs';

// BENCHMARKS.md's renderer (scripts/benchmarks.mjs) on small hand-made results: each table row it prints is the
// one the JSON holds, formatted as the READMEs printed it, and a run's meta (or its absence) shows in Runs.

const timing = (median: number, min = median, max = median) => ({ median, min, max, runs: 5, batch: 1 });
const variant = (ours: number, plain: number, three: number) => ({
  ours: timing(ours),
  plain: timing(plain),
  bytes: 0,
  threeOverOurs: three / ours,
  oursOverPlain: ours / plain,
});

const META = {
  date: '2026-11-23T10:15:30.000Z',
  commit: '0123456789abcdef0123456789abcdef01234567',
  dirty: false,
  machine: { cpus: 2, cpuModel: 'Test CPU', memoryGiB: 8, freeMemoryGiB: 6, platform: 'linux x64' },
  loadavg: [1, 2, 3],
  loadavgEnd: [0.5, 1.5, 2.5],
  node: 'v20.0.0',
  chromium: 'not used',
  three: '0.187.0',
};

const sphere = {
  meta: META,
  quick: false,
  sampleMs: 5,
  normals: 'smooth',
  builds: [
    {
      base: 'tetrahedron',
      level: 8,
      triangles: 262144,
      threeDetail: 113,
      threeTriangles: 259920,
      three: timing(342.4),
      indexed: variant(5.55, 3.71, 342.4),
      nonIndexed: variant(19.1, 12.4, 342.4),
    },
  ],
  errors: [
    { base: 'tetrahedron', level: 0, triangles: 4, error: 2 / 3, errorTimesTriangles: 8 / 3 },
    { base: 'octahedron', level: 0, triangles: 8, error: 0.42264973, errorTimesTriangles: 3.38119784 },
  ],
  budgets: [
    {
      budget: 0.5,
      picks: [null, { base: 'octahedron', level: 0, triangles: 8 }],
      best: { base: 'octahedron', level: 0, triangles: 8 },
    },
  ],
  errorCost: [
    { base: 'tetrahedron', levels: '0-10', firstCallMs: 33.04 },
    { base: 'octahedron', levels: '0-10', firstCallMs: 0.123 },
  ],
};

const size = {
  meta: { ...META, dirty: true },
  rows: [
    {
      package: '@shadelab/sphere',
      entry: '@shadelab/sphere',
      measure: 'whole entry',
      minified: 10471,
      gzipped: 3786,
      budget: 4096,
      ok: true,
    },
    {
      package: '@shadelab/sphere',
      entry: '@shadelab/sphere/detail',
      measure: 'whole entry',
      minified: 18279,
      gzipped: 6480,
      budget: null,
      ok: true,
    },
    {
      package: '@shadelab/sphere',
      entry: '@shadelab/sphere/detail',
      measure: 'added to main',
      minified: 8214,
      gzipped: 2801,
      budget: 4096,
      ok: true,
    },
    {
      package: '@shadelab/camera',
      entry: '@shadelab/camera',
      measure: 'whole entry',
      minified: 12342,
      gzipped: 4140,
      budget: 4096,
      ok: false,
    },
    {
      package: '@shadelab/sphere',
      entry: '@shadelab/sphere (all entries)',
      measure: 'total',
      minified: 21618,
      gzipped: 7494,
      budget: null,
      ok: true,
    },
  ],
};

const cameraDepth = {
  method: 'a test method',
  rows: [
    {
      mode: 'standard',
      active: 'standard',
      ratio: 100,
      near: 0.04,
      far: 4,
      z: 1,
      minSeparation: 0.0000025118864,
    },
    { mode: 'standard', active: 'standard', ratio: 1e9, near: 0.01, far: 1e7, z: 1, minSeparation: 'lost' },
    { mode: 'reversed', active: 'reversed', ratio: 100, near: 0.04, far: 4, z: 1, minSeparation: 6.3e-8 },
    { mode: 'reversed', active: 'reversed', ratio: 1e9, near: 0.01, far: 1e7, z: 1, minSeparation: 1e-10 },
  ],
};

const lines = (page: string) => page.split('\n');

describe('renderBenchmarks', () => {
  const page = renderBenchmarks({ sphere, size, 'camera-depth': cameraDepth });

  it('prints the sphere build row and the target as the bench computed them', () => {
    expect(lines(page)).toContain(
      '| tetrahedron | 8 | 262,144 | 5.55 | 3.71 | 19.1 | 12.4 | 342 (113 → 259,920) | 62× | 1.5× | 18× | 1.5× |',
    );
    expect(page).toContain(
      'Target (indexed level 8 tetrahedron, 262,144 triangles): 62× faster than three (goal ≥ 10×), 1.5× the plain write (goal ≤ 5×): **met**.',
    );
  });

  it('prints the error table, the budget picks and the sphereError cost', () => {
    expect(lines(page)).toContain('| 0 | 4 | 6.667e-1 | 2.667 | 8 | 4.226e-1 | 3.381 |');
    expect(lines(page)).toContain('| 5e-1 | > L0 | L0: 8 | octahedron L0 |');
    expect(lines(page)).toContain('| tetrahedron | 33.0 |');
    expect(lines(page)).toContain('| octahedron | 0.12 |');
  });

  it('prints every size entry with its whole-entry gzip, what a subpath adds, and the budget verdict', () => {
    expect(lines(page)).toContain('| `@shadelab/sphere` | 10,471 B | 3,786 B |  | 4,096 B | yes |');
    expect(lines(page)).toContain(
      '| `@shadelab/sphere/detail` | 18,279 B | 6,480 B | 2,801 B | 4,096 B | yes |',
    );
    expect(lines(page)).toContain('| `@shadelab/camera` | 12,342 B | 4,140 B |  | 4,096 B | **no** |');
    expect(page).toContain('All entries of a package together: `@shadelab/sphere` 7,494 B.');
  });

  it('prints depth separations per far/near, a lost order as > 1 and the near plane of each cell', () => {
    expect(lines(page)).toContain('| mode | far/near 1e2 | 1e9 |');
    expect(lines(page)).toContain('| _near_ | _0.04_ | _0.01_ |');
    expect(lines(page)).toContain('| standard | 2.5e-6 | > 1 |');
    expect(lines(page)).toContain('| reversed | 6.3e-8 | ≤ 1e-9 |');
  });

  it("shows each run's meta in Runs, and 'not recorded' where a file has none", () => {
    const runs = lines(page).filter((l) => l.startsWith('| ['));
    expect(runs).toContain(
      '| [`sphere.json`](bench/results/sphere.json) | [`bench/sphere.bench.mjs`](bench/sphere.bench.mjs) | 2026-11-23 10:15 UTC | `0123456` | 2 × Test CPU, 8 GiB, linux x64 | 1.00 / 2.00 / 3.00 → 0.50 / 1.50 / 2.50 | v20.0.0 | not used | 0.187.0 |',
    );
    expect(runs.find((l) => l.startsWith('| [`size.json`]'))).toContain('`0123456` + uncommitted changes');
    expect(runs.find((l) => l.startsWith('| [`camera-depth.json`]'))).toBe(
      '| [`camera-depth.json`](bench/results/camera-depth.json) | [`bench/camera-depth.bench.mjs`](bench/camera-depth.bench.mjs) | _not recorded_ | _not recorded_ | _not recorded_ | _not recorded_ | _not recorded_ | _not recorded_ | _not recorded_ |',
    );
    expect(page).toContain('run of _not recorded_ (commit not recorded;');
  });

  it('says which command writes a section whose results are not committed', () => {
    expect(page).toContain(
      '## Tarballs\n\n_No committed results: `node scripts/pack.mjs --json bench/results/pack.json` writes them._',
    );
    expect(page).toContain(
      '## Trackball\n\n_No committed results: `npm run bench -- trackball` writes them._',
    );
  });

  it('gives the same page for the same results', () => {
    expect(renderBenchmarks(structuredClone({ sphere, size, 'camera-depth': cameraDepth }))).toBe(page);
  });
});

describe('renderBenchmarks: Material on WebGPURenderer', () => {
  const timed = (median: number, gpu: number | null) => ({
    frameMs: timing(median, median - 1, median + 1),
    gpuMs: gpu === null ? null : timing(gpu),
  });
  const pair = (paired: number, median: number, gpu: number | null = null) => ({
    paired,
    median,
    min: median,
    gpu,
  });
  const webgpu = {
    meta: META,
    note: 'Shared machine.',
    width: 1280,
    height: 720,
    frames: 60,
    rounds: 6,
    scene: 'the lecture scene',
    perBackend: {
      webgpu: {
        label: 'WebGPURenderer (WebGPU)',
        material: 'ShadingNodeMaterial',
        threePhong: 'MeshPhongNodeMaterial',
        gpuTimer: "three's trackTimestamp (timestamp-query)",
        variants: {
          'phong × phong': {
            ...timed(20, 18),
            vsThreePhong: pair(0.84, 0.82, 0.81),
            vsWebGLRenderer: pair(1.5, 1.42),
          },
          'gouraud × phong': { error: 'no adapter' },
          'three phong': { ...timed(24, 22), vsThreePhong: null, vsWebGLRenderer: pair(1.45, 1.4) },
        },
      },
      webgl: {
        label: 'WebGLRenderer',
        material: 'ShadingMaterial',
        threePhong: 'MeshPhongMaterial',
        gpuTimer: 'not available (no EXT_disjoint_timer_query_webgl2)',
        variants: {
          'phong × phong': { ...timed(16, null), vsThreePhong: pair(0.8, 0.81), vsWebGLRenderer: null },
          'three phong': { ...timed(20, null), vsThreePhong: null, vsWebGLRenderer: null },
        },
      },
    },
    targets: {
      'webgpu: phong × phong': { ratio: pair(0.84, 0.82, 0.81), target: '≤ 1.0', met: true },
      'webgl2: phong × phong': { ratio: pair(1.01, 1.03), target: '≤ 1.0', met: false },
    },
  };
  const page = renderBenchmarks({ webgpu });

  it("prints each renderer's rows with three's phong material named for that renderer", () => {
    expect(page).toContain('### WebGPURenderer (WebGPU): `ShadingNodeMaterial` and `MeshPhongNodeMaterial`');
    expect(lines(page)).toContain('| phong × phong | 20.0 (19.0) | 18.0 | 0.84 (0.82) | 1.50 (1.42) |');
    expect(lines(page)).toContain('| MeshPhongNodeMaterial | 24.0 (23.0) | 22.0 | — | 1.45 (1.40) |');
    expect(lines(page)).toContain('| gouraud × phong | does not render | — | — | — |');
    expect(page).toContain('- WebGPURenderer (WebGPU), gouraud × phong does not render: no adapter');
    expect(lines(page)).toContain('| MeshPhongMaterial | 20.0 (19.0) | n/a | — |');
  });

  it('says where GPU time comes from, and the target per backend with its GPU-time ratio', () => {
    expect(page).toContain(
      "GPU ms: the median of WebGPURenderer (WebGPU): three's trackTimestamp (timestamp-query); WebGLRenderer: not available (no EXT_disjoint_timer_query_webgl2).",
    );
    expect(lines(page)).toContain('| WebGPU: phong × phong | 0.84 (0.82) | 0.81 | ≤ 1.0 | met |');
    expect(lines(page)).toContain('| WebGL2: phong × phong | 1.01 (1.03) | n/a | ≤ 1.0 | **not met** |');
  });
});

describe('renderBenchmarks: the playground before and after issue 17', () => {
  const refactor = {
    meta: META,
    before: { commit: '61841d5', bundle: { raw: 1_000_000, gzip: 300_000 }, firstFrameMs: [700, 720, 710] },
    after: { commit: 'abcdef0', bundle: { raw: 1_050_000, gzip: 340_000 }, firstFrameMs: [730, 740, 735] },
    viewport: { width: 800, height: 600 },
    rounds: 3,
    ratios: { bundleGzip: 340_000 / 300_000, bundleRaw: 1.05, firstFrame: 1.03 },
  };

  it('prints both builds, the ratios and the 10 % verdict of each row', () => {
    const page = renderBenchmarks({ 'playground-refactor': refactor });
    expect(page).toContain('### Before and after issue 17');
    expect(page).toContain('| `index.html` bundle, gzip -9 | 300.0 kB | 340.0 kB | 1.133 | **no** |');
    expect(page).toContain('| `index.html` bundle, raw | 1,000.0 kB | 1,050.0 kB | 1.050 | yes |');
    expect(page).toContain('| first frame, median | 710 ms | 735 ms | 1.030 | yes |');
  });
});

describe('formatting', () => {
  it('groups thousands with commas whatever the locale', () => {
    expect([int(0), int(999), int(1000), int(-1234567), int(1234.5)]).toEqual([
      '0',
      '999',
      '1,000',
      '-1,234,567',
      '1,234.5',
    ]);
  });

  it('writes a Markdown table with the alignment asked', () => {
    expect(table(['a', 'b'], 'lr', [['x', 1]])).toEqual(['| a | b |', '| --- | ---: |', '| x | 1 |']);
  });
});
