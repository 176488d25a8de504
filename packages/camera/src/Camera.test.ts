import { Camera } from '@shadelab/camera';
import fc from 'fast-check';
import {
  Group,
  Matrix4,
  type Object3D,
  OrthographicCamera,
  PerspectiveCamera,
  Vector3,
  Vector4,
} from 'three';
import { describe, expect, it } from 'vitest';

const TOL = 1e-6;

function expectMatrixClose(actual: Matrix4, expected: Matrix4, tol = TOL): void {
  for (let i = 0; i < 16; i++) {
    const a = actual.elements[i];
    const e = expected.elements[i];
    expect(Math.abs(a - e), `element ${i}: ${a} vs ${e}`).toBeLessThanOrEqual(tol * Math.max(1, Math.abs(e)));
  }
}

const coord = fc.double({ min: -100, max: 100, noNaN: true });
const vec = fc.tuple(coord, coord, coord);
const dir = vec.filter(([x, y, z]) => Math.hypot(x, y, z) > 1e-3);
/** eye, at, up with eye far enough from at and up at least 1e-3 rad from the gaze line. */
const lookAtInput = fc.tuple(vec, vec, dir).filter(([e, a, u]) => {
  const g = new Vector3(...e).sub(new Vector3(...a));
  if (g.length() < 1e-3) return false;
  return new Vector3(...u).normalize().cross(g.normalize()).length() > 1e-3;
});

