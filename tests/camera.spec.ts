import { expect, type Locator } from '@playwright/test';
import type {} from './harness/camera';
import { test, timedLoad } from './harness-helpers';

// The harness page camera (tests/harness/camera.ts): a 400 × 300 canvas at (50, 50) seen through @shadelab/camera's
// Camera, moved by CameraMovement (moveSpeed 0.5, turnSpeed 0.005); window.cameraDepth probes depth order per mode.

async function state(canvas: Locator) {
  return canvas.evaluate((el: HTMLCanvasElement) => ({
    frames: Number(el.dataset.frames),
    eye: JSON.parse(el.dataset.eye ?? '[]') as number[],
    w: JSON.parse(el.dataset.w ?? '[]') as number[],
    image: el.toDataURL('image/png'),
  }));
}

/** Opens the camera page and waits, for as long as the test may, until it drew its first frame. */
async function open(page: import('@playwright/test').Page) {
  const canvas = page.getByTestId('viewport');
  await timedLoad(async () => {
    await page.goto('/harness/?page=camera');
    await expect(canvas).toHaveAttribute('data-ready', 'true', { timeout: 0 });
  });
  await expect(canvas).toHaveAttribute('data-frames', '1');
  return canvas;
}

const dot = (a: number[], b: number[]) => a.reduce((s, x, i) => s + x * b[i], 0);

test('pressing W moves the camera 0.5 along −w and the picture changes', async ({ page }) => {
  const canvas = await open(page);
  const before = await state(canvas);
  await expect(canvas).toHaveScreenshot('before.png');
  await canvas.focus();
  await page.keyboard.press('KeyW');
  await expect(canvas).toHaveAttribute('data-frames', '2');
  const after = await state(canvas);
  expect(after.image).not.toBe(before.image);
  const moved = after.eye.map((x, i) => x - before.eye[i]);
  expect(dot(moved, before.w)).toBeCloseTo(-0.5, 9);
  expect(Math.hypot(...moved)).toBeCloseTo(0.5, 9);
  await expect(canvas).toHaveScreenshot('after-w.png');
});

test('arrow keys strafe along u and a drag turns the gaze; the picture follows', async ({ page }) => {
  const canvas = await open(page);
  await canvas.click({ position: { x: 200, y: 150 } }); // focuses (zero-length drag: no turn)
  const start = await state(canvas);
  await page.keyboard.press('ArrowRight');
  const strafed = await state(canvas);
  expect(strafed.image).not.toBe(start.image);
  expect(dot(strafed.w, start.w)).toBeCloseTo(1, 12);
  await page.mouse.move(250, 200);
  await page.mouse.down();
  await page.mouse.move(290, 200, { steps: 4 });
  await page.mouse.up();
  const turned = await state(canvas);
  expect(turned.image).not.toBe(strafed.image);
  expect(turned.eye).toEqual(strafed.eye);
  // 40 px × 0.005 rad/px = 0.2 rad about v.
  expect(Math.acos(Math.min(1, dot(turned.w, strafed.w)))).toBeCloseTo(0.2, 6);
});

test('two surfaces 1 unit apart at z = 1e4 (near 0.01, far 1e6): which depth modes keep their order', async ({
  page,
}) => {
  await open(page);
  const result = await page.evaluate(() => {
    const d = window.cameraDepth;
    const modes = [
      'standard',
      'logarithmic',
      'reversed',
      'reversed-or-logarithmic',
      'reversed-float',
    ] as const;
    return Object.fromEntries(modes.map((m) => [m, [d.activeMode(m), d.kept(m, 0.01, 1e6, 1e4, 1e-4)]]));
  });
  expect(result).toEqual({
    standard: ['standard', 'far'], // standard depth loses Δz/z = 1e-4 at z/near = 1e6 (it needs ≈ 6e-8 · z/near)
    logarithmic: ['logarithmic', 'near'],
    reversed: ['reversed', 'near'], // EXT_clip_control is available under SwiftShader
    'reversed-or-logarithmic': ['reversed', 'near'], // …so three takes reversed-Z and ignores the logarithmic switch
    'reversed-float': ['reversed', 'near'],
  });
});

