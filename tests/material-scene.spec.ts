import { createHash } from 'node:crypto';
import { expect, type Page } from '@playwright/test';
import { activeGlsl } from '../playground/src/learn/compiledShader';
import { withoutUseFog } from './glsl-active';
import type { ProgramSource, SceneConfig, SceneInstance, SceneStats } from './harness/material';
import { openHarness, test } from './harness-helpers';

// ShadingMaterial in an ordinary three.js scene (issue 14, phase 1): three's program parameters (instancing,
// batching, skinning, morph targets, fog, clipping, tone mapping, output colour space) through three's shader
// chunks, judged against three's own MeshPhongMaterial for where and whether something is drawn, and against
// shade() for colours. Runs in headless Chromium (SwiftShader) on the material harness page.

async function open(page: Page): Promise<void> {
  await openHarness(page, 'material');
}

function scene(page: Page, config: SceneConfig): Promise<SceneStats> {
  return page.evaluate((c) => window.materialHarness.sceneCompare(c), config);
}

/** Drawn exactly where three's MeshPhongMaterial draws (every pixel whose 3 × 3 neighbourhood is uniform there). */
function expectOracleCoverage(stats: SceneStats, minCovered: number): void {
  const info = JSON.stringify(stats);
  expect(stats.covered, info).toBeGreaterThan(minCovered);
  expect(stats.coverageCompared, info).toBeGreaterThan(30000);
  expect(stats.coverageMismatches, info).toBe(0);
}

/** Colours within 2/255 of shade() away from edges, on enough pixels, and no NaN (black) pixel. */
function expectShade(stats: SceneStats, minCompared: number): void {
  const info = JSON.stringify(stats);
  expect(stats.compared, info).toBeGreaterThan(minCompared);
  expect(stats.maxError, info).toBeLessThanOrEqual(2);
  expect(stats.mismatches, info).toBe(0);
  expect(stats.darkPixels, info).toBe(0);
}

/** The colours of three's own material (its emissive = ka·Ia) on every pixel both draw, away from edges. */
function expectOracleColours(stats: SceneStats, minCompared: number, tolerance = 0): void {
  const info = JSON.stringify(stats);
  expect(stats.oracleCompared, info).toBeGreaterThan(minCompared);
  expect(stats.oracleMaxError, info).toBeLessThanOrEqual(tolerance);
  expect(stats.darkPixels, info).toBe(0);
}

const SHADINGS = [
  ['phong', {}],
  ['phong (analytic sphere normals)', { analytic: true }],
  ['gouraud', { shading: 'gouraud' }],
  ['flat (triangle soup)', { shading: 'flat' }],
  ['flat (flatShadingGeometry)', { shading: 'flat', flatCorners: true }],
] as const;

/** Three instances at x = −2, 0, 2, each with its instanceColor. */
const THREE_INSTANCES: SceneInstance[] = [
  { position: [-2, 0, 0], scale: [0.8, 0.8, 0.8], color: [1, 0.5, 0.25] },
  { position: [0, 0, 0], scale: [0.8, 0.8, 0.8], color: [0.25, 1, 0.5] },
  { position: [2, 0, 0], scale: [0.8, 0.8, 0.8], color: [0.5, 0.25, 1] },
];

const sha = (text: string) => createHash('sha256').update(text).digest('hex').slice(0, 16);

