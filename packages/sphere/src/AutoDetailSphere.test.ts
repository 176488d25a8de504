import { SPHERE_BASES, SubdivisionSphereGeometry, sphereCounts } from '@shadelab/sphere';
import { AutoDetailSphere, projectedRadiusPx, sphereError } from '@shadelab/sphere/detail';
import fc from 'fast-check';
import {
  Matrix4,
  MeshBasicMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  Vector3,
  type Vector4,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it } from 'vitest';

function perspective(distance: number, fov = 90, aspect = 16 / 9): PerspectiveCamera {
  const camera = new PerspectiveCamera(fov, aspect, 0.01, 1e4);
  camera.position.set(0, 0, distance);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

/** The on-screen radius, in pixels, of a sphere of radius R at the origin, by projecting its tangent point. */
function exactRadiusPx(camera: PerspectiveCamera, R: number, heightPx: number): number {
  const d = camera.position.length();
  const tangent = new Vector3(0, R * Math.sqrt(1 - (R * R) / (d * d)), (R * R) / d);
  return (tangent.project(camera).y * heightPx) / 2;
}

/**
 * The silhouette error scale of a sphere of radius R on the view axis of `camera` at distance d, from the exact
 * formula: the derivative of the on-screen radius, R · d/dR [(H/2)·P₁₁·R/√(d² − R²)] = (H/2)·P₁₁·R·d²/(d² − R²)^{3/2}.
 * silhouetteBound.test.ts checks the bound against the error measured in the image.
 */
function onAxisScalePx(camera: PerspectiveCamera, R: number, heightPx: number): number {
  const d = camera.position.length();
  const f = (heightPx / 2) * camera.projectionMatrix.elements[5];
  return (f * R * d * d) / (d * d - R * R) ** 1.5;
}

/** The fewest triangles of any allowed (base, level ≤ maxLevel) whose error on screen meets the budget. */
function cheapest(radiusPx: number, budget: number, maxLevel: number): number {
  let best = Number.POSITIVE_INFINITY;
  for (const base of SPHERE_BASES) {
    for (let level = 0; level <= maxLevel; level++) {
      if (radiusPx * sphereError(base, level) <= budget)
        best = Math.min(best, sphereCounts(base, level).triangles);
    }
  }
  return best;
}

describe('projectedRadiusPx', () => {
  it('perspective: equals the projected tangent point of a sphere on the view axis', () => {
    for (const d of [1.5, 3, 10, 100]) {
      for (const fov of [30, 90, 120]) {
        const camera = perspective(d, fov);
        const r = projectedRadiusPx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: 720 });
        expect(r).toBeCloseTo(exactRadiusPx(camera, 1, 720), 6);
        // The lecture-note approximation r·(H/2)/(d·tan(fovy/2)) is a lower bound, close when far.
        const approx = 360 / (d * Math.tan((fov * Math.PI) / 360));
        expect(r).toBeGreaterThanOrEqual(approx);
        if (d >= 10) expect(r / approx).toBeLessThan(1.006);
      }
    }
  });

  it('uses the largest scale axis of the world matrix (the lecture scale (2, 1, 2) → 2)', () => {
    const camera = perspective(6);
    const r = projectedRadiusPx({
      camera,
      matrixWorld: new Matrix4().makeScale(2, 1, 2),
      viewportHeightPx: 720,
    });
    expect(r).toBeCloseTo(exactRadiusPx(camera, 2, 720), 6);
  });

  it('orthographic: r·H·zoom/(top − bottom)', () => {
    const camera = new OrthographicCamera(-4, 4, 3, -3, 0.1, 10);
    camera.zoom = 2.5;
    camera.updateProjectionMatrix();
    camera.position.set(0, 0, 5);
    camera.updateMatrixWorld();
    const r = projectedRadiusPx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: 600, radius: 0.75 });
    expect(r).toBeCloseTo((0.75 * 600 * 2.5) / 6, 9);
  });

  it('is infinite with the eye inside the sphere; refuses bad sizes', () => {
    expect(
      projectedRadiusPx({ camera: perspective(0.5), matrixWorld: new Matrix4(), viewportHeightPx: 10 }),
    ).toBe(Number.POSITIVE_INFINITY);
    const camera = perspective(3);
    for (const bad of [0, -1, Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => projectedRadiusPx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: bad })).toThrow(
        /viewportHeightPx/,
      );
      expect(() =>
        projectedRadiusPx({ camera, matrixWorld: new Matrix4(), viewportHeightPx: 10, radius: bad }),
      ).toThrow(RangeError);
    }
  });
});