describe('Camera matches three.js', () => {
  it('perspective projection equals PerspectiveCamera for the same fovy, aspect, near, far', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.01, max: 179.9, noNaN: true }),
        fc.double({ min: 0.01, max: 100, noNaN: true }),
        fc.double({ min: 1e-4, max: 10, noNaN: true }),
        fc.double({ min: 1.001, max: 1e9, noNaN: true }),
        (fovy, aspect, near, ratio) => {
          const far = near * ratio;
          const camera = new Camera().setPerspective(fovy, aspect, near, far);
          const three = new PerspectiveCamera(fovy, aspect, near, far);
          expectMatrixClose(camera.getProjectionMatrix(), three.projectionMatrix);
          expectMatrixClose(camera.projectionMatrixInverse, three.projectionMatrixInverse, 1e-5);
        },
      ),
    );
  });

  it("orthographic projection equals OrthographicCamera(left, right, top, bottom) for the lecture's (r, l, t, b) order", () => {
    fc.assert(
      fc.property(
        coord,
        coord,
        coord,
        coord,
        fc.double({ min: -10, max: 10, noNaN: true }),
        fc.double({ min: 0.01, max: 1000, noNaN: true }),
        (r, l, t, b, n, depth) => {
          fc.pre(Math.abs(r - l) > 1e-3 && Math.abs(t - b) > 1e-3);
          const camera = new Camera().setOrthographic(r, l, t, b, n, n + depth);
          const three = new OrthographicCamera(l, r, t, b, n, n + depth);
          expectMatrixClose(camera.getProjectionMatrix(), three.projectionMatrix);
          expectMatrixClose(camera.projectionMatrixInverse, three.projectionMatrixInverse);
        },
      ),
    );
  });

  it('a concrete orthographic case maps the (r, l, t, b, n, f) box onto the NDC cube', () => {
    const camera = new Camera().setOrthographic(4, -2, 3, -1, 1, 11);
    const P = camera.getProjectionMatrix();
    const corner = (x: number, y: number, z: number) => new Vector3(x, y, z).applyMatrix4(P);
    expect(corner(4, 3, -1).distanceTo(new Vector3(1, 1, -1))).toBeLessThan(1e-15);
    expect(corner(-2, -1, -11).distanceTo(new Vector3(-1, -1, 1))).toBeLessThan(1e-15);
  });

  it('lookAt(eye, at, up) gives the same view matrix as three Matrix4.lookAt / Object3D.lookAt', () => {
    fc.assert(
      fc.property(lookAtInput, ([e, a, u]) => {
        const camera = new Camera().lookAt(e, a, u);
        const three = new PerspectiveCamera();
        three.position.set(...e);
        three.up.set(...u);
        three.lookAt(...a);
        three.updateMatrixWorld();
        expectMatrixClose(camera.getCameraTransformationMatrix(), three.matrixWorldInverse, 1e-6);
        const rotation = new Matrix4().lookAt(new Vector3(...e), new Vector3(...a), new Vector3(...u));
        const frame = camera.getFrame();
        const basis = new Matrix4().makeBasis(frame.u, frame.v, frame.w);
        expectMatrixClose(basis, rotation, 1e-9);
      }),
    );
  });

  it("three's lookAt(target) and lookAt(x, y, z) keep Object3D.lookAt semantics with this.up", () => {
    fc.assert(
      fc.property(lookAtInput, ([e, a, u]) => {
        const three = new PerspectiveCamera();
        three.position.set(...e);
        three.up.set(...u);
        three.lookAt(new Vector3(...a));
        three.updateMatrixWorld();
        const byVector = new Camera();
        byVector.position.set(...e);
        byVector.up.set(...u);
        byVector.lookAt(new Vector3(...a));
        const byNumbers = new Camera();
        byNumbers.position.set(...e);
        byNumbers.up.set(...u);
        byNumbers.lookAt(...a);
        expectMatrixClose(byVector.getCameraTransformationMatrix(), three.matrixWorldInverse);
        expectMatrixClose(byNumbers.getCameraTransformationMatrix(), three.matrixWorldInverse);
        expect(byVector.quaternion.angleTo(three.quaternion)).toBeLessThan(1e-6);
      }),
    );
  });

  it('getMatrix() = P · Mcam, and maps `at` onto the view axis in front of the camera', () => {
    fc.assert(
      fc.property(lookAtInput, ([e, a, u]) => {
        const camera = new Camera().lookAt(e, a, u).setPerspective(60, 1.5, 0.1, 1000);
        const expected = new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
        expectMatrixClose(camera.getMatrix(), expected, 0);
        const three = new PerspectiveCamera(60, 1.5, 0.1, 1000);
        three.position.set(...e);
        three.up.set(...u);
        three.lookAt(...a);
        three.updateMatrixWorld();
        expectMatrixClose(
          camera.getMatrix(),
          new Matrix4().multiplyMatrices(three.projectionMatrix, three.matrixWorldInverse),
          1e-6,
        );
        const d = new Vector3(...e).distanceTo(new Vector3(...a));
        const inView = new Vector3(...a).applyMatrix4(camera.getCameraTransformationMatrix());
        expect(Math.abs(inView.x)).toBeLessThan(1e-9 * Math.max(1, d) * 100);
        expect(Math.abs(inView.y)).toBeLessThan(1e-9 * Math.max(1, d) * 100);
        expect(inView.z).toBeCloseTo(-d, 6);
      }),
    );
  });

  it('the frame is orthonormal and right-handed, w opposite the gaze, e = eye, v on the up side', () => {
    fc.assert(
      fc.property(lookAtInput, ([e, a, u]) => {
        const { e: eye, u: uu, v, w } = new Camera().lookAt(e, a, u).getFrame();
        expect(eye.distanceTo(new Vector3(...e))).toBeLessThan(1e-9 * Math.max(1, eye.length()));
        for (const x of [uu, v, w]) expect(x.length()).toBeCloseTo(1, 12);
        expect(uu.dot(v)).toBeCloseTo(0, 12);
        expect(uu.dot(w)).toBeCloseTo(0, 12);
        expect(v.dot(w)).toBeCloseTo(0, 12);
        expect(new Vector3().crossVectors(uu, v).distanceTo(w)).toBeLessThan(1e-12);
        const gaze = new Vector3(...a).sub(new Vector3(...e)).normalize();
        expect(w.dot(gaze)).toBeCloseTo(-1, 12);
        expect(v.dot(new Vector3(...u))).toBeGreaterThan(0);
      }),
    );
  });

  it('the lecture example: eye (0,0,3), at 0, up y, 90° perspective', () => {
    const camera = new Camera();
    camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
    camera.setPerspective(90, 1, 0.1, 10);
    const { e, u, v, w } = camera.getFrame();
    expect(e.toArray()).toEqual([0, 0, 3]);
    expect(u.toArray()).toEqual([1, 0, 0]);
    expect(v.toArray()).toEqual([0, 1, 0]);
    expect(w.toArray()).toEqual([0, 0, 1]);
    // The origin lands at the centre of the screen, at its depth between near and far.
    const clip = new Vector4(0, 0, 0, 1).applyMatrix4(camera.getMatrix());
    expect(clip.x).toBe(0);
    expect(clip.y).toBe(0);
    expect(clip.w).toBe(3);
    expect(clip.z / clip.w).toBeCloseTo((10 + 0.1) / (10 - 0.1) - (2 * 10 * 0.1) / (10 - 0.1) / 3, 12);
  });

  it('accepts Vector3, {x, y, z}, [x, y, z] and typed arrays alike', () => {
    const reference = new Camera().lookAt(new Vector3(1, 2, 3), new Vector3(0, 0, 0), new Vector3(0, 1, 0));
    const inputs = [
      new Camera().lookAt({ x: 1, y: 2, z: 3 }, { x: 0, y: 0, z: 0 }, { x: 0, y: 1, z: 0 }),
      new Camera().lookAt([1, 2, 3], [0, 0, 0], [0, 1, 0]),
      new Camera().lookAt(new Float32Array([1, 2, 3]), new Float64Array(3), new Float32Array([0, 1, 0])),
    ];
    for (const c of inputs) expectMatrixClose(c.matrixWorldInverse, reference.matrixWorldInverse, 0);
    expect(() => new Camera().lookAt(new Float32Array(4), [0, 0, 0], [0, 1, 0])).toThrow(TypeError);
  });

  it('lookAt with a rotated, translated parent still puts the world frame where asked', () => {
    const parent = new Group();
    parent.position.set(5, -2, 1);
    parent.rotation.set(0.3, -1.1, 0.7);
    parent.scale.setScalar(2);
    const camera = new Camera();
    parent.add(camera);
    camera.lookAt([1, 2, 3], [-4, 0, 1], [0, 1, 0]);
    const frame = camera.getFrame();
    const reference = new Camera().lookAt([1, 2, 3], [-4, 0, 1], [0, 1, 0]).getFrame();
    expect(frame.e.distanceTo(reference.e)).toBeLessThan(1e-9);
    expect(frame.u.distanceTo(reference.u)).toBeLessThan(1e-9);
    expect(frame.w.distanceTo(reference.w)).toBeLessThan(1e-9);
  });

  it('position/quaternion changes made the three.js way show up in the frame and matrices', () => {
    const camera = new Camera().lookAt([0, 0, 5], [0, 0, 0], [0, 1, 0]);
    camera.position.set(1, 2, 3);
    camera.rotateY(Math.PI / 2);
    const { e, w } = camera.getFrame();
    expect(e.toArray()).toEqual([1, 2, 3]);
    expect(w.x).toBeCloseTo(1, 12);
    const three = new PerspectiveCamera();
    three.position.set(1, 2, 3);
    three.rotateY(Math.PI / 2);
    three.updateMatrixWorld();
    expectMatrixClose(camera.getCameraTransformationMatrix(), three.matrixWorldInverse, 1e-12);
  });

  it('isPerspectiveCamera / isOrthographicCamera follow the projection', () => {
    const camera = new Camera();
    expect(camera.projection).toBe('perspective');
    expect([camera.isPerspectiveCamera, camera.isOrthographicCamera]).toEqual([true, false]);
    camera.setOrthographic(1, -1, 1, -1, 0.1, 10);
    expect(camera.projection).toBe('orthographic');
    expect([camera.isPerspectiveCamera, camera.isOrthographicCamera]).toEqual([false, true]);
    camera.setPerspective(45, 1, 0.1, 10);
    expect([camera.isPerspectiveCamera, camera.isOrthographicCamera]).toEqual([true, false]);
  });

  it('setAspect keeps fovy (perspective) and the vertical extent and centre (orthographic)', () => {
    const camera = new Camera().setPerspective(60, 1, 0.5, 50).setAspect(16 / 9);
    expect(camera.fovy).toBe(60);
    expectMatrixClose(
      camera.projectionMatrix,
      new PerspectiveCamera(60, 16 / 9, 0.5, 50).projectionMatrix,
      1e-15,
    );
    camera.setOrthographic(3, 1, 2, -2, 0, 10).setAspect(2);
    expect([camera.left, camera.right, camera.top, camera.bottom]).toEqual([-2, 6, 2, -2]);
    expectMatrixClose(
      camera.projectionMatrix,
      new OrthographicCamera(-2, 6, 2, -2, 0, 10).projectionMatrix,
      1e-15,
    );
    expect(() => camera.setAspect(0)).toThrow(RangeError);
  });

  it('zoom, fov alias and direct field edits follow three (updateProjectionMatrix)', () => {
    const camera = new Camera();
    camera.fov = 30;
    camera.zoom = 2;
    camera.aspect = 2;
    camera.updateProjectionMatrix();
    const three = new PerspectiveCamera(30, 2, 0.1, 2000);
    three.zoom = 2;
    three.updateProjectionMatrix();
    expect(camera.fovy).toBe(30);
    expectMatrixClose(camera.projectionMatrix, three.projectionMatrix, 1e-15);
  });

  it('reversed depth: matches three when the renderer flips reversedDepth, near → 1 and far → 0', () => {
    const camera = new Camera().setPerspective(50, 1.3, 0.01, 1e6);
    const three = new PerspectiveCamera(50, 1.3, 0.01, 1e6);
    for (const c of [camera, three]) {
      (c as unknown as { _reversedDepth: boolean })._reversedDepth = true;
      c.updateProjectionMatrix();
    }
    expect(camera.reversedDepth).toBe(true);
    expectMatrixClose(camera.projectionMatrix, three.projectionMatrix, 1e-15);
    const ndcZ = (z: number) => new Vector3(0, 0, -z).applyMatrix4(camera.projectionMatrix).z;
    expect(ndcZ(0.01)).toBeCloseTo(1, 12);
    expect(ndcZ(1e6)).toBeCloseTo(0, 12);
    camera.setOrthographic(1, -1, 1, -1, 0.5, 20);
    const ortho = new OrthographicCamera(-1, 1, 1, -1, 0.5, 20);
    (ortho as unknown as { _reversedDepth: boolean })._reversedDepth = true;
    ortho.updateProjectionMatrix();
    expectMatrixClose(camera.projectionMatrix, ortho.projectionMatrix, 1e-15);
  });

  it('reversedDepth can be switched back off (three never does), updating the matrix', () => {
    const camera = new Camera().setPerspective(50, 1, 0.1, 100);
    const standard = camera.projectionMatrix.clone();
    camera.reversedDepth = true;
    expect(new Vector3(0, 0, -0.1).applyMatrix4(camera.projectionMatrix).z).toBeCloseTo(1, 12);
    camera.reversedDepth = false;
    expectMatrixClose(camera.projectionMatrix, standard, 0);
  });

  it('copy/clone keep projection, frame and kind', () => {
    const camera = new Camera().lookAt([1, 2, 3], [0, 0, 0], [0, 0, 1]).setOrthographic(2, -2, 1, -1, 0.1, 9);
    const copy = camera.clone();
    expect(copy).toBeInstanceOf(Camera);
    expect(copy).not.toBe(camera);
    expect(copy.isOrthographicCamera).toBe(true);
    expectMatrixClose(copy.projectionMatrix, camera.projectionMatrix, 0);
    expectMatrixClose(copy.getCameraTransformationMatrix(), camera.getCameraTransformationMatrix(), 0);
    expect(copy.up.toArray()).toEqual([0, 0, 1]);
    const other = new Camera().copy(camera);
    expect(other.right).toBe(2);
  });

  it("copy/clone do not carry reversedDepth (as three's cameras): the target keeps its own, matrix to match", () => {
    // reversedDepth belongs to the renderer a camera is drawn with (a reversed renderer switches it on).
    const reversed = new Camera().setPerspective(50, 1.5, 0.1, 100);
    reversed.reversedDepth = true;
    const three = new PerspectiveCamera(50, 1.5, 0.1, 100);
    (three as unknown as { _reversedDepth: boolean })._reversedDepth = true;
    three.updateProjectionMatrix();
    expect(three.clone().reversedDepth).toBe(false); // three does not carry it either
    const clone = reversed.clone();
    expect(clone.reversedDepth).toBe(false);
    // …but unlike three's clone (which keeps the reversed matrix under reversedDepth = false) the matrix follows.
    expectMatrixClose(clone.projectionMatrix, new PerspectiveCamera(50, 1.5, 0.1, 100).projectionMatrix, 0);
    const target = new Camera();
    target.reversedDepth = true;
    target.copy(new Camera().setPerspective(50, 1.5, 0.1, 100));
    expect(target.reversedDepth).toBe(true);
    expectMatrixClose(target.projectionMatrix, three.projectionMatrix, 0);
    expectMatrixClose(target.projectionMatrixInverse, three.projectionMatrixInverse, 0);
  });

  it("dispatches 'change' from lookAt and the projection setters", () => {
    const camera = new Camera();
    let changes = 0;
    (camera as unknown as Object3D).addEventListener('change' as never, () => changes++);
    camera.lookAt([0, 0, 1], [0, 0, 0], [0, 1, 0]);
    camera.setPerspective(40, 1, 1, 2);
    camera.setOrthographic(1, -1, 1, -1, 1, 2);
    camera.setAspect(2);
    expect(changes).toBe(4);
  });
});