test('a scene without the new features compiles the same programs as before (active GLSL and cache keys)', async ({
  page,
}) => {
  await open(page);
  const programs: ProgramSource[] = await page.evaluate(() => window.materialHarness.programSources());
  expect(programs.length).toBe(74);
  // One line per scene: the cache key (three's parameters and the material's defines; the only difference
  // allowed is `useFog`, true by default like MeshPhongMaterial's, which compiles to nothing without
  // scene.fog) and the hashes of the code the GPU compiles (the preprocessor's active lines, see playground/src/learn/compiledShader.ts).
  const table = programs
    .map(
      (p) =>
        `${p.name} | ${withoutUseFog(p.cacheKey)} | ${sha(activeGlsl(p.vertex))} | ${sha(activeGlsl(p.fragment))}`,
    )
    .join('\n');
  expect(`${table}\n`).toMatchSnapshot('lecture-programs.txt');
  // The README's lecture program in full, for a readable diff.
  const lecture = programs.find((p) => p.name === 'standard phong blinn-phong cel 0 normals');
  expect(lecture).toBeDefined();
  expect(
    `${activeGlsl(lecture?.vertex ?? '')}\n----\n${activeGlsl(lecture?.fragment ?? '')}\n`,
  ).toMatchSnapshot('lecture-program.glsl');
});

for (const [name, variant] of SHADINGS) {
  const config = { shading: 'phong', ...variant } as const;
  const flat = config.shading === 'flat';
  test(`InstancedMesh, ${name}: 3 instances at x = −2, 0, 2 where MeshPhongMaterial draws them; instanceColor × ka, kd = shade()`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { ...config, object: 'instanced', instances: THREE_INSTANCES });
    expectOracleCoverage(stats, 7000);
    expectShade(stats, flat ? 4500 : 6500);
  });

  test(`BatchedMesh, ${name}: 3 instances with colours, where MeshPhongMaterial draws them, colours = shade()`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { ...config, object: 'batched', instances: THREE_INSTANCES });
    expectOracleCoverage(stats, 7000);
    expectShade(stats, flat ? 4500 : 6500);
  });
}

// Deformed meshes carry normals (the analytic sphere normal is the rest sphere's, documented).
for (const [name, variant] of SHADINGS.filter(([n]) => !n.includes('analytic'))) {
  const config = { shading: 'phong', ...variant } as const;
  const flat = config.shading === 'flat';
  test(`SkinnedMesh with a moved bone, ${name}: MeshPhongMaterial's silhouette, colours = shade() of three's CPU skinning`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { ...config, object: 'skinned', bone: 0.7 });
    expectOracleCoverage(stats, 3000);
    expectShade(stats, flat ? 2500 : 3000);
  });

  test(`morph targets at full influence (positions and normals), ${name}: MeshPhongMaterial's silhouette, shade() colours`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { ...config, object: 'morphed' });
    expectOracleCoverage(stats, 4500);
    expectShade(stats, flat ? 3000 : 4000);
  });
}

test('per-instance morph weights (InstancedMesh.setMorphAt) move every instance', async ({ harness }) => {
  const { page } = await harness('material');
  const instances: SceneInstance[] = [
    { position: [-1.5, 0, 0], scale: [0.7, 0.7, 0.7] },
    { position: [1.5, 0, 0], scale: [0.7, 0.7, 0.7] },
  ];
  for (const config of [{ shading: 'phong' }, { shading: 'flat', flatCorners: true }] as const) {
    const stats = await scene(page, { ...config, object: 'instanced-morphed', instances });
    expectOracleCoverage(stats, 4000);
    expectShade(stats, 2500);
  }
});

test('instancing × skinning × flat shading: a skinned mesh with instance matrices (three combines both chunks)', async ({
  harness,
}) => {
  const { page } = await harness('material');
  const instances: SceneInstance[] = [
    { position: [-1.5, 0, 0] },
    { position: [1.5, 0.2, 0], rotation: [0, 0.4, 0.5], scale: [0.8, 1.1, 0.9] },
  ];
  for (const config of [
    { shading: 'flat', flatCorners: true },
    { shading: 'flat' },
    { shading: 'phong' },
    { shading: 'gouraud' },
  ] as const) {
    const stats = await scene(page, { ...config, object: 'instanced-skinned', instances });
    expectOracleCoverage(stats, 6000);
    expectShade(stats, 4500);
  }
});

