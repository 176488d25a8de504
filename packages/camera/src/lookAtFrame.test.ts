import { Camera, type CameraFrame, createPoleMemory, lookAtFrame, POLE_CAP_RAD } from '@shadelab/camera';
import fc from 'fast-check';
import { Matrix4, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';

const newFrame = (): CameraFrame => ({
  e: new Vector3(),
  u: new Vector3(),
  v: new Vector3(),
  w: new Vector3(),
});

function expectOrthonormal({ u, v, w }: CameraFrame): void {
  for (const x of [u, v, w]) {
    expect(Number.isFinite(x.x + x.y + x.z)).toBe(true);
    expect(Math.abs(x.length() - 1)).toBeLessThan(1e-12);
  }
  expect(Math.abs(u.dot(v))).toBeLessThan(1e-12);
  expect(Math.abs(u.dot(w))).toBeLessThan(1e-12);
  expect(Math.abs(v.dot(w))).toBeLessThan(1e-12);
  expect(new Vector3().crossVectors(u, v).distanceTo(w)).toBeLessThan(1e-12);
}

/** Largest angle (radians) any basis vector turned between consecutive frames. */
function frameStep(a: CameraFrame, b: CameraFrame): number {
  return Math.max(a.u.angleTo(b.u), a.v.angleTo(b.v), a.w.angleTo(b.w));
}

const copyFrame = (f: CameraFrame): CameraFrame => ({
  e: f.e.clone(),
  u: f.u.clone(),
  v: f.v.clone(),
  w: f.w.clone(),
});

/**
 * Sweeps t over ±3·POLE_CAP_RAD in 12,000 steps (5e-8 rad each) through `look(camera, t)`, checking every frame
 * is orthonormal (and `each`). `limit`: across the cap the right vector turns by π over 2·POLE_CAP_RAD of
 * sweep, so a continuous turn moves no basis vector by more than about π·step/POLE_CAP_RAD per step.
 */
function sweepCamera(
  look: (camera: Camera, t: number) => void,
  each?: (frame: CameraFrame, t: number) => void,
): { first: CameraFrame; last: CameraFrame; maxStep: number; limit: number } {
  const camera = new Camera();
  const steps = 12000;
  const span = 3 * POLE_CAP_RAD;
  let first: CameraFrame | undefined;
  let last: CameraFrame | undefined;
  let maxStep = 0;
  for (let i = 0; i <= steps; i++) {
    const t = -span + (2 * span * i) / steps;
    look(camera, t);
    const frame = camera.getFrame();
    expectOrthonormal(frame);
    each?.(frame, t);
    if (last) maxStep = Math.max(maxStep, frameStep(last, frame));
    last = copyFrame(frame);
    first ??= last;
  }
  return { first: first!, last: last!, maxStep, limit: 1.05 * Math.PI * ((2 * span) / steps / POLE_CAP_RAD) };
}

describe('lookAt with up parallel to the gaze (docs/design.md extremes)', () => {
  const gazes: [number, number, number][] = [
    [0, -1, 0],
    [0, 1, 0],
    [0, 0, -1],
    [1, 0, 0],
    [0.6, -0.8, 0],
    [1, 2, -3],
  ];

  it.each(gazes)('up exactly along ±gaze (%d, %d, %d) gives a finite orthonormal frame', (x, y, z) => {
    for (const sign of [1, -1]) {
      const camera = new Camera();
      camera.lookAt([0, 0, 0], [x, y, z], [sign * x, sign * y, sign * z]);
      const frame = camera.getFrame();
      expectOrthonormal(frame);
      expect(frame.w.dot(new Vector3(x, y, z).normalize())).toBeCloseTo(-1, 12);
      expect(Number.isFinite(camera.getMatrix().determinant())).toBe(true);
    }
  });

  it('up within 1e-9 rad of the gaze, in any direction around it, gives a finite orthonormal frame', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
        fc.double({ min: 0, max: 1e-9, noNaN: true }),
        fc.constantFrom(...gazes),
        (around, off, g) => {
          const w = new Vector3(...g).normalize().negate();
          const p = new Vector3(w.z, w.x, w.y).cross(w).normalize();
          const q = new Vector3().crossVectors(w, p);
          const up = new Vector3()
            .copy(w)
            .multiplyScalar(-Math.cos(off))
            .addScaledVector(
              p.multiplyScalar(Math.cos(around)).addScaledVector(q, Math.sin(around)),
              Math.sin(off),
            );
          const frame = lookAtFrame([0, 0, 0], g, up, newFrame(), createPoleMemory());
          expectOrthonormal(frame);
          expect(frame.w.distanceTo(w)).toBeLessThan(1e-12);
        },
      ),
    );
  });

  it('turns continuously while up sweeps through the pole (fixed gaze), and meets three outside the cap', () => {
    const eye = new Vector3(0, 5, 0);
    const at = new Vector3(0, 0, 0); // gaze −y
    const upAt = (angle: number) => new Vector3(0, Math.cos(angle), Math.sin(angle)); // from +y towards +z
    const { first, last, maxStep, limit } = sweepCamera(
      (camera, angle) => camera.lookAt(eye, at, upAt(angle)),
      (frame, angle) => {
        if (Math.abs(angle) > POLE_CAP_RAD * 1.01) {
          const m = new Matrix4().lookAt(eye, at, upAt(angle));
          expect(frame.u.distanceTo(new Vector3().setFromMatrixColumn(m, 0))).toBeLessThan(1e-9);
        }
      },
    );
    expect(maxStep).toBeLessThan(limit);
    expect(maxStep).toBeLessThan(0.01);
    // …and the two sides are the two exact, opposite frames (the turn really happened, continuously).
    expect(first.u.dot(last.u)).toBeCloseTo(-1, 9);
  });

  it('turns continuously while the eye orbits over the pole with up fixed', () => {
    const { maxStep } = sweepCamera((camera, phi) =>
      camera.lookAt([0, 10 * Math.cos(phi), 10 * Math.sin(phi)], [0, 0, 0], [0, 1, 0]),
    );
    expect(maxStep).toBeLessThan(0.01);
  });

  it('sweeps that pass beside the pole (any miss distance inside the cap) stay continuous', () => {
    fc.assert(
      fc.property(fc.double({ min: -POLE_CAP_RAD, max: POLE_CAP_RAD, noNaN: true }), (miss) => {
        const memory = createPoleMemory();
        const frame = newFrame();
        let previous: CameraFrame | undefined;
        let maxStep = 0;
        const steps = 3000;
        for (let i = 0; i <= steps; i++) {
          const t = -3 * POLE_CAP_RAD + (6 * POLE_CAP_RAD * i) / steps;
          const up = new Vector3(miss, 1, t); // gaze −y: up passes the pole at distance `miss`
          lookAtFrame([0, 1, 0], [0, 0, 0], up, frame, memory);
          if (previous) maxStep = Math.max(maxStep, frameStep(previous, frame));
          previous = copyFrame(frame);
        }
        expect(maxStep).toBeLessThan(0.02);
      }),
      { numRuns: 40 },
    );
  });

  it('is deterministic without memory and stays finite', () => {
    const a = lookAtFrame([0, 0, 0], [0, 0, -1], [0, 0, 1], newFrame());
    const b = lookAtFrame([0, 0, 0], [0, 0, -1], [0, 0, 1], newFrame());
    expect(a.u.toArray()).toEqual(b.u.toArray());
    expectOrthonormal(a);
  });

  it('huge and tiny (non-zero) eye − at keep working without overflow or underflow', () => {
    // Down to the smallest subnormal (5e-324: 1/s overflows, so the scaling must divide, not multiply).
    for (const s of [5e-324, 1e-310, 1e-300, 1e-30, 1e30, 1e300]) {
      const frame = lookAtFrame([0, 0, s], [0, 0, 0], [0, 1, 0], newFrame());
      expectOrthonormal(frame);
      expect(frame.w.toArray()).toEqual([0, 0, 1]);
    }
    // eye − at itself overflowing float64 is refused, naming it.
    expect(() => lookAtFrame([1.7e308, 0, 0], [-1.7e308, 0, 0], [0, 1, 0], newFrame())).toThrow(
      /^eye − at overflows/,
    );
  });
});

