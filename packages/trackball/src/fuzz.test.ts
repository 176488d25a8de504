// @vitest-environment happy-dom
import { arcRotation, projectToBall, Trackball } from '@shadelab/trackball';
import fc from 'fast-check';
import { Matrix4, Object3D, OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import { afterAll, afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { fuzzSeed, hostileNumbers, hostileValue, worksOrNamedError } from '../../../test-utils/fuzz.js';

// Issue 8: every constructor option, setter and method, fed hostile values, either works with finite results or
// throws a TypeError/RangeError naming the parameter; hostile pointer and wheel input never yields NaN.

const hostileNumber = hostileNumbers(1);
const hostile = hostileValue(hostileNumber, { values: ['2', 'arcball', 'bell'] });

const num = (min: number, max: number) =>
  fc.oneof({ weight: 2, arbitrary: fc.double({ min, max, noNaN: true }) }, hostile) as fc.Arbitrary<unknown>;

const counts = { calls: 0, threw: 0, events: 0 };

// A release starts a damped spin only within 100 ms of the last move (performance.now): the suite runs on a
// clock of its own, which moves only when a drag is held before its release, so no machine's speed changes
// what is tested.
let clock = 0;
beforeEach(() => {
  clock = 0;
  vi.spyOn(performance, 'now').mockImplementation(() => clock);
});
afterEach(() => {
  vi.restoreAllMocks();
});
afterAll(() => {
  console.log(
    `trackball fuzz: seed ${fuzzSeed()}, ${counts.calls} calls (${counts.threw} refused with a named TypeError/RangeError), ${counts.events} hostile input events`,
  );
});

function makeElement(): HTMLElement {
  const el = document.createElement('div');
  el.getBoundingClientRect = () =>
    ({ left: 0, top: 0, width: 200, height: 100, right: 200, bottom: 100, x: 0, y: 0 }) as DOMRect;
  return el;
}

const finite = (xs: ArrayLike<number>) => Array.from(xs).every(Number.isFinite);

/** Everything the trackball writes is finite; the rotation is a unit quaternion. */
function expectSane(trackball: Trackball, camera: Object3D | null): void {
  const q = trackball.rotation;
  expect(finite(q.toArray()), `rotation ${q.toArray()}`).toBe(true);
  expect(Math.abs(q.length() - 1)).toBeLessThan(1e-9);
  expect(finite(trackball.getMatrix().elements)).toBe(true);
  expect(finite(trackball.getWorldMatrix().elements)).toBe(true);
  expect(finite(trackball.object.quaternion.toArray()), 'object quaternion').toBe(true);
  expect(Number.isFinite(trackball.zoom) && trackball.zoom > 0, `zoom ${trackball.zoom}`).toBe(true);
  if (camera) {
    expect(finite(camera.position.toArray()), `camera position ${camera.position.toArray()}`).toBe(true);
    const projection = (camera as PerspectiveCamera).projectionMatrix;
    expect(finite(projection.elements), 'camera projection').toBe(true);
  }
}

const OPTIONS = [
  'options',
  'camera',
  'mapping',
  'rotateSpeed',
  'zoomSpeed',
  'minZoom',
  'maxZoom',
  'enableDamping',
  'dampingFactor',
  'radius',
  'target',
];

const options = fc.record(
  {
    mapping: fc.oneof(fc.constantFrom('arcball', 'bell'), hostile),
    rotateSpeed: num(0, 10),
    zoomSpeed: num(0, 10),
    minZoom: num(1e-3, 1),
    maxZoom: num(1, 1e3),
    enableDamping: fc.oneof(fc.boolean(), hostile),
    dampingFactor: num(0.01, 1),
    radius: num(0.1, 10),
    target: fc.oneof(
      // A Vector3 with any numbers (NaN and ±Infinity included), or anything else.
      fc.tuple(hostileNumber, hostileNumber, hostileNumber).map(([x, y, z]) => new Vector3(x, y, z)),
      hostile,
    ),
  },
  { requiredKeys: [] },
);

type Input =
  | { kind: 'drag'; points: [number, number][]; heldMs: number }
  | { kind: 'wheel'; deltaY: number; deltaMode: number }
  | { kind: 'pinch'; a: [number, number]; b: [number, number]; to: [number, number] }
  | { kind: 'update'; delta: unknown }
  | { kind: 'zoomBy'; factor: unknown }
  | { kind: 'set'; name: string; value: unknown };

const coordinate = fc.oneof(
  { weight: 3, arbitrary: fc.double({ min: -300, max: 500, noNaN: true }) },
  hostileNumber,
);
const point = fc.tuple(coordinate, coordinate);
const input: fc.Arbitrary<Input> = fc.oneof(
  // Released at once (a fling, which spins), or after holding still (no spin).
  fc
    .tuple(fc.array(point, { minLength: 1, maxLength: 6 }), fc.constantFrom(0, 16, 150))
    .map(([points, heldMs]) => ({ kind: 'drag' as const, points, heldMs })),
  fc.record({ kind: fc.constant('wheel' as const), deltaY: coordinate, deltaMode: fc.constantFrom(0, 1, 2) }),
  fc.record({ kind: fc.constant('pinch' as const), a: point, b: point, to: point }),
  fc.record({ kind: fc.constant('update' as const), delta: num(0, 1) }),
  fc.record({ kind: fc.constant('zoomBy' as const), factor: num(0.1, 10) }),
  fc.record({
    kind: fc.constant('set' as const),
    name: fc.constantFrom(
      'mapping',
      'rotateSpeed',
      'zoomSpeed',
      'minZoom',
      'maxZoom',
      'dampingFactor',
      'radius',
    ),
    value: hostile,
  }),
);

function send(el: HTMLElement, type: string, [x, y]: [number, number], pointerId = 1): void {
  counts.events++;
  const init = { pointerId, pointerType: 'touch', button: 0, clientX: x, clientY: y, bubbles: true };
  (type === 'pointerdown' ? el : el.ownerDocument).dispatchEvent(new PointerEvent(type, init));
}

function apply(trackball: Trackball, el: HTMLElement, step: Input): void {
  switch (step.kind) {
    case 'drag': {
      const [first, ...rest] = step.points;
      send(el, 'pointerdown', first);
      for (const p of rest) send(el, 'pointermove', p);
      clock += step.heldMs;
      send(el, 'pointerup', step.points.at(-1)!);
      return;
    }
    case 'wheel':
      counts.events++;
      el.dispatchEvent(
        new WheelEvent('wheel', { deltaY: step.deltaY, deltaMode: step.deltaMode, cancelable: true }),
      );
      return;
    case 'pinch':
      send(el, 'pointerdown', step.a, 1);
      send(el, 'pointerdown', step.b, 2);
      send(el, 'pointermove', step.to, 2);
      send(el, 'pointerup', step.to, 2);
      send(el, 'pointerup', step.a, 1);
      return;
    case 'update':
      worksOrNamedError(counts, ['delta'], () => trackball.update(step.delta as number));
      return;
    case 'zoomBy':
      worksOrNamedError(counts, ['factor'], () => trackball.zoomBy(step.factor as number));
      return;
    case 'set': {
      const before = (trackball as unknown as Record<string, unknown>)[step.name];
      const ok = worksOrNamedError(counts, [step.name], () => {
        (trackball as unknown as Record<string, unknown>)[step.name] = step.value;
      });
      // A refused value changes nothing; an accepted one reads back as given.
      expect((trackball as unknown as Record<string, unknown>)[step.name]).toBe(ok ? step.value : before);
      if (ok) expect(typeof step.value === 'number' || step.name === 'mapping').toBe(true);
    }
  }
}

describe('trackball fuzz (hostile values everywhere)', () => {
  it('new Trackball(object, element, options): a sane trackball or a named error', () => {
    fc.assert(
      fc.property(fc.oneof({ weight: 9, arbitrary: options }, hostile), (o) => {
        let trackball: Trackball | undefined;
        const camera = new PerspectiveCamera();
        camera.position.set(0, 0, 5);
        const withCamera = o !== null && typeof o === 'object' ? { ...o, camera } : o;
        if (
          worksOrNamedError(
            counts,
            OPTIONS,
            () => (trackball = new Trackball(null, makeElement(), withCamera as never)),
          )
        ) {
          expectSane(trackball!, camera);
          trackball!.dispose();
        }
      }),
      { numRuns: 500 },
    );
  });

  it('any sequence of hostile input, calls and assignments keeps every matrix finite and the rotation unit', () => {
    fc.assert(
      fc.property(
        fc.constantFrom('perspective', 'orthographic', 'none'),
        fc.array(input, { minLength: 1, maxLength: 10 }),
        (kind, steps) => {
          const camera =
            kind === 'perspective'
              ? new PerspectiveCamera(50, 2, 0.1, 100)
              : kind === 'orthographic'
                ? new OrthographicCamera(-2, 2, 1, -1, 0.1, 100)
                : null;
          camera?.position.set(0, 0, 5);
          const el = makeElement();
          const object = new Object3D();
          const trackball = new Trackball(object, el, {
            camera,
            enableDamping: true,
            minZoom: 1e-3,
            maxZoom: 1e3,
          });
          for (const step of steps) {
            apply(trackball, el, step);
            expectSane(trackball, camera);
          }
          trackball.dispose();
          expectSane(trackball, camera);
        },
      ),
      { numRuns: 400 },
    );
  });

  it('the extreme zoom limits keep the camera finite (minZoom = 1e-300 .. maxZoom = 1e300)', () => {
    for (const [minZoom, maxZoom] of [
      [Number.MIN_VALUE, 1],
      [1e-300, 1e300],
      [1, Number.MAX_VALUE],
    ]) {
      for (const camera of [
        new PerspectiveCamera(),
        new OrthographicCamera(),
        new OrthographicCamera(-2, 2, 1, -1),
      ]) {
        camera.position.set(0, 0, 5);
        const trackball = new Trackball(null, makeElement(), { camera, minZoom, maxZoom });
        // Twice in a row, so the zoom reaches maxZoom itself: three's ortho update computes 2 · zoom, which
        // overflows above 9e307 (a fuzz run found it through a pinch from a 5e-324 px span to an infinite one).
        for (const factor of [1e-300, 1e300, 1e300, 1e-300, 1e-300, 1e300, 0.5, 2]) {
          worksOrNamedError(counts, ['factor'], () => trackball.zoomBy(factor));
          expectSane(trackball, camera);
        }
      }
    }
  });

  it('projectToBall and arcRotation: finite unit results or a named error', () => {
    fc.assert(
      fc.property(
        hostileNumber,
        hostileNumber,
        fc.oneof(fc.constantFrom('arcball', 'bell'), hostile),
        (x, y, m) => {
          if (worksOrNamedError(counts, ['x', 'y', 'mapping'], () => projectToBall(x, y, m as never))) {
            const p = projectToBall(x, y, m as never);
            expect(finite(p)).toBe(true);
            // On the unit sphere for the arcball; the bell's hyperbolic sheet (z = 1 / 2r) is not, by design.
            if (m === 'arcball') expect(Math.abs(Math.hypot(...p) - 1)).toBeLessThan(1e-9);
            // arcRotation refuses a point whose length overflows (bell far out), naming it.
            let q: number[] = [0, 0, 0, 1];
            if (worksOrNamedError(counts, ['b'], () => (q = arcRotation([0, 0, 1], p, 1)))) {
              expect(finite(q)).toBe(true);
              expect(Math.abs(Math.hypot(...q) - 1)).toBeLessThan(1e-6);
            }
          }
        },
      ),
      { numRuns: 1000 },
    );
  });

  it('getMatrix matches three: the rotation matrix of the rotation quaternion', () => {
    const trackball = new Trackball(null, makeElement());
    const el = trackball.domElement as HTMLElement;
    send(el, 'pointerdown', [100, 50]);
    send(el, 'pointermove', [150, 20]);
    send(el, 'pointerup', [150, 20]);
    expect(trackball.getMatrix().elements).toEqual(
      new Matrix4().makeRotationFromQuaternion(trackball.rotation).elements,
    );
  });
});

// Every counterexample a fuzz run found, as a named test (DEVELOPERS.md, "Fuzzing"): fixed values, so they keep
// testing the case even when the arbitraries above change.
describe('trackball fuzz counterexamples (regression tests)', () => {
  it('an orthographic zoom above 9e307 is refused: three computes 2 · zoom, which overflows (fuzz, 626c68a)', () => {
    // Found as a pinch from a 5e-324 px span to a huge one with maxZoom = Number.MAX_VALUE.
    const camera = new OrthographicCamera(-2, 2, 1, -1, 0.1, 100);
    const el = makeElement();
    const trackball = new Trackball(null, el, { camera, maxZoom: Number.MAX_VALUE });
    send(el, 'pointerdown', [0, 0], 1);
    send(el, 'pointerdown', [5e-324, 0], 2);
    send(el, 'pointermove', [1e308, 0], 2);
    send(el, 'pointerup', [1e308, 0], 2);
    send(el, 'pointerup', [0, 0], 1);
    // The ratio is ∞, clamped to maxZoom: a zoom three cannot draw, so the step is refused.
    expect(trackball.zoom).toBe(1);
    expect(camera.zoom).toBe(1);
    expectSane(trackball, camera);
    // The same through zoomBy: the step past the limit three can draw is refused and changes nothing.
    const zoomed = new Trackball(null, makeElement(), { camera, maxZoom: Number.MAX_VALUE });
    expect(zoomed.zoomBy(1e300)).toBe(true);
    const atLimit = camera.projectionMatrix.clone();
    expect(zoomed.zoomBy(1e300)).toBe(false);
    expect(zoomed.zoom).toBe(1e300);
    expect(camera.projectionMatrix.equals(atLimit)).toBe(true);
    expectSane(zoomed, camera);
    trackball.dispose();
    zoomed.dispose();
  });

  it('rotateSpeed near Number.MAX_VALUE keeps the rotation a unit quaternion: speed · θ overflowed to sin(∞) = NaN (fuzz, e45651b)', () => {
    for (const rotateSpeed of [Number.MAX_VALUE, 1.7e308]) {
      const el = makeElement();
      const object = new Object3D();
      const trackball = new Trackball(object, el, { rotateSpeed });
      send(el, 'pointerdown', [100, 50]);
      send(el, 'pointermove', [100, 160]); // a 110 px drag, as found
      send(el, 'pointerup', [100, 160]);
      expectSane(trackball, null);
      expect(Math.abs(object.quaternion.length() - 1)).toBeLessThan(1e-9);
      trackball.dispose();
    }
  });
});
