// Issue 23's parity test: every row of the any-scene table drawn by ShadingMaterial on WebGLRenderer and by
// ShadingNodeMaterial (the same options) on WebGPURenderer's WebGPU and WebGL2 backends, compared through the kit's
// own matcher (`toMatchAcrossRenderers`, which proves each backend ran and attaches the pictures and diffs on a
// failure) within the bound: each pixel within 2 codes of the other picture's 3 × 3 neighbourhood. The
// rows' colours are judged against shade() and three's own materials in material-webgpu-scene.spec.ts,
// material-surface.spec.ts and material-dropin.spec.ts; this spec holds the renderers to one picture.
// Harness: tests/harness/parity-rows.ts (one named scene per row); one page per worker, its renderers shared.
import type { Browser, Page } from '@playwright/test';
import { shadelabUse } from '@shadelab/playwright';
import type { PageRenderers, RendererName } from '@shadelab/playwright/page';
import { compareNeighbourhood, expect, RENDERER_NAMES, test } from '@shadelab/playwright/test';

test.use(shadelabUse({ webgpu: true }));

let shared: Page | undefined;
async function harness(browser: Browser, baseURL: string | undefined): Promise<Page> {
  if (shared === undefined || shared.isClosed()) {
    shared = await browser.newPage({ baseURL });
    await shared.goto('/harness/?page=parity-rows');
  }
  return shared;
}
test.afterAll(async () => {
  await shared?.close();
});

/** The bound: 2 codes, a pixel's 3 × 3 neighbourhood (an edge may move by a pixel between backends). */
const PARITY = { maxChannelDiff: 2, radiusPx: 1, maxDiffPixels: 0, width: 160, height: 120 } as const;

const ROWS: [string, string][] = [
  ['map', 'a colour map (sRGB texels) multiplies ka and kd'],
  ['vertexColors', 'vertex colours'],
  ['normalMap', 'a tangent-space normal map'],
  ['emissive', 'emissive × emissiveMap'],
  ['alphaTest', 'alphaTest with an alphaMap, DoubleSide'],
  ['linearOutput', 'a linear output colour space'],
  ['threeLights', 'three’s five light kinds together (the drop-in 1/π mapping)'],
  ['phongLights', 'two PhongLights, one attenuated'],
  ['flatSoup', 'flat shading of an indexed mesh (a triangle soup made by the material)'],
  ['flatPrepared', 'flat shading of flatShadingGeometry made for the backend’s provoking vertex'],
  ['gouraud', 'Gouraud shading'],
  ['cel', 'cel shading, 4 bands, Blinn-Phong'],
  ['doubleSide', 'DoubleSide (an open sphere, its inside lit)'],
  ['instanced', 'an InstancedMesh with non-uniform scales and instanceColor'],
  [
    'instancedSphere',
    'an InstancedMesh of the subdivided sphere without a normal attribute (normal = position)',
  ],
  ['shadows', 'a DirectionalLight’s shadow cast and received'],
];

for (const [name, what] of ROWS) {
  test(`${name}: ${what}: the same picture on WebGLRenderer and both WebGPURenderer backends`, async ({
    browser,
    baseURL,
  }) => {
    const page = await harness(browser, baseURL);
    await expect(page).toMatchAcrossRenderers(name, { ...PARITY, name });
  });
}

/** One picture of the registered scene `name` per renderer, through the page side of the kit's matcher. */
async function pictures(page: Page, name: string, arg: unknown): Promise<Map<RendererName, Uint8Array>> {
  const drawn = await page.evaluate(
    ([n, a, w, h]) =>
      ((globalThis as Record<symbol, unknown>)[Symbol.for('shadelab.renderers')] as PageRenderers).render(n, {
        renderers: ['webgl', 'webgpu', 'webgpu-webgl2'],
        width: w,
        height: h,
        arg: a,
      }),
    [name, arg, PARITY.width, PARITY.height] as const,
  );
  const out = new Map<RendererName, Uint8Array>();
  for (const p of drawn) {
    if (!p.ok) throw new Error(`${name} on ${p.renderer}: ${p.error}`);
    out.set(p.renderer, new Uint8Array(Buffer.from(p.pixels, 'base64')));
  }
  return out;
}

// Where WebGPURenderer has its own way (docs/design.md, "WebGPURenderer's own ways"), the node material follows
// it as three's own node materials do: fog (three's node fog), tone mapping (the output pass, the clear colour
// included) and blending (in linear). The WebGL and WebGPU pictures then differ, for three's MeshPhongMaterial as
// for ours. So each row is held to three's material on the same renderer (diffuse-only objects, which three's
// MeshPhongMaterial with specular 0 draws with the same pixels under three's lights), and the two WebGPU backends
// to one picture through the kit's matcher.
const OWN_WAY: [string, string][] = [
  ['fog', 'linear Fog'],
  ['fogExp2', 'FogExp2'],
  ['toneMapping', 'ACES tone mapping, exposure 1.4'],
  ['alpha', 'opacity + transparent over a ground'],
];

for (const [name, what] of OWN_WAY) {
  test(`${name}: ${what}: on every renderer the picture of three’s MeshPhongMaterial there; both WebGPURenderer backends one picture`, async ({
    browser,
    baseURL,
  }) => {
    const page = await harness(browser, baseURL);
    await expect(page).toMatchAcrossRenderers(name, {
      ...PARITY,
      name,
      renderers: ['webgpu', 'webgpu-webgl2'],
    });
    const ours = await pictures(page, name, { three: false });
    const three = await pictures(page, name, { three: true });
    const { width, height } = PARITY;
    for (const renderer of RENDERER_NAMES) {
      const a = { width, height, data: ours.get(renderer) as Uint8Array };
      const b = { width, height, data: three.get(renderer) as Uint8Array };
      const c = compareNeighbourhood(a, b, { radiusPx: 1, maxChannelDiff: PARITY.maxChannelDiff });
      expect(c.failingPixels, `${name} on ${renderer}: ${JSON.stringify({ ...c, excess: undefined })}`).toBe(
        0,
      );
    }
  });
}