test('non-uniform and sheared instance matrices: normals through the instance matrix (sign(det)·cofactor), = shade()', async ({
  harness,
}) => {
  const { page } = await harness('material');
  const instances: SceneInstance[] = [
    { position: [-1.8, 0, 0], scale: [0.4, 1.4, 0.8], rotation: [0.3, 0.5, 0.2], color: [1, 0.8, 0.6] },
    { position: [0.2, 0, 0], scale: [1.2, 0.5, 0.9], shear: 0.8 },
    { position: [2, 0, 0], scale: [0.6, 0.6, 1.5], rotation: [-0.4, 0.9, 0], shear: -0.5 },
  ];
  for (const variant of [
    { shading: 'phong', analytic: true },
    { shading: 'gouraud' },
    { shading: 'flat', flatCorners: true },
  ] as const) {
    const stats = await scene(page, { ...variant, object: 'instanced', instances });
    expectOracleCoverage(stats, 5000);
    expectShade(stats, 3500);
  }
});

test('instances that are rotations × scales (mirrored, non-uniform) take the cheaper normal A·(n/|aᵢ|²) and light as the cofactor does, = shade(); one sheared instance puts the mesh back on the cofactor', async ({
  harness,
}) => {
  const { page } = await harness('material');
  const orthogonal: SceneInstance[] = [
    { position: [-2, 0, 0], scale: [0.4, 1.2, 0.8], rotation: [0.3, 0.5, 0.2], color: [1, 0.8, 0.6] },
    { position: [0, 0, 0], scale: [-0.8, 0.5, 0.7], rotation: [0, 0.7, -0.3] },
    { position: [2, 0, 0], scale: [0.6, 0.6, 1.2], rotation: [-0.4, 0.9, 0] },
  ];
  const sheared: SceneInstance[] = [...orthogonal, { position: [0, 0, -40], shear: 0.3 }];
  for (const variant of [
    { shading: 'phong', analytic: true },
    { shading: 'phong' },
    { shading: 'gouraud' },
    { shading: 'flat', flatCorners: true },
  ] as const) {
    const fast = await scene(page, { ...variant, object: 'instanced', instances: orthogonal });
    expect(fast.defines, variant.shading).toHaveProperty('SHADING_INSTANCE_ORTHOGONAL');
    expectOracleCoverage(fast, 4000);
    expectShade(fast, 3000);
    const cofactor = await scene(page, { ...variant, object: 'instanced', instances: sheared });
    expect(cofactor.defines, variant.shading).not.toHaveProperty('SHADING_INSTANCE_ORTHOGONAL');
    expectShade(cofactor, 3000);
  }
});

test('extremes: a mirrored instance (negative determinant) keeps outward normals (lit as shade() lights them)', async ({
  harness,
}) => {
  const { page } = await harness('material');
  // three sets the front face per object, not per instance: a mirrored instance shows its inner side (for
  // MeshPhongMaterial too); its outward normals face away from the eye and the light, as shade() says.
  const instances: SceneInstance[] = [
    { position: [-1.5, 0, 0], scale: [-0.9, 0.9, 0.9] },
    { position: [1.5, 0, 0], scale: [0.9, 0.9, 0.9], rotation: [0, 0, 0.3] },
  ];
  for (const variant of [
    { shading: 'phong', analytic: true },
    { shading: 'gouraud' },
    { shading: 'flat' },
  ] as const) {
    const stats = await scene(page, { ...variant, object: 'instanced', instances });
    expectOracleCoverage(stats, 4000);
    expectShade(stats, 3000);
  }
});

test('extremes: an instance with a zero scale draws the flattened disc with finite normals, = shade()', async ({
  harness,
}) => {
  const { page } = await harness('material');
  const instances: SceneInstance[] = [
    { position: [-1.5, 0, 0], scale: [0.9, 0.9, 0] },
    { position: [1.5, 0, 0], scale: [0.9, 0.9, 0.9] },
  ];
  for (const variant of [
    { shading: 'phong', analytic: true },
    { shading: 'flat', flatCorners: true },
  ] as const) {
    const stats = await scene(page, { ...variant, object: 'instanced', instances });
    expectOracleCoverage(stats, 4000);
    expectShade(stats, 3000);
  }
});

