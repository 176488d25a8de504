// The Learn panel (playground/src/learn/Lesson.tsx, lessonSteps.ts), walked as a student takes it: opened from the
// first screen, every step in order with back and next, left half-way and opened again where it was, each step's
// claim checked on the page: the state it sets, and what it says to look at (the probe's terms, r under Phong
// lighting, the attenuation factor, the Mach-band count).
import { expect, type Page } from '@playwright/test';
import { LESSON_LIGHT_POSITION, LESSON_STEPS } from '../playground/src/learn/lessonSteps';
import { test } from './harness-helpers';
import { open, openFolderOf, settle, typeInto, urlState } from './playground-helpers';

let probes = 0;

/** Alt+clicks the view at (fx, fy) (fractions of its size); the probe panel once it has probed that pixel. */
async function probe(page: Page, fx: number, fy: number) {
  const canvas = page.getByTestId('viewport');
  const box = (await canvas.boundingBox())!;
  await canvas.click({
    modifiers: ['Alt'],
    position: { x: Math.floor(box.width * fx) + 0.5, y: Math.floor(box.height * fy) + 0.5 },
  });
  probes++;
  const panel = page.getByTestId('probe-panel');
  await expect(panel).toHaveAttribute('data-probed', String(probes));
  return panel;
}

/** A row of the probe panel (its `dt` named `name`, in the section of light `light` when given): its numbers. */
async function row(page: Page, name: string, light?: number): Promise<number[]> {
  const scope = light
    ? page.getByTestId('probe-panel').locator(`section[aria-label="light ${light}"]`)
    : page.getByTestId('probe-panel');
  const text = await scope
    .locator('dt', { hasText: name })
    .first()
    .locator('xpath=following-sibling::dd[1]')
    .textContent();
  return (text?.match(/-?\d+(\.\d+)?(e-?\d+)?/g) ?? []).map(Number);
}

/** The probe's 8-bit colour is the GPU's pixel within 1/255. */
async function expectProbeAgrees(page: Page, where: string) {
  const rgb = async (id: string) =>
    ((await page.getByTestId(id).getAttribute('data-rgb')) ?? '').split(',').map(Number);
  const cpu = await rgb('probe-cpu');
  const gpu = await rgb('probe-gpu');
  expect(cpu, where).toHaveLength(3);
  expect(
    Math.max(...cpu.map((c, i) => Math.abs(c - gpu[i]!))),
    `${where}: ${cpu} vs ${gpu}`,
  ).toBeLessThanOrEqual(1);
}

/** Goes to the next step and waits until the page shows its state. */
async function next(page: Page, id: string) {
  await page.getByTestId('lesson').getByRole('button', { name: 'next' }).click();
  await expect(page.getByTestId('lesson')).toHaveAttribute('data-step', id);
  await settle(page);
}

