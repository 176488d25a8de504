// ShadingNodeMaterial (@shadelab/material/webgpu) under WebGPURenderer: on its WebGPU backend (Chromium launched
// with the kit's WebGPU flags: SwiftShader's adapter) and its WebGL2 backend (forceWebGL), rendered offscreen
// into a RenderTarget and read back; every shading × lighting × cel variant against the CPU shade(), the same
// scene against WebGLRenderer + ShadingMaterial, and the bad-input errors against ShadingMaterial's.
// Harness: tests/harness/webgpu-material.ts.
import { expect } from '@playwright/test';
import { webgpuTest as test } from './harness-helpers';

type Backend = 'webgpu' | 'webgl2';
type Scenario =
  | 'lecture'
  | 'attenuated'
  | 'three-lights'
  | 'analytic'
  | 'indexed'
  | 'instanced'
  | 'fog'
  | 'prepared'
  | 'prepared-other'
  | 'flattened'
  | 'backside'
  | 'doubleside';
interface Variant {
  shading: 'flat' | 'gouraud' | 'phong';
  lighting: 'phong' | 'blinn-phong';
  celBands: number;
}
interface PictureDelta {
  compared: number;
  max: number;
  mean: number;
}
/** three's surface properties on both materials (see the harness's SurfaceCase). */
interface SurfaceCase {
  map?: boolean;
  vertexColors?: 'rgb' | 'rgba';
  instanceColor?: boolean;
  emissive?: boolean;
  emissiveMap?: boolean;
  opacity?: number;
  transparent?: boolean;
  alphaTest?: number;
  alphaMap?: boolean;
  side?: 'front' | 'back' | 'double';
  normalMap?: 'tangent' | 'object';
}
interface Harness {
  backendInfo(
    b: Backend,
  ): Promise<{ isWebGPUBackend: boolean; isWebGLBackend: boolean; device: boolean; adapter: boolean }>;
  compare(
    b: Backend,
    v: Variant,
    scenario?: Scenario,
    surface?: SurfaceCase,
  ): Promise<{
    covered: number;
    compared: number;
    maxError: number;
    mismatches: number;
    facesChecked: number;
    facesMultiColour: number;
    worst: unknown;
  }>;
  crossRenderer(
    b: Backend,
    v: Variant,
    scenario?: Scenario,
    surface?: SurfaceCase,
  ): Promise<{ covered: number; maxDelta: number; differing: number; coverageMismatch: number }>;
  emissiveEdits(b: Backend): Promise<{
    frames: { step: string; is: 'black' | 'red' | 'other'; version: number }[];
    impostorVersions: number[];
  }>;
  errors(): { options: string; webgl: string; node: string }[];
  fogEffect(b: Backend, v: Variant): Promise<number>;
  fogParity(
    b: Backend,
    fog: 'none' | 'range' | 'exp2',
  ): Promise<{
    againstPhong: PictureDelta;
    againstLambert: PictureDelta;
    againstWebGL: PictureDelta;
    fraction: { node: number; phongNode: number; webgl: number; webglPhong: number };
  }>;
  inPlaceEdits(b: Backend): Promise<{ errors: string[]; sameAsFirst: boolean; index: number }[]>;
  sceneLights(b: Backend): Promise<Record<string, boolean>>;
}

const VARIANTS: Variant[] = (['flat', 'gouraud', 'phong'] as const).flatMap((shading) =>
  (['phong', 'blinn-phong'] as const).flatMap((lighting) =>
    [0, 4].map((celBands) => ({ shading, lighting, celBands })),
  ),
);

test('WebGPURenderer runs the WebGPU backend on a WebGPU device (no silent WebGL2 fallback), and forceWebGL the WebGL2 one', async ({
  harness,
}) => {
  const { page } = await harness('webgpu-material');
  expect(
    await page.evaluate(() => (window as never as { harness: Harness }).harness.backendInfo('webgpu')),
  ).toEqual({ isWebGPUBackend: true, isWebGLBackend: false, device: true, adapter: true });
  const webgl2 = await page.evaluate(() =>
    (window as never as { harness: Harness }).harness.backendInfo('webgl2'),
  );
  expect(webgl2.isWebGPUBackend).toBe(false);
  expect(webgl2.isWebGLBackend).toBe(true);
});

