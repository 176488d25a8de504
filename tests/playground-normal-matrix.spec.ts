// The normal matrix, live (issue 24): the "normal matrix" tool shows the lecture's sphere shaded with
// normalMatrix 'inverse-transpose' (left) and 'model' (right) side by side, with the tangent and both normals
// drawn at the point under the view's centre (or the probed point). Checked against the CPU: the model matrix
// M = R(q)·S from the state, the point on the view axis and on the ellipsoid, the drawn arrows' directions =
// (M⁻¹)ᵀn = R(n/s) and Mn = R(s∘n) (normalised), the first perpendicular to the tangent M·t and the second not;
// the two pictures cover the same pixels and differ in shading, each half's pixel at the point = shade() with
// its own normal (and not with the other's).
import { expect, type Page } from '@playwright/test';
import * as THREE from 'three';
import { shade } from '../packages/material/src/shade';
import { test } from './harness-helpers';
import { open, settle } from './playground-helpers';

const MATERIAL = {
  shading: 'phong',
  lighting: 'blinn-phong',
  ka: [0.8, 0.35, 0.15],
  kd: [0.8, 0.35, 0.15],
  ks: [1, 1, 1],
  shininess: 50,
} as const;
const LIGHT = {
  position: [-5, 10, 20],
  ambient: [0.2, 0.2, 0.2],
  diffuse: [1, 1, 1],
  specular: [0.8, 0.8, 0.8],
};
const ROTATION = new THREE.Quaternion().setFromEuler(new THREE.Euler(0.5, 0.7, 0.1));
const SCALE = [2, 1, 2] as const;
const STATE = {
  material: MATERIAL,
  lights: [LIGHT],
  model: { scale: SCALE },
  trackball: { rotation: ROTATION.toArray() },
};

const vec = (text: string | null) => new THREE.Vector3(...(text ?? '').split(',').map(Number));

/** Linear to the displayed 8-bit sRGB code. */
const srgb8 = (c: number) => {
  const v = Math.min(Math.max(c, 0), 1);
  return Math.round(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055));
};

/**
 * The figure's two halves compared in the page: pixels covered (any channel above 8) in one half only, pixels
 * covered in the left half, pixels whose largest channel differs by more than 3; and the RGB at `points`.
 */
async function figureRead(page: Page, points: number[][]) {
  return page.getByTestId('normal-matrix-canvas').evaluate((canvas: HTMLCanvasElement, points) => {
    const gl = canvas.getContext('webgl2')!;
    const { width: w, height: h } = canvas;
    const data = new Uint8Array(4 * w * h);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, data);
    const half = Math.floor(w / 2);
    let oneOnly = 0;
    let covered = 0;
    let differing = 0;
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < half; x++) {
        const [i, j] = [4 * (y * w + x), 4 * (y * w + x + half)];
        const litA = data[i]! > 8 || data[i + 1]! > 8 || data[i + 2]! > 8;
        const litB = data[j]! > 8 || data[j + 1]! > 8 || data[j + 2]! > 8;
        if (litA !== litB) oneOnly++;
        if (litA) covered++;
        let d = 0;
        for (let k = 0; k < 3; k++) d = Math.max(d, Math.abs(data[i + k]! - data[j + k]!));
        if (d > 3) differing++;
      }
    }
    // Rows of readPixels run from the bottom; the points' y from the top.
    const rgb = points.map(([x, y]) => {
      const i = 4 * ((h - 1 - Math.floor(y!)) * w + Math.floor(x!));
      return [data[i]!, data[i + 1]!, data[i + 2]!];
    });
    return { oneOnly, covered, differing, rgb };
  }, points);
}

async function openFigure(page: Page, state: object) {
  await open(page, state);
  await page.getByRole('button', { name: 'normal matrix' }).click();
  const canvas = page.getByTestId('normal-matrix-canvas');
  await expect(canvas).toHaveAttribute('data-point', /\d/);
  await settle(page);
  return canvas;
}

