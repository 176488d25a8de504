import { expect, type Locator, type Page } from '@playwright/test';
import { test } from './harness-helpers';

// The harness canvas is 400 × 300 CSS px at (50, 50): its centre is (250, 200), the ball radius 150 px.
const CX = 250;
const CY = 200;

async function state(canvas: Locator) {
  return canvas.evaluate((el: HTMLCanvasElement) => ({
    frames: Number(el.dataset.frames),
    quaternion: JSON.parse(el.dataset.quaternion ?? '[]') as number[],
    dragging: el.dataset.dragging,
    distance: Number(el.dataset.distance),
    image: el.toDataURL('image/png'),
    // Pixels the box covers (the background is cleared to black).
    covered: (() => {
      const gl = el.getContext('webgl2')!;
      const all = new Uint8Array(el.width * el.height * 4);
      gl.readPixels(0, 0, el.width, el.height, gl.RGBA, gl.UNSIGNED_BYTE, all);
      let n = 0;
      for (let i = 0; i < all.length; i += 4) if (all[i] || all[i + 1] || all[i + 2]) n++;
      return n;
    })(),
    centre: (() => {
      const gl = el.getContext('webgl2')!;
      const out = new Uint8Array(4);
      gl.readPixels(el.width / 2, el.height / 2, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
      return Array.from(out);
    })(),
  }));
}

async function open(page: Page, mapping = 'bell', camera = 'perspective') {
  await page.goto(`/harness/?page=trackball&mapping=${mapping}&camera=${camera}`);
  const canvas = page.getByTestId('viewport');
  await expect(canvas).toHaveAttribute('data-frames', '1');
  return canvas;
}

test('a drag turns the rendered box about the camera up axis, and the pixels change', async ({ page }) => {
  const canvas = await open(page);
  const before = await state(canvas);
  expect(Math.max(...before.centre.slice(0, 3))).toBeGreaterThan(40); // the box covers the centre

  await page.mouse.move(CX, CY);
  await page.mouse.down();
  await page.mouse.move(CX + 60, CY, { steps: 6 });
  await page.mouse.up();

  const after = await state(canvas);
  expect(after.frames).toBeGreaterThan(before.frames);
  expect(after.dragging).toBe('false');
  expect(after.image).not.toBe(before.image);
  expect(after.centre).not.toEqual(before.centre);
  // World rotation = Δ · before, with Δ about +y (the camera looks down −z with y up).
  const [x0, y0, z0, w0] = before.quaternion;
  const [x1, y1, z1, w1] = after.quaternion;
  const delta = [
    // Δ = after · before⁻¹
    x1 * w0 - w1 * x0 - y1 * z0 + z1 * y0,
    y1 * w0 - w1 * y0 - z1 * x0 + x1 * z0,
    z1 * w0 - w1 * z0 - x1 * y0 + y1 * x0,
    w0 * w1 + x0 * x1 + y0 * y1 + z0 * z1,
  ];
  expect(Math.abs(delta[0])).toBeLessThan(1e-9);
  expect(Math.abs(delta[2])).toBeLessThan(1e-9);
  expect(delta[1] * Math.sign(delta[3])).toBeGreaterThan(0.1);
});

test('releasing outside the canvas ends the drag, and the trackball keeps working', async ({ page }) => {
  const canvas = await open(page, 'arcball');
  const before = await state(canvas);

  await page.mouse.move(CX, CY);
  await page.mouse.down();
  await page.mouse.move(700, 560, { steps: 8 }); // far outside the 400 × 300 canvas
  const during = await state(canvas);
  expect(during.dragging).toBe('true');
  await page.mouse.up();

  const released = await state(canvas);
  expect(released.dragging).toBe('false');
  expect(released.quaternion.every(Number.isFinite)).toBe(true);
  expect(Math.hypot(...released.quaternion)).toBeCloseTo(1, 12);
  expect(released.image).not.toBe(before.image);

  // Moving without a button changes nothing any more.
  await page.mouse.move(CX - 100, CY - 100, { steps: 4 });
  const idle = await state(canvas);
  expect(idle.frames).toBe(released.frames);

  // A new drag inside still turns the box; a closed drag returns to where it started.
  await page.mouse.move(CX - 40, CY + 20);
  await page.mouse.down();
  await page.mouse.move(CX + 80, CY - 50, { steps: 5 });
  const turned = await state(canvas);
  expect(turned.image).not.toBe(released.image);
  await page.mouse.move(CX - 40, CY + 20, { steps: 5 });
  await page.mouse.up();
  const closed = await state(canvas);
  closed.quaternion.forEach((c, i) => {
    expect(Math.abs(c - released.quaternion[i])).toBeLessThan(1e-9);
  });
});

for (const camera of ['perspective', 'ortho']) {
  test(`the wheel zooms the ${camera === 'ortho' ? 'orthographic' : camera} camera in and out: the box grows and shrinks on screen`, async ({
    page,
  }) => {
    const canvas = await open(page, 'bell', camera);
    const before = await state(canvas);
    await page.mouse.move(CX, CY);
    await page.mouse.wheel(0, -200); // up: in
    await expect.poll(async () => (await state(canvas)).frames).toBeGreaterThan(before.frames);
    const zoomedIn = await state(canvas);
    expect(zoomedIn.covered).toBeGreaterThan(before.covered * 1.2);
    await page.mouse.wheel(0, 600); // down: out, past the start
    await expect.poll(async () => (await state(canvas)).covered).toBeLessThan(before.covered / 1.2);
    if (camera === 'perspective') expect((await state(canvas)).distance).toBeGreaterThan(before.distance);
  });
}

test('a two-finger pinch zooms in, and the remaining finger then rotates', async ({ browser }) => {
  const context = await browser.newContext({ hasTouch: true, viewport: { width: 800, height: 600 } });
  const page = await context.newPage();
  const canvas = await open(page);
  const before = await state(canvas);
  const cdp = await context.newCDPSession(page);
  const touch = (
    type: 'touchStart' | 'touchMove' | 'touchEnd',
    points: { x: number; y: number; id: number }[],
  ) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points });
  await touch('touchStart', [{ x: CX - 30, y: CY, id: 1 }]);
  await touch('touchStart', [
    { x: CX - 30, y: CY, id: 1 },
    { x: CX + 30, y: CY, id: 2 },
  ]);
  for (let i = 1; i <= 5; i++) {
    await touch('touchMove', [
      { x: CX - 30 - 6 * i, y: CY, id: 1 },
      { x: CX + 30 + 6 * i, y: CY, id: 2 },
    ]);
  }
  // Span 60 → 120 px: zoom × 2, whatever the order and grouping of the pointer moves (the ratios telescope).
  // Polled: under load Chromium may still be delivering the last pointer moves when the CDP call returns.
  await expect
    .poll(async () => (await state(canvas)).distance, { timeout: 10_000 })
    .toBeCloseTo(before.distance / 2, 6);
  const pinched = await state(canvas);
  expect(pinched.quaternion).toEqual(before.quaternion); // no rotation while pinching
  // CDP's touchEnd lists the points that lift.
  await touch('touchEnd', [{ x: CX + 60, y: CY, id: 2 }]);
  const lifted = await state(canvas);
  expect(lifted.quaternion).toEqual(pinched.quaternion); // no jump when a finger lifts
  for (let i = 1; i <= 5; i++) await touch('touchMove', [{ x: CX - 60 + 12 * i, y: CY, id: 1 }]);
  await touch('touchEnd', [{ x: CX, y: CY, id: 1 }]);
  const turned = await state(canvas);
  expect(turned.quaternion).not.toEqual(pinched.quaternion);
  expect(turned.dragging).toBe('false');
  await context.close();
});
