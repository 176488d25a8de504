import { arcRotation, projectToBall } from '@shadelab/trackball';
import fc from 'fast-check';
import { Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';

/** Same rotation within `tol` radians: the angle of a·b⁻¹ (q and −q are the same rotation). */
function sameRotation(a: readonly number[], b: readonly number[], tol: number): boolean {
  const r = new Quaternion(a[0], a[1], a[2], a[3]).multiply(new Quaternion(b[0], b[1], b[2], b[3]).invert());
  return 2 * Math.atan2(Math.hypot(r.x, r.y, r.z), Math.abs(r.w)) <= tol;
}

/** Rotation angle of a unit quaternion, radians in [0, π]. */
const angleOf = (q: readonly number[]) => 2 * Math.atan2(Math.hypot(q[0], q[1], q[2]), Math.abs(q[3]));

const pointer = fc.double({ min: -3, max: 3, noNaN: true });
const ballPoint = fc
  .tuple(pointer, pointer, fc.constantFrom<'arcball' | 'bell'>('arcball', 'bell'))
  .map(([x, y, m]) => projectToBall(x, y, m));

describe('arcRotation', () => {
  it('is three.js setFromUnitVectors applied twice (Shoemake: twice the arc)', () => {
    fc.assert(
      fc.property(ballPoint, ballPoint, (a, b) => {
        const va = new Vector3(...a).normalize();
        const vb = new Vector3(...b).normalize();
        if (va.dot(vb) < -0.999) return true; // setFromUnitVectors picks its own axis there
        const half = new Quaternion().setFromUnitVectors(va, vb);
        const twice = half.clone().multiply(half);
        return (
          sameRotation(arcRotation(a, b, 0.5), half.toArray(), 1e-12) &&
          sameRotation(arcRotation(a, b), twice.toArray(), 1e-12)
        );
      }),
    );
  });

  it('turns by 180° for a drag from the centre to the arcball rim, and 2·atan(2) for Bell', () => {
    const centre = projectToBall(0, 0, 'arcball');
    const q = arcRotation(centre, projectToBall(1, 0, 'arcball'));
    expect(angleOf(q)).toBeCloseTo(Math.PI, 12);
    // The axis is the camera's up (y) for a drag to the right.
    expect(Math.abs(q[1])).toBeCloseTo(1, 12);
    const bell = arcRotation(projectToBall(0, 0, 'bell'), projectToBall(1, 0, 'bell'));
    expect(angleOf(bell)).toBeCloseTo(2 * Math.atan(2), 12);
  });

  it('maps a to the direction of b when speed = 1/2 (the rotation follows the pointer)', () => {
    fc.assert(
      fc.property(ballPoint, ballPoint, (a, b) => {
        const q = arcRotation(a, b, 0.5);
        const moved = new Vector3(...a).normalize().applyQuaternion(new Quaternion(...q));
        return moved.distanceTo(new Vector3(...b).normalize()) < 1e-12;
      }),
    );
  });

  it('is exact for a one-pixel drag where acos would round to zero', () => {
    // A pointer 1e-8 ball radii from the centre: cos θ rounds to one ulp below 1, so acos(a·b) is 49% off;
    // atan2(|a×b|, a·b) is exact.
    const x = 1e-8;
    const a = projectToBall(0, 0, 'arcball');
    const b = projectToBall(x, 0, 'arcball');
    const dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    expect(Math.abs(Math.acos(dot) / Math.asin(x) - 1)).toBeGreaterThan(0.4);
    const q = arcRotation(a, b);
    expect(q[1] / Math.sin(Math.asin(x))).toBeCloseTo(1, 12); // sin(θ) with θ = asin(x), exactly
    expect(angleOf(q) / (2 * Math.asin(x))).toBeCloseTo(1, 12);
    // And at 1 px on a 500 px ball.
    const p = projectToBall(1 / 500, 0, 'arcball');
    expect(angleOf(arcRotation(a, p)) / (2 * Math.asin(1 / 500))).toBeCloseTo(1, 14);
  });

  it('Bell never turns faster than 2√2 rad per ball radius of pointer motion; the arcball does near the rim', () => {
    const far = fc.double({ min: -4, max: 4, noNaN: true });
    fc.assert(
      fc.property(far, far, far, far, (x0, y0, x1, y1) => {
        const angle = angleOf(arcRotation(projectToBall(x0, y0, 'bell'), projectToBall(x1, y1, 'bell')));
        return angle <= 2 * Math.SQRT2 * Math.hypot(x1 - x0, y1 - y0) + 1e-12;
      }),
    );
    // The arcball's last pixel before the rim of a 250 px-radius ball turns by more than 10°.
    const lastPixel = arcRotation(projectToBall(249 / 250, 0, 'arcball'), projectToBall(1, 0, 'arcball'));
    expect((angleOf(lastPixel) * 180) / Math.PI).toBeGreaterThan(10);
  });

  it('composes exactly at speed 1: q(b→c)·q(a→b) = q(a→c) (property)', () => {
    fc.assert(
      fc.property(ballPoint, ballPoint, ballPoint, (a, b, c) => {
        // three's Hamilton product, as the Trackball composes its rotations.
        const chained = new Quaternion(...arcRotation(b, c)).multiply(new Quaternion(...arcRotation(a, b)));
        return sameRotation(chained.toArray(), arcRotation(a, c), 1e-12);
      }),
    );
  });

  it('returns the identity for a zero-length drag and for speed 0', () => {
    const p = projectToBall(0.2, 0.3, 'bell');
    expect(arcRotation(p, p)).toEqual([0, 0, 0, 1]);
    expect(sameRotation(arcRotation(p, projectToBall(-0.7, 0.1), 0), [0, 0, 0, 1], 0)).toBe(true);
  });

  it('stays finite for antipodal rim points (a drag across the arcball equator)', () => {
    const a = projectToBall(5, 0, 'arcball');
    const b = projectToBall(-5, 0, 'arcball');
    const full = arcRotation(a, b);
    expect(full.every(Number.isFinite)).toBe(true);
    expect(sameRotation(full, [0, 0, 0, 1], 1e-15)).toBe(true); // twice 180° = a full turn
    const half = arcRotation(a, b, 0.5);
    const moved = new Vector3(...a).applyQuaternion(new Quaternion(...half));
    expect(moved.distanceTo(new Vector3(...b))).toBeLessThan(1e-15);
    for (const axis of [
      [0, 1, 0],
      [0, 0, 1],
      [0.3, 0.3, -0.9],
    ] as const) {
      const q = arcRotation(axis, [-axis[0], -axis[1], -axis[2]], 0.5);
      expect(Math.hypot(...q)).toBeCloseTo(1, 15);
      expect(Math.abs(q[3])).toBeLessThan(1e-15);
    }
  });

  it('stays a unit quaternion when speed · θ overflows (speed near Number.MAX_VALUE)', () => {
    // Found by the trackball fuzz: rotateSpeed 1.8e308 and a 110 px drag gave sin(∞) = NaN.
    for (const speed of [Number.MAX_VALUE, 1.7e308, 1e300]) {
      const q = arcRotation([0, 0, 1], projectToBall(0, -3), speed); // θ ≈ 1.5 rad
      expect(q.every(Number.isFinite)).toBe(true);
      expect(Math.hypot(...q)).toBeCloseTo(1, 15);
    }
  });

  it('refuses zero or non-finite points and a bad speed, naming them', () => {
    expect(() => arcRotation([0, 0, 0], [0, 0, 1])).toThrow(/a must be a finite non-zero vector/);
    expect(() => arcRotation([0, 0, 1], [Number.NaN, 0, 1])).toThrow(/b must be a finite non-zero vector/);
    expect(() => arcRotation([0, 0, 1], [0, 1, 0], -1)).toThrow(RangeError);
    expect(() => arcRotation([0, 0, 1], [0, 1, 0], Number.NaN)).toThrow(
      /speed must be a finite number ≥ 0, got NaN/,
    );
  });
});