for (const backend of ['webgpu', 'webgl2'] as const) {
  test(`${backend} backend: every shading × lighting × cel variant = shade() within 2/255 away from edges; flat is one colour per face`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-material');
    for (const variant of VARIANTS) {
      const stats = await page.evaluate(
        ([b, v]) => (window as never as { harness: Harness }).harness.compare(b, v),
        [backend, variant] as const,
      );
      const label = `${backend} ${JSON.stringify(variant)} ${JSON.stringify(stats.worst)}`;
      expect(stats.compared, label).toBeGreaterThan(2000);
      expect(stats.mismatches, label).toBe(0);
      expect(stats.maxError, label).toBeLessThanOrEqual(2);
      if (variant.shading === 'flat') {
        expect(stats.facesChecked, label).toBeGreaterThan(40);
        expect(stats.facesMultiColour, label).toBe(0);
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: three's ambient, hemisphere, directional, point and spot lights, an attenuated PhongLight with shininess 0 (0⁰ = 1), a sphere without normals, flat shading of an indexed geometry (by derivatives) and of an InstancedMesh's soup (each face one colour at its centroid, as ShadingMaterial) = shade() within 2/255`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-material');
    const cases: [Scenario, Variant[]][] = [
      ['three-lights', VARIANTS],
      ['attenuated', VARIANTS.filter((v) => v.celBands === 0)],
      ['analytic', VARIANTS.filter((v) => v.shading !== 'flat' && v.lighting === 'blinn-phong')],
      // Flat shading by derivatives (per fragment, the face normal): an indexed geometry; exact (one colour per
      // face, at its centroid): an InstancedMesh's soup.
      ['indexed', VARIANTS.filter((v) => v.shading === 'flat')],
      ['instanced', VARIANTS.filter((v) => v.lighting === 'phong')],
      // Back faces: flat shading lights each with the face normal turned round.
      ['doubleside', VARIANTS.filter((v) => v.shading === 'flat' && v.celBands === 0)],
    ];
    for (const [scenario, variants] of cases) {
      for (const variant of variants) {
        const stats = await page.evaluate(
          ([b, v, sc]) => (window as never as { harness: Harness }).harness.compare(b, v, sc),
          [backend, variant, scenario] as const,
        );
        const label = `${backend} ${scenario} ${JSON.stringify(variant)} ${JSON.stringify(stats.worst)}`;
        // Five lights with cel bands leave out more pixels near their edges (gouraud: whole triangles).
        expect(stats.compared, label).toBeGreaterThan(1000);
        expect(stats.mismatches, label).toBe(0);
        expect(stats.maxError, label).toBeLessThanOrEqual(2);
        if (variant.shading === 'flat' && scenario !== 'indexed') {
          expect(stats.facesMultiColour, label).toBe(0);
        }
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: a flatShadingGeometry made for this backend's provoking vertex is one exact colour per face; one made for the other backend is lit by derivatives with one warning`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-material');
    const warnings: string[] = [];
    page.on('console', (m) => {
      if (m.type() === 'warning') warnings.push(m.text());
    });
    const flat = VARIANTS.filter((v) => v.shading === 'flat');
    for (const scenario of ['prepared', 'prepared-other'] as const) {
      for (const variant of flat) {
        const stats = await page.evaluate(
          ([b, v, sc]) => (window as never as { harness: Harness }).harness.compare(b, v, sc),
          [backend, variant, scenario] as const,
        );
        const label = `${backend} ${scenario} ${JSON.stringify(variant)} ${JSON.stringify(stats.worst)}`;
        expect(stats.compared, label).toBeGreaterThan(2000);
        expect(stats.mismatches, label).toBe(0);
        expect(stats.maxError, label).toBeLessThanOrEqual(2);
        if (scenario === 'prepared') {
          expect(stats.facesChecked, label).toBeGreaterThan(40);
          expect(stats.facesMultiColour, label).toBe(0);
        }
      }
    }
    const [made, wanted] = backend === 'webgpu' ? ['last', 'first'] : ['first', 'last'];
    expect(warnings).toEqual([
      `ShadingNodeMaterial: this flatShadingGeometry was made with provokingVertex '${made}', but this backend's is the ${wanted}: flat shading lights it per fragment with the face normal. Make it with flatShadingGeometry(geometry, { provokingVertex: '${wanted}' })`,
    ]);
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: a mesh scaled to y = 0 (a disc; the robust normal matrix), a sphere drawn BackSide and an open cylinder drawn DoubleSide (back faces lit with the normal turned round, per vertex too) = WebGLRenderer + ShadingMaterial`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-material');
    for (const scenario of ['flattened', 'backside', 'doubleside'] as const) {
      for (const variant of VARIANTS.filter((v) => v.celBands === 0 && v.lighting === 'phong')) {
        const stats = await page.evaluate(
          ([b, v, sc]) => (window as never as { harness: Harness }).harness.crossRenderer(b, v, sc),
          [backend, variant, scenario] as const,
        );
        const label = `${backend} ${scenario} ${JSON.stringify(variant)} ${JSON.stringify(stats)}`;
        expect(stats.covered, label).toBeGreaterThan(3000);
        expect(stats.coverageMismatch, label).toBe(0);
        expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: a PhongLight added to or removed from the scene lights the material from that frame on; a material's lights list excludes the scene's others`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-material');
    const result = await page.evaluate(
      (b) => (window as never as { harness: Harness }).harness.sceneLights(b),
      backend,
    );
    expect(result).toEqual({
      addedChanges: true,
      addedAsFresh: true,
      removedAsFirst: true,
      listedAsFirst: true,
    });
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: ka or a PhongLight edited in place to a bad value is reported once and drawn with the last valid values`, async ({
    harness,
  }) => {
    const { page } = await harness('webgpu-material');
    const frames = await page.evaluate(
      (b) => (window as never as { harness: Harness }).harness.inPlaceEdits(b),
      backend,
    );
    expect(frames.map((f) => f.errors)).toEqual([
      [],
      [
        'ShadingNodeMaterial.ka must have finite channels ≥ 0 (linear RGB), got Color(NaN, 0.35, 0.2) (edited in place; drawing with the last valid values)',
      ],
      [],
      [
        'ShadingNodeMaterial: PhongLight.diffuse must have finite channels ≥ 0 (linear RGB), got Color(1, -1, 1) (edited in place; drawing with the last valid values)',
      ],
      [],
    ]);
    expect(frames.map((f) => f.sameAsFirst)).toEqual([true, true, true, true, false]);
  });

  test(`${backend} backend: the emissive is built in only while it is not black (as ShadingMaterial's): set black → red → black, the next frame is a new black or red material's picture; edited in place, from the frame after; steady frames rebuild nothing, nor does an emissive impostor (which adds none)`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-material');
    const r = await page.evaluate(
      (b) => (window as never as { harness: Harness }).harness.emissiveEdits(b),
      backend,
    );
    const info = JSON.stringify(r);
    expect(
      r.frames.map((f) => `${f.step}: ${f.is}`),
      info,
    ).toEqual([
      'black: black',
      'black, steady: black',
      'set red: red',
      'red, steady: red',
      'red, steady: red',
      'set black: black',
      // The in-place edit is seen while the frame's bindings are refreshed, after its pipeline was chosen.
      'red in place: black',
      'red in place, next frame: red',
      'red in place, steady: red',
      'black in place: black',
      'black in place, next frame: black',
      'black in place, steady: black',
    ]);
    // needsUpdate raises the version: once at each change of whether the emissive is built in (an in-place edit
    // during the frame that sees it), never on a steady frame.
    expect(
      r.frames.map((f) => f.version - r.frames[0].version),
      info,
    ).toEqual([0, 0, 1, 1, 1, 2, 3, 3, 3, 4, 4, 4]);
    expect(new Set(r.impostorVersions).size, info).toBe(1);
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: the lecture scene, and the same in three's Fog, = WebGLRenderer + ShadingMaterial within 2/255, same coverage`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-material');
    for (const variant of [
      { shading: 'phong', lighting: 'phong', celBands: 0 },
      { shading: 'gouraud', lighting: 'blinn-phong', celBands: 4 },
      { shading: 'flat', lighting: 'phong', celBands: 0 },
    ] as const) {
      for (const scenario of ['lecture', 'fog'] as const) {
        const stats = await page.evaluate(
          ([b, v, sc]) => (window as never as { harness: Harness }).harness.crossRenderer(b, v, sc),
          [backend, variant, scenario] as const,
        );
        const label = `${backend} ${scenario} ${JSON.stringify(variant)}`;
        expect(stats.covered, label).toBeGreaterThan(5000);
        expect(stats.coverageMismatch, label).toBe(0);
        expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
      }
      // The fog is really there: it changes the picture.
      const fogged = await page.evaluate(
        ([b, v]) => (window as never as { harness: Harness }).harness.fogEffect(b, v),
        [backend, variant] as const,
      );
      expect(fogged, `${backend} ${JSON.stringify(variant)}`).toBeGreaterThan(1000);
    }
    expect(problems).toEqual([]);
  });
}

/** The surface cases: each feature alone, then together. */
const SURFACES: SurfaceCase[] = [
  { map: true },
  { vertexColors: 'rgb' },
  { map: true, vertexColors: 'rgb', instanceColor: true },
  { emissive: true },
  { emissive: true, emissiveMap: true, map: true },
  { opacity: 0.6, transparent: true },
  { map: true, vertexColors: 'rgba', alphaMap: true, opacity: 0.9, transparent: true },
  { map: true, vertexColors: 'rgba', alphaTest: 0.4 },
];
const SURFACE_VARIANTS: Variant[] = (['flat', 'gouraud', 'phong'] as const).map((shading) => ({
  shading,
  lighting: 'blinn-phong',
  celBands: 0,
}));

for (const backend of ['webgpu', 'webgl2'] as const) {
  test(`${backend} backend: map, vertexColors, instanceColor, emissive, emissiveMap, opacity, transparent, alphaTest and alphaMap in each shading = shade() with the tint (texel × vertex colour × instance colour on ka and kd, never ks; per fragment in every shading), emissive and alpha, within 2/255`, async ({
    harness,
  }) => {
    test.setTimeout(180_000);
    const { page, problems } = await harness('webgpu-material');
    for (const surface of SURFACES) {
      for (const variant of [
        ...SURFACE_VARIANTS,
        { shading: 'phong', lighting: 'phong', celBands: 4 } as const,
      ]) {
        const stats = await page.evaluate(
          ([b, v, sf]) => (window as never as { harness: Harness }).harness.compare(b, v, 'lecture', sf),
          [backend, variant, surface] as const,
        );
        const label = `${backend} ${JSON.stringify(surface)} ${JSON.stringify(variant)} ${JSON.stringify(stats.worst)}`;
        expect(stats.compared, label).toBeGreaterThan(1500);
        expect(stats.mismatches, label).toBe(0);
        expect(stats.maxError, label).toBeLessThanOrEqual(2);
        // Without a texture or alpha, exact flat shading is one colour per face (the vertex colour of the
        // triangle's last vertex, ShadingMaterial's, whichever vertex the backend's flat varyings come from).
        if (variant.shading === 'flat' && !surface.map && !surface.emissiveMap && !surface.transparent) {
          expect(stats.facesChecked, label).toBeGreaterThan(40);
          expect(stats.facesMultiColour, label).toBe(0);
        }
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: the surface features = WebGLRenderer + ShadingMaterial within 2/255, same coverage, front, back and both sides`, async ({
    harness,
  }) => {
    test.setTimeout(180_000);
    const { page, problems } = await harness('webgpu-material');
    const cases: SurfaceCase[] = [
      ...SURFACES,
      { map: true, vertexColors: 'rgb', emissive: true, side: 'double' },
      { map: true, alphaTest: 0.6, side: 'double' },
      { map: true, vertexColors: 'rgb', side: 'back' },
    ];
    for (const surface of cases) {
      // Flat shading of an InstancedMesh too: both light each face at its centroid.
      for (const variant of SURFACE_VARIANTS) {
        const stats = await page.evaluate(
          ([b, v, sf]) =>
            (window as never as { harness: Harness }).harness.crossRenderer(b, v, 'lecture', sf),
          [backend, variant, surface] as const,
        );
        const label = `${backend} ${JSON.stringify(surface)} ${JSON.stringify(variant)} ${JSON.stringify(stats)}`;
        expect(stats.covered, label).toBeGreaterThan(2000);
        expect(stats.coverageMismatch, label).toBe(0);
        expect(stats.maxDelta, label).toBeLessThanOrEqual(2);
      }
    }
    expect(problems).toEqual([]);
  });
}

for (const backend of ['webgpu', 'webgl2'] as const) {
  test(`${backend} backend: normalMap (tangent space through the derivative tangent frame, and object space) perturbs the material's own normal in phong shading: = shade() with the perturbed normal within 2/255, with a map too, and = WebGLRenderer + ShadingMaterial within 2/255; gouraud and flat shading ignore it with one console warning each`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-material');
    const warnings: string[] = [];
    page.on('console', (m) => {
      if (m.type() === 'warning' && m.text().includes('normalMap')) warnings.push(m.text());
    });
    const info = await page.evaluate(
      (b) => (window as never as { harness: Harness }).harness.backendInfo(b),
      backend,
    );
    expect(info).toMatchObject(
      backend === 'webgpu'
        ? { isWebGPUBackend: true, isWebGLBackend: false, device: true }
        : { isWebGPUBackend: false, isWebGLBackend: true },
    );
    const phongVariants: Variant[] = [
      { shading: 'phong', lighting: 'blinn-phong', celBands: 0 },
      { shading: 'phong', lighting: 'phong', celBands: 0 },
    ];
    for (const surface of [
      { normalMap: 'tangent' },
      { normalMap: 'object' },
      { normalMap: 'tangent', map: true },
    ] as SurfaceCase[]) {
      for (const variant of phongVariants) {
        const stats = await page.evaluate(
          ([b, v, sf]) => (window as never as { harness: Harness }).harness.compare(b, v, 'lecture', sf),
          [backend, variant, surface] as const,
        );
        const label = `${backend} ${JSON.stringify(surface)} ${JSON.stringify(variant)} ${JSON.stringify(stats.worst)}`;
        expect(stats.compared, label).toBeGreaterThan(1500);
        expect(stats.mismatches, label).toBe(0);
        expect(stats.maxError, label).toBeLessThanOrEqual(2);
        const cross = await page.evaluate(
          ([b, v, sf]) =>
            (window as never as { harness: Harness }).harness.crossRenderer(b, v, 'lecture', sf),
          [backend, variant, surface] as const,
        );
        const crossLabel = `${backend} ${JSON.stringify(surface)} ${JSON.stringify(variant)} ${JSON.stringify(cross)}`;
        expect(cross.covered, crossLabel).toBeGreaterThan(2000);
        expect(cross.coverageMismatch, crossLabel).toBe(0);
        expect(cross.maxDelta, crossLabel).toBeLessThanOrEqual(2);
      }
    }
    expect(warnings).toEqual([]);
    for (const shading of ['gouraud', 'flat'] as const) {
      const variant: Variant = { shading, lighting: 'phong', celBands: 0 };
      // Ignored: = shade() with the vertex normals (the harness perturbs only phong shading's).
      const stats = await page.evaluate(
        ([b, v]) =>
          (window as never as { harness: Harness }).harness.compare(b, v, 'lecture', {
            normalMap: 'tangent',
          }),
        [backend, variant] as const,
      );
      expect(stats.mismatches, `${shading} ${JSON.stringify(stats.worst)}`).toBe(0);
      expect(stats.compared).toBeGreaterThan(1500);
    }
    await expect.poll(() => warnings.length).toBe(2);
    expect(warnings[0]).toContain(
      "ShadingNodeMaterial: normalMap needs a per-fragment normal (shading 'phong'); gouraud shading ignores it",
    );
    expect(warnings[1]).toContain('flat shading ignores it');
    expect(problems).toEqual([]);
  });

  test(`${backend} backend: in three's Fog and FogExp2 (sRGB output), ShadingNodeMaterial({ ka: c, kd: c, ks: 0 }) = MeshPhongNodeMaterial({ color: c, specular: 0 }) and MeshLambertNodeMaterial({ color: c }) within 2/255: fog blended in linear before the output conversion, as three's node materials blend it (WebGLRenderer blends it in the output colour space)`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-material');
    for (const fog of ['none', 'range', 'exp2'] as const) {
      const r = await page.evaluate(
        ([b, f]) => (window as never as { harness: Harness }).harness.fogParity(b, f),
        [backend, fog] as const,
      );
      const label = `${backend} ${fog} ${JSON.stringify(r)}`;
      expect(r.againstPhong.compared, label).toBeGreaterThan(4000);
      expect(r.againstPhong.max, label).toBeLessThanOrEqual(2);
      expect(r.againstLambert.max, label).toBeLessThanOrEqual(2);
      if (fog === 'none') {
        // Without fog the two renderers draw the same picture.
        expect(r.againstWebGL.max, label).toBeLessThanOrEqual(2);
        continue;
      }
      // How far the fog moves a pixel towards its colour: each material as its renderer's three material.
      expect(r.fraction.node, label).toBeGreaterThan(0.2);
      expect(Math.abs(r.fraction.node - r.fraction.phongNode), label).toBeLessThan(0.005);
      expect(Math.abs(r.fraction.webgl - r.fraction.webglPhong), label).toBeLessThan(0.005);
      // The renderers differ (linear against output-space blending; measured: max 19/255 for Fog, 23/255 for
      // FogExp2, mean ≈ 10/255 in this scene): documented in the WebGPU guide.
      expect(r.againstWebGL.max, label).toBeGreaterThan(5);
    }
    expect(problems).toEqual([]);
  });
}

test("bad input throws ShadingMaterial's errors (same class, same message but for the material's name)", async ({
  harness,
}) => {
  const { page } = await harness('webgpu-material');
  const rows = await page.evaluate(() => (window as never as { harness: Harness }).harness.errors());
  expect(rows.length).toBeGreaterThan(10);
  for (const row of rows) {
    expect(row.webgl, row.options).toMatch(/^(TypeError|RangeError): ShadingMaterial\./);
    expect(row.node.replace('ShadingNodeMaterial.', 'ShadingMaterial.'), row.options).toBe(row.webgl);
  }
});
