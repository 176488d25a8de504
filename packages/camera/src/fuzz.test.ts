// @vitest-environment happy-dom
import {
  Camera,
  CameraMovement,
  createPoleMemory,
  depthBufferParameters,
  lookAtFrame,
} from '@shadelab/camera';
import fc from 'fast-check';
import { Matrix4, PerspectiveCamera, Vector3 } from 'three';
import { afterAll, describe, expect, it } from 'vitest';
import { hostileNumbers, hostileValue, worksOrNamedError } from '../../../test-utils/fuzz.js';

// Issue 8: every constructor, option and setter, fed hostile values, either works with finite results or throws a
// TypeError/RangeError naming the parameter. A camera that has refused a call is still finite and usable.

const hostileNumber = hostileNumbers(179.99999999999997, 1e-300, 1e300);
const hostile = hostileValue(hostileNumber, { values: ['5', [1, 2], { x: 1 }] });

/** Sometimes a sensible number, sometimes a hostile value. */
const num = (min: number, max: number) =>
  fc.oneof({ weight: 3, arbitrary: fc.double({ min, max, noNaN: true }) }, hostile) as fc.Arbitrary<number>;

/** A vector in every accepted form, with hostile components, or not a vector at all. */
const vec = fc.oneof(
  { weight: 3, arbitrary: fc.tuple(num(-10, 10), num(-10, 10), num(-10, 10)) },
  fc.tuple(num(-10, 10), num(-10, 10), num(-10, 10)).map(([x, y, z]) => ({ x, y, z })),
  fc.tuple(hostileNumber, hostileNumber, hostileNumber).map((c) => Float64Array.from(c)),
  hostile,
) as fc.Arbitrary<never>;

const counts = { calls: 0, threw: 0 };
afterAll(() => {
  console.log(
    `camera fuzz: ${counts.calls} calls, ${counts.threw} refused with a named TypeError/RangeError`,
  );
});

function expectFiniteMatrix(m: Matrix4, what: string): void {
  for (const [i, x] of m.elements.entries()) if (!Number.isFinite(x)) expect.fail(`${what}[${i}] = ${x}`);
}

/** Everything a renderer or a user reads from the camera is finite, and the frame orthonormal. */
function expectSane(camera: Camera): void {
  expectFiniteMatrix(camera.projectionMatrix, 'projectionMatrix');
  expectFiniteMatrix(camera.projectionMatrixInverse, 'projectionMatrixInverse');
  expectFiniteMatrix(camera.getCameraTransformationMatrix(), 'matrixWorldInverse');
  expectFiniteMatrix(camera.getMatrix(), 'getMatrix()');
  const { e, u, v, w } = camera.getFrame();
  for (const [name, x] of Object.entries({ e, u, v, w })) {
    expect(x.toArray().every(Number.isFinite), `${name} = ${x.toArray()}`).toBe(true);
  }
  expect(u.length()).toBeCloseTo(1, 6);
  expect(v.length()).toBeCloseTo(1, 6);
  expect(w.length()).toBeCloseTo(1, 6);
  expect(Math.abs(u.dot(v)) + Math.abs(v.dot(w)) + Math.abs(w.dot(u))).toBeLessThan(1e-6);
}

const PROJECTION_NAMES = ['fovy', 'aspect', 'near', 'far', 'zoom', 'right', 'left', 'top', 'bottom'];

/** One random call on a camera (or a movement on it), with the parameter names its error may give. */
const operation = fc.oneof(
  fc
    .tuple(num(1, 179), num(0.1, 10), num(1e-3, 10), num(10, 1e6))
    .map((a) => ['setPerspective', PROJECTION_NAMES, (c: Camera) => c.setPerspective(...a)] as const),
  fc
    .tuple(num(-10, 10), num(-10, 10), num(-10, 10), num(-10, 10), num(-10, 10), num(-10, 10))
    .map((a) => ['setOrthographic', PROJECTION_NAMES, (c: Camera) => c.setOrthographic(...a)] as const),
  num(0.1, 10).map((a) => ['setAspect', ['aspect', 'left', 'right'], (c: Camera) => c.setAspect(a)] as const),
  fc
    .tuple(vec, vec, vec)
    .map(
      ([e, a, u]) => ['lookAt(eye, at, up)', ['eye', 'at', 'up'], (c: Camera) => c.lookAt(e, a, u)] as const,
    ),
  vec.map((t) => ['lookAt(target)', ['eye', 'at', 'target', 'up'], (c: Camera) => c.lookAt(t)] as const),
  fc
    .tuple(
      fc.constantFrom('fovy', 'fov', 'aspect', 'near', 'far', 'zoom', 'left', 'right', 'top', 'bottom'),
      hostile,
    )
    .map(
      ([field, value]) =>
        [
          `${field} = …; updateProjectionMatrix()`,
          PROJECTION_NAMES,
          (c: Camera) => {
            const saved = (c as unknown as Record<string, unknown>)[field];
            (c as unknown as Record<string, unknown>)[field] = value;
            try {
              c.updateProjectionMatrix();
            } catch (error) {
              // The documented contract: a refused field is put back by the caller.
              (c as unknown as Record<string, unknown>)[field] = saved;
              c.updateProjectionMatrix();
              throw error;
            }
          },
        ] as const,
    ),
  fc
    .tuple(num(-1, 1), num(-1, 1), num(-1, 1))
    .map(
      ([du, dv, dw]) =>
        ['move', ['du', 'dv', 'dw'], (c: Camera) => new CameraMovement(c).move(du, dv, dw)] as const,
    ),
  fc
    .tuple(num(-1, 1), num(-1, 1))
    .map(
      ([yaw, pitch]) =>
        ['turn', ['yaw', 'pitch'], (c: Camera) => new CameraMovement(c).turn(yaw, pitch)] as const,
    ),
);

