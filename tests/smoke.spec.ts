import { expect, test } from '@playwright/test';

test('the playground opens on a lit sphere over a black background', async ({ page }) => {
  await page.goto('/');
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveAttribute('data-frames', /[1-9]/);
  const pixels = await canvas.evaluate((el: HTMLCanvasElement) => {
    const gl = el.getContext('webgl2')!;
    const read = (fx: number, fy: number) => {
      const out = new Uint8Array(4);
      gl.readPixels(
        Math.floor(el.width * fx),
        Math.floor(el.height * fy),
        1,
        1,
        gl.RGBA,
        gl.UNSIGNED_BYTE,
        out,
      );
      return Array.from(out);
    };
    return { centre: read(0.5, 0.5), corner: read(0.02, 0.02) };
  });
  expect(Math.max(...pixels.centre.slice(0, 3))).toBeGreaterThan(40);
  expect(pixels.corner.slice(0, 3)).toEqual([0, 0, 0]);
});

test('the playground renders on demand, not in a loop, and reports its first frame', async ({ page }) => {
  await page.goto('/');
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveAttribute('data-frames', /[1-9]/);
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
