// The extremes table (docs/design.md, "Extremes every package is tested at") and reliability on WebGPURenderer,
// on its WebGPU backend and its WebGL2 backend (forceWebGL), rendered offscreen and read back: instance matrices
// with a zero, a 1e20 scale and a negative determinant (shade() of the expected outward normal), fog near = far and
// density 0 and 1e6, opacity and alphaTest 0 and 1 (against three's MeshPhongNodeMaterial), 0, 1 and 64 lights of
// each kind (compiled, finite, pipelines bounded), a lost device, 1,000 create/dispose cycles of the node
// materials, and 1,000 feature flips. Harness: tests/harness/webgpu-reliability.ts.
import { expect, type Page } from '@playwright/test';
import type { Backend, LightKind, WebGPUReliabilityHarness } from './harness/webgpu-reliability';
import { openHarness, webgpuTest as test } from './harness-helpers';

/** Opens the harness; returns the page errors and console errors seen. */
const open = (page: Page): Promise<string[]> => openHarness(page, 'webgpu-reliability');

type H = WebGPUReliabilityHarness;
function run<K extends keyof H>(page: Page, name: K, ...args: Parameters<H[K]>) {
  return page.evaluate(
    ([n, a]) => {
      const h = (window as never as { harness: H }).harness;
      return (h[n] as (...x: unknown[]) => unknown)(...(a as unknown[]));
    },
    [name, args] as const,
  ) as Promise<Awaited<ReturnType<H[K]>>>;
}

const BACKENDS: Backend[] = ['webgpu', 'webgl2'];
const proof = (backend: Backend) => ({
  isWebGPUBackend: backend === 'webgpu',
  isWebGLBackend: backend === 'webgl2',
});

