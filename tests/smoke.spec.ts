import { readFileSync } from 'node:fs';
import { Camera } from '@shadelab/camera';
import { expect, type ReferenceScene, test } from '@shadelab/playwright/reference';
import { Matrix4 } from 'three';
import { defaultState } from '../playground/src/state/schema';
import { expectPicture, LECTURE_VIEW, samplePixel, silhouetteSamples } from './picture-helpers';

/** The published trade-off (BENCHMARKS.md, "Speed against accuracy"). */
const tradeoff = JSON.parse(
  readFileSync(new URL('../bench/results/tradeoff.json', import.meta.url), 'utf8'),
) as { rows: Record<string, { error: { rmse: number; max: number; silhouettePx: number } }> };

// The default scene (playground/src/state/schema.ts) is the lecture's: an ellipsoid x²/4 + y² + z²/4 = 1 (unit
// sphere, model scale (2, 1, 2)), eye (0, 0, 3) looking at the origin, up +y, fovy 90°, one light at
// (−5, 10, 20), black background. picture-helpers.ts derives its silhouette (the ellipse u²/0.8 + v²/0.2 < 1)
// and samples 12 multiples of it in 36 directions each, 10 % clear of the edge.

test('the playground opens on a lit sphere: lit inside the silhouette, background outside, brighter towards the light', async ({
  page,
}) => {
  await page.goto('/');
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveRendered({ timeout: 30_000 }); // a loaded machine is slow to start
  const samples = silhouetteSamples(LECTURE_VIEW);
  const [width, height] = await canvas.evaluate((el: HTMLCanvasElement) => [el.width, el.height]);
  const read = await canvas.evaluate(
    (el: HTMLCanvasElement, pixels) => {
      const gl = el.getContext('webgl2')!;
      return pixels.map((p) => {
        if (p === null) return null;
        const out = new Uint8Array(4);
        gl.readPixels(p.x, p.yUp, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out); // rows from the bottom
        return Array.from(out.slice(0, 3));
      });
    },
    samples.map((s) => samplePixel(s, width, height)),
  );
  // Every inside sample is drawn, every outside one is exactly the black background, and the side facing the
  // light is much brighter than the far side (lit by the light, not by ambient alone).
  const { towardsLight, awayFromLight } = expectPicture(LECTURE_VIEW, samples, read);
  console.log(`mean r+g+b towards the light ${towardsLight.toFixed(1)}, away ${awayFromLight.toFixed(1)}`);

  // The whole picture against the exact reference of the playground's own default state (the ray-cast
  // ellipsoid, lit by shade()), within the error BENCHMARKS.md publishes for its option, Phong shading on the
  // tetrahedron at level 6 (bench/results/tradeoff.json, measured at 1280 × 720 with the trade-off's material).
  const state = defaultState();
  const camera = new Camera();
  camera.lookAt(state.camera.eye, state.camera.at, state.camera.up);
  camera.setPerspective(state.camera.fovy, width / height, state.camera.near, state.camera.far);
  const scene: ReferenceScene = {
    projectionMatrix: camera.projectionMatrix.elements,
    viewMatrix: camera.matrixWorldInverse.elements,
    modelMatrix: new Matrix4().makeScale(...state.model.scale).elements,
    radius: state.sphere.radius,
    material: state.material,
    lights: state.lights,
    background: [0, 0, 0],
  };
  const { rmse, max, silhouettePx } = tradeoff.rows['phong tetrahedron 6'].error;
  await expect(canvas).toMatchReference(scene, { rmse, max, silhouettePx });
});

test('the playground renders on demand, not in a loop, and reports its first frame', async ({ page }) => {
  await page.goto('/');
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveAttribute('data-frames', /[1-9]/, { timeout: 30_000 }); // a loaded machine is slow to start
  await expect(canvas).toHaveAttribute('data-first-frame-ms', /^\d+(\.\d+)?$/);
  await page.waitForTimeout(1000);
  const rested = await canvas.getAttribute('data-frames');
  await page.waitForTimeout(1000);
  expect(await canvas.getAttribute('data-frames')).toBe(rested);
  // A change renders exactly when asked: the frame counter moves.
  await page.locator('[id="Material.shininess"]').fill('10');
  await page.locator('[id="Material.shininess"]').press('Enter');
  await expect
    .poll(async () => Number(await canvas.getAttribute('data-frames')))
    .toBeGreaterThan(Number(rested));
  console.log(`first frame: ${await canvas.getAttribute('data-first-frame-ms')} ms after navigation start`);
});
