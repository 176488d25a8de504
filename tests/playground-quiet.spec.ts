// What every visitor meets: a console without warnings or errors on load and across the tools (the Learn panel, the
// probe, the intensity profile, the attenuation curve, the normal-matrix view, adaptive shading, copy as code, the
// compare and parity views, WebGPU mode), and every control named for a screen reader (Playwright's accessible
// names, as getByRole finds them).
import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import { listenConsole, open, settle } from './playground-helpers';

/** The ARIA roles of controls: each must have an accessible name. */
const CONTROLS = [
  'button',
  'checkbox',
  'combobox',
  'listbox',
  'radio',
  'slider',
  'spinbutton',
  'switch',
  'tab',
  'textbox',
];

/** The controls of the page's accessibility tree that have no accessible name, as the ARIA snapshot lists them. */
async function unnamed(page: Page): Promise<string[]> {
  const snapshot = await page.locator('body').ariaSnapshot();
  return snapshot
    .split('\n')
    .map((line) => line.trim().replace(/^- /, ''))
    .filter((line) => {
      const role = /^([a-z]+)\b/.exec(line)?.[1];
      // A named node is `role "name"` (or `role /name/`); an unnamed one is the role alone, maybe with [state].
      return role !== undefined && CONTROLS.includes(role) && !/^[a-z]+ ["/]/.test(line);
    });
}

test('the console stays quiet on load and across the tools, and every control has an accessible name', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await page.setViewportSize({ width: 1280, height: 800 });
  const heard = listenConsole(page);
  await open(page);
  expect(await unnamed(page), 'controls without a name on the first screen').toEqual([]);

  const canvas = page.getByTestId('viewport');
  const box = (await canvas.boundingBox())!;
  // The Learn panel, two steps of it.
  await page.getByRole('button', { name: /Learn the lecture/ }).click();
  await page.getByTestId('lesson').getByRole('button', { name: 'next' }).click();
  await settle(page);
  // The probe.
  await canvas.click({ modifiers: ['Alt'], position: { x: box.width / 2, y: box.height / 2 } });
  await expect(page.getByTestId('probe-panel')).toHaveAttribute('data-probed', '1');
  expect(await unnamed(page), 'controls without a name with the lesson and the probe open').toEqual([]);
  await page.getByTestId('lesson').getByRole('button', { name: 'leave the lesson' }).click();
  // Each learning tool, turned on and off.
  for (const tool of ['intensity profile', 'attenuation curve', 'normal matrix']) {
    await page.getByRole('button', { name: tool }).click();
    await settle(page);
    expect(await unnamed(page), `controls without a name with the ${tool} open`).toEqual([]);
    await page.getByRole('button', { name: tool }).click();
  }
  // Copy as code: the dialog opens and closes.
  await page.getByTestId('copy-code-three').click();
  await expect(page.getByRole('dialog')).toBeVisible();
  expect(await unnamed(page), 'controls without a name in the copy-as-code dialog').toEqual([]);
  await page.keyboard.press('Escape');
  await expect(page.getByRole('dialog')).toHaveCount(0);
  // The other views, the instanced scene with adaptive shading, and WebGPU mode and back.
  for (const state of [
    { view: 'compare' },
    { view: 'parity' },
    { scene: 'instanced' },
    { scene: 'lights', renderer: 'webgpu' },
    { scene: 'lights', renderer: 'webgl' },
  ]) {
    await page.evaluate(
      (hash) => {
        location.hash = hash;
      },
      `s=${encodeURIComponent(JSON.stringify(state))}`,
    );
    await settle(page, 400);
    if (state.scene === 'instanced') {
      await page.getByRole('button', { name: 'adaptive shading' }).click();
      await page.getByTestId('adaptive-toggle').check();
      await expect(page.getByTestId('adaptive-error')).toContainText('p99', { timeout: 20_000 });
      expect(await unnamed(page), 'controls without a name with adaptive shading open').toEqual([]);
      await page.getByTestId('adaptive-toggle').uncheck();
      await page.getByRole('button', { name: 'adaptive shading' }).click();
    }
  }
  await settle(page, 400);
  // Two notes of Chromium's own: this browser is launched without WebGPU (as most tests are), and Chromium warns
  // that it found no adapter when the page first asks for one (the page asks once, however often WebGPU mode and
  // the parity view start); and ANGLE notes once per WebGL context (the view's, the parity view's and WebGPU mode's
  // WebGL2 backend's) that a read-back waited for the GPU (the stats time each frame to a 1×1 read-back).
  const browserNotes: [RegExp, number][] = [
    [/^warning: No available adapters\.$/, 1],
    [/^warning: .*GL Driver Message .*Performance.*GPU stall due to ReadPixels/, 3],
  ];
  for (const [note, most] of browserNotes)
    expect(heard.filter((m) => note.test(m)).length).toBeLessThanOrEqual(most);
  expect(heard.filter((m) => !browserNotes.some(([note]) => note.test(m)))).toEqual([]);
});