describe('camera fuzz (hostile values everywhere)', () => {
  it('new Camera(options): finite matrices or a named error', () => {
    const options = fc.oneof(
      {
        weight: 6,
        arbitrary: fc.record(
          { fovy: num(1, 179), aspect: num(0.1, 10), near: num(1e-3, 1), far: num(10, 1e6) },
          { requiredKeys: [] },
        ),
      },
      hostile,
    );
    fc.assert(
      fc.property(options, (o) => {
        let camera: Camera | undefined;
        if (
          worksOrNamedError(counts, ['options', ...PROJECTION_NAMES], () => (camera = new Camera(o as never)))
        ) {
          expectSane(camera!);
        }
      }),
      { numRuns: 500 },
    );
  });

  it('any sequence of calls leaves a finite camera: each call works or is refused by name, changing nothing', () => {
    fc.assert(
      fc.property(fc.array(operation, { minLength: 1, maxLength: 12 }), (ops) => {
        const camera = new Camera();
        camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
        for (const [name, names, op] of ops) {
          const before = camera.getMatrix().clone();
          const projection = camera.projection;
          if (!worksOrNamedError(counts, names, () => op(camera))) {
            expect(camera.getMatrix().elements, `a refused ${name} changes nothing`).toEqual(before.elements);
            expect(camera.projection).toBe(projection);
          }
          expectSane(camera);
        }
      }),
      { numRuns: 400 },
    );
  });

  it('lookAtFrame: a finite orthonormal frame or a named error', () => {
    fc.assert(
      fc.property(vec, vec, vec, fc.boolean(), (eye, at, up, memory) => {
        const frame = { e: new Vector3(), u: new Vector3(), v: new Vector3(), w: new Vector3() };
        const ok = worksOrNamedError(counts, ['eye', 'at', 'up'], () =>
          lookAtFrame(eye, at, up, frame, memory ? createPoleMemory() : undefined),
        );
        if (!ok) return;
        const m = new Matrix4().makeBasis(frame.u, frame.v, frame.w);
        expectFiniteMatrix(m, 'frame');
        expect(frame.e.toArray().every(Number.isFinite)).toBe(true);
        // Orthonormal and right-handed: det = +1.
        expect(m.determinant()).toBeCloseTo(1, 6);
        expect(
          frame.u.dot(frame.v) ** 2 + frame.v.dot(frame.w) ** 2 + frame.w.dot(frame.u) ** 2,
        ).toBeLessThan(1e-12);
      }),
      { numRuns: 1000 },
    );
  });

  it('CameraMovement options and speeds: accepted finite ≥ 0, else a named error; keys never make NaN', () => {
    fc.assert(
      fc.property(
        fc.oneof(fc.record({ moveSpeed: num(0, 10), turnSpeed: num(0, 1) }, { requiredKeys: [] }), hostile),
        fc.constantFrom('moveSpeed', 'turnSpeed'),
        hostile,
        (options, field, value) => {
          const camera = new Camera();
          const element = document.createElement('div');
          let movement: CameraMovement | undefined;
          if (
            !worksOrNamedError(
              counts,
              ['options', 'moveSpeed', 'turnSpeed'],
              () => (movement = new CameraMovement(camera, element, options as never)),
            )
          ) {
            return;
          }
          // Assigning a speed directly is validated too (or it is refused by name).
          worksOrNamedError(counts, [field], () => {
            (movement as unknown as Record<string, unknown>)[field] = value;
          });
          for (const code of ['KeyW', 'KeyA', 'KeyE']) {
            worksOrNamedError(counts, [field], () =>
              element.dispatchEvent(new KeyboardEvent('keydown', { code })),
            );
          }
          element.dispatchEvent(
            new PointerEvent('pointerdown', { button: 0, pointerId: 1, clientX: 0, clientY: 0 }),
          );
          element.dispatchEvent(new PointerEvent('pointermove', { pointerId: 1, clientX: 30, clientY: -20 }));
          element.dispatchEvent(new PointerEvent('pointerup', { pointerId: 1 }));
          movement!.dispose();
          expectSane(camera);
        },
      ),
      { numRuns: 300 },
    );
  });

  it('depthBufferParameters: a mode or a named error', () => {
    fc.assert(
      fc.property(fc.oneof(fc.constantFrom('standard', 'logarithmic', 'reversed'), hostile), (mode) => {
        worksOrNamedError(counts, ['mode'], () => depthBufferParameters(mode as never));
      }),
      { numRuns: 200 },
    );
  });

  it('matches three where both accept: the PerspectiveCamera projection for sane inputs', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 1, max: 179, noNaN: true }),
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: 1e-3, max: 1, noNaN: true }),
        fc.double({ min: 2, max: 1e6, noNaN: true }),
        (fovy, aspect, near, far) => {
          const ours = new Camera().setPerspective(fovy, aspect, near, far).projectionMatrix.elements;
          const theirs = new PerspectiveCamera(fovy, aspect, near, far).projectionMatrix.elements;
          for (const [i, x] of ours.entries()) expect(x).toBeCloseTo(theirs[i], 6);
        },
      ),
      { numRuns: 100 },
    );
  });
});
