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
import { fuzzSeed, hostileNumbers, hostileValue } from '../../../test-utils/fuzz.js';

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
    `camera fuzz: seed ${fuzzSeed()}, ${counts.calls} calls, ${counts.threw} refused with a named TypeError/RangeError`,
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

/**
 * The outcome the documented checks predict: `name` = the parameter the error must start with (the first bad one
 * in the documented order), `null` = the call must work, except that a call whose parameters are all in range may
 * still be refused with `orElse` (the projection matrix overflowing float32: `near, far, zoom (…) … give a
 * non-finite float32 matrix`, or a move beyond ±1e30).
 */
type Expected = { name: string | null; orElse?: string };

/** Run `fn` and check it against `expected`; true when it worked. */
function outcome(expected: Expected, fn: () => unknown): boolean {
  counts.calls++;
  try {
    fn();
  } catch (error) {
    counts.threw++;
    expect(error).toSatisfy((e) => e instanceof TypeError || e instanceof RangeError);
    const message = (error as Error).message;
    const allowed = [expected.name, expected.orElse].filter((n) => n != null);
    expect(allowed.length, `expected to work, threw: ${message}`).toBeGreaterThan(0);
    expect(
      allowed.some((n) => message.startsWith(`${n} `)),
      `expected ${allowed.join(' or ')}, got: ${message}`,
    ).toBe(true);
    return false;
  }
  expect(expected.name, 'expected a refusal naming it, the call worked').toBeNull();
  return true;
}

type Check = [name: string, value: unknown, ok: (v: number) => boolean];
const isFiniteNumber = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);
/** The first check that fails (a non-number fails every check), or null. */
const firstBad = (checks: Check[]): string | null =>
  checks.find(([, v, ok]) => typeof v !== 'number' || !ok(v))?.[0] ?? null;
const positive = (v: number) => v > 0 && Number.isFinite(v);
const MATRIX = 'near, far, zoom';

/** The documented validation order of each projection, over the fields a camera would have. */
function projectionChecks(c: Record<string, unknown>): Check[] {
  const near = c.near as number;
  if (c.kind === 'perspective') {
    return [
      ['fovy', c.fovy, (v) => v > 0 && v < 180],
      ['aspect', c.aspect, positive],
      ['near', near, positive],
      ['far', c.far, (v) => v > near && Number.isFinite(v)],
      ['zoom', c.zoom, positive],
    ];
  }
  return [
    ['right', c.right, Number.isFinite],
    ['left', c.left, (v) => Number.isFinite(v) && v !== c.right],
    ['top', c.top, Number.isFinite],
    ['bottom', c.bottom, (v) => Number.isFinite(v) && v !== c.top],
    ['near', near, Number.isFinite],
    ['far', c.far, (v) => v > near && Number.isFinite(v)],
    ['zoom', c.zoom, positive],
  ];
}

const fieldsOf = (c: Camera): Record<string, unknown> => ({
  kind: c.projection,
  ...Object.fromEntries(
    ['fovy', 'aspect', 'near', 'far', 'zoom', 'left', 'right', 'top', 'bottom'].map((k) => [
      k,
      (c as unknown as Record<string, unknown>)[k],
    ]),
  ),
});

/** The components of something lookAt accepts as a vector, or null when it is not one (a TypeError). */
function components(x: unknown): unknown[] | null {
  if ((Array.isArray(x) || x instanceof Float32Array || x instanceof Float64Array) && x.length === 3)
    return [...x];
  if (typeof x === 'object' && x !== null && 'x' in x && 'y' in x && 'z' in x) {
    const { x: a, y, z } = x as Record<string, unknown>;
    return [a, y, z];
  }
  return null;
}
const validVector = (x: unknown) => components(x)?.every(isFiniteNumber) ?? false;

/**
 * lookAt(eye, at, up): eye, at, up read in order; then eye = at or eye − at overflowing; zero up; and (Camera only,
 * `bounded`) eye within ±1e30.
 */
