// ShadingNodeMaterial (@shadelab/material/webgpu) in the scenes apps have, on both backends of WebGPURenderer
// (WebGPU, and WebGL2 through forceWebGL), rendered offscreen and read back (issue 15: what TSL gives for free is
// kept; robustness). Oracles: for colours, the same scene through WebGLRenderer + ShadingMaterial (itself tested
// against MeshPhongMaterial and shade()), within 2/255 away from triangle edges; for where and whether something
// is drawn, three's MeshPhongNodeMaterial on the same WebGPURenderer; flat shading by derivatives against shade()
// per fragment with the deformed face's normal. Harness: tests/harness/webgpu-scene.ts.
import { expect, type Page } from '@playwright/test';
import type { Diff, SceneCase, WebGPUSceneHarness } from './harness/webgpu-scene';
import { openHarness, webgpuTest as test } from './harness-helpers';

type Harness = WebGPUSceneHarness;
const BACKENDS = ['webgpu', 'webgl2'] as const;

/** Opens the harness; returns the page and console errors seen (none are expected unless a test provokes them). */
const open = (page: Page): Promise<string[]> => openHarness(page, 'webgpu-scene');

function run<A extends unknown[], R>(page: Page, name: keyof Harness, ...args: A): Promise<R> {
  return page.evaluate(
    ([n, a]) =>
      (
        (window as unknown as { harness: Record<string, (...x: unknown[]) => unknown> }).harness[n] as (
          ...x: unknown[]
        ) => Promise<R>
      )(...a),
    [name, args] as const,
  ) as Promise<R>;
}

/** Covered where the other covers (every pixel away from the other's coverage edge), colours within 2/255. */
function expectSame(d: Diff, label: string, minCompared: number): void {
  const info = `${label} ${JSON.stringify(d)}`;
  expect(d.covered, info).toBeGreaterThan(minCompared);
  expect(d.compared, info).toBeGreaterThan(minCompared);
  expect(d.interiorCoverageMismatches, info).toBe(0);
  expect(d.differing, info).toBe(0);
  expect(d.maxDelta, info).toBeLessThanOrEqual(2);
}

type SceneStats = {
  phongNode: Diff;
  webgl: Diff;
  shade: { compared: number; maxError: number; mismatches: number; worst: unknown } | null;
};

const KINDS = ['skinned', 'morphed', 'batched', 'instanced'] as const;
const SHADINGS: Pick<SceneCase, 'shading' | 'lighting'>[] = [
  { shading: 'phong' },
  { shading: 'gouraud', lighting: 'blinn-phong' },
  { shading: 'flat' },
];

