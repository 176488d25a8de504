// Switching renderers back and forth, as a user tries them (issue 35): WebGL → WebGPU → WebGL five times in every
// scene the picker offers and on a loaded model, in a browser without WebGPU (the default flags: WebGPU mode runs
// WebGPURenderer's WebGL2 backend). Each time WebGPU mode runs the backend it says (its canvas holds a WebGL2
// context, and its first frames are drawn), and back in WebGL mode nothing is lost: the state in the URL (the
// camera and the trackball among it), the model, and the picture, pixel for pixel. No banner is left, and the
// console holds nothing but Chromium's own notes. With the WebGPU flags, where presenting loses the device:
// playground-webgpu-flags.spec.ts.
import { expect } from '@playwright/test';
import { BoxGeometry } from 'three';
import { glbOf } from './glb';
import { test } from './harness-helpers';
import { choose, listenConsole, open, picture, settle, urlState } from './playground-helpers';
import { toWebGPU } from './playground-webgpu-helpers';

const FALLBACK = /^Renderer: WebGL2 \(WebGPU's fallback: (no WebGPU adapter|this browser has no WebGPU)\)$/;
const ROUNDS = 5;

/** A state away from the defaults: the trackball turned and the eye moved, so that losing either shows. */
const MOVED = {
  camera: { eye: [0.4, 0.3, 3.2] },
  trackball: { rotation: [0.25881904510252074, 0.2, 0, 0.9450287318402637] },
};

const SCENES = ['sphere', 'instanced', 'skinned', 'textured', 'lights', 'model'] as const;

for (const scene of SCENES) {
  test(`${scene}: WebGL → WebGPU → WebGL ${ROUNDS} times runs the backend asked for each time and loses nothing`, async ({
    page,
  }) => {
    test.setTimeout(240_000);
    const heard = listenConsole(page);
    await open(page, { ...MOVED, scene: scene === 'model' ? 'sphere' : scene });
    if (scene === 'model') {
      const buffer = glbOf(new BoxGeometry(1, 0.6, 0.8), {
        baseColorFactor: [0.8, 0.3, 0.2, 1],
        metallicFactor: 0,
        roughnessFactor: 0.6,
      });
      await page
        .getByTestId('model-file')
        .setInputFiles({ name: 'box.glb', mimeType: 'model/gltf-binary', buffer });
      await expect(page.getByTestId('model-note')).toContainText('“box.glb”', { timeout: 20_000 });
      await settle(page);
    }
    const settings = await urlState(page);
    const webgl = await picture(page);
    for (let round = 1; round <= ROUNDS; round++) {
      const at = `round ${round}`;
      await toWebGPU(page);
      await expect(page.getByTestId('renderer-backend'), at).toHaveText(FALLBACK);
      const gpuCanvas = page.getByTestId('viewport-webgpu');
      expect(
        await gpuCanvas.evaluate((c: HTMLCanvasElement) => c.getContext('webgl2') !== null),
        `${at}: WebGPU mode's canvas holds the WebGL2 backend's context`,
      ).toBe(true);
      expect(await urlState(page), at).toEqual({ ...settings, renderer: 'webgpu' });
      if (scene === 'model') await expect(page.getByTestId('model-note'), at).toContainText('“box.glb”');

      await choose(page, 'View.renderer', 'WebGL');
      await expect(gpuCanvas, `${at}: WebGPU mode's canvas is gone`).toHaveCount(0);
      await settle(page);
      expect(await urlState(page), at).toEqual(settings);
      expect(await picture(page), `${at}: WebGL mode's picture`).toBe(webgl);
      await expect(page.getByTestId('renderer-note'), at).toHaveCount(0);
      await expect(page.locator('.messages .message'), `${at}: no banner left`).toHaveCount(0);
      if (scene === 'model') await expect(page.getByTestId('model-note'), at).toContainText('“box.glb”');
    }
    // Chromium's own notes (see playground-quiet.spec.ts): it found no WebGPU adapter (the page asks once), and
    // ANGLE notes once per WebGL context that a read-back waited for the GPU: the view's, and each WebGPU mode's
    // WebGL2 backend's.
    const browserNotes: [RegExp, number][] = [
      [/^warning: No available adapters\.$/, 1],
      [/^warning: .*GL Driver Message .*Performance.*GPU stall due to ReadPixels/, 1 + ROUNDS],
    ];
    for (const [note, most] of browserNotes)
      expect(heard.filter((m) => note.test(m)).length).toBeLessThanOrEqual(most);
    expect(heard.filter((m) => !browserNotes.some(([note]) => note.test(m)))).toEqual([]);
  });
}