function lookAtExpected(eye: unknown, at: unknown, up: unknown, bounded = true): string | null {
  for (const [name, x] of [
    ['eye', eye],
    ['at', at],
    ['up', up],
  ] as const)
    if (!validVector(x)) return name;
  const e = components(eye) as number[];
  const a = components(at) as number[];
  const d = e.map((x, i) => x - a[i]);
  if (d.every((x) => x === 0) || !d.every(Number.isFinite)) return 'eye';
  if ((components(up) as number[]).every((x) => x === 0)) return 'up';
  if (bounded && e.some((x) => Math.abs(x) > 1e30)) return 'eye';
  return null;
}

/** lookAt(target): read as `at`, from the current position, with this.up (always a valid non-zero vector). */
const targetExpected = (c: Camera, target: unknown) =>
  validVector(target) ? lookAtExpected(c.position.toArray(), target, c.up.toArray()) : 'at';

/** Arguments as fast-check prints values (NaN, -0, undefined, 10n, Symbol(s), strings quoted). */
const show = (...args: unknown[]) => args.map((a) => fc.stringify(a)).join(', ');

/** An operation that a counterexample prints as the call it makes, e.g. `lookAt(0, -1e+308, undefined)`. */
function call<T extends readonly unknown[]>(text: string, operation: T): T {
  return Object.assign(operation, { [fc.toStringMethod]: () => text });
}