for (const backend of BACKENDS) {
  for (const kind of KINDS) {
    test(`${backend}: ${kind === 'skinned' ? 'SkinnedMesh (a bone rotated and moved)' : kind === 'morphed' ? 'morph targets (positions and normals at influence 0.5)' : kind === 'batched' ? 'BatchedMesh (two instances, different matrices and colours)' : 'InstancedMesh (two instances, different matrices and colours)'}, phong, gouraud and flat: drawn where MeshPhongNodeMaterial draws, colours = WebGLRenderer + ShadingMaterial within 2/255; flat = shade() with the deformed face normal`, async ({
      harness,
    }) => {
      test.setTimeout(90_000);
      const { page, problems } = await harness('webgpu-scene');
      for (const s of SHADINGS) {
        const c: SceneCase = { kind, ...s };
        const stats = await run<[string, SceneCase], SceneStats>(page, 'sceneCompare', backend, c);
        const label = `${backend} ${JSON.stringify(c)}`;
        // Where and whether: exactly three's own node material's pixels.
        expect(stats.phongNode.coverageMismatches, `${label} ${JSON.stringify(stats.phongNode)}`).toBe(0);
        // Flat by derivatives in both (indexed geometry): compared away from triangle edges.
        expectSame(stats.webgl, label, s.shading === 'flat' ? 300 : 1500);
        if (s.shading === 'flat') {
          const sh = stats.shade;
          expect(sh?.compared, label).toBeGreaterThan(300);
          expect(sh?.mismatches, `${label} ${JSON.stringify(sh)}`).toBe(0);
          expect(sh?.maxError, label).toBeLessThanOrEqual(2);
        }
        if (kind === 'batched' || kind === 'instanced') {
          // Per-instance colours multiply ka and kd, as on ShadingMaterial.
          const tinted = { ...c, instanceColor: true };
          const t = await run<[string, SceneCase], SceneStats>(page, 'sceneCompare', backend, tinted);
          const tlabel = `${backend} ${JSON.stringify(tinted)}`;
          expect(t.phongNode.coverageMismatches, tlabel).toBe(0);
          expectSame(t.webgl, tlabel, s.shading === 'flat' ? 300 : 1500);
        }
      }
      expect(problems).toEqual([]);
    });
  }

  test(`${backend}: exact flat shading of a triangle soup and of a flatShadingGeometry made for this backend's provoking vertex, for a SkinnedMesh, a morphed mesh and an InstancedMesh (two instances): exactly one colour per face, = shade() at the moved face's centroid with its face normal, = WebGLRenderer + ShadingMaterial within 2/255, drawn where MeshPhongNodeMaterial draws`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-scene');
    for (const flatGeometry of ['soup', 'prepared'] as const) {
      for (const kind of ['skinned', 'morphed', 'instanced', 'mesh'] as const) {
        for (const lighting of ['phong', 'blinn-phong'] as const) {
          const c: SceneCase = { kind, shading: 'flat', flatGeometry, lighting };
          const stats = await run<
            [string, SceneCase],
            {
              backend: { isWebGPUBackend: boolean; isWebGLBackend: boolean };
              phongNode: Diff;
              webgl: Diff;
              exact: {
                compared: number;
                maxError: number;
                mismatches: number;
                faces: number;
                multiColour: number;
                worst: unknown;
              };
            }
          >(page, 'flatExactCompare', backend, c);
          const label = `${backend} ${JSON.stringify(c)} ${JSON.stringify(stats.exact)}`;
          expect(stats.backend, label).toEqual(
            backend === 'webgpu'
              ? { isWebGPUBackend: true, isWebGLBackend: false }
              : { isWebGPUBackend: false, isWebGLBackend: true },
          );
          expect(stats.phongNode.coverageMismatches, `${label} ${JSON.stringify(stats.phongNode)}`).toBe(0);
          expectSame(stats.webgl, label, 300);
          expect(stats.exact.compared, label).toBeGreaterThan(300);
          expect(stats.exact.faces, label).toBeGreaterThan(12);
          expect(stats.exact.multiColour, label).toBe(0);
          expect(stats.exact.mismatches, label).toBe(0);
          expect(stats.exact.maxError, label).toBeLessThanOrEqual(2);
        }
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend}: ClippingGroup (around the object, nested as the renderer's global planes, clipIntersection) cuts where MeshPhongNodeMaterial is cut; the clipped pixels are exactly background, the rest unchanged, = WebGL ShadingMaterial with material and renderer clipping planes`, async ({
    harness,
  }) => {
    test.setTimeout(90_000);
    const { page, problems } = await harness('webgpu-scene');
    for (const clip of ['local', 'global', 'intersection'] as const) {
      for (const shading of ['phong', 'flat'] as const) {
        const c: SceneCase = { kind: shading === 'flat' ? 'morphed' : 'mesh', shading, clip };
        const r = await run<
          [string, SceneCase],
          {
            removed: number;
            removedNotBackground: number;
            kept: number;
            keptChanged: number;
            added: number;
            phongNode: Diff;
            webgl: Diff;
          }
        >(page, 'clipCompare', backend, c);
        const label = `${backend} ${JSON.stringify(c)} ${JSON.stringify(r)}`;
        expect(r.removed, label).toBeGreaterThan(100);
        expect(r.kept, label).toBeGreaterThan(500);
        expect(r.removedNotBackground, label).toBe(0);
        expect(r.added, label).toBe(0);
        expect(r.keptChanged, label).toBe(0);
        expect(r.phongNode.coverageMismatches, label).toBe(0);
        expectSame(r.webgl, label, 300);
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend}: material.clippingPlanes is ignored by WebGPURenderer (its clipping is ClippingGroup), for ShadingNodeMaterial as for MeshPhongNodeMaterial`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-scene');
    const c: SceneCase = { kind: 'mesh', shading: 'phong', clip: 'material-planes' };
    const r = await run<[string, SceneCase], { removed: number; keptChanged: number; phongNode: Diff }>(
      page,
      'clipCompare',
      backend,
      c,
    );
    expect(r.removed, JSON.stringify(r)).toBe(0);
    expect(r.keptChanged, JSON.stringify(r)).toBe(0);
    expect(r.phongNode.coverageMismatches, JSON.stringify(r)).toBe(0);
    const phong = await run<[string, SceneCase, SceneCase], Diff>(page, 'phongPairDiff', backend, c, {
      ...c,
      clip: 'none',
    });
    expect(phong.coverageMismatches, JSON.stringify(phong)).toBe(0);
    expect(problems).toEqual([]);
  });

  test(`${backend}: ACES tone mapping and the sRGB or linear output colour space = WebGLRenderer + ShadingMaterial on its canvas within 2/255; linear output = the linear target; toneMapped = false changes nothing, as for MeshPhongNodeMaterial (WebGPURenderer tones the whole frame)`, async ({
    harness,
  }) => {
    test.setTimeout(90_000);
    const { page, problems } = await harness('webgpu-scene');
    const cases: SceneCase[] = [
      { kind: 'skinned', shading: 'phong', output: 'srgb', toneMapping: true },
      { kind: 'morphed', shading: 'gouraud', output: 'srgb', toneMapping: true },
      { kind: 'mesh', shading: 'flat', output: 'srgb', toneMapping: true },
      { kind: 'instanced', shading: 'phong', output: 'srgb' },
      { kind: 'instanced', shading: 'phong', output: 'linear' },
    ];
    for (const c of cases) {
      const stats = await run<[string, SceneCase], SceneStats>(page, 'sceneCompare', backend, c);
      const label = `${backend} ${JSON.stringify(c)}`;
      expect(stats.phongNode.coverageMismatches, label).toBe(0);
      expectSame(stats.webgl, label, c.shading === 'flat' ? 300 : 1500);
    }
    const base: SceneCase = { kind: 'instanced', shading: 'phong' };
    // Linear output is the linear picture; sRGB output and tone mapping change it.
    const linear = await run<[string, SceneCase, SceneCase], Diff>(page, 'pairDiff', backend, base, {
      ...base,
      output: 'linear',
    });
    expect(linear.coverageMismatches).toBe(0);
    expect(linear.maxDelta, JSON.stringify(linear)).toBe(0);
    const srgb = await run<[string, SceneCase, SceneCase], Diff>(page, 'pairDiff', backend, base, {
      ...base,
      output: 'srgb',
    });
    expect(srgb.differing).toBeGreaterThan(1000);
    const toned = await run<[string, SceneCase, SceneCase], Diff>(
      page,
      'pairDiff',
      backend,
      { ...base, output: 'srgb' },
      { ...base, output: 'srgb', toneMapping: true },
    );
    expect(toned.differing).toBeGreaterThan(1000);
    // material.toneMapped: WebGPURenderer tone-maps the frame in its output pass, for every material
    // (three.js #28831: not supported by WebGPURenderer); an app that needs a part untoned renders it apart.
    const untoned = await run<[string, SceneCase, SceneCase], Diff>(
      page,
      'pairDiff',
      backend,
      { ...base, output: 'srgb', toneMapping: true },
      { ...base, output: 'srgb', toneMapping: true, toneMapped: false },
    );
    expect(untoned.coverageMismatches).toBe(0);
    expect(untoned.maxDelta, JSON.stringify(untoned)).toBe(0);
    const phongUntoned = await run<[string, SceneCase, SceneCase], Diff>(
      page,
      'phongPairDiff',
      backend,
      { ...base, output: 'srgb', toneMapping: true },
      { ...base, output: 'srgb', toneMapping: true, toneMapped: false },
    );
    expect(phongUntoned.maxDelta, JSON.stringify(phongUntoned)).toBe(0);
    expect(problems).toEqual([]);
  });

  test(`${backend}: materials of different variants drawn together in one scene each draw their own variant`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-scene');
    const d = await run<[string], Diff>(page, 'mixedVariants', backend);
    expect(d.coverageMismatches, JSON.stringify(d)).toBe(0);
    expect(d.covered).toBeGreaterThan(1500);
    expect(d.maxDelta, JSON.stringify(d)).toBe(0);
    expect(problems).toEqual([]);
  });

  test(`${backend}: a variant changed through the setters after the first frame (shading, lighting, celBands) draws as a new material of that variant`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-scene');
    const from: SceneCase = { kind: 'mesh', shading: 'phong' };
    for (const to of [{ shading: 'gouraud' }, { lighting: 'blinn-phong' }, { celBands: 4 }] as const) {
      const r = await run<[string, SceneCase, Partial<SceneCase>], { changed: number; againstFresh: Diff }>(
        page,
        'variantSwitch',
        backend,
        from,
        to,
      );
      const label = `${backend} ${JSON.stringify(to)} ${JSON.stringify(r)}`;
      expect(r.changed, label).toBeGreaterThan(100);
      expect(r.againstFresh.coverageMismatches, label).toBe(0);
      expect(r.againstFresh.maxDelta, label).toBe(0);
    }
    expect(problems).toEqual([]);
  });
}

interface LossReport {
  messages: string[];
  deviceLostCalls: { api: string; message: string; reason: string | null }[];
  isDeviceLost: boolean;
  renderAfterLoss: string;
  readAfterLoss: string;
  identical: boolean;
  covered: number;
}

/** What the harness's deviceLoss() reports (tests/harness/webgpu-scene.ts). */
const lossMessage = /WebGPURenderer: (WebGPU|WebGL) Device Lost:/;

test('WebGPU backend, device lost (GPU process crash, driver reset; simulated with the reason "unknown"): three calls renderer.onDeviceLost once with a clear message and stops drawing; a new WebGPURenderer draws the same scene with the same ShadingNodeMaterial to the same pixels', async ({
  page,
}) => {
  // What the app does: renderer.onDeviceLost = (info) => { stop the animation loop; const next = new
  // WebGPURenderer(options); await next.init(); go on rendering the same scene with `next` }. Scenes, geometries
  // and ShadingNodeMaterials are kept: the new renderer builds their GPU resources again. three's default
  // handler only logs the message and makes later render() calls return at once (a readback of a target drawn
  // after the loss throws three's TypeError: the target was never allocated).
  const problems = await open(page);
  const r = await run<[string], LossReport>(page, 'deviceLoss', 'lost');
  const info = JSON.stringify(r);
  expect(r.deviceLostCalls, info).toEqual([
    { api: 'WebGPU', message: 'simulated GPU process loss', reason: 'unknown' },
  ]);
  expect(r.messages, info).toHaveLength(1);
  expect(r.messages[0], info).toMatch(lossMessage);
  expect(r.messages[0], info).toContain('Message: simulated GPU process loss\nReason: unknown');
  expect(r.isDeviceLost, info).toBe(true);
  expect(r.renderAfterLoss, info).toBe('returned');
  expect(r.readAfterLoss, info).toMatch(/Error/);
  expect(r.covered, info).toBeGreaterThan(1000);
  expect(r.identical, info).toBe(true);
  expect(problems.filter((p) => !lossMessage.test(p))).toEqual([]);
});

test('WebGPU backend, device.destroy() by the app: three does not call onDeviceLost (it ignores the reason "destroyed"), renders are dropped silently and a readback rejects; a new WebGPURenderer draws the same pixels', async ({
  page,
}) => {
  // An app that destroys the device itself knows it: it makes the new renderer then, as above.
  const problems = await open(page);
  const r = await run<[string], LossReport>(page, 'deviceLoss', 'destroyed');
  const info = JSON.stringify(r);
  expect(r.deviceLostCalls, info).toEqual([]);
  expect(r.messages, info).toEqual([]);
  expect(r.isDeviceLost, info).toBe(false);
  expect(r.renderAfterLoss, info).toBe('returned');
  expect(r.readAfterLoss, info).toMatch(/^AbortError: .*Device was lost/);
  expect(r.identical, info).toBe(true);
  // three's pipeline creation pops a GPU error scope whose promise rejects, unhandled, on the destroyed device.
  expect(problems.filter((p) => p !== 'Instance dropped in popErrorScope')).toEqual([]);
});

test('WebGL2 backend, context lost (WEBGL_lose_context): three calls onDeviceLost with the WebGL message and stops drawing; a new WebGPURenderer (forceWebGL) draws the same pixels', async ({
  page,
}) => {
  const problems = await open(page);
  const r = await run<[string], LossReport>(page, 'deviceLoss', 'context');
  const info = JSON.stringify(r);
  expect(
    r.deviceLostCalls.map((c) => c.api),
    info,
  ).toEqual(['WebGL']);
  expect(r.messages, info).toHaveLength(1);
  expect(r.messages[0], info).toMatch(lossMessage);
  expect(r.isDeviceLost, info).toBe(true);
  expect(r.renderAfterLoss, info).toBe('returned');
  expect(r.readAfterLoss, info).toMatch(/Error/);
  expect(r.identical, info).toBe(true);
  expect(problems.filter((p) => !lossMessage.test(p))).toEqual([]);
});

interface Counts {
  memory: Record<string, number>;
  pipelines: number;
  vertexPrograms: number;
  fragmentPrograms: number;
  nodeBuilds: number;
}

for (const backend of BACKENDS) {
  test(`${backend}: 1,000 ShadingNodeMaterials created, drawn for one frame and disposed: renderer.info.memory, the pipelines, programs and node builds back to where they were; same-variant materials share one pipeline; the picture unchanged`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-scene');
    const r = await run<
      [string, number, number],
      {
        before: Counts;
        peak: Counts;
        after: Counts;
        released: Counts;
        builds: number;
        frames: number;
        sameAsFirst: boolean[];
        covered: number[];
      }
    >(page, 'cycles', backend, 1000, 1);
    const info = JSON.stringify(r);
    expect(r.frames).toBe(1000);
    expect(r.after, info).toEqual(r.before);
    // One pipeline (and one vertex and one fragment program) per variant, kept by the pinned materials: no
    // cycle compiled another.
    expect(r.before.pipelines, info).toBe(3);
    expect(r.peak.pipelines, info).toBe(3);
    expect(r.peak.vertexPrograms, info).toBe(3);
    expect(r.peak.fragmentPrograms, info).toBe(3);
    // At most the one material alive beside the pins holds a node build.
    expect(r.peak.nodeBuilds, info).toBeLessThanOrEqual(4);
    // Each material builds its node graph once (its uniforms are its own), none per frame.
    expect(r.builds, info).toBeLessThanOrEqual(1000);
    test.info().annotations.push({
      type: 'node builds',
      description: `${backend}: ${r.builds} TSL builds for 1,000 materials; pipelines ${r.peak.pipelines}, programs ${r.peak.vertexPrograms} + ${r.peak.fragmentPrograms}`,
    });
    // Disposing the pins releases the rest.
    for (const k of ['pipelines', 'vertexPrograms', 'fragmentPrograms', 'nodeBuilds'] as const)
      expect(r.released[k], info).toBe(0);
    expect(r.released.memory.programs, info).toBe(0);
    expect(r.released.memory.uniformBuffers, info).toBe(0);
    expect(r.sameAsFirst, info).toEqual([true, true, true]);
    for (const c of r.covered) expect(c).toBeGreaterThan(3000);
    expect(problems).toEqual([]);
  });
}

// Shadows (issue 23): a ground plane in the shadow of an occluder, lit by one of three's shadow-casting lights and an
// AmbientLight (tests/material-shadow.spec.ts on WebGLRenderer). Where the shadow falls: three's
// MeshPhongNodeMaterial on the same renderer; colours: shade() with the light × three's shadow factor, and
// WebGLRenderer + ShadingMaterial in the same scene (away from either renderer's shadow edge: their shadow maps
// differ by a texel there).
type ShadowStats = import('./harness/webgpu-scene').ShadowStats;
type ShadowCase = import('./harness/webgpu-scene').ShadowCase;

function expectShadow(s: ShadowStats, label: string, backend: string, shadeable: boolean): void {
  const info = `${label} ${JSON.stringify({ ...s, webglWarnings: s.webglWarnings.length })}`;
  if (backend === 'webgpu') expect(s.backend, info).toEqual({ isWebGPUBackend: true, isWebGLBackend: false });
  else expect(s.backend, info).toEqual({ isWebGPUBackend: false, isWebGLBackend: true });
  expect(s.oracleShadowed, info).toBeGreaterThan(500);
  expect(s.maskCompared, info).toBeGreaterThan(10000);
  expect(s.maskMismatches, info).toBe(0);
  expect(s.webgl.compared, info).toBeGreaterThan(8000);
  expect(s.webgl.maskMismatches, info).toBeLessThan(s.webgl.compared / 100);
  expect(s.webgl.differing, info).toBe(0);
  expect(s.webgl.maxDelta, info).toBeLessThanOrEqual(2);
  if (shadeable) {
    expect(s.compared, info).toBeGreaterThan(8000);
    expect(s.shadowCompared, info).toBeGreaterThan(500);
    expect(s.mismatches, info).toBe(0);
    expect(s.maxError, info).toBeLessThanOrEqual(2);
  }
}

for (const backend of BACKENDS) {
  test(`${backend}: receiveShadow from three's DirectionalLight, SpotLight and PointLight (cube map) in flat, gouraud and phong shading: shadowed exactly where MeshPhongNodeMaterial is, colours = shade() with the light × shadow factor and = WebGLRenderer + ShadingMaterial within 2/255`, async ({
    harness,
  }) => {
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-scene');
    for (const shading of ['flat', 'gouraud', 'phong'] as const) {
      for (const light of ['directional', 'spot', 'point'] as const) {
        const c: ShadowCase = { shading, light, ks: light === 'directional' ? 0 : 0.5 };
        const s = await run<[string, ShadowCase], ShadowStats>(page, 'shadowCompare', backend, c);
        expectShadow(
          s,
          `${backend} ${JSON.stringify(c)}`,
          backend,
          shading !== 'gouraud' || light === 'directional',
        );
      }
    }
    expect(problems).toEqual([]);
  });

  test(`${backend}: shadows with shadow.intensity 0.5, a texture, DoubleSide, and receiveShadow false (lit everywhere), in gouraud and flat shading (the terms recorded per vertex or face, shadowed per fragment)`, async ({
    harness,
  }) => {
    test.setTimeout(90_000);
    const { page, problems } = await harness('webgpu-scene');
    for (const shading of ['flat', 'gouraud'] as const) {
      for (const extra of [{ intensity: 0.5 }, { map: true, ks: 0.5 }, { doubleSide: true }] as const) {
        const c: ShadowCase = { shading, light: 'directional', ...extra };
        const s = await run<[string, ShadowCase], ShadowStats>(page, 'shadowCompare', backend, c);
        expectShadow(s, `${backend} ${JSON.stringify(c)}`, backend, shading === 'flat' || !('ks' in extra));
      }
      const c: ShadowCase = { shading, light: 'directional', receive: false };
      const s = await run<[string, ShadowCase], ShadowStats>(page, 'shadowCompare', backend, c);
      const info = `${backend} ${JSON.stringify(c)} ${JSON.stringify(s)}`;
      expect(s.shadowed, info).toBe(0);
      expect(s.mismatches, info).toBe(0);
      expect(s.compared, info).toBeGreaterThan(8000);
    }
    expect(problems).toEqual([]);
  });

  test(`${backend}: a PhongLight with castShadow = true casts no shadow and breaks no material: the picture (ShadingNodeMaterial and three's MeshPhongNodeMaterial receiving a DirectionalLight's shadow) is exactly the one with castShadow false, no console error; three's light still shadows a ground lit by that PhongLight (= shade()); WebGLRenderer warns that it has no shadow and draws the same`, async ({
    harness,
  }) => {
    test.setTimeout(60_000);
    const { page, problems } = await harness('webgpu-scene');
    const r = await run<[string], { differing: number; drawn: number; black: number; backend: unknown }>(
      page,
      'phongCaster',
      backend,
    );
    const info = JSON.stringify(r);
    expect(r.backend, info).toEqual(
      backend === 'webgpu'
        ? { isWebGPUBackend: true, isWebGLBackend: false }
        : { isWebGPUBackend: false, isWebGLBackend: true },
    );
    expect(r.drawn, info).toBeGreaterThan(5000);
    expect(r.black, info).toBe(0);
    expect(r.differing, info).toBe(0);
    for (const shading of ['flat', 'gouraud', 'phong'] as const) {
      const c: ShadowCase = { shading, light: 'directional', phongCaster: true };
      const s = await run<[string, ShadowCase], ShadowStats>(page, 'shadowCompare', backend, c);
      expectShadow(s, `${backend} ${JSON.stringify(c)}`, backend, shading !== 'gouraud');
      test.info().annotations.push({
        type: 'WebGLRenderer and a PhongLight with castShadow',
        description: `${s.webglWarnings.length} console.warn over 2 frames: ${s.webglWarnings[0] ?? 'none'}`,
      });
    }
    expect(problems).toEqual([]);
  });
}