test('extremes: instances with 1e20 and 1e-20 scales render without NaN (no black pixel)', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const scale of [
    [1e20, 0.8, 0.8],
    [0.8, 1e-20, 0.8],
    [1e-20, 1e-20, 1e-20],
  ] as Array<[number, number, number]>) {
    for (const variant of [
      { shading: 'phong', analytic: true },
      { shading: 'flat', flatCorners: true },
    ] as const) {
      const stats = await scene(page, {
        ...variant,
        object: 'instanced',
        instances: [
          { position: [0, 0, 0], scale },
          { position: [-2, 0, 0], scale: [0.8, 0.8, 0.8] },
        ],
      });
      expect(stats.darkPixels, `${variant.shading} ${scale}: ${JSON.stringify(stats)}`).toBe(0);
      expect(stats.covered).toBeGreaterThan(2000);
    }
  }
});

const FOGS = [
  ['Fog(1.5, 4)', { near: 1.5, far: 4 }],
  ['FogExp2(0.3)', { density: 0.3 }],
] as const;

for (const [name, fog] of FOGS) {
  test(`scene.fog ${name}: the fog blend of MeshPhongMaterial at every depth, and shade() blended by fogFactor()`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    // Constant colour (ka·Ia only) against MeshPhongMaterial's emissive: the same fog factor at every pixel.
    expectOracleColours(
      await scene(page, { shading: 'phong', fog, scale: [2, 1, 2], constant: true }),
      10000,
    );
    for (const [, variant] of SHADINGS) {
      const stats = await scene(page, { shading: 'phong', ...variant, fog, scale: [2, 1, 2] });
      expectOracleCoverage(stats, 11000);
      expectShade(stats, 8000);
    }
  });
}

test('fog × logarithmic depth: the same fog as MeshPhongMaterial with a logarithmic depth buffer', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const [, fog] of FOGS) {
    const config = { shading: 'phong', fog, scale: [2, 1, 2], logarithmic: true } as const;
    expectOracleColours(await scene(page, { ...config, constant: true }), 10000);
    const stats = await scene(page, config);
    expectOracleCoverage(stats, 11000);
    expectShade(stats, 10000);
    const flat = await scene(page, { ...config, shading: 'flat', flatCorners: true });
    expectShade(flat, 7000);
  }
});

test('extremes: fog near = far is a step at that depth, density 0 no fog, density 1e6 all fog: finite, = fogFactor()', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const fog of [{ near: 2.2, far: 2.2 }, { density: 0 }, { density: 1e6 }]) {
    const stats = await scene(page, { shading: 'phong', fog, scale: [2, 1, 2] });
    expectOracleCoverage(stats, 11000);
    expectShade(stats, 8000);
  }
});

const CLIPS = [
  ['a material plane (x ≥ 0 kept)', { planes: [[1, 0, 0, 0]] }],
  ["the renderer's global plane", { planes: [[0, -1, 0, 0.3]], global: true }],
  [
    'two planes, union',
    {
      planes: [
        [1, 0, 0, 0],
        [0, 1, 0, 0],
      ],
    },
  ],
  [
    'two planes, clipIntersection',
    {
      planes: [
        [1, 0, 0, 0],
        [0, 1, 0, 0],
      ],
      intersection: true,
    },
  ],
] as const;

for (const [name, clip] of CLIPS) {
  test(`clipping: ${name} cuts where MeshPhongMaterial is cut, colours = shade()`, async ({ harness }) => {
    const { page } = await harness('material');
    for (const [, variant] of SHADINGS) {
      const stats = await scene(page, {
        shading: 'phong',
        ...variant,
        clip: { ...clip, planes: clip.planes.map((p) => [...p] as [number, number, number, number]) },
        scale: [2, 1, 2],
      });
      expectOracleCoverage(stats, 2500);
      expectShade(stats, 2000);
    }
  });
}