/** One random call on a camera (or a movement on it), with the outcome its arguments predict. */
const operation = fc.oneof(
  fc.tuple(num(1, 179), num(0.1, 10), num(1e-3, 10), num(10, 1e6)).map(([fovy, aspect, near, far]) =>
    call(`setPerspective(${show(fovy, aspect, near, far)})`, [
      'setPerspective',
      (c: Camera): Expected => ({
        name: firstBad(projectionChecks({ ...fieldsOf(c), kind: 'perspective', fovy, aspect, near, far })),
        orElse: MATRIX,
      }),
      (c: Camera) => c.setPerspective(fovy, aspect, near, far),
    ] as const),
  ),
  fc
    .tuple(num(-10, 10), num(-10, 10), num(-10, 10), num(-10, 10), num(-10, 10), num(-10, 10))
    .map(([right, left, top, bottom, near, far]) =>
      call(`setOrthographic(${show(right, left, top, bottom, near, far)})`, [
        'setOrthographic',
        (c: Camera): Expected => ({
          name: firstBad(
            projectionChecks({ ...fieldsOf(c), kind: 'orthographic', right, left, top, bottom, near, far }),
          ),
          orElse: MATRIX,
        }),
        (c: Camera) => c.setOrthographic(right, left, top, bottom, near, far),
      ] as const),
    ),
  num(0.1, 10).map((aspect) =>
    call(`setAspect(${show(aspect)})`, [
      'setAspect',
      (c: Camera): Expected => {
        if (typeof aspect !== 'number' || !positive(aspect)) return { name: 'aspect' };
        const f = fieldsOf(c);
        if (c.projection === 'perspective') return { name: null, orElse: MATRIX };
        // Orthographic: keeps the vertical extent and the centre; the new left/right are checked as planes.
        const cx = (c.left + c.right) / 2;
        const half = (Math.sign(c.right - c.left) * aspect * Math.abs(c.top - c.bottom)) / 2;
        return {
          name: firstBad(projectionChecks({ ...f, left: cx - half, right: cx + half })),
          orElse: MATRIX,
        };
      },
      (c: Camera) => c.setAspect(aspect),
    ] as const),
  ),
  fc.tuple(vec, vec, vec).map(([e, a, u]) =>
    call(`lookAt(${show(e, a, u)})`, [
      'lookAt(eye, at, up)',
      (c: Camera): Expected => ({
        // A number first is three's lookAt(x, y, z); at = undefined its lookAt(target); up = undefined
        // keeps this.up.
        name:
          typeof e === 'number'
            ? targetExpected(c, [e, a, u])
            : a === undefined
              ? targetExpected(c, e)
              : lookAtExpected(e, a, u === undefined ? c.up.toArray() : u),
      }),
      (c: Camera) => c.lookAt(e, a, u),
    ] as const),
  ),
  vec.map((t) =>
    call(`lookAt(${show(t)})`, [
      'lookAt(target)',
      (c: Camera): Expected => ({ name: targetExpected(c, t) }),
      (c: Camera) => c.lookAt(t),
    ] as const),
  ),
  fc
    .tuple(
      fc.constantFrom('fovy', 'fov', 'aspect', 'near', 'far', 'zoom', 'left', 'right', 'top', 'bottom'),
      hostile,
    )
    .map(([field, value]) =>
      call(`${field} = ${show(value)}; updateProjectionMatrix()`, [
        `${field} = …; updateProjectionMatrix()`,
        (c: Camera): Expected => ({
          name: firstBad(projectionChecks({ ...fieldsOf(c), [field === 'fov' ? 'fovy' : field]: value })),
          orElse: MATRIX,
        }),
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
      ] as const),
    ),
  fc.tuple(num(-1, 1), num(-1, 1), num(-1, 1)).map(([du, dv, dw]) =>
    call(`move(${show(du, dv, dw)})`, [
      'move',
      (): Expected =>
        [du, dv, dw].every(isFiniteNumber)
          ? { name: null, orElse: 'du, dv, dw' } // refused only beyond ±1e30 world units
          : { name: 'du, dv, dw' },
      (c: Camera) => new CameraMovement(c).move(du, dv, dw),
    ] as const),
  ),
  fc
    .tuple(num(-1, 1), num(-1, 1))
    .map(([yaw, pitch]) =>
      call(`turn(${show(yaw, pitch)})`, [
        'turn',
        (): Expected => ({ name: [yaw, pitch].every(isFiniteNumber) ? null : 'yaw, pitch' }),
        (c: Camera) => new CameraMovement(c).turn(yaw, pitch),
      ] as const),
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
        // Anything but an object with fields (null, numbers, strings…) gives the defaults.
        const given = (typeof o === 'object' && o !== null ? o : {}) as Record<string, unknown>;
        const or = (v: unknown, fallback: number) => (v === undefined ? fallback : v);
        const expected = firstBad(
          projectionChecks({
            kind: 'perspective',
            fovy: or(given.fovy, 50),
            aspect: or(given.aspect, 1),
            near: or(given.near, 0.1),
            far: or(given.far, 2000),
            zoom: 1,
          }),
        );
        if (outcome({ name: expected, orElse: MATRIX }, () => (camera = new Camera(o as never)))) {
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
        for (const [name, expect_, op] of ops) {
          const before = camera.getMatrix().clone();
          const projection = camera.projection;
          if (!outcome(expect_(camera), () => op(camera))) {
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
        const ok = outcome({ name: lookAtExpected(eye, at, up, false) }, () =>
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

  it('CameraMovement options and speeds: accepted finite ≥ 0, else a named error; a bad speed assigned later moves nothing', () => {
    const validSpeed = (v: unknown) => typeof v === 'number' && v >= 0 && Number.isFinite(v);
    fc.assert(
      fc.property(
        fc.oneof(fc.record({ moveSpeed: num(0, 10), turnSpeed: num(0, 1) }, { requiredKeys: [] }), hostile),
        fc.constantFrom('moveSpeed', 'turnSpeed'),
        hostile,
        (options, field, value) => {
          const camera = new Camera();
          const element = document.createElement('div');
          let movement: CameraMovement | undefined;
          // Anything but an object with fields (null, numbers, strings…) gives the defaults.
          const given = (typeof options === 'object' && options !== null ? options : {}) as Record<
            string,
            unknown
          >;
          const speeds = {
            moveSpeed: given.moveSpeed === undefined ? 0.1 : given.moveSpeed,
            turnSpeed: given.turnSpeed === undefined ? 0.005 : given.turnSpeed,
          };
          const expected = validSpeed(speeds.moveSpeed)
            ? validSpeed(speeds.turnSpeed)
              ? null
              : 'turnSpeed'
            : 'moveSpeed';
          if (
            !outcome(
              { name: expected },
              () => (movement = new CameraMovement(camera, element, options as never)),
            )
          ) {
            return;
          }
          // A field assigned directly is not checked then; input events with a bad value move nothing.
          (movement as unknown as Record<string, unknown>)[field] = value;
          const before = camera.matrixWorld.clone();
          const stays = !validSpeed(value);
          if (field === 'moveSpeed') {
            for (const code of ['KeyW', 'KeyA', 'KeyE']) {
              element.dispatchEvent(new KeyboardEvent('keydown', { code }));
            }
          } else {
            element.dispatchEvent(
              new PointerEvent('pointerdown', { button: 0, pointerId: 1, clientX: 0, clientY: 0 }),
            );
            element.dispatchEvent(
              new PointerEvent('pointermove', { pointerId: 1, clientX: 30, clientY: -20 }),
            );
            element.dispatchEvent(new PointerEvent('pointerup', { pointerId: 1 }));
          }
          if (stays) expect(camera.matrixWorld.elements).toEqual(before.elements);
          movement!.dispose();
          expectSane(camera);
        },
      ),
      { numRuns: 300 },
    );
  });

  it('depthBufferParameters: a mode or a named error', () => {
    fc.assert(
      fc.property(
        fc.oneof(fc.constantFrom('standard', 'logarithmic', 'reversed', 'reversed-or-logarithmic'), hostile),
        (mode) => {
          const known = ['standard', 'logarithmic', 'reversed', 'reversed-or-logarithmic'].includes(
            mode as never,
          );
          outcome({ name: known ? null : 'mode' }, () => depthBufferParameters(mode as never));
        },
      ),
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

// Every counterexample a fuzz run found, as a named test (DEVELOPERS.md, "Fuzzing"): fixed values, so they keep
// testing the case even when the arbitraries above change.
describe('camera fuzz counterexamples (regression tests)', () => {
  it('lookAt(0, -1e308, undefined) is a TypeError naming at (seed -318908392, path "239:0:0", issue 13)', () => {
    // three's lookAt(x, y, z) with z missing: Vector3.set kept the previous z, so the camera looked at a point
    // nobody gave (down −y) instead of refusing. Found on "any sequence of calls leaves a finite camera".
    const camera = new Camera().lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
    const before = camera.matrixWorld.clone();
    for (const args of [
      [0, -1e308, undefined],
      [0, -1e308],
      [1, 2],
      [1, undefined, 3],
      [1, '2', 3],
      [1, 2, null],
      [1, 2, [3]],
    ] as const) {
      expect(() => camera.lookAt(...(args as unknown as [number, number, number])), String(args)).toThrow(
        new TypeError(
          `at must have numeric x, y, z, got (${[0, 1, 2].map((i) => typeof args[i]).join(', ')})`,
        ),
      );
      expect(camera.matrixWorld.elements).toEqual(before.elements);
    }
    // With all three numbers it is three's lookAt(x, y, z): from (0, 0, 3) straight down −y (w = eye − at).
    camera.lookAt(0, -1e308, 3);
    expect(camera.getFrame().w.distanceTo(new Vector3(0, 1, 0))).toBeLessThan(1e-15);
  });

  it('eye − at of subnormal length (5e-324) gives the exact frame, not an overflow refusal (CI fuzz, f439681)', () => {
    // three's divideScalar multiplies by 1/m, which is Infinity for m = 5e-324.
    for (const s of [5e-324, -5e-324, 1e-310]) {
      const { u, v, w } = new Camera().lookAt([0, 0, s], [0, 0, 0], [0, 1, 0]).getFrame();
      expect(w.toArray()).toEqual([0, 0, Math.sign(s)]);
      expect(v.toArray()).toEqual([0, 1, 0]);
      expect(u.toArray()).toEqual([Math.sign(s), 0, 0]);
    }
  });
});
