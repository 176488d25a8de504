// The shader as compiled (issue 24): WebGL mode's GLSL view opens on the program this scene compiles (the
// material's source without its inactive #if branches), with a toggle for the full source. The oracle is the
// GPU's own input: every `shaderSource` call of the page is recorded, and the shown text, compiled as an edit,
// must give the same active program (three's prefix included, see playground/src/learn/compiledShader.ts) and
// the same picture as the generated source. WebGPU mode's WGSL: playground-webgpu-flags.spec.ts.
import { expect, type Page } from '@playwright/test';
import { activeGlsl, isConditional } from '../playground/src/learn/compiledShader';
import { test } from './harness-helpers';
import { open, picture, settle } from './playground-helpers';

/** Records every GLSL source the page hands to WebGL, in order (three compiles the vertex stage first). */
async function recordShaders(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const seen: string[] = [];
    (window as unknown as { shaderSources: string[] }).shaderSources = seen;
    const proto = WebGL2RenderingContext.prototype;
    const original = proto.shaderSource;
    proto.shaderSource = function (shader: WebGLShader, source: string) {
      seen.push(source);
      return original.call(this, shader, source);
    };
  });
}

/** The last program (vertex, fragment) handed to WebGL whose vertex stage passes `pick`. */
async function lastProgram(page: Page, pick: 'generated' | 'edited'): Promise<[string, string]> {
  const sources = await page.evaluate(() => (window as unknown as { shaderSources: string[] }).shaderSources);
  for (let i = sources.length - 2; i >= 0; i--) {
    const [vertex, fragment] = [sources[i]!, sources[i + 1]!];
    if (!vertex.includes('shadingNormalMatrix') || !/gl_Position/.test(vertex)) continue;
    const tagged = vertex.includes('// @L');
    if (vertex.includes('// @A')) continue; // the view's own off-screen compile
    if ((pick === 'edited') === tagged) return [vertex, fragment];
  }
  throw new Error(`no ${pick} program among ${sources.length} sources`);
}

const text = (page: Page) => page.getByTestId('shader-text');

/** The shown text of both stages. */
async function shown(page: Page): Promise<{ vertex: string; fragment: string }> {
  await page.getByRole('tab', { name: 'vertex' }).click();
  const vertex = await text(page).inputValue();
  await page.getByRole('tab', { name: 'fragment' }).click();
  return { vertex, fragment: await text(page).inputValue() };
}

const STATES: Record<string, object> = {
  'the lecture’s sphere (Phong shading, Blinn-Phong)': {},
  'flat shading, Phong lighting': { material: { shading: 'flat', lighting: 'phong' } },
  'Gouraud, 4 cel bands, two attenuated lights': {
    material: { shading: 'gouraud', celBands: 4 },
    lights: [
      { position: [-5, 10, 20], attenuation: { a: 1, b: 0.05, c: 0.01 } },
      { position: [4, -2, 6], diffuse: [0.2, 0.4, 1] },
    ],
  },
  'a logarithmic depth buffer (three adds USE_LOGARITHMIC_DEPTH_BUFFER)': {
    camera: { depth: 'logarithmic' },
  },
};

for (const [name, state] of Object.entries(STATES)) {
  test(`${name}: the view shows the compiled lines only, and they compile to the program the GPU runs`, async ({
    page,
  }) => {
    await recordShaders(page);
    await open(page, state);
    await expect(text(page)).toHaveAttribute('data-view', 'compiled');
    const good = await picture(page);
    const { vertex, fragment } = await shown(page);
    for (const stage of [vertex, fragment]) {
      expect(stage.split('\n').filter(isConditional)).toEqual([]);
      expect(stage).not.toContain('USE_INSTANCING');
      expect(stage).toContain('void main()');
    }
    const generated = await lastProgram(page, 'generated');
    // The shown text, run as an edit (a comment added so that it is a change): the same active program.
    await text(page).fill(`${fragment}\n// the shown text, unchanged\n`);
    await expect(page.getByTestId('shader-status')).toHaveText(/compiled and rendering/);
    await settle(page);
    const edited = await lastProgram(page, 'edited');
    expect(activeGlsl(edited[0])).toBe(activeGlsl(generated[0]));
    expect(activeGlsl(edited[1])).toBe(activeGlsl(generated[1]));
    expect(await picture(page)).toBe(good);
    // Much shorter than what three gets, which is the full source behind three's prefix.
    expect(vertex.length + fragment.length).toBeLessThan(0.5 * (generated[0].length + generated[1].length));
  });
}

test('the full-source toggle shows every #if branch; the compiled lines are a subsequence of it', async ({
  page,
}) => {
  await open(page);
  const compiled = await shown(page);
  const toggle = page.getByTestId('shader-full');
  await toggle.check();
  await expect(text(page)).toHaveAttribute('data-view', 'full');
  const full = await shown(page);
  for (const stage of ['vertex', 'fragment'] as const) {
    expect(full[stage]).toContain('USE_INSTANCING');
    expect(full[stage].split('\n').some(isConditional)).toBe(true);
    const lines = full[stage].split('\n');
    let at = 0;
    for (const line of compiled[stage].split('\n').filter((l) => l.trim() !== '')) {
      at = lines.indexOf(line, at);
      expect(at, `line ${JSON.stringify(line)} of the compiled view, in order`).toBeGreaterThanOrEqual(0);
      at++;
    }
  }
  // An edit keeps its view until reset; back to the compiled view after it.
  await text(page).fill(`${full.fragment}\n// edited\n`);
  await expect(text(page)).toHaveAttribute('data-view', 'edited');
  await expect(toggle).toBeDisabled();
  await page.getByRole('button', { name: 'reset to generated' }).click();
  await expect(text(page)).toHaveAttribute('data-view', 'full');
  await toggle.uncheck();
  await expect(text(page)).toHaveAttribute('data-view', 'compiled');
  expect((await shown(page)).fragment).toBe(compiled.fragment);
});