test('without EXT_clip_control: reversed-or-logarithmic runs logarithmic and keeps the 1e4 order; plain reversed falls back to standard', async ({
  page,
}) => {
  // Hide the extension from every WebGL2 context of the page before any script runs.
  await page.addInitScript(() => {
    const proto = WebGL2RenderingContext.prototype;
    const getExtension = proto.getExtension;
    const getSupportedExtensions = proto.getSupportedExtensions;
    proto.getExtension = function (this: WebGL2RenderingContext, name: string) {
      return name === 'EXT_clip_control' ? null : getExtension.call(this, name as never);
    } as typeof getExtension;
    proto.getSupportedExtensions = function (this: WebGL2RenderingContext) {
      return getSupportedExtensions.call(this)?.filter((n) => n !== 'EXT_clip_control') ?? null;
    };
  });
  await open(page);
  const result = await page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    const d = window.cameraDepth;
    const modes = ['standard', 'reversed', 'reversed-or-logarithmic', 'reversed-float'] as const;
    return {
      hidden:
        gl !== null &&
        gl.getExtension('EXT_clip_control') === null &&
        !gl.getSupportedExtensions()?.includes('EXT_clip_control'),
      ...Object.fromEntries(modes.map((m) => [m, [d.activeMode(m), d.kept(m, 0.01, 1e6, 1e4, 1e-4)]])),
    };
  });
  expect(result).toEqual({
    hidden: true,
    standard: ['standard', 'far'],
    reversed: ['standard', 'far'], // three's fallback: the least precise mode, the order is lost
    'reversed-or-logarithmic': ['logarithmic', 'near'],
    'reversed-float': ['standard', 'far'], // a float depth buffer alone does not help standard depth here
  });
});

test("Camera through three's shaders: a Phong sphere's pixels equal OrthographicCamera's and PerspectiveCamera's", async ({
  page,
}) => {
  await open(page);
  const result = await page.evaluate(() => ({
    orthographic: window.cameraCompare('orthographic'),
    perspective: window.cameraCompare('perspective'),
  }));
  for (const kind of ['orthographic', 'perspective'] as const) {
    const r = result[kind];
    expect(r.differing, kind).toBe(0); // every byte of the 96 × 96 picture
    expect(r.brightest, `${kind}: a white specular highlight is in the picture`).toBeGreaterThan(200);
    expect(r.lit, `${kind}: the sphere covers a good part of it`).toBeGreaterThan(1000);
  }
  expect(result.orthographic.isOrthographicCamera).toBe(true);
  expect(result.perspective.isOrthographicCamera).toBe(false);
  // The comparison can see the flag: the same orthographic matrices through a camera that is not flagged
  // orthographic are shaded differently (three's isOrthographic uniform sets the specular view direction).
  expect(result.orthographic.flaglessDiffering).toBeGreaterThan(0);
});

test('ShadingMaterial keeps the same depth modes, alone and next to three materials (it writes logarithmic depth like them)', async ({
  page,
}) => {
  await open(page);
  const result = await page.evaluate(() => {
    const d = window.cameraDepth;
    const modes = ['standard', 'logarithmic', 'reversed', 'reversed-float'] as const;
    const materials = ['shading', 'shading-near', 'shading-far'] as const;
    return Object.fromEntries(
      modes.map((m) => [m, materials.map((q) => d.kept(m, 0.01, 1e6, 1e4, 1e-4, q))]),
    );
  });
  expect(result).toEqual({
    standard: ['far', 'far', 'far'],
    logarithmic: ['near', 'near', 'near'],
    reversed: ['near', 'near', 'near'],
    'reversed-float': ['near', 'near', 'near'],
  });
});

test('far/near from 10 to 1e9 (docs/design.md extremes): logarithmic and reversed keep Δz/z = 1e-5 at z = far/4', async ({
  page,
}) => {
  // Every depth mode at every far/near ratio: 31 s in a fresh-clone run on a busy machine, half the default 60 s.
  test.setTimeout(180_000);
  await open(page);
  const result = await page.evaluate(() => {
    const d = window.cameraDepth;
    const modes = ['standard', 'logarithmic', 'reversed', 'reversed-float'] as const;
    const near = 0.01;
    return Object.fromEntries(
      modes.map((m) => [
        m,
        [1, 2, 3, 4, 5, 6, 7, 8, 9].map((e) => {
          const far = near * 10 ** e;
          return d.kept(m, near, far, far / 4, 1e-5);
        }),
      ]),
    );
  });
  expect(result.logarithmic).toEqual(Array(9).fill('near'));
  expect(result.reversed).toEqual(Array(9).fill('near'));
  expect(result['reversed-float']).toEqual(Array(9).fill('near'));
  // Standard depth needs Δz/z ≳ 6e-8 · z/near: kept while z/near = 2.5 and 25, lost at z/near = 2.5e8.
  expect(result.standard.slice(0, 2)).toEqual(['near', 'near']);
  expect(result.standard[8]).toBe('far');
});