for (const backend of BACKENDS) {
  for (const shading of ['phong', 'gouraud', 'flat'] as const) {
    test(`${backend}, ${shading}: instances with a negative determinant, a zero scale (a box flattened to a square, and all zero) and a 1e20 scale are lit with unit outward finite normals: each face = shade() of its expected normal, with the instance matrices read as three shares them (vertex attributes) and as three binds them for a mesh of its own (a uniform array: a geometry with more attributes)`, async ({
      harness,
    }) => {
      const { page, problems } = await harness('webgpu-reliability');
      for (const crowded of [false, true]) {
        const r = await run(page, 'instanceExtremes', backend, shading, crowded);
        const info = JSON.stringify(r);
        expect(r.backend, info).toEqual(proof(backend));
        expect(r.instanceArray, info).toBe(crowded);
        // Drawn exactly where three's MeshBasicNodeMaterial draws the same instances (the id pass).
        expect(r.coverageMismatches, info).toBe(0);
        expect(r.unexpected, info).toBe(0);
        for (const [name, stats] of Object.entries(r.perInstance)) {
          if (name === 'all zero') {
            expect(stats.drawn, `${name}: ${info}`).toBe(0);
            continue;
          }
          expect(stats.compared, `${name}: ${info}`).toBeGreaterThan(200);
          expect(stats.maxError, `${name}: ${info}`).toBeLessThanOrEqual(2);
        }
      }
      expect(problems).toEqual([]);
    });
  }

  test(`${backend}: fog near = far, density 0 and 1e6, opacity 0 and 1, alphaTest 0 and 1: finite (float target), drawn where MeshPhongNodeMaterial draws and within 2/255 of it; density 0 = no fog, 1e6 = the fog colour, near = far a step`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-reliability');
    const r = await run(page, 'surfaceExtremes', backend);
    const info = JSON.stringify(r);
    expect(r.backend, info).toEqual(proof(backend));
    for (const [name, row] of Object.entries(r.rows)) {
      expect(row.nonFinite, `${name}: ${info}`).toBe(0);
      expect(row.coverageMismatches, `${name}: ${info}`).toBe(0);
      expect(row.maxDelta, `${name}: ${info}`).toBeLessThanOrEqual(2);
    }
    // Opacity 0 draws nothing visible (blended away); alphaTest 1 discards every pixel, as three's node materials
    // discard alpha ≤ alphaTest (WebGLRenderer's chunks: alpha < alphaTest); opacity 1 and alphaTest 0 draw all.
    expect(r.rows['opacity 0, transparent'].covered, info).toBe(0);
    expect(r.rows['alphaTest 1'].covered, info).toBe(0);
    for (const name of ['no fog', 'opacity 1, transparent', 'alphaTest 0'])
      expect(r.rows[name].covered, info).toBeGreaterThan(800);
    expect(r.zeroDelta, info).toBe(0);
    expect(r.fullDelta, info).toBeLessThanOrEqual(1);
    // near = far: each pixel is either unfogged or all fog (three's smoothstep at one depth), both present.
    expect(r.step.other, info).toBe(0);
    expect(r.step.fogged, info).toBeGreaterThan(50);
    expect(r.step.unfogged, info).toBeGreaterThan(50);
    expect(problems).toEqual([]);
  });

  test(`${backend}: no light, and 1 of each kind (ambient, hemisphere, directional, point, spot, PhongLight) alone and all together, in flat, gouraud and phong: compiled, finite, drawn; 200 flips among them add no pipeline`, async ({
    harness,
  }) => {
    const { page, problems } = await harness('webgpu-reliability');
    const r = await run(page, 'lightExtremes', backend, ['flat', 'gouraud', 'phong'], [0, 1], 'both', 200);
    const info = JSON.stringify({ ...r, before: undefined, swept: undefined, peak: undefined });
    expect(r.backend, info).toEqual(proof(backend));
    expect(r.results, info).toHaveLength(8 * 3);
    for (const row of r.results) {
      expect(row.nonFinite, JSON.stringify(row)).toBe(0);
      expect(row.drawn, JSON.stringify(row)).toBe(true);
    }
    // One pipeline per configuration and shading at most; drawing them again compiles nothing.
    expect(r.swept.pipelines - r.before.pipelines, info).toBeLessThanOrEqual(8 * 3);
    expect(r.peak.pipelines, info).toBe(r.swept.pipelines);
    expect(r.peak.vertexPrograms, info).toBe(r.swept.vertexPrograms);
    expect(r.peak.fragmentPrograms, info).toBe(r.swept.fragmentPrograms);
    expect(r.peak.nodeBuilds, info).toBe(r.swept.nodeBuilds);
    expect(r.flipProblems, info).toBe(0);
    expect(problems).toEqual([]);
  });

  // 64 lights of one kind compile for about 2 s here (SwiftShader), up to three times that on a busy machine: three
  // kinds a test.
  for (const shading of ['flat', 'gouraud', 'phong'] as const) {
    for (const kinds of [
      ['ambient', 'hemisphere', 'directional'],
      ['point', 'spot', 'phong'],
    ] as LightKind[][]) {
      test(`${backend}, ${shading}: 64 lights of one kind (${kinds.join(', ')}; phong = PhongLight): compiled, finite, drawn; 30 flips among them add no pipeline`, async ({
        harness,
      }) => {
        const { page, problems } = await harness('webgpu-reliability');
        const r = await run(page, 'lightExtremes', backend, [shading], [64], 'each', 30, kinds);
        const info = JSON.stringify({ ...r, before: undefined, swept: undefined, peak: undefined });
        expect(r.backend, info).toEqual(proof(backend));
        expect(r.results.map((x) => x.config)).toEqual(kinds.map((k) => `64 × ${k}`));
        for (const row of r.results) {
          expect(row.nonFinite, JSON.stringify(row)).toBe(0);
          expect(row.drawn, JSON.stringify(row)).toBe(true);
        }
        expect(r.swept.pipelines - r.before.pipelines, info).toBeLessThanOrEqual(3);
        expect(r.peak.pipelines, info).toBe(r.swept.pipelines);
        expect(r.peak.nodeBuilds, info).toBe(r.swept.nodeBuilds);
        expect(r.flipProblems, info).toBe(0);
        expect(problems).toEqual([]);
      });
    }
  }

  test(`${backend}: 64 lights of every kind in one scene (384 lights), phong: compiled, finite, drawn`, async ({
    harness,
  }) => {
    // One shading: its shader takes about 15 s to compile on an idle machine (SwiftShader), three times that on a
    // busy one; the other shadings are covered per kind above.
    test.setTimeout(120_000);
    const { page, problems } = await harness('webgpu-reliability');
    const r = await run(page, 'lightExtremes', backend, ['phong'], [64], 'together', 0);
    const info = JSON.stringify(r.results);
    expect(r.backend, info).toEqual(proof(backend));
    expect(r.results, info).toEqual([
      {
        config: '64 × ambient+hemisphere+directional+point+spot+phong',
        shading: 'phong',
        nonFinite: 0,
        drawn: true,
      },
    ]);
    expect(problems).toEqual([]);
  });
}

/** Console messages three writes about a device it lost (its default handler), expected in these tests. */
const lossMessage =
  /WebGPURenderer: (WebGPU|WebGL) Device Lost|Instance dropped in popErrorScope|Device was destroyed/;