test('clipping × outline: createOutline shares the planes, the hull is cut with the mesh', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const clip of [{ planes: [[1, 0, 0, 0]] }, { planes: [[1, 0, 0, 0]], global: true }] as Array<
    SceneConfig['clip']
  >) {
    const stats = await scene(page, { shading: 'phong', analytic: true, clip, outline: 0.08 });
    expectOracleCoverage(stats, 1500);
    expectShade(stats, 1200);
    expect(stats.black, JSON.stringify(stats)).toBeGreaterThan(60); // the ring on the kept side
    expect(stats.clippedBlack, JSON.stringify(stats)).toBe(0);
  }
});

test("tone mapping (ACES, exposure 2) and toneMapped: three's own tone mapping, as MeshPhongMaterial's", async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const level of [0.05, 0.3, 1, 4]) {
    const ka: [number, number, number] = [level, level * 0.6, level * 0.3];
    const stats = await scene(page, {
      shading: 'phong',
      toneMapping: 2,
      constant: true,
      ka,
      scale: [2, 1, 2],
    });
    expectOracleColours(stats, 10000);
  }
  // toneMapped = false: untouched by the renderer's tone mapping, the colours of shade().
  const off = { shading: 'phong', toneMapping: 2, toneMapped: false, scale: [2, 1, 2] } as const;
  expectOracleColours(await scene(page, { ...off, constant: true, ka: [4, 2.4, 1.2] }), 10000);
  expectShade(await scene(page, off), 10000);
});

test('output colour space: a linear-sRGB canvas gets the linear colours of shade()', async ({ harness }) => {
  const { page } = await harness('material');
  for (const [, variant] of SHADINGS) {
    const stats = await scene(page, { shading: 'phong', ...variant, linearOutput: true, scale: [2, 1, 2] });
    expectOracleCoverage(stats, 11000);
    expectShade(stats, 7000);
  }
});

test('the impostor is fogged and clipped like a mesh (the same chunks): MeshPhongMaterial on a fine sphere', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const extra of [
    { fog: { near: 1.5, far: 4 } },
    { clip: { planes: [[1, 0, 0, 0]] } },
    { toneMapping: 2 },
  ] as Array<Partial<SceneConfig>>) {
    const stats = await scene(page, {
      shading: 'phong',
      object: 'impostor',
      scale: [2, 1, 2],
      constant: true,
      ...extra,
    });
    expectOracleCoverage(stats, 5000);
    // The oracle is a level-7 mesh: its interpolated depth differs from the exact sphere's by a hair.
    expectOracleColours(stats, 5000, 1);
  }
});

test('flipping the object kind, fog, clipping and tone mapping 1,000 times keeps renderer.info.programs bounded', async ({
  page,
}) => {
  await open(page);
  const result = await page.evaluate(() => window.materialHarness.flipFeatures(1000));
  // 5 object kinds × fog × clipping × tone mapping: at most 40 variants, each compiled once.
  expect(result.variants).toBe(40);
  expect(result.max).toBeLessThanOrEqual(result.before + result.variants);
  expect(result.after).toBeLessThanOrEqual(result.before + result.variants);
});

test('a colour edited in place is one console error, not one per frame; drawn with the last good values, reported again after a fix', async ({
  page,
}) => {
  await open(page);
  // Counted from here (after the page's own loading, e.g. a missing favicon).
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  const frames = 60;
  const centre = await page.evaluate((n) => window.materialHarness.inPlaceEdits(n), frames);
  // 5 phases × 60 frames: good, kd = (NaN, -1, 0), fixed, a PhongLight's Is.b = Infinity, fixed.
  expect(errors).toEqual([
    'ShadingMaterial.kd must have finite channels ≥ 0 (linear RGB), got Color(NaN, -1, 0) (edited in place; drawing with the last valid values)',
    'ShadingMaterial.lights[0]: PhongLight.specular must have finite channels ≥ 0 (linear RGB), got Color(0.8, 0.8, Infinity) (edited in place; drawing with the last valid values)',
  ]);
  // Every phase draws the sphere lit as in the first (the last good uniforms while bad), never black or missing.
  expect(centre[0].some((c) => c > 40)).toBe(true);
  for (const c of centre) expect(c).toEqual(centre[0]);
});

