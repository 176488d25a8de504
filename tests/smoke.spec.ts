import { expect, test } from '@playwright/test';

// The default scene (playground/src/state/schema.ts): an ellipsoid x²/4 + y² + z²/4 = 1 (unit sphere, model
// scale (2, 1, 2)), eye (0, 0, 3) looking at the origin, up +y, fovy 90°, one light at (−5, 10, 20), black
// background. A view ray d = (u, v, −1) (u, v in units of tan(fovy/2) = 1) meets the ellipsoid (matrix
// A = diag(1/4, 1, 1/4)) when (dᵀAe)² > (dᵀAd)(eᵀAe − 1), i.e. 9/16 > (5/4)(u²/4 + v² + 1/4): inside the ellipse
// u²/0.8 + v²/0.2 < 1. NDC x = u / aspect, y = v. The mesh (tetrahedron level 6) lies inside the true surface by
// 0.1 % of its size, and the edge pixels are antialiased: samples keep 10 % away from the silhouette.
const SILHOUETTE_U = Math.sqrt(0.8);
const SILHOUETTE_V = Math.sqrt(0.2);

test('the playground opens on a lit sphere: lit inside the silhouette, background outside, brighter towards the light', async ({
  page,
}) => {
  await page.goto('/');
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveAttribute('data-frames', /[1-9]/, { timeout: 30_000 }); // a loaded machine is slow to start
  // Samples at r times the silhouette ellipse (r < 1 inside, r > 1 outside), 36 directions each.
  const samples: { r: number; angle: number; u: number; v: number }[] = [];
  for (const r of [0.15, 0.35, 0.55, 0.75, 0.9, 1.1, 1.2, 1.35, 1.5, 1.75, 2, 2.2]) {
    for (let k = 0; k < 36; k++) {
      const angle = (2 * Math.PI * k) / 36;
      samples.push({
        r,
        angle,
        u: r * SILHOUETTE_U * Math.cos(angle),
        v: r * SILHOUETTE_V * Math.sin(angle),
      });
    }
  }
  const read = await canvas.evaluate((el: HTMLCanvasElement, points) => {
    const gl = el.getContext('webgl2')!;
    const aspect = el.width / el.height;
    return points.map(({ u, v }) => {
      const x = Math.floor(((u / aspect + 1) / 2) * el.width);
      const y = Math.floor(((v + 1) / 2) * el.height); // readPixels counts rows from the bottom
      if (x < 0 || y < 0 || x >= el.width || y >= el.height) return null;
      const out = new Uint8Array(4);
      gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
      return Array.from(out.slice(0, 3));
    });
  }, samples);
  const inside: number[][] = [];
  const outside: number[][] = [];
  const towardsLight: number[] = [];
  const awayFromLight: number[] = [];
  // The light's direction seen from the eye: up (+y) and to the left (−x); the far side is down and right.
  const light = Math.atan2(10, -5);
  samples.forEach(({ r, angle }, i) => {
    const rgb = read[i];
    if (rgb === null) return; // off the canvas (the ellipsoid is wider than a narrow canvas)
    (r < 1 ? inside : outside).push(rgb);
    if (r >= 0.35 && r < 1) {
      const off = Math.abs(Math.atan2(Math.sin(angle - light), Math.cos(angle - light)));
      if (off <= Math.PI / 4) towardsLight.push(rgb[0] + rgb[1] + rgb[2]);
      if (off >= (3 * Math.PI) / 4) awayFromLight.push(rgb[0] + rgb[1] + rgb[2]);
    }
  });
  expect(inside.length).toBeGreaterThanOrEqual(150);
  expect(outside.length).toBeGreaterThanOrEqual(90);
  // Every inside sample is drawn (not the background); every outside one is exactly the black background.
  expect(inside.filter((rgb) => rgb[0] + rgb[1] + rgb[2] === 0)).toEqual([]);
  expect(outside.filter((rgb) => rgb[0] + rgb[1] + rgb[2] !== 0)).toEqual([]);
  // Lit by the light, not by ambient alone: the side facing it is much brighter than the far side.
  const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;
  expect(towardsLight.length).toBeGreaterThanOrEqual(12);
  expect(awayFromLight.length).toBeGreaterThanOrEqual(12);
  console.log(
    `mean r+g+b towards the light ${mean(towardsLight).toFixed(1)}, away ${mean(awayFromLight).toFixed(1)}`,
  );
  // The light (−5, 10, 20) is mostly in front, so the far side still gets some diffuse light (and sRGB output
  // lifts dark tones); ambient alone would shade every sample alike.
  expect(mean(towardsLight)).toBeGreaterThan(1.25 * mean(awayFromLight));
  expect(Math.min(...towardsLight)).toBeGreaterThan(Math.max(...awayFromLight));
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