for (const trigger of ['destroyed', 'lost', 'context'] as const) {
  const what = {
    destroyed:
      'WebGPU backend, device.destroy() on the renderer’s own device (three ignores the reason "destroyed": the app watches device.lost, as the playground does)',
    lost: 'WebGPU backend, the device lost for another reason (a GPU process crash; simulated, reason "unknown"): three calls onDeviceLost',
    context: 'WebGL2 backend, the context lost (WEBGL_lose_context): three calls onDeviceLost',
  }[trigger];
  test(`${what}: the app's handler makes a new WebGPURenderer and it draws ShadingNodeMaterial, its node outline and SphereImpostorNodeMaterial to the same pixels`, async ({
    page,
  }) => {
    const problems = await open(page);
    const r = await run(page, 'deviceLoss', trigger);
    const info = JSON.stringify(r);
    expect(r.backend, info).toEqual(proof(trigger === 'context' ? 'webgl2' : 'webgpu'));
    if (trigger === 'destroyed') {
      expect(r.onDeviceLost, info).toEqual([]);
      expect(r.deviceLost?.reason, info).toBe('destroyed');
    } else if (trigger === 'lost') {
      expect(r.onDeviceLost, info).toEqual([
        { api: 'WebGPU', message: 'simulated GPU process loss', reason: 'unknown' },
      ]);
    } else
      expect(
        r.onDeviceLost.map((c) => c.api),
        info,
      ).toEqual(['WebGL']);
    expect(r.recovered, info).toBe(true);
    expect(r.covered, info).toBeGreaterThan(1500);
    expect(r.outlinePixels, info).toBeGreaterThan(80);
    expect(r.identical, info).toBe(true);
    expect(problems.filter((p) => !lossMessage.test(p))).toEqual([]);
  });
}

for (const backend of BACKENDS) {
  test(`${backend}: 1,000 create/dispose cycles of ShadingNodeMaterial, createOutlineNode's OutlineNodeMaterial and SphereImpostorNodeMaterial end at the baseline (renderer.info.memory, pipelines, programs, node builds); the picture unchanged`, async ({
    page,
  }) => {
    const problems = await open(page);
    // Each cycle creates, configures and disposes all three; every 4th cycle on the WebGPU backend, every 8th on
    // the WebGL2 backend (and the first and last three) is drawn first: 255 and 130 frames, about 5 and 13 s here,
    // so that the test stays well inside its timeout on a busy machine.
    const every = backend === 'webgpu' ? 4 : 8;
    const r = await run(page, 'cycles', backend, 1000, every);
    const info = JSON.stringify(r);
    expect(r.backend, info).toEqual(proof(backend));
    expect(r.frames, info).toBe(backend === 'webgpu' ? 255 : 130);
    expect(r.after, info).toEqual(r.before);
    // At most one pipeline beside the pinned materials' while a cycle's materials are alive.
    expect(r.peak.pipelines, info).toBeLessThanOrEqual(r.before.pipelines + 3);
    expect(r.peak.nodeBuilds, info).toBeLessThanOrEqual(r.before.nodeBuilds + 3);
    for (const k of ['pipelines', 'vertexPrograms', 'fragmentPrograms', 'nodeBuilds'] as const)
      expect(r.released[k], info).toBe(0);
    expect(r.released.memory.programs, info).toBe(0);
    expect(r.released.memory.uniformBuffers, info).toBe(0);
    expect(r.covered, info).toBeGreaterThan(150);
    expect(r.sameAsFirst, info).toEqual([true, true, true, true, true, true]);
    expect(problems).toEqual([]);
  });

  // 1,000 flips on the WebGPU backend, 250 on the WebGL2 backend (three's node and pipeline caches are the same
  // code on both), in runs of 125: every flip rebuilds the material's node graph and compiles its pipeline (about
  // 75 ms here, 250 ms on a busy machine).
  const runs = backend === 'webgpu' ? 8 : 2;
  for (let part = 1; part <= runs; part++) {
    const seed = 987654321 + 7919 * part;
    test(`${backend}: flipping every feature (shading, lighting, celBands, map, emissiveMap, alphaMap, transparent, alphaTest, side, fog, the outline's fog) keeps pipelines, programs and node builds bounded and releases them on dispose (flips ${125 * (part - 1) + 1}–${125 * part} of ${125 * runs})`, async ({
      harness,
    }) => {
      const { page, problems } = await harness('webgpu-reliability');
      const r = await run(page, 'flipFeatures', backend, 125, seed);
      const info = JSON.stringify(r);
      expect(r.backend, info).toEqual(proof(backend));
      expect(r.states, info).toBeGreaterThan(50);
      // The material and its outline: one pipeline each in use (and one being replaced), never one per state.
      expect(r.peak.pipelines, info).toBeLessThanOrEqual(r.before.pipelines + 4);
      expect(r.peak.vertexPrograms, info).toBeLessThanOrEqual(r.before.vertexPrograms + 4);
      expect(r.peak.nodeBuilds, info).toBeLessThanOrEqual(r.before.nodeBuilds + 4);
      expect(r.released.pipelines, info).toBe(r.before.pipelines);
      expect(r.released.nodeBuilds, info).toBe(r.before.nodeBuilds);
      expect(r.released.memory.programs, info).toBe(r.before.memory.programs);
      expect(r.drawn, info).toBeGreaterThan(0);
      expect(problems).toEqual([]);
    });
  }
}
