import fc from 'fast-check';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { normalMatrixVectors, objectNormalOf } from './normalMatrix';

/** M = R·S from a unit quaternion and a scale, as the playground's trackball and model scale make it. */
function model(q: THREE.Quaternion, s: THREE.Vector3): THREE.Matrix4 {
  return new THREE.Matrix4().compose(new THREE.Vector3(0.3, -0.2, 0.1), q, s);
}

const unit = (v: THREE.Vector3) => v.clone().normalize();
const closeTo = (a: readonly number[], b: THREE.Vector3, digits = 9) => {
  expect(a[0]).toBeCloseTo(b.x, digits);
  expect(a[1]).toBeCloseTo(b.y, digits);
  expect(a[2]).toBeCloseTo(b.z, digits);
};

const quaternion = fc
  .tuple(
    fc.double({ min: -1, max: 1, noNaN: true }),
    fc.double({ min: -1, max: 1, noNaN: true }),
    fc.double({ min: -1, max: 1, noNaN: true }),
  )
  .filter(([x, y, z]) => x * x + y * y + z * z > 1e-3)
  .chain(([x, y, z]) =>
    fc
      .double({ min: 0, max: Math.PI, noNaN: true })
      .map((angle) => new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(x, y, z).normalize(), angle)),
  );
const scale = fc
  .tuple(
    fc.double({ min: 0.2, max: 5, noNaN: true }),
    fc.double({ min: 0.2, max: 5, noNaN: true }),
    fc.double({ min: 0.2, max: 5, noNaN: true }),
  )
  .map(([x, y, z]) => new THREE.Vector3(x, y, z));
const direction = fc
  .tuple(
    fc.double({ min: -1, max: 1, noNaN: true }),
    fc.double({ min: -1, max: 1, noNaN: true }),
    fc.double({ min: -1, max: 1, noNaN: true }),
  )
  .filter(([x, y, z]) => x * x + y * y + z * z > 1e-2)
  .map(([x, y, z]) => new THREE.Vector3(x, y, z).normalize());

describe('normalMatrixVectors', () => {
  it('(M⁻¹)ᵀn = R·(n/s) is perpendicular to M·t; M·n = R·(s∘n) is what M gives; both unit', () => {
    fc.assert(
      fc.property(quaternion, scale, direction, (q, s, n) => {
        const v = normalMatrixVectors(model(q, s), [1, 2, 3], n.toArray());
        closeTo(v.inverseTranspose, unit(n.clone().divide(s).applyQuaternion(q)));
        closeTo(v.model, unit(n.clone().multiply(s).applyQuaternion(q)));
        const t = new THREE.Vector3(...v.tangent);
        expect(t.length()).toBeCloseTo(1, 12);
        expect(Math.abs(t.dot(new THREE.Vector3(...v.inverseTranspose)))).toBeLessThan(1e-9);
        expect(v.angles.inverseTranspose).toBeCloseTo(90, 6);
        // The tangent is M·t for a t perpendicular to n in object space.
        const back = t.clone().applyQuaternion(q.clone().invert()).divide(s);
        expect(Math.abs(back.normalize().dot(n))).toBeLessThan(1e-9);
      }),
      { numRuns: 200 },
    );
  });

  it('M·n leans off the perpendicular under a non-uniform scale, by the angle of the formula', () => {
    const q = new THREE.Quaternion().setFromEuler(new THREE.Euler(0.4, -0.7, 0.2));
    const s = new THREE.Vector3(2, 1, 2);
    const n = new THREE.Vector3(1, 1, 0.5).normalize();
    const v = normalMatrixVectors(model(q, s), [0, 0, 0], n.toArray());
    const wrong = new THREE.Vector3(...v.model);
    const t = new THREE.Vector3(...v.tangent);
    // (Mn)·(Mt) = nᵀMᵀMt = (s²∘n)·t for t the object tangent.
    expect(Math.abs(90 - v.angles.model)).toBeGreaterThan(10);
    expect(v.angles.model).toBeCloseTo(THREE.MathUtils.radToDeg(wrong.angleTo(t)), 9);
  });

  it('under a uniform scale, or at a principal axis, M·n is right too', () => {
    const q = new THREE.Quaternion().setFromEuler(new THREE.Euler(0.4, -0.7, 0.2));
    const uniform = normalMatrixVectors(model(q, new THREE.Vector3(3, 3, 3)), [0, 0, 0], [1, 2, 3]);
    expect(uniform.angles.model).toBeCloseTo(90, 9);
    closeTo(uniform.model, new THREE.Vector3(...uniform.inverseTranspose));
    const axis = normalMatrixVectors(model(q, new THREE.Vector3(2, 1, 2)), [0, 0, 0], [0, 0, 1]);
    expect(axis.angles.model).toBeCloseTo(90, 9);
  });

  it('refuses a zero normal and a singular model matrix, naming them', () => {
    const m = model(new THREE.Quaternion(), new THREE.Vector3(2, 1, 2));
    expect(() => normalMatrixVectors(m, [0, 0, 0], [0, 0, 0])).toThrow(RangeError);
    expect(() => normalMatrixVectors(m, [0, 0, 0], [0, 0, 0])).toThrow(/objectNormal/);
    const flat = model(new THREE.Quaternion(), new THREE.Vector3(1, 0, 1));
    expect(() => normalMatrixVectors(flat, [0, 0, 0], [0, 1, 0])).toThrow(/matrixWorld: M·n/);
  });
});

describe('objectNormalOf', () => {
  it('undoes the normal matrix: (M⁻¹)ᵀ · objectNormalOf(M, n_world) ∥ n_world', () => {
    fc.assert(
      fc.property(quaternion, scale, direction, (q, s, nWorld) => {
        const m = model(q, s);
        const n = new THREE.Vector3(...objectNormalOf(m, nWorld.toArray()));
        const v = normalMatrixVectors(m, [0, 0, 0], n.toArray());
        closeTo(v.inverseTranspose, nWorld);
      }),
      { numRuns: 100 },
    );
  });
});
