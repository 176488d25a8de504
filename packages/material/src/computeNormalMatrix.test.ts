import { computeNormalMatrix } from '@shadelab/material';
import fc from 'fast-check';
import { Euler, Matrix3, Matrix4, Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';

function compose(scale: [number, number, number], rotation = new Euler(0.3, -0.7, 1.1)): Matrix4 {
  return new Matrix4().compose(
    new Vector3(1, -2, 3),
    new Quaternion().setFromEuler(rotation),
    new Vector3(...scale),
  );
}

/** Unit directions spread over the sphere (a Fibonacci lattice). */
function directions(count: number): Vector3[] {
  const out: Vector3[] = [];
  for (let i = 0; i < count; i++) {
    const y = 1 - (2 * (i + 0.5)) / count;
    const r = Math.sqrt(1 - y * y);
    const phi = i * Math.PI * (3 - Math.sqrt(5));
    out.push(new Vector3(r * Math.cos(phi), y, r * Math.sin(phi)));
  }
  return out;
}

describe('computeNormalMatrix', () => {
  it('is a positive multiple of three’s getNormalMatrix (the inverse transpose) for regular matrices', () => {
    const finite = (lo: number, hi: number) => fc.double({ min: lo, max: hi, noNaN: true });
    const scale = fc.oneof(finite(0.05, 20), finite(-20, -0.05));
    fc.assert(
      fc.property(
        fc.tuple(scale, scale, scale),
        fc.tuple(finite(-Math.PI, Math.PI), finite(-Math.PI, Math.PI), finite(-Math.PI, Math.PI)),
        (s, [x, y, z]) => {
          const m = compose(s, new Euler(x, y, z));
          const ours = computeNormalMatrix(m, new Matrix3()).elements;
          const three = new Matrix3().getNormalMatrix(m).elements;
          let dot = 0;
          let norm = 0;
          for (let i = 0; i < 9; i++) {
            dot += ours[i] * three[i];
            norm += three[i] * three[i];
          }
          const k = dot / norm;
          expect(k).toBeGreaterThan(0);
          expect(Math.max(...ours.map(Math.abs))).toBeCloseTo(1, 12);
          for (let i = 0; i < 9; i++) expect(ours[i]).toBeCloseTo(k * three[i], 9);
        },
      ),
    );
  });

  it('ignores translation and is exactly the identity for rotations-free unit scale', () => {
    const m = new Matrix4().makeTranslation(5, -7, 9);
    expect(computeNormalMatrix(m, new Matrix3()).elements).toEqual(new Matrix3().elements);
  });

  // The docs/design.md extremes rows: zero, 1e-20 and 1e20 scale, negative determinant.
  const cases: Array<[string, [number, number, number]]> = [
    ['1e-20 on one axis', [1, 1e-20, 2]],
    ['1e-20 on all axes', [1e-20, 1e-20, 1e-20]],
    ['1e20 on one axis', [1e20, 1, 2]],
    ['1e20 on all axes', [1e20, 1e20, 1e20]],
    ['mixed 1e-20 and 1e20', [1e20, 1e-20, 1]],
    ['a mirror (det < 0)', [-2, 1, 2]],
    ['a mirror with 1e-20', [2, -1e-20, 1]],
  ];
  for (const [name, s] of cases) {
    it(`${name}: finite, unit, outward normals for a sphere`, () => {
      const m = compose(s);
      const n3 = computeNormalMatrix(m, new Matrix3());
      expect(n3.elements.every(Number.isFinite)).toBe(true);
      // Reference: the inverse transpose of R·S is R·S⁻¹, exact in float64 even at 1e±20.
      const rotation = new Matrix3().setFromMatrix4(
        new Matrix4().makeRotationFromEuler(new Euler(0.3, -0.7, 1.1)),
      );
      let checked = 0;
      for (const d of directions(500)) {
        const n = d.clone().applyMatrix3(n3);
        const reference = new Vector3(d.x / s[0], d.y / s[1], d.z / s[2]);
        reference.divideScalar(Math.max(Math.abs(reference.x), Math.abs(reference.y), Math.abs(reference.z)));
        reference.applyMatrix3(rotation).normalize();
        n.normalize();
        expect(Number.isFinite(n.x + n.y + n.z)).toBe(true);
        expect(n.length()).toBeCloseTo(1, 12);
        // Same direction as the outward reference normal (so unit, outward and right).
        expect(n.dot(reference)).toBeCloseTo(1, 9);
        checked++;
      }
      expect(checked).toBeGreaterThan(450);
    });
  }

  it('a zero scale: finite; the flattened disc gets its plane normal, three gets zeros', () => {
    const m = new Matrix4().makeScale(2, 1, 0);
    const n3 = computeNormalMatrix(m, new Matrix3());
    expect(n3.elements.every(Number.isFinite)).toBe(true);
    expect(new Matrix3().getNormalMatrix(m).elements.every((x) => x === 0)).toBe(true);
    for (const d of directions(200)) {
      const n = d.clone().applyMatrix3(n3);
      if (Math.abs(d.z) > 1e-9) {
        const u = n.normalize();
        expect(Math.abs(u.x)).toBe(0);
        expect(Math.abs(u.y)).toBe(0);
        expect(u.z).toBeCloseTo(Math.sign(d.z), 12);
      }
    }
    // Rank ≤ 1 and all-zero matrices give the zero matrix (normals then fall back to the view vector).
    expect(
      computeNormalMatrix(new Matrix4().makeScale(0, 0, 3), new Matrix3()).elements.every((x) => x === 0),
    ).toBe(true);
    expect(
      computeNormalMatrix(new Matrix4().makeScale(0, 0, 0), new Matrix3()).elements.every((x) => x === 0),
    ).toBe(true);
    expect(
      computeNormalMatrix(new Matrix4().makeScale(Number.NaN, 1, 1), new Matrix3()).elements.every(
        (x) => x === 0,
      ),
    ).toBe(true);
  });
});
