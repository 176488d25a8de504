import { linearToSrgb8, type ShadeLight, type ShadeMaterial } from '@shadelab/material';
import { compareToReference, intersectSphere, renderReference } from '@shadelab/reference';
import fc from 'fast-check';
import { Euler, Matrix4, OrthographicCamera, PerspectiveCamera, Plane, Ray, Sphere, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';

const white: [number, number, number] = [1, 1, 1];
const black: [number, number, number] = [0, 0, 0];

function ortho(size = 1.25): OrthographicCamera {
  const camera = new OrthographicCamera(-size, size, size, -size, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

function lecture(
  width: number,
  height: number,
): {
  camera: PerspectiveCamera;
  model: Matrix4;
  material: ShadeMaterial;
  lights: ShadeLight[];
} {
  const camera = new PerspectiveCamera(90, width / height, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return {
    camera,
    model: new Matrix4().makeScale(2, 1, 2),
    material: { ka: [0.6, 0.35, 0.2], kd: [0.6, 0.35, 0.2], ks: [0.5, 0.5, 0.5], shininess: 32 },
    lights: [{ position: [-5, 10, 20], ambient: [0.2, 0.2, 0.2], diffuse: white, specular: [0.8, 0.8, 0.8] }],
  };
}

/** The analytic normal of the unit sphere seen by the orthographic camera `ortho(size)` at pixel (i, j). */
function orthoNormal(i: number, j: number, n: number, size: number): [number, number, number] | null {
  const x = (((i + 0.5) / n) * 2 - 1) * size;
  const y = (((j + 0.5) / n) * 2 - 1) * size;
  const z2 = 1 - x * x - y * y;
  return z2 >= -1e-9 ? [x, y, Math.sqrt(Math.max(z2, 0))] : null; // the rim itself counts as on
}

describe('renderReference against closed forms', () => {
  const N = 65;
  const size = 1.25;
  const camera = ortho(size);
  const base = {
    width: N,
    height: N,
    projectionMatrix: camera.projectionMatrix.elements,
    viewMatrix: camera.matrixWorldInverse.elements,
  };

  it('centre pixel: head-on light gives ka·Ia + kd·Id + ks·Is exactly', () => {
    const material: ShadeMaterial = {
      ka: [0.1, 0.2, 0.3],
      kd: [0.3, 0.2, 0.1],
      ks: [0.25, 0.5, 0.125],
      shininess: 7,
    };
    const lights: ShadeLight[] = [
      { position: [0, 0, 50], ambient: [0.5, 0.5, 0.5], diffuse: [1, 0.5, 0.25], specular: [0.5, 1, 2] },
    ];
    const image = renderReference({ ...base, material, lights });
    const k = ((N - 1) / 2) * N + (N - 1) / 2;
    expect(image.hit[k]).toBe(1);
    const expected = [
      0.1 * 0.5 + 0.3 * 1 + 0.25 * 0.5,
      0.2 * 0.5 + 0.2 * 0.5 + 0.5,
      0.3 * 0.5 + 0.1 * 0.25 + 0.125 * 2,
    ];
    for (let c = 0; c < 3; c++) expect(image.linear[3 * k + c]).toBeCloseTo(expected[c], 6);
    // The hit is at z = 1: window depth of (0, 0, 1) through the camera.
    const ndc = new Vector3(0, 0, 1).project(camera);
    expect(image.depth[k]).toBeCloseTo(ndc.z * 0.5 + 0.5, 6);
  });

  it('terminator: a light along +x lights exactly the pixels with n·l > 0 (diffuse = max(n·l, 0))', () => {
    const material: ShadeMaterial = { ka: black, kd: white, ks: black, shininess: 1 };
    const L = 1e7;
    const lights: ShadeLight[] = [{ position: [L, 0, 0], ambient: black, diffuse: white, specular: black }];
    const image = renderReference({ ...base, material, lights });
    let lit = 0;
    for (let j = 0; j < N; j++) {
      for (let i = 0; i < N; i++) {
        const n = orthoNormal(i, j, N, size);
        const k = j * N + i;
        if (n === null || n[2] < 1e-4) {
          // On or outside the rim: the hit must agree except within rounding of the rim itself.
          if (n === null) expect(image.hit[k], `pixel ${i}, ${j}`).toBe(0);
          continue;
        }
        expect(image.hit[k]).toBe(1);
        // l = normalize((L, 0, 0) − n)
        const lx = L - n[0];
        const ll = Math.hypot(lx, n[1], n[2]);
        const expected = Math.max((n[0] * lx - n[1] * n[1] - n[2] * n[2]) / ll, 0);
        expect(image.linear[3 * k]).toBeCloseTo(expected, 6);
        if (image.linear[3 * k] > 0) {
          lit++;
          expect(n[0]).toBeGreaterThan(0);
        }
      }
    }
    expect(lit).toBeGreaterThan(1000);
  });

  for (const lighting of ['phong', 'blinn-phong'] as const) {
    it(`${lighting}: specular matches its closed form everywhere and peaks at n = normalize(l + v)`, () => {
      const material: ShadeMaterial = { ka: black, kd: black, ks: white, shininess: 20, lighting };
      const dir = new Vector3(1, 1, 2).normalize();
      const L = 1e8;
      const lights: ShadeLight[] = [
        { position: [dir.x * L, dir.y * L, dir.z * L], ambient: black, diffuse: black, specular: white },
      ];
      const image = renderReference({ ...base, material, lights });
      const v = new Vector3(0, 0, 1);
      let best = -1;
      let bestK = -1;
      for (let j = 0; j < N; j++) {
        for (let i = 0; i < N; i++) {
          const nn = orthoNormal(i, j, N, size);
          if (nn === null) continue;
          const n = new Vector3(...nn);
          const k = j * N + i;
          const ndl = n.dot(dir);
          let x: number;
          if (lighting === 'phong') {
            const r = n
              .clone()
              .multiplyScalar(2 * ndl)
              .sub(dir);
            x = Math.max(v.dot(r), 0);
          } else {
            x = Math.max(n.dot(dir.clone().add(v).normalize()), 0);
          }
          const expected = ndl > 0 ? x ** 20 : 0;
          expect(image.linear[3 * k]).toBeCloseTo(expected, 5);
          if (image.linear[3 * k] > best) {
            best = image.linear[3 * k];
            bestK = k;
          }
        }
      }
      // The peak is the pixel nearest to the projection of h = normalize(l + v).
      const h = dir.clone().add(v).normalize();
      const pi = ((h.x / size + 1) / 2) * N - 0.5;
      const pj = ((h.y / size + 1) / 2) * N - 0.5;
      expect(Math.abs((bestK % N) - pi)).toBeLessThanOrEqual(0.5);
      expect(Math.abs(Math.floor(bestK / N) - pj)).toBeLessThanOrEqual(0.5);
    });
  }

  it('phong and blinn-phong differ off the peak as (v·r)^α vs (n·h)^α', () => {
    const dir = [0.6, 0, 0.8];
    const lights: ShadeLight[] = [
      { position: [dir[0] * 1e8, 0, dir[2] * 1e8], ambient: black, diffuse: black, specular: white },
    ];
    const a = renderReference({
      ...base,
      material: { ka: black, kd: black, ks: white, shininess: 4 },
      lights,
    });
    const b = renderReference({
      ...base,
      material: { ka: black, kd: black, ks: white, shininess: 4, lighting: 'blinn-phong' },
      lights,
    });
    const k = ((N - 1) / 2) * N + (N - 1) / 2; // n = v = (0, 0, 1)
    // v·r = 2(l·n)(v·n) − v·l = 2·0.8·1 − 0.8 = 0.8; n·h with h = normalize(l + v) = (0.6, 0, 1.8)/|…|
    expect(a.linear[3 * k]).toBeCloseTo(0.8 ** 4, 6);
    expect(b.linear[3 * k]).toBeCloseTo((1.8 / Math.hypot(0.6, 1.8)) ** 4, 6);
  });
});

describe('renderReference: the lecture scene (ellipsoid 2, 1, 2 under a 90° perspective)', () => {
  const W = 161;
  const H = 121;
  const { camera, model, material, lights } = lecture(W, H);
  const image = renderReference({
    width: W,
    height: H,
    projectionMatrix: camera.projectionMatrix.elements,
    viewMatrix: camera.matrixWorldInverse.elements,
    modelMatrix: model.elements,
    material,
    lights,
  });

  it('silhouette crosses the centre row at NDC x = ±tan(asin(2/3)) and the centre column at y = ±1/√5', () => {
    const xEdge = 2 / Math.sqrt(5) / (W / H); // tan θ / (aspect · tan 45°)
    const yEdge = 1 / Math.sqrt(5);
    const jc = (H - 1) / 2;
    const ic = (W - 1) / 2;
    for (let i = 0; i < W; i++) {
      const ndc = ((i + 0.5) / W) * 2 - 1;
      const expectedPx = (Math.abs(ndc) - xEdge) * (W / 2); // signed distance along the row, px
      const d = image.edgeDistance[jc * W + i];
      if (Math.abs(expectedPx) < 1) expect(d).toBeCloseTo(expectedPx, 1);
      expect(image.hit[jc * W + i]).toBe(expectedPx < 0 ? 1 : 0);
    }
    for (let j = 0; j < H; j++) {
      const ndc = ((j + 0.5) / H) * 2 - 1;
      const expectedPx = (Math.abs(ndc) - yEdge) * (H / 2);
      const d = image.edgeDistance[j * W + ic];
      if (Math.abs(expectedPx) < 1) expect(d).toBeCloseTo(expectedPx, 1);
      expect(image.hit[j * W + ic]).toBe(expectedPx < 0 ? 1 : 0);
    }
  });

  it('centre pixel: hit at (0, 0, 2), normal +z, depth as three projects it', () => {
    const k = ((H - 1) / 2) * W + (W - 1) / 2;
    const ndc = new Vector3(0, 0, 2).project(camera);
    expect(image.depth[k]).toBeCloseTo(ndc.z * 0.5 + 0.5, 6);
  });

  it('coverage is 1 inside, 0 outside, fractional only within 1 px of the silhouette', () => {
    for (let k = 0; k < W * H; k++) {
      const d = image.edgeDistance[k];
      if (d < -1) expect(image.coverage[k]).toBe(1);
      else if (d > 1) expect(image.coverage[k]).toBe(0);
      else expect(image.coverage[k]).toBeGreaterThanOrEqual(0);
    }
  });

  it('a mirrored model (negative determinant) renders the same sphere with outward normals', () => {
    const mirrored = renderReference({
      width: W,
      height: H,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      modelMatrix: new Matrix4().makeScale(-2, 1, 2).elements,
      material,
      lights,
    });
    let maxDiff = 0;
    for (let k = 0; k < W * H * 3; k++)
      maxDiff = Math.max(maxDiff, Math.abs(mirrored.linear[k] - image.linear[k]));
    expect(maxDiff).toBeLessThan(1e-9);
  });
});

/**
 * Exact area of the disc of radius r centred at the origin inside the rectangle [x0, x1] × [y0, y1]:
 * ∫ overlap([y0, y1], [−s(x), s(x)]) dx with s(x) = √(r² − x²), split where the overlap's form changes
 * (x = ±√(r² − y²) for y = y0, y1), each piece integrated in closed form with
 * ∫ s(x) dx = (x·s(x) + r²·asin(x/r)) / 2.
 */
function discAreaInRect(r: number, x0: number, x1: number, y0: number, y1: number): number {
  const s = (x: number) => Math.sqrt(Math.max(r * r - x * x, 0));
  const S = (x: number) => {
    const c = Math.min(Math.max(x, -r), r);
    return (c * s(c) + r * r * Math.asin(c / r)) / 2;
  };
  const a = Math.max(x0, -r);
  const b = Math.min(x1, r);
  if (!(a < b)) return 0;
  const cuts = [a, b];
  for (const y of [y0, y1]) {
    if (Math.abs(y) < r) {
      const x = Math.sqrt(r * r - y * y);
      for (const c of [-x, x]) if (c > a && c < b) cuts.push(c);
    }
  }
  cuts.sort((p, q) => p - q);
  let area = 0;
  for (let k = 0; k + 1 < cuts.length; k++) {
    const [u, v] = [cuts[k], cuts[k + 1]];
    const m = (u + v) / 2;
    const sm = s(m);
    const top = Math.min(y1, sm);
    const bottom = Math.max(y0, -sm);
    if (!(top > bottom)) continue;
    // On this piece the top is y1 or s(x), the bottom y0 or −s(x): integrate each in closed form.
    area += (top === y1 ? y1 * (v - u) : S(v) - S(u)) - (bottom === y0 ? y0 * (v - u) : -(S(v) - S(u)));
  }
  return area;
}

describe('renderReference: silhouette supersampling against the exact pixel coverage of a disc', () => {
  // An orthographic camera with 1 world unit = 1 pixel looks at a sphere of radius R off the pixel grid: its
  // image is the disc of radius R, and a pixel's exact coverage is the disc's area inside the pixel square.
  const W = 40;
  const H = 36;
  const R = 13.37;
  const [cx, cy] = [0.37, -0.21];
  const camera = new OrthographicCamera(-W / 2, W / 2, H / 2, -H / 2, 1, 100);
  camera.position.set(0, 0, 50);
  camera.updateMatrixWorld();
  const colour: [number, number, number] = [0.8, 0.5, 0.3];
  const background: [number, number, number] = [0, 0, 1];
  const render = (samples: number) =>
    renderReference({
      width: W,
      height: H,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      modelMatrix: new Matrix4().makeTranslation(cx, cy, 0).elements,
      radius: R,
      // Ambient only: every hit has the same colour, so a pixel is exactly coverage·colour + (1 − coverage)·bg.
      material: { ka: colour, kd: black, ks: black, shininess: 1 },
      lights: [{ position: [0, 0, 100], ambient: white, diffuse: black, specular: black }],
      background,
      samples,
    });
  const exact = new Float64Array(W * H);
  for (let j = 0; j < H; j++) {
    for (let i = 0; i < W; i++) {
      const x0 = i - W / 2 - cx;
      const y0 = j - H / 2 - cy;
      exact[j * W + i] = discAreaInRect(R, x0, x0 + 1, y0, y0 + 1);
    }
  }

  it('the exact areas themselves: the pixel coverages sum to πR²', () => {
    expect(exact.reduce((a, b) => a + b, 0)).toBeCloseTo(Math.PI * R * R, 9);
    expect(discAreaInRect(1, -2, 2, -2, 2)).toBeCloseTo(Math.PI, 12);
    expect(discAreaInRect(1, 0, 2, 0, 2)).toBeCloseTo(Math.PI / 4, 12);
    expect(discAreaInRect(1, -1, 1, 0.5, 2)).toBeCloseTo(Math.PI / 3 - Math.sqrt(3) / 4, 12);
  });

  for (const samples of [4, 8, 16]) {
    it(`${samples}×${samples} samples: every pixel within 1/(2·${samples}) of its exact coverage, the total within 0.1 %`, () => {
      const image = render(samples);
      let partial = 0;
      let sumError = 0;
      let total = 0;
      for (let k = 0; k < W * H; k++) {
        // A regular grid of s×s samples across a nearly straight edge miscounts at most half a sample per
        // column: |coverage − exact| ≤ 1/(2s) (+ a margin for the edge's curvature inside one pixel).
        expect(Math.abs(image.coverage[k] - exact[k])).toBeLessThanOrEqual(1 / (2 * samples) + 0.01);
        if (exact[k] > 0 && exact[k] < 1) {
          partial++;
          sumError += Math.abs(image.coverage[k] - exact[k]);
        }
        total += image.coverage[k];
      }
      expect(partial).toBeGreaterThan(2 * Math.PI * R); // about the perimeter in pixels
      expect(sumError / partial).toBeLessThan(1 / (4 * samples));
      expect(Math.abs(total - Math.PI * R * R) / (Math.PI * R * R)).toBeLessThan(1e-3);
    });
  }

  it('rgba blends the sphere and the background by coverage in linear light, then encodes sRGB', () => {
    const image = render(4);
    let blended = 0;
    for (let k = 0; k < W * H; k++) {
      const c = image.coverage[k];
      const expected = linearToSrgb8([0, 1, 2].map((i) => c * colour[i] + (1 - c) * background[i]));
      expect([
        image.rgba[4 * k],
        image.rgba[4 * k + 1],
        image.rgba[4 * k + 2],
        image.rgba[4 * k + 3],
      ]).toEqual([...expected, 255]);
      if (c > 0 && c < 1) blended++;
      if (Math.abs(image.edgeDistance[k]) >= 1) {
        // Away from the silhouette: the centre sample alone, the colour or the background.
        expect(c).toBe(image.hit[k]);
      }
    }
    expect(blended).toBeGreaterThan(Math.PI * R); // most of the ~8R pixels the edge crosses
    // Not the centre sample's colour: a blended pixel lies strictly between the two.
    const k = image.coverage.findIndex((c) => c > 0.3 && c < 0.7);
    expect(image.rgba[4 * k + 2]).toBeGreaterThan(linearToSrgb8(colour)[2]);
    expect(image.rgba[4 * k + 2]).toBeLessThan(255);
  });
});

describe('renderReference against three (property)', () => {
  it('hit points and depths match three.Ray.intersectSphere for random cameras and spheres', () => {
    fc.assert(
      fc.property(
        fc.tuple(fc.double({ min: -3, max: 3, noNaN: true }), fc.double({ min: -3, max: 3, noNaN: true })),
        fc.double({ min: 0.2, max: 2, noNaN: true }),
        fc.double({ min: 30, max: 120, noNaN: true }),
        fc.tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true })),
        ([cx, cy], scale, fov, [ex, ey]) => {
          const camera = new PerspectiveCamera(fov, 1.5, 0.1, 100);
          camera.position.set(ex, ey, 8);
          camera.lookAt(0, 0, 0);
          camera.updateMatrixWorld();
          const model = new Matrix4().makeScale(scale, scale, scale).setPosition(cx, cy, 0);
          const W = 24;
          const H = 16;
          const image = renderReference({
            width: W,
            height: H,
            projectionMatrix: camera.projectionMatrix.elements,
            viewMatrix: camera.matrixWorldInverse.elements,
            modelMatrix: model.elements,
            material: { ka: white, kd: black, ks: black, shininess: 1 },
            lights: [{ position: [0, 0, 10], ambient: white, diffuse: black, specular: black }],
            samples: 1,
          });
          const sphere = new Sphere(new Vector3(cx, cy, 0), scale);
          const ray = new Ray();
          const p = new Vector3();
          for (let j = 0; j < H; j++) {
            for (let i = 0; i < W; i++) {
              const k = j * W + i;
              const a = new Vector3(((i + 0.5) / W) * 2 - 1, ((j + 0.5) / H) * 2 - 1, -1).unproject(camera);
              const b = new Vector3(((i + 0.5) / W) * 2 - 1, ((j + 0.5) / H) * 2 - 1, 1).unproject(camera);
              ray.set(a, b.sub(a).normalize());
              const hit = ray.intersectSphere(sphere, p);
              // Skip rays grazing the silhouette, where the two may round differently.
              if (Math.abs(image.edgeDistance[k]) < 1e-3) continue;
              expect(image.hit[k]).toBe(hit ? 1 : 0);
              if (hit) {
                const ndc = p.project(camera);
                expect(image.depth[k]).toBeCloseTo(ndc.z * 0.5 + 0.5, 6);
              }
            }
          }
        },
      ),
      { numRuns: 25 },
    );
  });
});

describe('renderReference extremes', () => {
  const camera = ortho();
  const ok = {
    width: 4,
    height: 4,
    projectionMatrix: camera.projectionMatrix.elements,
    viewMatrix: camera.matrixWorldInverse.elements,
    material: { ka: white, kd: white, ks: white, shininess: 1 },
    lights: [],
  };
  it.each([
    ['width', { width: 0 }, RangeError],
    ['width', { width: 2.5 }, RangeError],
    ['height', { height: Number.NaN }, RangeError],
    ['height', { height: '4' }, TypeError],
    ['samples', { samples: 0 }, RangeError],
    ['samples', { samples: 17 }, RangeError],
    ['radius', { radius: 0 }, RangeError],
    ['radius', { radius: Number.POSITIVE_INFINITY }, RangeError],
    ['modelMatrix', { modelMatrix: [1, 2, 3] }, TypeError],
    [
      'modelMatrix\\[0\\]',
      { modelMatrix: [Number.NaN, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1] },
      RangeError,
    ],
    [
      'projectionMatrix · viewMatrix must be invertible',
      { projectionMatrix: new Array(16).fill(0) },
      RangeError,
    ],
  ])('%s is refused', (name, bad, E) => {
    expect(() => renderReference({ ...ok, ...(bad as object) })).toThrow(E);
    expect(() => renderReference({ ...ok, ...(bad as object) })).toThrow(new RegExp(name));
  });

  it('tiny (1e-20) and huge (1e20) radii stay finite', () => {
    for (const s of [1e-20, 1e20]) {
      const cam = new OrthographicCamera(-2 * s, 2 * s, 2 * s, -2 * s, 0.1 * s, 10 * s);
      cam.position.set(0, 0, 3 * s);
      cam.updateMatrixWorld();
      const image = renderReference({
        ...ok,
        width: 9,
        height: 9,
        projectionMatrix: cam.projectionMatrix.elements,
        viewMatrix: cam.matrixWorldInverse.elements,
        radius: s,
        lights: [{ position: [0, 0, 10 * s], ambient: white, diffuse: white, specular: white }],
      });
      expect(image.hit[4 * 9 + 4]).toBe(1);
      expect(image.linear.every(Number.isFinite)).toBe(true);
    }
  });
});

describe('renderReference: model matrices scaled by 1e-20 and 1e20', () => {
  // The lecture scene with everything (model, camera, light) scaled by s is the same picture: the normals
  // sign(det)·cof(M)·p are unit after normalising whatever |det| (1e-60 … 1e60), and the colours equal s = 1's.
  const W = 64;
  const H = 48;
  const { material, lights } = lecture(W, H);
  const render = (s: number, rotation = new Matrix4()) => {
    const camera = new PerspectiveCamera(90, W / H, 0.1 * s, 10 * s);
    camera.position.set(0, 0, 3 * s);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    return renderReference({
      width: W,
      height: H,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      modelMatrix: new Matrix4().makeScale(2 * s, s, 2 * s).premultiply(rotation).elements,
      material,
      lights: lights.map((l) => ({
        ...l,
        position: [l.position[0] * s, l.position[1] * s, l.position[2] * s],
      })),
      background: [0, 0, 1],
    });
  };
  const unit = render(1);
  for (const s of [1e-20, 1e20]) {
    it(`scale ${s}: the same hits, colours and depths as scale 1`, () => {
      const image = render(s);
      expect(Array.from(image.hit)).toEqual(Array.from(unit.hit));
      expect(unit.hit.reduce((a, b) => a + b, 0)).toBeGreaterThan(W * H * 0.2);
      for (let k = 0; k < 3 * W * H; k++) expect(image.linear[k]).toBeCloseTo(unit.linear[k], 6);
      for (let k = 0; k < W * H; k++) {
        if (unit.hit[k]) expect(image.depth[k]).toBeCloseTo(unit.depth[k], 5);
        expect(Math.abs(image.rgba[4 * k] - unit.rgba[4 * k])).toBeLessThanOrEqual(1);
        expect(Math.abs(image.rgba[4 * k + 1] - unit.rgba[4 * k + 1])).toBeLessThanOrEqual(1);
        expect(Math.abs(image.rgba[4 * k + 2] - unit.rgba[4 * k + 2])).toBeLessThanOrEqual(1);
      }
    });
  }
  it('rotated, and mixed scales (1e20 along one axis, 1e-20 along another): finite, and lit like the analytic ellipsoid', () => {
    const rotation = new Matrix4().makeRotationFromEuler(new Euler(0.4, -0.7, 0.2));
    const rotated = render(1e-20, rotation);
    const reference = render(1, rotation);
    expect(Array.from(rotated.hit)).toEqual(Array.from(reference.hit));
    for (let k = 0; k < 3 * W * H; k++) expect(rotated.linear[k]).toBeCloseTo(reference.linear[k], 5);
    // A needle: 1e20 along x, 1e-20 along y. Its normals are cof(M)·p = (1e-20·px, 1e20·py, pz) normalised.
    const camera = ortho(2);
    const needle = renderReference({
      width: 16,
      height: 16,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      modelMatrix: new Matrix4().makeScale(1e20, 1e-20, 1).elements,
      material: { ka: black, kd: white, ks: black, shininess: 1 },
      lights: [{ position: [0, 0, 100], ambient: black, diffuse: white, specular: black }],
    });
    expect(needle.linear.every(Number.isFinite)).toBe(true);
    expect(needle.hit.some((h) => h === 1)).toBe(false); // 1e-20 high: no pixel centre hits it
    const slab = renderReference({
      width: 16,
      height: 16,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      modelMatrix: new Matrix4().makeScale(1e20, 1, 1e-20).elements,
      material: { ka: black, kd: white, ks: black, shininess: 1 },
      lights: [{ position: [0, 0, 100], ambient: black, diffuse: white, specular: black }],
    });
    // A slab 1e-20 deep seen face on: every hit's normal is +z (to 1e-40), so the diffuse term is l·n = 1.
    expect(slab.linear.every(Number.isFinite)).toBe(true);
    for (let k = 0; k < 256; k++) {
      if (slab.hit[k] && Math.abs(slab.edgeDistance[k]) > 1) {
        // l from the hit (x, y, 0) to (0, 0, 100): l·n = 100 / |l|.
        const x = (((k % 16) + 0.5) / 16) * 4 - 2;
        const y = ((Math.floor(k / 16) + 0.5) / 16) * 4 - 2;
        const lz = 100 / Math.hypot(x, y, 100);
        expect(slab.linear[3 * k]).toBeCloseTo(lz, 5);
      }
    }
    // 1e20 wide, 2 high: the band |y| < 1 across the whole image (it was a unit disc when the model-space ray
    // came from (P·V·M)⁻¹, whose rounding swamped the 1e-20 components).
    for (let k = 0; k < 256; k++) {
      const y = ((Math.floor(k / 16) + 0.5) / 16) * 4 - 2;
      expect(slab.hit[k]).toBe(Math.abs(y) < 1 ? 1 : 0);
    }
  });
});

describe('renderReference: a zero scale (singular model matrix) renders the flattened ellipsoid', () => {
  const diffuseOnly = { ka: black, kd: white, ks: black, shininess: 1 };
  const render = (camera: OrthographicCamera | PerspectiveCamera, model: Matrix4, light: number[], N = 48) =>
    renderReference({
      width: N,
      height: N,
      projectionMatrix: camera.projectionMatrix.elements,
      viewMatrix: camera.matrixWorldInverse.elements,
      modelMatrix: model.elements,
      material: diffuseOnly,
      lights: [{ position: [light[0], light[1], light[2]], ambient: black, diffuse: white, specular: black }],
      samples: 1,
    });
  const look = <C extends OrthographicCamera | PerspectiveCamera>(camera: C, eye: number[]): C => {
    camera.position.set(eye[0], eye[1], eye[2]);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    return camera;
  };

  it('scale (2, 1, 0) face on: the ellipse x²/4 + y² < 1, lit with the normal facing the viewer, from either side', () => {
    const N = 48;
    for (const side of [1, -1]) {
      const camera = look(new OrthographicCamera(-2.5, 2.5, 2.5, -2.5, 0.1, 10), [0, 0, 3 * side]);
      const image = render(camera, new Matrix4().makeScale(2, 1, 0), [0, 0, 100 * side]);
      let hits = 0;
      for (let j = 0; j < N; j++) {
        for (let i = 0; i < N; i++) {
          const k = j * N + i;
          // Window x grows to the camera's right: −x seen from behind.
          const x = side * ((((i + 0.5) / N) * 2 - 1) * 2.5);
          const y = (((j + 0.5) / N) * 2 - 1) * 2.5;
          const inside = (x * x) / 4 + y * y;
          if (Math.abs(inside - 1) < 1e-9) continue;
          expect(image.hit[k]).toBe(inside < 1 ? 1 : 0);
          if (inside < 1) {
            hits++;
            // n = ±z towards the viewer, lit from the viewer's side: l·n = 100 / |l|.
            expect(image.linear[3 * k]).toBeCloseTo(100 / Math.hypot(x, y, 100), 6);
            expect(image.depth[k]).toBeCloseTo(new Vector3(x, y, 0).project(camera).z * 0.5 + 0.5, 6);
          }
        }
      }
      expect(hits).toBeGreaterThan(300);
      // Lit from the other side: the sheet facing the viewer is dark (no light through a surface).
      const back = render(camera, new Matrix4().makeScale(2, 1, 0), [0, 0, -100 * side]);
      expect(back.hit).toEqual(image.hit);
      expect(back.linear.every((c) => c === 0)).toBe(true);
    }
  });

  it('rotated, oblique perspective view: hits and depths where three.Ray meets the disc, normal ±(plane normal)', () => {
    const camera = look(new PerspectiveCamera(60, 1, 0.1, 20), [1.2, 2.5, 2.2]);
    const rotation = new Matrix4().makeRotationFromEuler(new Euler(0.3, 0.5, -0.2));
    const model = new Matrix4().makeScale(1.5, 0, 0.8).premultiply(rotation).setPosition(0.2, -0.1, 0.1);
    const light = [3, 8, 5];
    const N = 40;
    const image = render(camera, model, light, N);
    const normal = new Vector3(0, 1, 0).transformDirection(rotation);
    const centre = new Vector3(0.2, -0.1, 0.1);
    const plane = new Plane().setFromNormalAndCoplanarPoint(normal, centre);
    const inverse = rotation.clone().transpose();
    const ray = new Ray();
    const p = new Vector3();
    let hits = 0;
    for (let j = 0; j < N; j++) {
      for (let i = 0; i < N; i++) {
        const k = j * N + i;
        const a = new Vector3(((i + 0.5) / N) * 2 - 1, ((j + 0.5) / N) * 2 - 1, -1).unproject(camera);
        const b = new Vector3(((i + 0.5) / N) * 2 - 1, ((j + 0.5) / N) * 2 - 1, 1).unproject(camera);
        ray.set(a, b.sub(a).normalize());
        const onPlane = ray.intersectPlane(plane, p) !== null;
        // The point in the disc's own axes: inside the ellipse (x/1.5)² + (z/0.8)² < 1.
        const local = p.clone().sub(centre).applyMatrix4(inverse);
        const inside = onPlane ? (local.x / 1.5) ** 2 + (local.z / 0.8) ** 2 : 2;
        if (Math.abs(inside - 1) < 1e-6) continue;
        expect(image.hit[k]).toBe(inside < 1 ? 1 : 0);
        if (inside < 1) {
          hits++;
          expect(image.depth[k]).toBeCloseTo(p.clone().project(camera).z * 0.5 + 0.5, 6);
          // The visible normal faces the eye: ±normal, whichever points to the camera's side.
          const n = normal.clone().multiplyScalar(Math.sign(normal.dot(camera.position.clone().sub(p))));
          const l = new Vector3(light[0], light[1], light[2]).sub(p).normalize();
          expect(image.linear[3 * k]).toBeCloseTo(Math.max(n.dot(l), 0), 5);
        }
      }
    }
    expect(hits).toBeGreaterThan(100);
  });

  it('edge on, and rank ≤ 1 (a segment or a point): no area, nothing drawn, everything finite', () => {
    const side = look(new OrthographicCamera(-2, 2, 2, -2, 0.1, 10), [3, 0, 0]);
    for (const model of [
      new Matrix4().makeScale(1, 1, 0), // the disc z = 0, seen along −x
      new Matrix4().makeScale(1, 0, 0),
      new Matrix4().makeScale(0, 0, 0),
    ]) {
      const image = render(side, model, [0, 0, 100], 16);
      expect(image.hit.every((h) => h === 0)).toBe(true);
      expect(image.linear.every(Number.isFinite)).toBe(true);
      expect(image.coverage.every((c) => c === 0)).toBe(true);
    }
  });
});

describe('intersectSphere (Ray Tracing Gems ch. 7)', () => {
  it('hits lie on the sphere, for random rays', () => {
    fc.assert(
      fc.property(
        fc.tuple(...[0, 1, 2].map(() => fc.double({ min: -50, max: 50, noNaN: true }))),
        fc.tuple(...[0, 1, 2].map(() => fc.double({ min: -1, max: 1, noNaN: true }))),
        fc.double({ min: 0.01, max: 10, noNaN: true }),
        (o, d, r) => {
          const len = Math.hypot(...d);
          fc.pre(len > 1e-3);
          const hit = intersectSphere(o, d, [0, 0, 0], r);
          const ray = new Ray(new Vector3(...o), new Vector3(...d).normalize());
          const three = ray.intersectSphere(new Sphere(new Vector3(), r), new Vector3());
          if (hit === null) {
            expect(three).toBeNull();
            return;
          }
          for (const t of [hit.t0, hit.t1]) {
            const p = [0, 1, 2].map((i) => o[i] + (t * d[i]) / len);
            expect(Math.hypot(...p) / r).toBeCloseTo(1, 6);
          }
          expect(hit.t0).toBeLessThanOrEqual(hit.t1);
        },
      ),
    );
  });

  it('stays accurate for a small sphere far away, where the textbook discriminant cancels', () => {
    const o = [0, 0, 1e9];
    const d = [1e-10, 0, -1];
    const hit = intersectSphere(o, d, [0, 0, 0], 1);
    expect(hit).not.toBeNull();
    const len = Math.hypot(...d);
    const p = [0, 1, 2].map((i) => o[i] + ((hit?.t0 ?? 0) * d[i]) / len);
    // The ray passes 0.1 from the centre: the entry point is at z = √(1 − 0.01).
    expect(p[0]).toBeCloseTo(0.1, 5);
    expect(p[2]).toBeCloseTo(Math.sqrt(0.99), 5);
    // The textbook form b² − (f·f − r²) loses every digit here.
    const b = -1e9;
    const naive = b * b - (1e18 - 1);
    expect(Math.abs(naive - 0.99)).toBeGreaterThan(0.5);
  });

  it('returns null for zero or non-finite directions', () => {
    expect(intersectSphere([0, 0, 5], [0, 0, 0])).toBeNull();
    expect(intersectSphere([0, 0, 5], [Number.NaN, 0, 0])).toBeNull();
  });
});

describe('compareToReference', () => {
  const camera = ortho();
  const N = 48;
  const reference = renderReference({
    width: N,
    height: N,
    projectionMatrix: camera.projectionMatrix.elements,
    viewMatrix: camera.matrixWorldInverse.elements,
    material: { ka: [0.3, 0.2, 0.1], kd: [0.6, 0.35, 0.2], ks: [0.5, 0.5, 0.5], shininess: 32 },
    lights: [{ position: [-5, 10, 20], ambient: white, diffuse: white, specular: white }],
  });
  /** What a perfect rasteriser of the exact shape writes: the centre colour where the centre hits. */
  function perfect(shift = 0): Uint8Array {
    const out = new Uint8Array(4 * N * N);
    for (let j = 0; j < N; j++) {
      for (let i = 0; i < N; i++) {
        const k = j * N + i;
        const s = j * N + Math.min(Math.max(i - shift, 0), N - 1);
        if (reference.hit[s]) {
          const c = linearToSrgb8([
            reference.linear[3 * s],
            reference.linear[3 * s + 1],
            reference.linear[3 * s + 2],
          ]);
          out.set([c[0], c[1], c[2], 255], 4 * k);
        } else out.set([0, 0, 255, 255], 4 * k);
      }
    }
    return out;
  }
  it('scores a perfect image 0', () => {
    const e = compareToReference(perfect(), reference);
    expect(e.rmse).toBe(0);
    expect(e.max).toBe(0);
    expect(e.silhouettePx).toBe(0);
    expect(e.mismatchedPixels).toBe(0);
    expect(e.interiorPixels).toBeGreaterThan(500);
  });
  it('a one-pixel shift costs about one pixel of silhouette', () => {
    const e = compareToReference(perfect(1), reference);
    expect(e.silhouettePx).toBeGreaterThan(0);
    expect(e.silhouettePx).toBeLessThan(1.01);
    expect(e.max).toBeGreaterThan(0);
  });
  it('refuses a wrong size', () => {
    expect(() => compareToReference(new Uint8Array(12), reference)).toThrow(RangeError);
  });
});