/** three's lights of every kind around the lecture's sphere (colours linear, intensities in range). */
const THREE_LIGHTS = [
  { type: 'ambient', color: [0.1, 0.1, 0.1] },
  { type: 'hemisphere', color: [0.2, 0.3, 0.5], groundColor: [0.3, 0.2, 0.1], position: [0, 1, 0] },
  { type: 'directional', color: [0.3, 0.4, 0.5], position: [-1, 2, 1] },
  { type: 'point', color: [1, 0.8, 0.6], intensity: 3, position: [2, 1, 2], distance: 6, decay: 2 },
  {
    type: 'spot',
    color: [0.6, 0.8, 1],
    intensity: 2,
    position: [0, 3, 2],
    angle: 0.35,
    penumbra: 0.5,
    decay: 1,
  },
] as const;

for (const [name, variant] of SHADINGS) {
  test(`three's Ambient, Hemisphere, Directional, Point and Spot lights with a PhongLight, ${name}: = shade() (Id = Is = colour × intensity / π, three's falloff)`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { shading: 'phong', ...variant, threeLights: THREE_LIGHTS });
    expectOracleCoverage(stats, 3000);
    expectShade(stats, 'shading' in variant && variant.shading === 'flat' ? 1500 : 2500);
  });
}

for (const [name, light, object] of [
  ['a SpotLight (angle, penumbra, decay)', THREE_LIGHTS[4], 'mesh'],
  [
    'a PointLight (distance cut-off, decay)',
    { ...THREE_LIGHTS[3], position: [1, 0.5, 1.2], distance: 1.6 },
    'mesh',
  ],
  ['a DirectionalLight', THREE_LIGHTS[2], 'mesh'],
  ['a SpotLight on instances', THREE_LIGHTS[4], 'instanced'],
] as const) {
  test(`${name} alone lights the pixels MeshPhongMaterial lights (and only those), colours = shade()`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const config = {
      shading: 'phong',
      phongLight: false,
      threeLights: [light],
      object,
      ...(object === 'instanced' ? { instances: THREE_INSTANCES } : {}),
    } as const;
    const stats = await scene(page, config);
    const info = JSON.stringify(stats);
    expectOracleCoverage(stats, 3000);
    expect(stats.litCompared, info).toBeGreaterThan(1500);
    expect(stats.litMismatches, info).toBe(0);
    expect(stats.compared, info).toBeGreaterThan(1500);
    expect(stats.maxError, info).toBeLessThanOrEqual(2);
  });
}

test("0, 1 and 64 of each of three's light kinds compile in every shading; flipping them keeps programs bounded", async ({
  page,
}) => {
  // 45 programs compiled by SwiftShader: about 40 s on an idle machine, over a minute when it is shared.
  test.setTimeout(180_000);
  await open(page);
  const errors: string[] = [];
  page.on('console', (m) => {
    // three's shader errors and warnings (not the browser's own, e.g. a GPU stall note on readPixels).
    if (m.type() === 'error' || (m.type() === 'warning' && m.text().includes('THREE'))) errors.push(m.text());
  });
  const { swept, programs, variants, centres } = await page.evaluate(() =>
    window.materialHarness.threeLightExtremes(),
  );
  expect(errors).toEqual([]); // no shader compile or link error
  // 5 kinds × 3 counts × 3 shadings: three keeps each material's programs, one per light state (at most
  // 5 kinds × 2 counts + none = 11 per material; ambient lights of any number share one); 200 random flips
  // of the same states add none.
  expect(variants).toBe(45);
  expect(swept).toBeLessThanOrEqual(33);
  expect(programs).toBe(swept);
  expect(centres).toHaveLength(245);
  // Every render drew the sphere (not the clear colour (0, 0, 255)) with finite colours.
  for (const c of centres) expect(c).not.toEqual([0, 0, 255]);
});