describe('Camera.lookAt near the pole (docs/design.md extremes, through the Camera and its pole memory)', () => {
  const gazes: [number, number, number][] = [
    [0, -1, 0],
    [0, 1, 0],
    [0, 0, -1],
    [0.6, -0.8, 0],
    [1, 2, -3],
  ];

  it('up within 1e-9 rad of +gaze or of −gaze, in any direction around it: finite orthonormal frame, right gaze', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
        fc.double({ min: 0, max: 1e-9, noNaN: true }),
        fc.constantFrom(...gazes),
        fc.constantFrom(1, -1),
        fc.boolean(),
        (around, off, g, sign, fromElsewhere) => {
          const gaze = new Vector3(...g).normalize();
          const p = new Vector3(gaze.z, gaze.x, gaze.y).cross(gaze).normalize();
          const q = new Vector3().crossVectors(gaze, p);
          // sign · gaze tilted by `off` towards the direction `around` in the plane ⊥ gaze.
          const up = gaze
            .clone()
            .multiplyScalar(sign * Math.cos(off))
            .addScaledVector(
              p.multiplyScalar(Math.cos(around)).addScaledVector(q, Math.sin(around)),
              Math.sin(off),
            );
          const camera = new Camera();
          // Either a fresh camera, or one whose pole memory was set by an ordinary lookAt first.
          if (fromElsewhere) camera.lookAt([3, 1, 2], [0, 0, 0], [0, 1, 0]);
          camera.lookAt([1, 2, 3], new Vector3(1, 2, 3).add(new Vector3(...g)), up);
          const frame = camera.getFrame();
          expectOrthonormal(frame);
          expect(frame.w.distanceTo(gaze.clone().negate())).toBeLessThan(1e-12);
          expect(frame.e.distanceTo(new Vector3(1, 2, 3))).toBeLessThan(1e-12);
          for (const x of camera.getMatrix().elements) expect(Number.isFinite(x)).toBe(true);
          for (const x of camera.matrixWorldInverse.elements) expect(Number.isFinite(x)).toBe(true);
        },
      ),
    );
  });

  it('turns continuously while the eye passes under the pole (eye below at, up = +y: up ≈ +gaze)', () => {
    const { first, last, maxStep, limit } = sweepCamera(
      // The eye on a circle below `at`: the gaze is ≈ +y, along up.
      (camera, phi) => camera.lookAt([0, -10 * Math.cos(phi), 10 * Math.sin(phi)], [0, 0, 0], [0, 1, 0]),
      (frame, phi) => {
        expect(frame.w.y).toBeLessThan(-0.99); // looking up
        if (Math.abs(phi) > POLE_CAP_RAD * 1.01) {
          const m = new Matrix4().lookAt(frame.e, new Vector3(), new Vector3(0, 1, 0));
          expect(frame.u.distanceTo(new Vector3().setFromMatrixColumn(m, 0))).toBeLessThan(1e-9);
        }
      },
    );
    expect(maxStep).toBeLessThan(limit);
    expect(first.u.dot(last.u)).toBeCloseTo(-1, 9);
  });

  it('turns continuously while up sweeps through +gaze (fixed gaze −y, up from −y side)', () => {
    const { maxStep, limit } = sweepCamera(
      (camera, angle) => camera.lookAt([0, 5, 0], [0, 0, 0], [0, -Math.cos(angle), Math.sin(angle)]), // up ≈ +gaze
    );
    expect(maxStep).toBeLessThan(limit);
  });
});
