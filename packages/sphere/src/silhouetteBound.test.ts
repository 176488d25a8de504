// The error AutoDetailSphere budgets (silhouetteErrorScalePx · sphereError) against the silhouette error
// actually seen in the image, measured independently (silhouetteGap.test-util.ts: projected mesh vertices,
// their hull, against the ray-cast exact outline of the ellipsoid, on screen only).
import {
  AutoDetailSphere,
  chooseSphereDetail,
  projectedRadiusPx,
  silhouetteErrorScalePx,
  sphereError,
} from '@shadelab/sphere/detail';
import fc from 'fast-check';
import {
  type Camera,
  Euler,
  Matrix4,
  MeshBasicMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  Quaternion,
  Vector3,
} from 'three';
import { describe, expect, it } from 'vitest';
import { silhouetteGapPx, sphereMesh } from './silhouetteGap.test-util.js';

const W = 1280;
const H = 720;
/** Bisection and polyline sampling of the measurement: far below what is asserted. */
const MEASURE_TOL = 2e-3;
/** The lecture zoom sweep (the bench's): 25 distances from 2.25 to about 64 units. */
const SWEEP = Array.from({ length: 25 }, (_, i) => 2.25 * 1.15 ** i);

/** The mesh an AutoDetailSphere draws, measured in the image: within its own bound and within 0.5 px. */
function expectDrawnWithinBudget(sphere: AutoDetailSphere, camera: Camera): void {
  const gap = silhouetteGapPx(sphere.geometry, {
    camera,
    matrixWorld: sphere.matrixWorld,
    widthPx: W,
    heightPx: H,
  });
  expect(gap).toBeLessThanOrEqual(sphere.detail.errorPx + MEASURE_TOL);
  expect(gap).toBeLessThanOrEqual(0.5);
}

function lectureCamera(d: number): PerspectiveCamera {
  const camera = new PerspectiveCamera(90, W / H, 0.01, 1000);
  camera.position.set(0, 0, d);
  camera.updateMatrixWorld();
  return camera;
}

describe('silhouetteErrorScalePx', () => {
  it('on the view axis: (H/2)·P₁₁·R·d²/(d² − R²)^{3/2}, the derivative of the exact on-screen radius', () => {
    for (const d of [1.2, 2.25, 3, 10, 100]) {
      for (const fov of [30, 90, 120]) {
        const camera = new PerspectiveCamera(fov, 1.5, 0.01, 1e4);
        camera.position.set(0, 0, d);
        camera.updateMatrixWorld();
        const f = (H / 2) * camera.projectionMatrix.elements[5];
        const K = silhouetteErrorScalePx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: H });
        expect(K).toBeCloseTo((f * d * d) / (d * d - 1) ** 1.5, 6);
        // Numerically: R · d(radius on screen)/dR, from projectedRadiusPx (exact on the axis).
        const r = (R: number) =>
          projectedRadiusPx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: H, radius: R });
        const h = 1e-6;
        expect(K / ((r(1 + h) - r(1 - h)) / (2 * h))).toBeCloseTo(1, 6);
      }
    }
  });

  it('orthographic: (H/2)·P₁₁ times the largest radius across the view', () => {
    const camera = new OrthographicCamera(-4, 4, 3, -3, 0.1, 100);
    camera.zoom = 2;
    camera.updateProjectionMatrix();
    camera.position.set(0, 0, 10);
    camera.updateMatrixWorld();
    const K = silhouetteErrorScalePx({
      camera,
      matrixWorld: new Matrix4().makeScale(0.5, 1.5, 7), // z (along the view) does not count
      viewportHeightPx: 600,
    });
    expect(K).toBeCloseTo(((600 * 2) / 6) * 1.5, 9);
  });

  it('infinite with the eye inside, or the ellipsoid across the eye plane; 0 when behind the eye', () => {
    const camera = lectureCamera(1.5);
    const K = (m: Matrix4) => silhouetteErrorScalePx({ camera, matrixWorld: m, viewportHeightPx: H });
    expect(K(new Matrix4().makeScale(2, 1, 2))).toBe(Number.POSITIVE_INFINITY); // inside
    expect(K(new Matrix4().makeTranslation(3, 0, 1.5))).toBe(Number.POSITIVE_INFINITY); // beside the eye
    expect(K(new Matrix4().makeTranslation(0, 0, 5))).toBe(0); // behind
    expect(() => silhouetteErrorScalePx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: 0 })).toThrow(
      /viewportHeightPx/,
    );
    expect(() =>
      silhouetteErrorScalePx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: H, radius: -1 }),
    ).toThrow(/radius/);
  });

  it('a flat (zero-scale axis) ellipsoid still gets a finite bound that holds', () => {
    const camera = lectureCamera(4);
    const matrixWorld = new Matrix4().makeScale(1, 1, 0);
    const K = silhouetteErrorScalePx({ camera, matrixWorld, viewportHeightPx: H });
    expect(Number.isFinite(K)).toBe(true);
    expect(K).toBeGreaterThan(0);
  });
});