describe('AutoDetailSphere', () => {
  const material = new MeshBasicMaterial();
  const H = 720;

  it('meets the 0.5 px budget (error bound) over a zoom sweep and never draws more triangles than needed', () => {
    const sphere = new AutoDetailSphere(material);
    sphere.scale.set(2, 1, 2);
    const seen = new Set<string>();
    for (let i = 0; i <= 60; i++) {
      const d = 2.05 * 1.1 ** i; // from just outside the sphere to ~620 units away
      const camera = perspective(d);
      sphere.update(camera, H);
      const { detail } = sphere;
      seen.add(`${detail.base}/${detail.level}`);
      expect(detail.radiusPx).toBeCloseTo(exactRadiusPx(camera, 2, H), 6);
      // The ellipsoid (2, 1, 2) seen along z: its widest section (x, z) is the radius-2 sphere's.
      const scalePx = onAxisScalePx(camera, 2, H);
      expect(detail.errorScalePx / scalePx).toBeCloseTo(1, 9);
      const needed = cheapest(scalePx, 0.5, 8);
      if (Number.isFinite(needed)) {
        expect(detail.meetsBudget).toBe(true);
        expect(scalePx * sphereError(detail.base, detail.level)).toBeLessThanOrEqual(0.5 + 1e-9);
        expect(detail.triangles).toBe(needed);
      } else {
        expect(detail.meetsBudget).toBe(false);
        expect(detail.level).toBe(8);
      }
      expect(sphere.geometry).toBeInstanceOf(SubdivisionSphereGeometry);
      const g = sphere.geometry as SubdivisionSphereGeometry;
      expect(g.parameters.base).toBe(detail.base);
      expect(g.parameters.level).toBe(detail.level);
      expect(g.index?.count).toBe(3 * detail.triangles);
    }
    expect(seen.size).toBeGreaterThan(4);
    // Zoom back in: every detail comes from the cache.
    const builds = sphere.builds;
    for (let i = 60; i >= 0; i--) sphere.update(perspective(2.05 * 1.1 ** i), H);
    expect(sphere.builds).toBe(builds);
    expect(builds).toBe(seen.size + 1); // + the initial coarsest sphere
  });

  it('property: any camera, scale and budget gets the cheapest sphere meeting it', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 1.5, max: 1000, noNaN: true }),
        fc.double({ min: 10, max: 150, noNaN: true }),
        fc.double({ min: 0.1, max: 4, noNaN: true }),
        fc.double({ min: 0.05, max: 8, noNaN: true }),
        fc.integer({ min: 16, max: 4096 }),
        (d, fov, s, budget, height) => {
          const sphere = new AutoDetailSphere(material, { maxErrorPx: budget, maxLevel: 10 });
          sphere.scale.setScalar(s);
          const camera = perspective(d * s, fov);
          sphere.update(camera, height);
          const scalePx = onAxisScalePx(camera, s, height);
          expect(sphere.detail.errorScalePx / scalePx).toBeCloseTo(1, 9);
          const needed = cheapest(scalePx, budget, 10);
          fc.pre(Number.isFinite(needed));
          expect(sphere.detail.triangles).toBe(needed);
          expect(sphere.detail.errorPx).toBeLessThanOrEqual(budget);
        },
      ),
      { numRuns: 200 },
    );
  });

  it('does nothing while camera and viewport stay put; follows the viewport height', () => {
    const sphere = new AutoDetailSphere(material);
    const camera = perspective(5);
    expect(sphere.update(camera, 200)).toBe(true);
    const before = sphere.detail;
    expect(sphere.update(camera, 200)).toBe(false);
    expect(sphere.detail).toBe(before); // not even chosen again
    expect(sphere.update(camera, 4000)).toBe(true);
    expect(sphere.detail.triangles).toBeGreaterThan(before.triangles);
  });

  it('updates in onBeforeRender from the renderer viewport and dispatches change', () => {
    const sphere = new AutoDetailSphere(material);
    const renderer = {
      getCurrentViewport: (v: Vector4) => v.set(0, 0, 1280, 720),
    } as unknown as WebGLRenderer;
    let changes = 0;
    sphere.addEventListener('change' as never, () => {
      changes++;
    });
    const camera = perspective(3);
    const call = () =>
      sphere.onBeforeRender(renderer, null as never, camera, sphere.geometry, material, null as never);
    call();
    call();
    expect(changes).toBe(1);
    expect(sphere.detail.radiusPx).toBeCloseTo(exactRadiusPx(camera, 1, 720), 6);
  });

  it('orthographic zoom sweep meets the budget', () => {
    const sphere = new AutoDetailSphere(material, { bases: ['icosahedron'] });
    const camera = new OrthographicCamera(-2, 2, 1, -1, 0.1, 10);
    camera.position.z = 5;
    for (const zoom of [0.01, 0.1, 1, 10, 100]) {
      camera.zoom = zoom;
      camera.updateProjectionMatrix();
      camera.updateMatrixWorld();
      sphere.update(camera, H);
      expect(sphere.detail.base).toBe('icosahedron');
      expect(sphere.detail.radiusPx).toBeCloseTo((H * zoom) / 2, 6);
      expect(sphere.detail.errorScalePx).toBeCloseTo((H * zoom) / 2, 6); // orthographic: exact, the radius
      if (sphere.detail.meetsBudget) expect(sphere.detail.errorPx).toBeLessThanOrEqual(0.5);
    }
  });

  it('eye inside the sphere: the finest allowed sphere, budget not met', () => {
    const sphere = new AutoDetailSphere(material, { maxLevel: 3 });
    sphere.update(perspective(0.5), H);
    expect(sphere.detail).toMatchObject({ base: 'icosahedron', level: 3, meetsBudget: false });
  });

  it('refuses bad options, naming them', () => {
    expect(() => new AutoDetailSphere(material, { maxErrorPx: 0 })).toThrow(/maxErrorPx/);
    expect(() => new AutoDetailSphere(material, { maxErrorPx: Number.NaN })).toThrow(RangeError);
    expect(() => new AutoDetailSphere(material, { maxLevel: 11 })).toThrow(/maxLevel/);
    expect(() => new AutoDetailSphere(material, { maxLevel: 1.5 })).toThrow(RangeError);
    expect(() => new AutoDetailSphere(material, { bases: [] })).toThrow(/bases/);
    expect(() => new AutoDetailSphere(material, { radius: -1 })).toThrow(/radius/);
  });

  it('disposeGeometries() (and dispose() where three has it) disposes every cached geometry', () => {
    for (const how of ['disposeGeometries', 'dispose'] as const) {
      const sphere = new AutoDetailSphere(material);
      const geometries = new Set([sphere.geometry]);
      sphere.update(perspective(3), 100);
      geometries.add(sphere.geometry);
      sphere.update(perspective(30), 100);
      geometries.add(sphere.geometry);
      expect(geometries.size).toBeGreaterThan(1);
      let disposed = 0;
      for (const g of geometries) g.addEventListener('dispose', () => disposed++);
      const dispose = (sphere as unknown as Record<string, (() => void) | undefined>)[how];
      if (how === 'dispose' && !dispose) continue; // three < 0.186 has no Object3D#dispose
      dispose!.call(sphere);
      expect(disposed).toBe(geometries.size);
    }
  });
});