test('non-uniform scale: the drawn normals are the CPU’s (M⁻¹)ᵀn ⊥ M·t and Mn, which is not', async ({
  page,
}) => {
  const canvas = await openFigure(page, STATE);
  await expect(canvas).toHaveAttribute('data-source', 'centre');
  const m = new THREE.Matrix4().compose(new THREE.Vector3(), ROTATION, new THREE.Vector3(...SCALE));
  const point = vec(await canvas.getAttribute('data-point'));
  // On the view axis (eye (0, 0, 3) towards the origin) and on the ellipsoid M·(unit sphere), within the
  // tessellation's error.
  expect(Math.hypot(point.x, point.y)).toBeLessThan(1e-6);
  const local = point.clone().applyMatrix4(m.clone().invert());
  expect(local.length()).toBeGreaterThan(0.995);
  expect(local.length()).toBeLessThanOrEqual(1 + 1e-6);
  const n = local.normalize();
  const s = new THREE.Vector3(...SCALE);
  const right = n.clone().divide(s).applyQuaternion(ROTATION).normalize();
  const wrong = n.clone().multiply(s).applyQuaternion(ROTATION).normalize();
  const tangent = vec(await canvas.getAttribute('data-tangent'));
  const drawnRight = vec(await canvas.getAttribute('data-normal-it'));
  const drawnWrong = vec(await canvas.getAttribute('data-normal-m'));
  for (const [drawn, expected] of [
    [drawnRight, right],
    [drawnWrong, wrong],
  ] as const) {
    expect(drawn.distanceTo(expected), `${drawn.toArray()} vs ${expected.toArray()}`).toBeLessThan(1e-6);
  }
  // The tangent is M·t for a t ⊥ n: back in object space it is perpendicular to n.
  const t = tangent.clone().applyQuaternion(ROTATION.clone().invert()).divide(s).normalize();
  expect(Math.abs(t.dot(n))).toBeLessThan(1e-6);
  expect(Math.abs(drawnRight.dot(tangent))).toBeLessThan(1e-6);
  expect(Math.abs(drawnWrong.dot(tangent))).toBeGreaterThan(0.2);
  await expect(page.getByTestId('angle-it')).toHaveText('90.0°');
  const angle = THREE.MathUtils.radToDeg(drawnWrong.angleTo(tangent));
  await expect(page.getByTestId('angle-m')).toHaveText(`${angle.toFixed(1)}°`);

  // The pictures: the same pixels covered, different shading; at the point, each half is shade() with its normal.
  await expect(canvas).toHaveScreenshot('normal-matrix.png');
  // The arrows off, to see the surface under them (they are drawn over it).
  await page.getByLabel('draw the tangent and the normals').uncheck();
  const pixels = (await canvas.getAttribute('data-pixels'))!.split(';').map((p) => p.split(',').map(Number));
  const read = await figureRead(page, pixels);
  expect(read.oneOnly, 'pixels covered in one half only').toBe(0);
  expect(read.covered).toBeGreaterThan(2000);
  expect(read.differing).toBeGreaterThan(0.05 * read.covered);
  const expected = [right, wrong].map((normal) =>
    shade({ position: point.toArray(), normal: normal.toArray(), eye: [0, 0, 3] }, MATERIAL, [LIGHT]).map(
      srgb8,
    ),
  );
  expect(Math.max(...expected[0]!.map((c, k) => Math.abs(c - expected[1]![k]!)))).toBeGreaterThan(20);
  read.rgb.forEach((got, i) => {
    const own = Math.max(...got.map((c, k) => Math.abs(c - expected[i]![k]!)));
    const other = Math.max(...got.map((c, k) => Math.abs(c - expected[1 - i]![k]!)));
    // Within the tessellation's error (the interpolated vertex normals, the pixel centre ≤ 0.5 px off the point).
    expect(own, `half ${i}: ${got} vs shade() ${expected[i]}`).toBeLessThanOrEqual(5);
    expect(other, `half ${i}: ${got} vs the other normal's shade() ${expected[1 - i]}`).toBeGreaterThan(15);
  });
});

test('uniform scale: both normals agree, and the text says so', async ({ page }) => {
  const canvas = await openFigure(page, { ...STATE, model: { scale: [1.5, 1.5, 1.5] } });
  await expect(page.getByTestId('angle-m')).toHaveText('90.0°');
  const [it, model] = await Promise.all([
    canvas.getAttribute('data-normal-it'),
    canvas.getAttribute('data-normal-m'),
  ]);
  expect(vec(model).distanceTo(vec(it))).toBeLessThan(1e-6);
  await expect(page.getByTestId('normal-matrix-text')).toContainText('uniform');
});

test('the figure follows the trackball; a view with no sphere under its centre says so', async ({ page }) => {
  const canvas = await openFigure(page, STATE);
  const before = await canvas.getAttribute('data-point');
  const box = (await page.getByTestId('viewport').boundingBox())!;
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.6);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.7, box.y + box.height * 0.55, { steps: 8 });
  await page.mouse.up();
  await settle(page);
  await expect(canvas).not.toHaveAttribute('data-point', before!);
  await page.goto('about:blank');
  await open(page, { ...STATE, camera: { at: [0, 5, 0] } });
  await page.getByRole('button', { name: 'normal matrix' }).click();
  await expect(page.getByTestId('normal-matrix-text')).toContainText(
    'No point of the sphere under the view’s centre',
  );
});

test('a probed point (Alt+click on the sphere) is the one shown, until the probe closes', async ({
  page,
}) => {
  const canvas = await openFigure(page, STATE);
  const box = (await page.getByTestId('viewport').boundingBox())!;
  await page.keyboard.down('Alt');
  await page.mouse.click(box.x + box.width * 0.7, box.y + box.height * 0.75);
  await page.keyboard.up('Alt');
  await expect(page.getByTestId('probe-panel')).toBeVisible();
  await expect(canvas).toHaveAttribute('data-source', 'probe');
  const m = new THREE.Matrix4().compose(new THREE.Vector3(), ROTATION, new THREE.Vector3(...SCALE));
  const point = vec(await canvas.getAttribute('data-point'));
  const n = point.clone().applyMatrix4(m.clone().invert()).normalize();
  const right = n
    .clone()
    .divide(new THREE.Vector3(...SCALE))
    .applyQuaternion(ROTATION)
    .normalize();
  const wrong = n
    .clone()
    .multiply(new THREE.Vector3(...SCALE))
    .applyQuaternion(ROTATION)
    .normalize();
  // The probe's normal is the interpolated one the pixel is lit with: the sphere's within its tessellation.
  expect(vec(await canvas.getAttribute('data-normal-it')).distanceTo(right)).toBeLessThan(1e-2);
  expect(vec(await canvas.getAttribute('data-normal-m')).distanceTo(wrong)).toBeLessThan(1e-2);
  expect(
    Math.abs(
      vec(await canvas.getAttribute('data-normal-it')).dot(vec(await canvas.getAttribute('data-tangent'))),
    ),
  ).toBeLessThan(1e-6);
  await page.getByRole('button', { name: 'close the probe' }).click();
  await expect(canvas).toHaveAttribute('data-source', 'centre');
});
