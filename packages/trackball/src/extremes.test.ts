import {
  arcRotation,
  multiplyQuaternions,
  normalizeQuaternion,
  projectToBall,
  type Quat,
} from '@shadelab/trackball';
import { Matrix4, Quaternion } from 'three';
import { describe, expect, it } from 'vitest';

/** Largest deviation of the rotation matrix of q from orthonormal with det +1 (three.js builds the matrix). */
function orthonormalError(q: Quat): number {
  const e = new Matrix4().makeRotationFromQuaternion(new Quaternion(...q)).elements;
  const col = (j: number) => [e[4 * j], e[4 * j + 1], e[4 * j + 2]];
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const [u, v, w] = [col(0), col(1), col(2)];
  const det = new Matrix4().makeRotationFromQuaternion(new Quaternion(...q)).determinant();
  return Math.max(
    Math.abs(dot(u, u) - 1),
    Math.abs(dot(v, v) - 1),
    Math.abs(dot(w, w) - 1),
    Math.abs(dot(u, v)),
    Math.abs(dot(v, w)),
    Math.abs(dot(w, u)),
    Math.abs(det - 1),
  );
}

/** Small deterministic PRNG (mulberry32), so a failure can be replayed. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Pointer coordinates that hit the centre, the rim, just inside/outside it, far outside, or anywhere. */
function pointerPicker(rand: () => number): () => [number, number] {
  return () => {
    const kind = Math.floor(rand() * 6);
    const angle = rand() * 2 * Math.PI;
    const r =
      kind === 0
        ? 0
        : kind === 1
          ? 1
          : kind === 2
            ? Math.SQRT1_2
            : kind === 3
              ? 1 + (rand() - 0.5) * 1e-9
              : kind === 4
                ? 10 ** (rand() * 12)
                : rand() * 3;
    return [r * Math.cos(angle), r * Math.sin(angle)];
  };
}

describe('trackball extremes (DESIGN.md): the pure rotation core', () => {
  it('keeps the rotation orthonormal within 1e-6 and never NaN over 10⁶ random drags', () => {
    const rand = random(20261123);
    const pick = pointerPicker(rand);
    const q: Quat = [0, 0, 0, 1];
    const a: [number, number, number] = [0, 0, 1];
    const b: [number, number, number] = [0, 0, 1];
    const dq: Quat = [0, 0, 0, 1];
    let nonFinite = 0;
    let worst = 0;
    for (let i = 0; i < 1_000_000; i++) {
      const mapping = i & 1 ? 'arcball' : 'bell';
      const [x0, y0] = pick();
      // One drag in eight has zero length.
      const [x1, y1] = (i & 7) === 0 ? [x0, y0] : pick();
      projectToBall(x0, y0, mapping, a);
      projectToBall(x1, y1, mapping, b);
      arcRotation(a, b, (i % 5) * 0.75, dq);
      normalizeQuaternion(multiplyQuaternions(dq, q, q));
      if (
        !(Number.isFinite(q[0]) && Number.isFinite(q[1]) && Number.isFinite(q[2]) && Number.isFinite(q[3]))
      ) {
        nonFinite++;
      }
      if (i % 10_000 === 0) worst = Math.max(worst, orthonormalError(q));
    }
    expect(nonFinite).toBe(0);
    expect(Math.max(worst, orthonormalError(q))).toBeLessThan(1e-6);
    expect(Math.abs(Math.hypot(...q) - 1)).toBeLessThan(1e-12);
  });

  it.each(['arcball', 'bell'] as const)(
    '%s: centre, rim, beyond the rim and zero-length drags give finite unit rotations',
    (mapping) => {
      const points: [number, number][] = [
        [0, 0],
        [1, 0],
        [0, -1],
        [Math.SQRT1_2, Math.SQRT1_2],
        [Math.SQRT1_2, 0],
        [1 + 1e-15, 0],
        [1 - 1e-15, 0],
        [2, 2],
        [-1e9, 3],
        [1e300, -1e300],
        [Number.MIN_VALUE, 0],
      ];
      for (const [x0, y0] of points) {
        for (const [x1, y1] of points) {
          const q = arcRotation(projectToBall(x0, y0, mapping), projectToBall(x1, y1, mapping));
          expect(q.every(Number.isFinite)).toBe(true);
          expect(Math.abs(Math.hypot(...q) - 1)).toBeLessThan(1e-15);
          expect(orthonormalError(q)).toBeLessThan(1e-12);
          if (x0 === x1 && y0 === y1) expect(q).toEqual([0, 0, 0, 1]);
        }
      }
    },
  );
});