/** Assign `zoom` and update, as three's cameras are used (a refusal leaves the matrices unchanged). */
function withZoom(c: Camera, zoom: number): Camera {
  c.zoom = zoom;
  c.updateProjectionMatrix();
  return c;
}

describe('Camera refuses bad input (docs/design.md extremes)', () => {
  const camera = new Camera();
  it.each([
    ['fovy', () => camera.setPerspective(0, 1, 0.1, 10)],
    ['fovy', () => camera.setPerspective(-5, 1, 0.1, 10)],
    ['fovy', () => camera.setPerspective(180, 1, 0.1, 10)],
    ['fovy', () => camera.setPerspective(Number.NaN, 1, 0.1, 10)],
    ['aspect', () => camera.setPerspective(50, 0, 0.1, 10)],
    ['aspect', () => camera.setPerspective(50, -1, 0.1, 10)],
    ['aspect', () => camera.setPerspective(50, Number.NaN, 0.1, 10)],
    ['near', () => camera.setPerspective(50, 1, 0, 10)],
    ['near', () => camera.setPerspective(50, 1, -1, 10)],
    ['near', () => camera.setPerspective(50, 1, Number.NaN, 10)],
    ['far', () => camera.setPerspective(50, 1, 1, 1)],
    ['far', () => camera.setPerspective(50, 1, 1, 0.5)],
    ['far', () => camera.setPerspective(50, 1, 1, Number.NaN)],
    ['far', () => camera.setPerspective(50, 1, 1, Number.POSITIVE_INFINITY)],
    ['left', () => camera.setOrthographic(1, 1, 1, -1, 0, 10)],
    ['bottom', () => camera.setOrthographic(1, -1, 2, 2, 0, 10)],
    ['right', () => camera.setOrthographic(Number.NaN, -1, 1, -1, 0, 10)],
    ['top', () => camera.setOrthographic(1, -1, Number.NaN, -1, 0, 10)],
    ['near', () => camera.setOrthographic(1, -1, 1, -1, Number.NaN, 10)],
    ['far', () => camera.setOrthographic(1, -1, 1, -1, 5, 5)],
    ['left', () => camera.setOrthographic(1, Number.NaN, 1, -1, 0, 10)],
    ['bottom', () => camera.setOrthographic(1, -1, 1, Number.NaN, 0, 10)],
    ['far', () => camera.setOrthographic(1, -1, 1, -1, 0, Number.NaN)],
    ['fovy', () => camera.setPerspective(Number.POSITIVE_INFINITY, 1, 0.1, 10)],
    ['fovy', () => camera.setPerspective(Number.NEGATIVE_INFINITY, 1, 0.1, 10)],
    ['zoom', () => withZoom(new Camera(), Number.NaN)],
    ['zoom', () => withZoom(new Camera().setOrthographic(1, -1, 1, -1, 0, 10), Number.NaN)],
    ['zoom', () => withZoom(new Camera(), Number.POSITIVE_INFINITY)],
    ['aspect', () => camera.setAspect(Number.NaN)],
    ['fovy', () => new Camera({ fovy: 200 })],
    ['eye', () => camera.lookAt([Number.NaN, 0, 0], [0, 0, 0], [0, 1, 0])],
    ['at', () => camera.lookAt([1, 0, 0], [0, Number.NaN, 0], [0, 1, 0])],
    ['up', () => camera.lookAt([1, 0, 0], [0, 0, 0], [0, 1, Number.NaN])],
    ['up', () => camera.lookAt([1, 0, 0], [0, 0, 0], [0, 0, 0])],
    ['eye and at', () => camera.lookAt([1, 2, 3], [1, 2, 3], [0, 1, 0])],
    ['eye and at', () => camera.lookAt(new Vector3(0, 0, 0))],
  ])('%s', (name, call) => {
    expect(call).toThrow(RangeError);
    expect(call).toThrow(new RegExp(`^${name} `));
  });

  it('names the value and the allowed range', () => {
    expect(() => camera.setPerspective(180, 1, 0.1, 10)).toThrow('fovy must be in (0, 180) degrees, got 180');
    expect(() => camera.setPerspective(50, 1, 2, 1)).toThrow('far must be finite and > near (2), got 1');
  });

  it('a refused call leaves the camera as it was', () => {
    const c = new Camera().setPerspective(30, 2, 1, 100);
    const before = c.projectionMatrix.clone();
    expect(() => c.setPerspective(30, 2, 1, 0.5)).toThrow(RangeError);
    expect(c.far).toBe(100);
    expectMatrixClose(c.projectionMatrix, before, 0);
  });

  it('non-vectors are a TypeError', () => {
    expect(() => camera.lookAt('x' as never, [0, 0, 0], [0, 1, 0])).toThrow(TypeError);
    expect(() => camera.lookAt([0, 0, 1], { x: 1, y: 2 } as never, [0, 1, 0])).toThrow(TypeError);
  });

  it('far/near from 10 to 1e9 gives finite, invertible matrices with near → −1 and far → +1', () => {
    for (let exponent = 1; exponent <= 9; exponent++) {
      const near = 0.01;
      const far = near * 10 ** exponent;
      const c = new Camera().setPerspective(60, 1, near, far);
      for (const x of c.projectionMatrix.elements) expect(Number.isFinite(x)).toBe(true);
      for (const x of c.projectionMatrixInverse.elements) expect(Number.isFinite(x)).toBe(true);
      const ndc = (z: number) => new Vector3(0, 0, -z).applyMatrix4(c.projectionMatrix).z;
      expect(ndc(near)).toBeCloseTo(-1, 9);
      expect(ndc(far)).toBeCloseTo(1, 6);
      // Depth still grows with distance at the far end (the float64 matrix keeps order; the buffer is measured).
      expect(ndc(far * 0.999)).toBeLessThan(ndc(far));
    }
  });
});
