import fc from 'fast-check';
import {
  BoxGeometry,
  Euler,
  InstancedMesh,
  Matrix3,
  Matrix4,
  MeshBasicMaterial,
  Quaternion,
  Vector3,
} from 'three';
import { describe, expect, it } from 'vitest';
import { computeNormalMatrix } from './computeNormalMatrix.js';
import { hasOrthogonalInstances } from './orthogonalInstances.js';

function meshOf(matrices: Matrix4[]): InstancedMesh {
  const mesh = new InstancedMesh(new BoxGeometry(), new MeshBasicMaterial(), matrices.length);
  matrices.forEach((m, i) => {
    mesh.setMatrixAt(i, m);
  });
  mesh.instanceMatrix.needsUpdate = true;
  return mesh;
}

function compose(scale: [number, number, number], rotation = new Euler(0.3, -0.7, 1.1)): Matrix4 {
  return new Matrix4().compose(
    new Vector3(1, -2, 3),
    new Quaternion().setFromEuler(rotation),
    new Vector3(...scale),
  );
}

/** A · (n / |aᵢ|²): the vertex stage's normal for an orthogonal instance (SHADING_INSTANCE_ORTHOGONAL). */
function orthogonalNormal(m: Matrix4, n: Vector3): Vector3 {
  const [a0, a1, a2] = [new Vector3(), new Vector3(), new Vector3()];
  m.extractBasis(a0, a1, a2);
  const k = new Vector3(n.x / a0.lengthSq(), n.y / a1.lengthSq(), n.z / a2.lengthSq());
  return a0.multiplyScalar(k.x).add(a1.multiplyScalar(k.y)).add(a2.multiplyScalar(k.z));
}

describe('hasOrthogonalInstances', () => {
  const magnitude = fc.double({ min: -8, max: 8, noNaN: true }).map((e) => 10 ** e);
  const signed = fc.tuple(magnitude, fc.boolean()).map(([m, negative]) => (negative ? -m : m));
  const angle = fc.double({ min: -Math.PI, max: Math.PI, noNaN: true });

  it('holds for rotations × scales (mirrored or not, scales 1e-8 to 1e8), whose normal A·(n/|aᵢ|²) has the direction of sign(det)·cof(A)·n', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(signed, signed, signed, angle, angle, angle), { minLength: 1, maxLength: 8 }),
        fc.tuple(angle, fc.double({ min: -1, max: 1, noNaN: true })),
        (instances, [phi, y]) => {
          const matrices = instances.map(([sx, sy, sz, a, b, c]) =>
            compose([sx, sy, sz], new Euler(a, b, c)),
          );
          expect(hasOrthogonalInstances(meshOf(matrices))).toBe(true);
          const r = Math.sqrt(1 - y * y);
          const n = new Vector3(r * Math.cos(phi), y, r * Math.sin(phi));
          for (const m of matrices) {
            const robust = n.clone().applyMatrix3(computeNormalMatrix(m, new Matrix3())).normalize();
            const fast = orthogonalNormal(m, n).normalize();
            expect(fast.distanceTo(robust)).toBeLessThan(1e-6);
          }
        },
      ),
    );
  });

  it('fails for a sheared, singular, huge, tiny or non-finite instance (they take the cofactor)', () => {
    const sheared = compose([1, 1, 1]).multiply(new Matrix4().makeShear(0.001, 0, 0, 0, 0, 0));
    for (const [what, m] of [
      ['sheared by 1e-3', sheared],
      ['a zero scale', compose([1, 0, 1])],
      ['a 1e20 scale', compose([1e20, 1, 1])],
      ['a 1e-10 scale', compose([1, 1e-10, 1])],
      ['NaN', compose([Number.NaN, 1, 1])],
      ['Infinity', compose([1, Number.POSITIVE_INFINITY, 1])],
    ] as const) {
      expect(hasOrthogonalInstances(meshOf([compose([2, 1, 0.5]), m])), what).toBe(false);
    }
  });

  it('reads the drawn instances (count) and reads them again when they change (instanceMatrix.version)', () => {
    const mesh = meshOf([
      compose([1, 2, 3]),
      compose([1, 1, 1]).multiply(new Matrix4().makeShear(0.5, 0, 0, 0, 0, 0)),
    ]);
    expect(hasOrthogonalInstances(mesh)).toBe(false);
    mesh.count = 1;
    expect(hasOrthogonalInstances(mesh)).toBe(true);
    mesh.count = 2;
    expect(hasOrthogonalInstances(mesh)).toBe(false);
    mesh.setMatrixAt(1, compose([-1, 1, 1]));
    // Not yet uploaded (no needsUpdate): the GPU still draws the sheared matrix, and so the verdict stands.
    expect(hasOrthogonalInstances(mesh)).toBe(false);
    mesh.instanceMatrix.needsUpdate = true;
    expect(hasOrthogonalInstances(mesh)).toBe(true);
  });
});