describe('the image-space silhouette error stays within the bound', () => {
  it('lecture zoom sweep: AutoDetailSphere at 0.5 px measures ≤ 0.5 px at every distance', () => {
    const sphere = new AutoDetailSphere(new MeshBasicMaterial(), { maxLevel: 10 });
    sphere.scale.set(2, 1, 2);
    for (const d of SWEEP) {
      const camera = lectureCamera(d);
      sphere.update(camera, H);
      expect(sphere.detail.meetsBudget).toBe(true);
      expectDrawnWithinBudget(sphere, camera);
    }
  });

  it('the measurement sees the bug it guards against: the radius model picked icosahedron 4 at d = 2.59, 1.02 px', () => {
    const camera = lectureCamera(2.25 * 1.15);
    const matrixWorld = new Matrix4().makeScale(2, 1, 2);
    const radiusPx = projectedRadiusPx({ camera, matrixWorld, viewportHeightPx: H });
    const old = chooseSphereDetail({ radiusPx, maxErrorPx: 0.5 });
    expect(old).toMatchObject({ base: 'icosahedron', level: 4 });
    const gap = silhouetteGapPx(sphereMesh('icosahedron', 4), {
      camera,
      matrixWorld,
      widthPx: W,
      heightPx: H,
    });
    expect(gap).toBeGreaterThan(0.9);
    expect(gap).toBeLessThan(1.1);
  });

  it('every base and level 0 … 5 near the camera: measured ≤ the bound (coarse meshes test the bound itself)', () => {
    for (const d of [2.25, 2.6, 4]) {
      const camera = lectureCamera(d);
      const matrixWorld = new Matrix4().makeScale(2, 1, 2);
      const K = silhouetteErrorScalePx({ camera, matrixWorld, viewportHeightPx: H });
      for (const base of ['tetrahedron', 'octahedron', 'icosahedron'] as const) {
        for (let level = 0; level <= 5; level++) {
          const gap = silhouetteGapPx(sphereMesh(base, level), {
            camera,
            matrixWorld,
            widthPx: W,
            heightPx: H,
          });
          expect(gap).toBeLessThanOrEqual(K * sphereError(base, level) + MEASURE_TOL);
        }
      }
    }
  });

  it('off axis: near the image edges and corners, near the camera, rotated non-uniform scale', () => {
    const sphere = new AutoDetailSphere(new MeshBasicMaterial(), { maxLevel: 10 });
    sphere.scale.set(1.5, 0.6, 1);
    sphere.rotation.set(0.3, 0.8, -0.4);
    const camera = new PerspectiveCamera(90, W / H, 0.01, 1000);
    camera.updateMatrixWorld();
    const tanY = 1;
    const tanX = W / H;
    for (const depth of [3, 6, 20]) {
      for (const [u, v] of [
        [0.9, 0],
        [0, 0.85],
        [-0.9, -0.8],
        [0.75, 0.7],
        [0.5, -0.3],
      ]) {
        sphere.position.set(u * tanX * depth, v * tanY * depth, -depth);
        sphere.update(camera, H);
        const { detail } = sphere;
        expectDrawnWithinBudget(sphere, camera);
        // And a coarse mesh, whose error is large enough to test the bound closely.
        const K = detail.errorScalePx;
        const coarse = silhouetteGapPx(sphereMesh('octahedron', 2), {
          camera,
          matrixWorld: sphere.matrixWorld,
          widthPx: W,
          heightPx: H,
        });
        expect(coarse).toBeLessThanOrEqual(K * sphereError('octahedron', 2) + MEASURE_TOL);
      }
    }
  });

  it('orthographic camera: zoom sweep with a rotated non-uniform scale', () => {
    const sphere = new AutoDetailSphere(new MeshBasicMaterial(), { maxLevel: 10 });
    sphere.scale.set(2, 1, 2);
    sphere.rotation.set(0.5, 0.2, 0.1);
    sphere.position.set(0.7, -0.3, 0);
    const camera = new OrthographicCamera(-4 * (W / H), 4 * (W / H), 4, -4, 0.1, 100);
    camera.position.set(0, 0, 10);
    for (const zoom of [0.5, 1, 2, 4]) {
      camera.zoom = zoom;
      camera.updateProjectionMatrix();
      camera.updateMatrixWorld();
      sphere.update(camera, H);
      const { detail } = sphere;
      const scene = { camera, matrixWorld: sphere.matrixWorld, widthPx: W, heightPx: H };
      expect(silhouetteGapPx(sphere.geometry, scene)).toBeLessThanOrEqual(
        Math.min(0.5, detail.errorPx + MEASURE_TOL),
      );
      const coarse = silhouetteGapPx(sphereMesh('tetrahedron', 2), scene);
      expect(coarse).toBeLessThanOrEqual(detail.errorScalePx * sphereError('tetrahedron', 2) + MEASURE_TOL);
    }
  });

  it('property: random perspective scenes (scale, rotation, place on screen, fov, mesh): measured ≤ bound', () => {
    fc.assert(
      fc.property(
        fc.tuple(...[0, 1, 2].map(() => fc.double({ min: 0.3, max: 3, noNaN: true }))),
        fc.tuple(...[0, 1, 2].map(() => fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }))),
        fc.double({ min: -0.9, max: 0.9, noNaN: true }),
        fc.double({ min: -0.9, max: 0.9, noNaN: true }),
        fc.double({ min: 1.05, max: 8, noNaN: true }),
        fc.double({ min: 30, max: 110, noNaN: true }),
        fc.constantFrom('tetrahedron', 'octahedron', 'icosahedron'),
        fc.integer({ min: 0, max: 4 }),
        (scale, angles, u, v, away, fov, base, level) => {
          const camera = new PerspectiveCamera(fov, W / H, 0.01, 1e4);
          camera.updateMatrixWorld();
          const s = new Vector3(...scale);
          const depth = away * Math.max(...scale); // all of the ellipsoid in front of the eye
          const t = Math.tan((fov * Math.PI) / 360);
          const matrixWorld = new Matrix4().compose(
            new Vector3(u * t * (W / H) * depth, v * t * depth, -depth),
            new Quaternion().setFromEuler(new Euler(...angles)),
            s,
          );
          const K = silhouetteErrorScalePx({ camera, matrixWorld, viewportHeightPx: H });
          fc.pre(Number.isFinite(K)); // the ellipsoid crosses the eye plane: unbounded image, bound infinite
          const gap = silhouetteGapPx(
            sphereMesh(base, level),
            { camera, matrixWorld, widthPx: W, heightPx: H },
            1024,
          );
          expect(gap).toBeLessThanOrEqual(K * sphereError(base, level) + MEASURE_TOL);
        },
      ),
      { numRuns: 40 },
    );
  });
});