test('a student walks every step of the Learn panel, and each step shows what it says', async ({ page }) => {
  test.setTimeout(180_000);
  await page.setViewportSize({ width: 1280, height: 800 });
  await open(page);
  const lesson = page.getByTestId('lesson');
  // Light 1 sits behind the eye, up and to the left: an arrow on the view's border points that way.
  const arrows = page.getByTestId('light-arrow');
  await expect(arrows).toHaveCount(1);
  await expect(arrows).toHaveAttribute('data-light', '1');
  await expect(arrows).toHaveAttribute('aria-label', 'Light 1 is behind the eye: this way');
  const view = (await page.getByTestId('viewport').boundingBox())!;
  const arrow = (await arrows.boundingBox())!;
  expect(arrow.x).toBeGreaterThanOrEqual(view.x);
  expect(arrow.y).toBeGreaterThanOrEqual(view.y);
  expect(arrow.x + arrow.width / 2).toBeLessThan(view.x + view.width / 2);
  expect(arrow.y + arrow.height / 2).toBeLessThan(view.y + view.height / 2);
  await page.getByRole('button', { name: /Learn the lecture/ }).click();
  await expect(lesson).toHaveAttribute('data-step', 'lights');
  await expect(lesson).toContainText(`Step 1 of ${LESSON_STEPS.length}`);
  await expect(lesson).toContainText('Alt+click');
  await settle(page);

  // 1. Lights: light 2 is added beside the sphere, in the view; halving its Id halves its diffuse term.
  let state = await urlState(page);
  const lights = state['lights'] as { position: number[] }[];
  expect(lights).toHaveLength(2);
  expect(lights[1]!.position).toEqual(LESSON_LIGHT_POSITION);
  // Light 2 is in the view: no arrow for it.
  await expect(arrows).toHaveCount(1);
  await expect(arrows).toHaveAttribute('data-light', '1');
  await probe(page, 0.3, 0.32); // the upper left, which light 2 lights
  const diffuse = await row(page, 'att·kd·Id·max(l·n,0)', 2);
  expect(diffuse).toHaveLength(3);
  for (const c of diffuse) expect(c).toBeGreaterThan(0.02);
  await expectProbeAgrees(page, 'lights');
  // Leva names a vector's inputs by its path, then .y and .z.
  const ids = ['Light 2.light2Id', 'Light 2.light2Id.y', 'Light 2.light2Id.z'];
  await openFolderOf(page.locator(`[id="${ids[0]}"]`));
  for (const id of ids) await typeInto(page, id, '0.5');
  await probe(page, 0.3, 0.32);
  const halved = await row(page, 'att·kd·Id·max(l·n,0)', 2);
  for (const [i, c] of halved.entries())
    expect(Math.abs(c - diffuse[i]! / 2), `channel ${i}`).toBeLessThanOrEqual(0.0011);
  await expectProbeAgrees(page, 'lights, Id halved');

  // 2. The terms: the diffuse term alone; the probe evaluates the same view. Left here, and opened again here.
  await next(page, 'terms');
  expect(((await urlState(page))['material'] as { output: string }).output).toBe('diffuse');
  await probe(page, 0.45, 0.45);
  await expect(page.getByTestId('probe-panel')).toContainText('the diffuse view');
  await expectProbeAgrees(page, 'terms');
  await lesson.getByRole('button', { name: 'leave the lesson' }).click();
  await expect(lesson).toHaveCount(0);
  expect(((await urlState(page))['material'] as { output: string }).output).toBe('diffuse');
  await page.getByRole('button', { name: /Learn the lecture/ }).click();
  await expect(lesson).toHaveAttribute('data-step', 'terms');

  // 3. Phong lighting: the probe shows r and v·r.
  await next(page, 'specular');
  state = await urlState(page);
  expect(state['material']).toMatchObject({ lighting: 'phong', output: 'specular' });
  await probe(page, 0.45, 0.45);
  const r = await row(page, 'r', 1);
  expect(r.length).toBeGreaterThanOrEqual(4); // r's three components and v·r
  expect(Math.hypot(r[0]!, r[1]!, r[2]!)).toBeCloseTo(1, 2);
  await expect(page.getByTestId('probe-panel')).toContainText('v·r');
  await expectProbeAgrees(page, 'specular');

  // 4. Attenuation: c = 0.002 on light 1, and the probe's att is 1 / (1 + 0.002 t²) at its t.
  await next(page, 'attenuation');
  state = await urlState(page);
  expect((state['lights'] as { attenuation: object }[])[0]!.attenuation).toEqual({ a: 1, b: 0, c: 0.002 });
  await probe(page, 0.45, 0.45);
  const [t] = await row(page, 't', 1);
  const [att] = await row(page, 'att', 1);
  expect(att!).toBeCloseTo(1 / (1 + 0.002 * t! * t!), 3);
  await expectProbeAgrees(page, 'attenuation');

  // 5. The three shadings side by side on a coarse sphere.
  await next(page, 'shadings');
  state = await urlState(page);
  expect(state['view']).toBe('compare');
  expect((state['sphere'] as { level: number }).level).toBe(2);

  // 6. Mach bands: the profile's legend counts the slope jumps it marks; flat shading's are there.
  await next(page, 'mach-bands');
  expect(((await urlState(page))['material'] as { shading: string }).shading).toBe('gouraud');
  await page.getByRole('button', { name: 'intensity profile' }).click();
  await expect(page.getByTestId('profile-panel')).toContainText('Drag a line');
  const box = (await page.getByTestId('viewport').boundingBox())!;
  await page.mouse.move(box.x + box.width * 0.2, box.y + box.height * 0.55);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.8, box.y + box.height * 0.45, { steps: 8 });
  await page.mouse.up();
  const plot = page.getByTestId('profile-plot');
  await expect(plot).toBeVisible({ timeout: 15_000 });
  const flatMarks = await plot.locator('g:has(> polyline[data-shading="flat"]) > [data-break]').count();
  expect(flatMarks).toBeGreaterThan(0);
  await expect(page.getByTestId('profile-panel')).toContainText(`flat: ${flatMarks} slope jumps`);
  await expect(page.getByTestId('profile-panel')).not.toContainText(' 0 slope jumps');
  await page.getByRole('button', { name: 'intensity profile' }).click();

  // 7. The normal matrix: a non-uniform scale, and its figure for the probed point.
  await next(page, 'normal-matrix');
  const scale = ((await urlState(page))['model'] as { scale: number[] }).scale;
  expect(new Set(scale).size).toBeGreaterThan(1);

  // 8. The subdivided sphere: an icosahedron divided twice.
  await next(page, 'sphere');
  expect((await urlState(page))['sphere']).toMatchObject({ base: 'icosahedron', level: 2, render: 'mesh' });

  // 9–10. The camera and the trackball: the lecture's sphere, Phong shading, the lit colour.
  for (const step of ['camera', 'trackball']) {
    await next(page, step);
    expect((await urlState(page))['material']).toMatchObject({ output: 'color', shading: 'phong' });
  }

  // 11. Cel: four bands, and the probe names each light's band.
  await next(page, 'cel');
  expect(((await urlState(page))['material'] as { celBands: number }).celBands).toBe(4);
  await probe(page, 0.45, 0.45);
  await expect(page.getByTestId('probe-panel')).toContainText('cel band');

  // 12–13. The shader and the code to take home: what they name is on the page.
  await next(page, 'shader');
  await expect(page.getByRole('region', { name: 'GLSL editor' })).toBeVisible();
  await next(page, 'take-home');
  await expect(page.getByTestId('copy-code-three')).toBeVisible();
  await expect(lesson.getByRole('button', { name: 'next' })).toBeDisabled();

  // Back walks the path the other way; leave keeps the state reached.
  await lesson.getByRole('button', { name: 'back' }).click();
  await expect(lesson).toHaveAttribute('data-step', 'shader');
  await lesson.getByRole('button', { name: 'leave the lesson' }).click();
  await expect(page.getByRole('button', { name: /Learn the lecture/ })).toBeVisible();
});