for (const [name, variant] of [
  ['phong', {}],
  ['gouraud', { shading: 'gouraud' }],
  ['flat', { shading: 'flat' }],
  ['the impostor', { object: 'impostor' }],
  [
    'instanced, with three’s lights too',
    { object: 'instanced', instances: THREE_INSTANCES, threeLights: THREE_LIGHTS },
  ],
] as const) {
  test(`a PhongLight in the scene lights ${name} without being listed (= shade())`, async ({ harness }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { shading: 'phong', ...variant, listed: false });
    expectOracleCoverage(stats, 3000);
    expectShade(stats, 'shading' in variant && variant.shading === 'flat' ? 1500 : 2500);
  });
}

for (const side of ['double', 'back'] as const)
  for (const mirrored of [false, true])
    for (const shading of ['phong', 'gouraud', 'flat'] as const)
      test(`side ${side === 'double' ? 'DoubleSide' : 'BackSide'}${mirrored ? ' × mirrored (det < 0)' : ''}, ${shading}: a back face is lit with its flipped normal (= shade())`, async ({
        harness,
      }) => {
        const { page } = await harness('material');
        const stats = await page.evaluate((c) => window.materialHarness.sideCompare(c), {
          side,
          mirrored,
          shading,
        });
        const info = JSON.stringify(stats);
        expect(stats.compared, info).toBeGreaterThan(1000);
        expect(stats.maxError, info).toBeLessThanOrEqual(2);
        // Lit by the light in front (not the ambient-only colour of the unflipped normal).
        expect(stats.centre[0], info).toBeGreaterThan(150);
      });

// Flat shading of a plain indexed geometry (no flatShadingGeometry): lit per fragment at the fragment's world
// position with the face normal from screen-space derivatives; shade() with the normal of the triangle under
// the pixel, away from its edges.
for (const [name, config] of [
  ['TorusKnotGeometry', { object: 'torus-knot', indexedFlat: true }],
  ['the indexed lecture sphere', { object: 'mesh', indexedFlat: true, scale: [2, 1, 2] }],
  [
    'the indexed sphere, instanced with instanceColor',
    { object: 'instanced', indexedFlat: true, level: 3, instances: THREE_INSTANCES },
  ],
  ['an indexed SkinnedMesh with a moved bone', { object: 'skinned', indexedFlat: true, bone: 0.7 }],
  ['an indexed morphed sphere', { object: 'morphed', indexedFlat: true, level: 3 }],
  [
    "three's lights and fog",
    { object: 'torus-knot', indexedFlat: true, threeLights: THREE_LIGHTS, fog: { near: 1.5, far: 4 } },
  ],
] as const) {
  test(`flat shading without preparation, ${name}: drawn where MeshPhongMaterial (flatShading) draws, = shade() with the derivative face normal at the fragment`, async ({
    harness,
  }) => {
    const { page } = await harness('material');
    const stats = await scene(page, { shading: 'flat', ...config } as SceneConfig);
    expectOracleCoverage(stats, 2500);
    expectShade(stats, 1500);
  });
}

test('flat shading without preparation, DoubleSide and BackSide: a back face is lit with its flipped normal', async ({
  harness,
}) => {
  const { page } = await harness('material');
  for (const side of ['double', 'back'] as const)
    for (const mirrored of [false, true]) {
      const stats = await page.evaluate((c) => window.materialHarness.sideCompare(c), {
        side,
        mirrored,
        shading: 'flat' as const,
        indexed: true,
      });
      const info = JSON.stringify(stats);
      expect(stats.compared, info).toBeGreaterThan(1000);
      expect(stats.maxError, info).toBeLessThanOrEqual(2);
      expect(stats.centre[0], info).toBeGreaterThan(150);
    }
});
