// @vitest-environment happy-dom
import { Trackball, type TrackballOptions, trackballWorldMatrix } from '@shadelab/trackball';
import fc from 'fast-check';
import {
  Camera,
  Group,
  Matrix4,
  Mesh,
  Object3D,
  OrthographicCamera,
  PerspectiveCamera,
  Quaternion,
  Vector3,
} from 'three';
import { TrackballControls } from 'three/examples/jsm/controls/TrackballControls.js';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

const SIZE = 200; // the element is a 200 × 200 px square at (10, 20): ball radius 100 px, centre (110, 120)
const CX = 110;
const CY = 120;

function makeElement(width = SIZE, height = SIZE): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  canvas.getBoundingClientRect = () =>
    ({ left: 10, top: 20, width, height, right: 10 + width, bottom: 20 + height, x: 10, y: 20 }) as DOMRect;
  return canvas;
}

function pointer(target: EventTarget, type: string, x: number, y: number, init: PointerEventInit = {}): void {
  target.dispatchEvent(
    new PointerEvent(type, {
      pointerId: 1,
      pointerType: 'mouse',
      button: 0,
      clientX: x,
      clientY: y,
      bubbles: true,
      cancelable: true,
      ...init,
    }),
  );
}

/** A drag through the given points (client px), pressed on the element and released where it ends. */
function drag(element: HTMLElement, points: [number, number][], init: PointerEventInit = {}): void {
  const [first, ...rest] = points;
  pointer(element, 'pointerdown', first[0], first[1], init);
  for (const [x, y] of rest) pointer(element, 'pointermove', x, y, init);
  const last = points[points.length - 1];
  pointer(element, 'pointerup', last[0], last[1], init);
}

function wheel(element: HTMLElement, deltaY: number, deltaMode = 0): void {
  element.dispatchEvent(new WheelEvent('wheel', { deltaY, deltaMode, bubbles: true, cancelable: true }));
}

function expectMatrixClose(actual: Matrix4, expected: Matrix4, tol = 1e-12): void {
  actual.elements.forEach((v, i) => {
    expect(Math.abs(v - expected.elements[i])).toBeLessThan(tol);
  });
}

/** The angle (radians) of the rotation a·b⁻¹ that separates two rotations: 2·atan2(|v|, |w|). */
function angleBetween(a: Quaternion, b: Quaternion): number {
  const r = a.clone().multiply(b.clone().invert());
  return 2 * Math.atan2(Math.hypot(r.x, r.y, r.z), Math.abs(r.w));
}

/** Same rotation within `tol` radians (1 − |a·b| < tol would only bound the angle by about 2·√(2·tol)). */
function expectSameRotation(a: Quaternion, b: Quaternion, tol = 1e-12): void {
  expect(angleBetween(a, b)).toBeLessThan(tol);
}

const made: Trackball[] = [];
function trackball(
  object: Object3D | null,
  element: HTMLElement | null,
  options?: TrackballOptions,
): Trackball {
  const t = new Trackball(object, element, options);
  made.push(t);
  return t;
}

// A release spins only within 100 ms of the last move (performance.now): the clock stands still, so a release
// is always a fling however slow the machine (tests of a held release move it themselves).
beforeEach(() => {
  vi.spyOn(performance, 'now').mockReturnValue(0);
});

afterEach(() => {
  vi.restoreAllMocks();
  for (const t of made.splice(0)) t.dispose();
  document.body.innerHTML = '';
});

describe('Trackball: rotation by pointer drags', () => {
  it('rotates about the camera-frame up axis by twice the arc for a drag to the right (arcball)', () => {
    const element = makeElement();
    const tb = trackball(null, element, { mapping: 'arcball' });
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    // Ball point (0.5, 0, √0.75): the arc from the pole is asin(0.5) = 30°, the rotation 60° about +y.
    expectMatrixClose(tb.getMatrix(), new Matrix4().makeRotationY(Math.PI / 3));
  });

  it('rotates about the camera-frame right axis for an upward drag (y is up on screen)', () => {
    const element = makeElement();
    const tb = trackball(null, element, { mapping: 'arcball' });
    drag(element, [
      [CX, CY],
      [CX, CY - 50],
    ]);
    expectMatrixClose(tb.getMatrix(), new Matrix4().makeRotationX(-Math.PI / 3));
  });

  it('turns the object by 180° for a drag from the centre to the rim (arcball), 2·atan(2) (Bell)', () => {
    for (const [mapping, angle] of [
      ['arcball', Math.PI],
      ['bell', 2 * Math.atan(2)],
    ] as const) {
      const element = makeElement();
      const mesh = new Mesh();
      trackball(mesh, element, { mapping });
      drag(element, [
        [CX, CY],
        [CX + SIZE / 2, CY],
      ]);
      expectSameRotation(mesh.quaternion, new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), angle));
    }
  });

  it('returns to the start orientation after any closed drag, both mappings (property)', () => {
    const px = fc.integer({ min: -150, max: 350 });
    fc.assert(
      fc.property(
        fc.array(fc.tuple(px, px), { minLength: 2, maxLength: 12 }),
        fc.constantFrom<'arcball' | 'bell'>('arcball', 'bell'),
        fc.double({ min: 0, max: 4, noNaN: true }),
        (path, mapping, rotateSpeed) => {
          const element = makeElement();
          const mesh = new Mesh();
          mesh.quaternion.setFromAxisAngle(new Vector3(1, 2, 3).normalize(), 0.7);
          const before = mesh.quaternion.clone();
          const tb = new Trackball(mesh, element, { mapping, rotateSpeed });
          drag(element, [...path, path[0]]);
          tb.dispose();
          element.remove();
          // Angles (radians), not 1 − |q·q₀|, which would let through ~1e-4 rad.
          return (
            angleBetween(mesh.quaternion, before) < 1e-9 && angleBetween(tb.rotation, new Quaternion()) < 1e-9
          );
        },
      ),
      { numRuns: 200 },
    );
  });

  it('fixes the axes in the camera frame: a rotated camera rotates the object about its own up vector', () => {
    const element = makeElement();
    const camera = new PerspectiveCamera();
    camera.position.set(4, 3, 2);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    const mesh = new Mesh();
    mesh.quaternion.setFromAxisAngle(new Vector3(0, 0, 1), 0.3);
    const expected = mesh.clone();
    const tb = trackball(mesh, element, { camera, mapping: 'arcball' });
    drag(element, [
      [CX, CY],
      [CX + 30, CY + 10],
      [CX + 50, CY],
    ]);
    // Reference: three's own rotateOnWorldAxis about the camera's world up axis by 60°.
    const up = new Vector3(0, 1, 0).applyQuaternion(camera.quaternion);
    expected.rotateOnWorldAxis(up, Math.PI / 3);
    expectSameRotation(mesh.quaternion, expected.quaternion);
    // The trackball matrix stays in camera coordinates, and the world matrix is C·R·C⁻¹ about the target.
    expectMatrixClose(tb.getMatrix(), new Matrix4().makeRotationY(Math.PI / 3));
    const c = new Matrix4().makeRotationFromQuaternion(camera.quaternion);
    const world = c.clone().multiply(tb.getMatrix()).multiply(c.clone().invert());
    expectMatrixClose(tb.getWorldMatrix(), world);
  });

  it('rotates an object inside a rotated parent about the same world axis', () => {
    const element = makeElement();
    const parent = new Group();
    parent.quaternion.setFromAxisAngle(new Vector3(1, 0, 0), 1.1);
    const mesh = new Mesh();
    parent.add(mesh);
    parent.updateMatrixWorld();
    const before = mesh.getWorldQuaternion(new Quaternion());
    trackball(mesh, element, { mapping: 'arcball' });
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    const after = mesh.getWorldQuaternion(new Quaternion());
    const expected = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), Math.PI / 3).multiply(before);
    expectSameRotation(after, expected);
  });

  it('getWorldMatrix turns about the target: the target stays fixed', () => {
    const element = makeElement();
    const target = new Vector3(1, -2, 3);
    const tb = trackball(null, element, { target });
    drag(element, [
      [CX - 20, CY + 30],
      [CX + 60, CY - 10],
    ]);
    const m = tb.getWorldMatrix();
    expect(target.clone().applyMatrix4(m).distanceTo(target)).toBeLessThan(1e-12);
    expect(Math.abs(m.determinant() - 1)).toBeLessThan(1e-12);
  });

  it('keeps each drag about the camera axes of its time: the object and getWorldMatrix agree after the camera turns', () => {
    const element = makeElement();
    const camera = new PerspectiveCamera();
    camera.position.set(0, 0, 5);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    const target = new Vector3(1, -2, 3);
    const mesh = new Mesh();
    mesh.position.copy(target);
    mesh.updateMatrixWorld();
    const homeMatrix = mesh.matrixWorld.clone();
    const tb = trackball(mesh, element, { camera, mapping: 'arcball', enableDamping: true });
    // Reference: three's rotateOnWorldAxis about the camera's axes as they are during each drag.
    const expected = new Object3D();
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]); // 60° about the camera's up axis
    expected.rotateOnWorldAxis(new Vector3(0, 1, 0).applyQuaternion(camera.quaternion), Math.PI / 3);
    // Before the camera turns, getWorldMatrix is the lecture's trackballWorldMatrix(trackball, camera).
    expectMatrixClose(tb.getWorldMatrix(), trackballWorldMatrix(tb, camera));
    camera.position.set(4, 3, 2);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    drag(element, [
      [CX, CY],
      [CX, CY - 50],
    ]); // −60° about the new camera's right axis
    expected.rotateOnWorldAxis(new Vector3(1, 0, 0).applyQuaternion(camera.quaternion), -Math.PI / 3);
    const worldRotation = () => new Quaternion().setFromRotationMatrix(tb.getWorldMatrix());
    expectSameRotation(mesh.quaternion, expected.quaternion);
    expectSameRotation(worldRotation(), mesh.quaternion);
    // Exactly the object's motion about the target: getWorldMatrix · (matrix at the start) = matrix now.
    mesh.updateMatrixWorld();
    expectMatrixClose(tb.getWorldMatrix().multiply(homeMatrix), mesh.matrixWorld);
    // The trackball matrix (camera coordinates) is R₂·R₁, and the lecture's formula turns all of it about
    // the current camera: it no longer matches what the user dragged (by far more than rounding).
    expectMatrixClose(
      tb.getMatrix(),
      new Matrix4().makeRotationX(-Math.PI / 3).multiply(new Matrix4().makeRotationY(Math.PI / 3)),
    );
    const lecture = new Quaternion().setFromRotationMatrix(trackballWorldMatrix(tb, camera));
    expect(angleBetween(lecture, mesh.quaternion)).toBeGreaterThan(0.1);
    // A damped spin keeps them together (the spin turns about the camera's current axes).
    expect(tb.update()).toBe(true);
    expectSameRotation(worldRotation(), mesh.quaternion);
    // reset returns both to the start.
    tb.reset();
    expect(tb.getWorldMatrix().equals(new Matrix4())).toBe(true);
  });

  it("defaults to Bell's mapping, as documented", () => {
    expect(trackball(null, null).mapping).toBe('bell');
    expect(new Trackball(null, null, {}).mapping).toBe('bell');
  });

  it('multiplies the angle by rotateSpeed: speed 2 turns a known arcball drag twice as far', () => {
    const turn = (rotateSpeed: number, mapping: 'arcball' | 'bell', to: [number, number]) => {
      const element = makeElement();
      const tb = trackball(null, element, { mapping, rotateSpeed });
      drag(element, [[CX, CY], to]);
      return tb.rotation.clone();
    };
    // 50 px right on the arcball: an arc of 30°, 60° at speed 1, exactly 120° about y at speed 2.
    expectMatrixClose(
      new Matrix4().makeRotationFromQuaternion(turn(2, 'arcball', [CX + 50, CY])),
      new Matrix4().makeRotationY((2 * Math.PI) / 3),
    );
    expectMatrixClose(
      new Matrix4().makeRotationFromQuaternion(turn(0.5, 'arcball', [CX + 50, CY])),
      new Matrix4().makeRotationY(Math.PI / 6),
    );
    // Any drag, either mapping: the same axis, twice the angle (half-angle quaternions: w₂ = 2w₁² − 1).
    for (const mapping of ['arcball', 'bell'] as const) {
      const one = turn(1, mapping, [CX + 23, CY - 41]);
      const two = turn(2, mapping, [CX + 23, CY - 41]);
      expectSameRotation(two, one.clone().multiply(one));
      expect(two.w).toBeCloseTo(2 * one.w * one.w - 1, 14);
    }
    expect(turn(0, 'bell', [CX + 60, CY + 10]).toArray()).toEqual([0, 0, 0, 1]);
  });

  it('sends start, change on every move, and end', () => {
    const element = makeElement();
    const tb = trackball(null, element);
    const seen: string[] = [];
    for (const type of ['start', 'change', 'end'] as const) tb.addEventListener(type, () => seen.push(type));
    drag(element, [
      [CX, CY],
      [CX + 1, CY],
      [CX + 2, CY + 1],
    ]);
    expect(seen).toEqual(['start', 'change', 'change', 'end']);
  });

  it('ignores input while disabled, and secondary mouse buttons', () => {
    const element = makeElement();
    const tb = trackball(null, element);
    tb.enabled = false;
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    wheel(element, -100);
    expect(tb.rotation.w).toBe(1);
    expect(tb.zoom).toBe(1);
    tb.enabled = true;
    drag(
      element,
      [
        [CX, CY],
        [CX + 50, CY],
      ],
      { button: 2 },
    );
    expect(tb.rotation.w).toBe(1);
  });
});

describe('Trackball: docs/design.md extremes through the DOM', () => {
  it('stays finite with the pointer at the centre, on the rim, outside it and outside the element', () => {
    for (const mapping of ['arcball', 'bell'] as const) {
      const element = makeElement();
      const mesh = new Mesh();
      const tb = trackball(mesh, element, { mapping });
      drag(element, [
        [CX, CY],
        [CX + 100, CY],
        [CX, CY - 100],
        [CX + 500, CY + 500],
        [-1e7, 1e9],
        [CX, CY],
        [CX + 100, CY],
      ]);
      const e = tb.getMatrix().elements;
      expect(e.every(Number.isFinite)).toBe(true);
      expect(mesh.quaternion.toArray().every(Number.isFinite)).toBe(true);
      expect(Math.abs(mesh.quaternion.length() - 1)).toBeLessThan(1e-12);
    }
  });

  it('does nothing for zero-length drags (press/release, and moves to the same point)', () => {
    const element = makeElement();
    const tb = trackball(null, element);
    drag(element, [[CX + 13, CY - 7]]);
    drag(element, [
      [CX + 13, CY - 7],
      [CX + 13, CY - 7],
      [CX + 13, CY - 7],
    ]);
    expect(tb.rotation.toArray()).toEqual([0, 0, 0, 1]);
  });

  it('does nothing (and no NaN) while the element has no size', () => {
    const element = makeElement(0, 0);
    const tb = trackball(null, element);
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    expect(tb.rotation.toArray()).toEqual([0, 0, 0, 1]);
  });

  it('captures the pointer on press and releases it on release', () => {
    const element = makeElement();
    const captured = new Set<number>();
    element.setPointerCapture = (id: number) => void captured.add(id);
    element.releasePointerCapture = (id: number) => void captured.delete(id);
    element.hasPointerCapture = (id: number) => captured.has(id);
    trackball(null, element);
    pointer(element, 'pointerdown', CX, CY, { pointerId: 7 });
    expect([...captured]).toEqual([7]);
    pointer(element, 'pointerup', CX, CY, { pointerId: 7 });
    expect(captured.size).toBe(0);
  });

  it('ends cleanly when released outside the element, and the next drag works', () => {
    const element = makeElement();
    const outside = document.createElement('div');
    document.body.appendChild(outside);
    const tb = trackball(null, element, { mapping: 'arcball' });
    const ends = vi.fn();
    tb.addEventListener('end', ends);
    pointer(element, 'pointerdown', CX, CY);
    pointer(outside, 'pointermove', 900, CY);
    pointer(outside, 'pointerup', 900, CY);
    expect(ends).toHaveBeenCalledTimes(1);
    expect(tb.dragging).toBe(false);
    // Outside the arcball the point sits on the rim: 180° about y.
    expect(Math.abs(tb.rotation.y)).toBeCloseTo(1, 12);
    // Moves after the release change nothing; a new drag starts from the current orientation.
    const held = tb.rotation.clone();
    pointer(outside, 'pointermove', CX, CY + 40);
    expect(tb.rotation.equals(held)).toBe(true);
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    const expected = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), Math.PI / 3).multiply(held);
    expectSameRotation(tb.rotation, expected);
  });
});

describe('Trackball: zoom', () => {
  it('moves a perspective camera along the line to the target, in and out, within the limits', () => {
    const element = makeElement();
    const camera = new PerspectiveCamera();
    camera.position.set(0, 3, 4); // 5 from the origin
    camera.lookAt(0, 0, 0);
    const tb = trackball(null, element, { camera, minZoom: 0.5, maxZoom: 4 });
    wheel(element, -100); // wheel up: zoom in
    expect(tb.zoom).toBeCloseTo(Math.exp(100 / 500), 12);
    expect(camera.position.length()).toBeCloseTo(5 / tb.zoom, 12);
    expect(
      camera.position
        .clone()
        .normalize()
        .distanceTo(new Vector3(0, 0.6, 0.8)),
    ).toBeLessThan(1e-12);
    wheel(element, 3, 1); // three lines down = 48 px: zoom out
    expect(tb.zoom).toBeCloseTo(Math.exp((100 - 48) / 500), 12);
    wheel(element, 1e9);
    expect(tb.zoom).toBe(0.5);
    expect(camera.position.length()).toBeCloseTo(10, 10);
    wheel(element, -1e9);
    expect(tb.zoom).toBe(4);
    expect(camera.position.length()).toBeCloseTo(1.25, 10);
    tb.reset();
    expect(camera.position.distanceTo(new Vector3(0, 3, 4))).toBeLessThan(1e-12);
  });

  it('zooms an orthographic camera in and out through its zoom factor', () => {
    const element = makeElement();
    const camera = new OrthographicCamera(-2, 2, 2, -2, 0.1, 10);
    camera.zoom = 2;
    camera.updateProjectionMatrix();
    const tb = trackball(null, element, { camera });
    tb.zoomBy(3);
    expect(camera.zoom).toBeCloseTo(6, 12);
    expect(camera.projectionMatrix.elements[0]).toBeCloseTo(
      new OrthographicCamera(-2, 2, 2, -2).projectionMatrix.elements[0] * 6,
      12,
    );
    tb.zoomBy(1 / 12);
    expect(camera.zoom).toBeCloseTo(0.5, 12);
    tb.reset();
    expect(camera.zoom).toBeCloseTo(2, 12);
  });

  it('zooms any Camera flagged isOrthographicCamera (no zoom field) by scaling its projection', () => {
    class Flagged extends Camera {
      get isOrthographicCamera(): boolean {
        return true;
      }
    }
    const camera = new Flagged();
    camera.projectionMatrix.makeOrthographic(-1, 3, 2, -2, 0.1, 10);
    const before = camera.projectionMatrix.clone();
    const tb = trackball(null, makeElement(), { camera });
    tb.zoomBy(0.25);
    const p = new Vector3(0.7, -0.4, -1);
    const ndcBefore = p.clone().applyMatrix4(before);
    const ndcAfter = p.clone().applyMatrix4(camera.projectionMatrix);
    expect(ndcAfter.x).toBeCloseTo(ndcBefore.x * 0.25, 12);
    expect(ndcAfter.y).toBeCloseTo(ndcBefore.y * 0.25, 12);
    expect(ndcAfter.z).toBeCloseTo(ndcBefore.z, 12);
    expectMatrixClose(camera.projectionMatrixInverse, camera.projectionMatrix.clone().invert());
    tb.zoomBy(4);
    expectMatrixClose(camera.projectionMatrix, before);
    // A zoom whose projection would overflow is refused and leaves the camera as it was.
    camera.projectionMatrix.makeOrthographic(-0.01, 0.01, 0.01, -0.01, 0.1, 10);
    const big = new Trackball(null, null, { camera, maxZoom: Number.MAX_VALUE });
    big.zoomBy(1e300);
    const atLimit = camera.projectionMatrix.clone();
    expect(big.zoomBy(1e300)).toBe(false);
    expect(big.zoom).toBe(1e300);
    expect(camera.projectionMatrix.equals(atLimit)).toBe(true);
    expect(camera.projectionMatrix.elements.every(Number.isFinite)).toBe(true);
  });

  it('zooms any Camera flagged isPerspectiveCamera by moving it, even inside a parent', () => {
    class Flagged extends Camera {
      get isPerspectiveCamera(): boolean {
        return true;
      }
    }
    const rig = new Group();
    rig.position.set(10, 0, 0);
    const camera = new Flagged();
    camera.position.set(0, 0, 8);
    rig.add(camera);
    rig.updateMatrixWorld();
    const tb = trackball(null, makeElement(), { camera, target: new Vector3(10, 0, 0) });
    tb.zoomBy(2);
    expect(camera.getWorldPosition(new Vector3()).distanceTo(new Vector3(10, 0, 4))).toBeLessThan(1e-12);
  });

  it('only keeps the factor without a camera, and zoomSpeed scales the exponent', () => {
    const element = makeElement();
    const tb = trackball(null, element, { zoomSpeed: 2 });
    const changes = vi.fn();
    tb.addEventListener('change', changes);
    wheel(element, -250);
    expect(tb.zoom).toBeCloseTo(Math.exp(1), 12);
    expect(changes).toHaveBeenCalledTimes(1);
    tb.zoomSpeed = 0;
    wheel(element, -250);
    expect(tb.zoom).toBeCloseTo(Math.exp(1), 12);
  });

  it('without a camera, zoom leaves getMatrix and getWorldMatrix pure rotations (unlike the lecture)', () => {
    const element = makeElement();
    const tb = trackball(null, element);
    drag(element, [
      [CX - 10, CY + 20],
      [CX + 40, CY - 30],
    ]);
    const before = tb.getMatrix();
    tb.zoomBy(3);
    wheel(element, -300);
    expect(tb.zoom).toBeCloseTo(3 * Math.exp(300 / 500), 12);
    expect(tb.getMatrix().equals(before)).toBe(true);
    expect(tb.getMatrix().equals(new Matrix4().makeRotationFromQuaternion(tb.rotation))).toBe(true);
    expect(tb.getWorldMatrix().equals(before)).toBe(true); // no camera, target at the origin
    expect(Math.abs(tb.getMatrix().determinant() - 1)).toBeLessThan(1e-15);
  });

  it('counts a page-mode wheel step as 800 px', () => {
    const element = makeElement();
    const tb = trackball(null, element);
    wheel(element, 0.25, 2); // a quarter page = 200 px: zoom out by e^(−200/500)
    expect(tb.zoom).toBeCloseTo(Math.exp(-0.4), 14);
    wheel(element, -0.25, 2);
    expect(tb.zoom).toBeCloseTo(1, 14);
  });

  it('sends start, change, end for a wheel step (no change at a limit)', () => {
    const element = makeElement();
    const tb = trackball(null, element, { maxZoom: 1 });
    const seen: string[] = [];
    for (const type of ['start', 'change', 'end'] as const) tb.addEventListener(type, () => seen.push(type));
    wheel(element, 100);
    expect(seen).toEqual(['start', 'change', 'end']);
    seen.length = 0;
    wheel(element, -1000); // back up to the limit: a change
    wheel(element, -100); // already at maxZoom: no change
    expect(seen).toEqual(['start', 'change', 'end', 'start', 'end']);
  });

  it('cannot move a perspective camera that sits exactly at the target (and stays finite)', () => {
    const camera = new PerspectiveCamera();
    camera.position.set(1, 2, 3);
    const tb = trackball(null, makeElement(), { camera, target: new Vector3(1, 2, 3) });
    tb.zoomBy(2);
    tb.zoomBy(0.01);
    expect(camera.position.toArray()).toEqual([1, 2, 3]);
  });

  it("agrees with three's TrackballControls (r187), which zooms an orthographic camera out as well as in", () => {
    // three's wheel: zoom /= 1 + deltaY · 0.00025 · zoomSpeed (1.2) per pixel-mode step, applied in update().
    const threeZoom = (deltaY: number) => {
      const camera = new OrthographicCamera(-2, 2, 2, -2, 0.1, 10);
      const element = makeElement();
      const controls = new TrackballControls(camera, element);
      wheel(element, deltaY);
      controls.update();
      controls.dispose();
      return camera.zoom;
    };
    expect(threeZoom(100)).toBeCloseTo(1 / 1.03, 12); // out
    expect(threeZoom(-100)).toBeCloseTo(1 / 0.97, 12); // in
    const ours = (deltaY: number) => {
      const camera = new OrthographicCamera(-2, 2, 2, -2, 0.1, 10);
      const element = makeElement();
      trackball(null, element, { camera });
      wheel(element, deltaY);
      return camera.zoom;
    };
    expect(ours(100)).toBeCloseTo(Math.exp(-0.2), 12);
    expect(ours(-100)).toBeCloseTo(Math.exp(0.2), 12);
  });

  it('pinch-zooms with two touch pointers, then rotates from the remaining finger without a jump', () => {
    const element = makeElement();
    const camera = new PerspectiveCamera();
    camera.position.set(0, 0, 6);
    const tb = trackball(null, element, { camera, mapping: 'arcball' });
    const touch = (type: string, id: number, x: number, y: number) =>
      pointer(element, type, x, y, { pointerId: id, pointerType: 'touch' });
    touch('pointerdown', 1, CX - 20, CY);
    touch('pointerdown', 2, CX + 20, CY);
    touch('pointermove', 2, CX + 60, CY); // span 40 → 80
    expect(tb.zoom).toBeCloseTo(2, 12);
    expect(camera.position.z).toBeCloseTo(3, 12);
    expect(tb.rotation.w).toBe(1); // no rotation while pinching
    touch('pointerup', 2, CX + 60, CY);
    const held = tb.rotation.clone();
    touch('pointermove', 1, CX - 20, CY);
    expect(tb.rotation.equals(held)).toBe(true);
    touch('pointermove', 1, CX + 30, CY);
    expect(1 - tb.rotation.w).toBeGreaterThan(0.01);
    touch('pointerup', 1, CX + 30, CY);
    expect(tb.dragging).toBe(false);
  });
});

describe('Trackball: damping', () => {
  it('keeps spinning the same way after release, slowing down, and stops', () => {
    const element = makeElement();
    const mesh = new Mesh();
    const tb = trackball(mesh, element, { enableDamping: true, dampingFactor: 0.2 });
    drag(element, [
      [CX, CY],
      [CX + 5, CY],
      [CX + 10, CY],
    ]);
    const q0 = tb.rotation.clone();
    expect(tb.update()).toBe(true);
    const q1 = tb.rotation.clone();
    // Same direction as the drag (about +y), and the same angle as the last move's increment.
    expect(q1.y).toBeGreaterThan(q0.y);
    const lastMove = new Quaternion()
      .setFromAxisAngle(new Vector3(0, 1, 0), 2 * Math.asin(0.1))
      .angleTo(new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), 2 * Math.asin(0.05)));
    expect(q0.angleTo(q1)).toBeCloseTo(lastMove, 6);
    tb.update();
    expect(q1.angleTo(tb.rotation) / q0.angleTo(q1)).toBeCloseTo(0.8, 9);
    let frames = 0;
    while (tb.update() && frames < 10_000) frames++;
    expect(frames).toBeLessThan(10_000);
    expect(tb.update()).toBe(false);
    // The mesh follows the same rotation (no camera: camera frame = world).
    expectSameRotation(mesh.quaternion, tb.rotation);
  });

  it('stops the spin when pressed again, also after a press and release without a move', () => {
    const element = makeElement();
    const tb = trackball(null, element, { enableDamping: true });
    drag(element, [
      [CX, CY],
      [CX + 5, CY],
      [CX + 10, CY],
    ]);
    expect(tb.update()).toBe(true);
    pointer(element, 'pointerdown', CX + 30, CY + 30);
    expect(tb.update()).toBe(false); // held
    // Released at once (well within 100 ms of the fling's last move), without moving: no spin left.
    pointer(element, 'pointerup', CX + 30, CY + 30);
    const held = tb.rotation.clone();
    expect(tb.update()).toBe(false);
    expect(tb.rotation.equals(held)).toBe(true);
  });

  it('turns as far in one update(3/60) as in three update(1/60) calls', () => {
    const run = (steps: number[]) => {
      const element = makeElement();
      const tb = trackball(null, element, { enableDamping: true, dampingFactor: 0.3 });
      drag(element, [
        [CX, CY],
        [CX + 4, CY + 3],
        [CX + 9, CY + 5],
      ]);
      for (const s of steps) tb.update(s);
      return tb.rotation.clone();
    };
    expectSameRotation(run([3 / 60]), run([1 / 60, 1 / 60, 1 / 60]), 1e-14);
  });

  it('does not spin when released after holding still, or when damping is off', () => {
    const element = makeElement();
    const tb = trackball(null, element, { enableDamping: true });
    const now = vi.spyOn(performance, 'now');
    now.mockReturnValue(1000);
    pointer(element, 'pointerdown', CX, CY);
    pointer(element, 'pointermove', CX + 10, CY);
    now.mockReturnValue(1500);
    pointer(element, 'pointerup', CX + 10, CY);
    now.mockRestore();
    expect(tb.update()).toBe(false);
    tb.enableDamping = false;
    drag(element, [
      [CX, CY],
      [CX + 10, CY],
    ]);
    expect(tb.update()).toBe(false);
  });
});

describe('Trackball: lifecycle', () => {
  /** Record add/removeEventListener on a target; returns the listeners still attached. */
  function spyListeners(target: EventTarget): Set<string> {
    const live = new Set<string>();
    const ids = new WeakMap<object, number>();
    let next = 0;
    const key = (type: string, fn: unknown) => {
      const f = fn as object;
      if (!ids.has(f)) ids.set(f, next++);
      return `${type}#${ids.get(f)}`;
    };
    const add = target.addEventListener.bind(target);
    const remove = target.removeEventListener.bind(target);
    target.addEventListener = (type: string, fn: EventListenerOrEventListenerObject | null, o?: unknown) => {
      live.add(key(type, fn));
      add(type, fn, o as AddEventListenerOptions);
    };
    target.removeEventListener = (
      type: string,
      fn: EventListenerOrEventListenerObject | null,
      o?: unknown,
    ) => {
      live.delete(key(type, fn));
      remove(type, fn, o as EventListenerOptions);
    };
    return live;
  }

  it('leaves no listener on the element, the document or the window after dispose, even mid-drag', () => {
    const element = makeElement();
    const onElement = spyListeners(element);
    const onDocument = spyListeners(document);
    const onWindow = spyListeners(window);
    const tb = trackball(null, element);
    expect(onElement.size).toBeGreaterThan(0);
    pointer(element, 'pointerdown', CX, CY);
    expect(onDocument.size).toBeGreaterThan(0);
    const ends = vi.fn();
    tb.addEventListener('end', ends);
    tb.dispose();
    expect([...onElement, ...onDocument, ...onWindow]).toEqual([]);
    expect(ends).toHaveBeenCalledTimes(1);
    pointer(element, 'pointermove', CX + 50, CY);
    expect(tb.rotation.w).toBe(1);
  });

  it('connects later, and moves its listeners when connected to another element', () => {
    const a = makeElement();
    const b = makeElement();
    const onA = spyListeners(a);
    const tb = trackball(null, null);
    tb.connect(a);
    expect(onA.size).toBeGreaterThan(0);
    expect(a.style.touchAction).toBe('none');
    tb.connect(b);
    expect(onA.size).toBe(0);
    drag(b, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    expect(tb.rotation.w).toBeLessThan(1);
  });

  it('reset restores the rotation, the object and the zoom, and sends change', () => {
    const element = makeElement();
    const mesh = new Mesh();
    mesh.quaternion.setFromAxisAngle(new Vector3(0, 0, 1), 0.4);
    const home = mesh.quaternion.clone();
    const tb = trackball(mesh, element);
    drag(element, [
      [CX, CY],
      [CX + 40, CY + 70],
    ]);
    tb.zoomBy(3);
    const changes = vi.fn();
    tb.addEventListener('change', changes);
    tb.reset();
    expect(tb.rotation.toArray()).toEqual([0, 0, 0, 1]);
    expect(mesh.quaternion.equals(home)).toBe(true);
    expect(tb.zoom).toBe(1);
    expect(changes).toHaveBeenCalledTimes(1);
  });

  it('rotate(q) turns exactly as the same drag does (camera axes, parent, getWorldMatrix), stops a spin, sends change', () => {
    const camera = new PerspectiveCamera();
    camera.position.set(4, 3, 2);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    const parent = new Group();
    parent.quaternion.setFromAxisAngle(new Vector3(1, 1, 0).normalize(), 0.7);
    const setup = () => {
      const mesh = new Mesh();
      mesh.quaternion.setFromAxisAngle(new Vector3(0, 0, 1), 0.4);
      parent.clone().add(mesh).updateMatrixWorld(true);
      return mesh;
    };
    const byDrag = setup();
    const element = makeElement();
    const dragged = trackball(byDrag, element, { camera, mapping: 'arcball' });
    drag(element, [
      [CX, CY],
      [CX + 40, CY - 30],
    ]);
    const byCall = setup();
    const called = trackball(byCall, null, { camera, enableDamping: true });
    const changes = vi.fn();
    called.addEventListener('change', changes);
    const r = dragged.rotation;
    called.rotate(new Quaternion(-3 * r.x, -3 * r.y, -3 * r.z, -3 * r.w)); // any non-zero multiple: the same
    expectSameRotation(called.rotation, dragged.rotation);
    expectSameRotation(byCall.quaternion, byDrag.quaternion);
    expectMatrixClose(called.getWorldMatrix(), dragged.getWorldMatrix());
    expect(changes).toHaveBeenCalledTimes(1);
    expect(called.update()).toBe(false); // no spin from a call
    // Composition: a second call premultiplies, as a second drag would.
    const q = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), 0.3);
    called.rotate(q);
    expectSameRotation(called.rotation, q.clone().multiply(dragged.rotation));
  });

  it('setRotation(q) puts the trackball at q from the start orientation, keeps the zoom, and agrees with the lecture', () => {
    const camera = new PerspectiveCamera();
    camera.position.set(0, 0, 5);
    camera.updateMatrixWorld();
    const mesh = new Mesh();
    mesh.quaternion.setFromAxisAngle(new Vector3(0, 0, 1), 0.4);
    const home = mesh.quaternion.clone();
    const element = makeElement();
    const tb = trackball(mesh, element, { camera });
    drag(element, [
      [CX, CY],
      [CX + 40, CY + 70],
    ]);
    tb.zoomBy(2);
    camera.position.set(3, 1, 4);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    const q = new Quaternion().setFromAxisAngle(new Vector3(1, 2, 3).normalize(), 1.1);
    tb.setRotation(q);
    expectSameRotation(tb.rotation, q);
    expect(tb.zoom).toBeCloseTo(2, 12);
    // The object: home turned by C·q·C⁻¹ (C the camera's orientation now); the world matrix is the lecture's.
    const turn = camera.quaternion.clone().multiply(q).multiply(camera.quaternion.clone().invert());
    expectSameRotation(mesh.quaternion, turn.multiply(home));
    expectMatrixClose(tb.getWorldMatrix(), trackballWorldMatrix(tb, camera));
    // The identity is the start orientation, as reset() gives, without touching the zoom.
    tb.setRotation(new Quaternion());
    expect(mesh.quaternion.angleTo(home)).toBeLessThan(1e-12);
    expect(tb.zoom).toBeCloseTo(2, 12);
  });

  it('refuses a zero, NaN or infinite quaternion in rotate and setRotation, naming it, and changes nothing', () => {
    const tb = trackball(new Mesh(), null);
    for (const bad of [
      new Quaternion(0, 0, 0, 0),
      new Quaternion(Number.NaN, 0, 0, 1),
      new Quaternion(0, Infinity, 0, 1),
    ]) {
      expect(() => tb.rotate(bad)).toThrow(/rotation must be a finite, non-zero quaternion/);
      expect(() => tb.setRotation(bad)).toThrow(RangeError);
    }
    expect(tb.rotation.toArray()).toEqual([0, 0, 0, 1]);
    expect(tb.object.quaternion.toArray()).toEqual([0, 0, 0, 1]);
  });

  it('works without an object: object is a detached Object3D that receives the rotation', () => {
    const element = makeElement();
    const tb = trackball(null, element);
    expect(tb.object).toBeInstanceOf(Object3D);
    expect(tb.object.parent).toBeNull();
    drag(element, [
      [CX, CY],
      [CX + 40, CY - 30],
    ]);
    expectSameRotation(tb.object.quaternion, tb.rotation);
    expect(tb.target.toArray()).toEqual([0, 0, 0]);
  });

  it('takes the object position as the default target', () => {
    const mesh = new Mesh();
    mesh.position.set(1, 2, 3);
    expect(trackball(mesh, null).target.toArray()).toEqual([1, 2, 3]);
  });
});

describe('Trackball: option checks', () => {
  it.each<[TrackballOptions, RegExp]>([
    [{ rotateSpeed: -1 }, /rotateSpeed must be a number ≥ 0 and finite, got -1/],
    [{ rotateSpeed: Number.NaN }, /rotateSpeed .* got NaN/],
    [{ zoomSpeed: Number.POSITIVE_INFINITY }, /zoomSpeed .* got Infinity/],
    [{ minZoom: 0 }, /minZoom must be a number > 0 and finite, got 0/],
    [{ maxZoom: Number.POSITIVE_INFINITY }, /maxZoom .* got Infinity/],
    [{ minZoom: 3, maxZoom: 2 }, /minZoom \(3\) must be ≤ maxZoom \(2\)/],
    [{ dampingFactor: 0 }, /dampingFactor must be in \(0, 1\], got 0/],
    [{ dampingFactor: 1.5 }, /dampingFactor must be in \(0, 1\], got 1.5/],
    [{ radius: 0 }, /radius must be a number > 0 and finite, got 0/],
    [{ target: new Vector3(Number.NaN, 0, 0) }, /target must have finite x, y and z, got \(NaN,0,0\)/],
    [{ target: new Vector3(0, Number.POSITIVE_INFINITY, 0) }, /target .* got \(0,Infinity,0\)/],
    [{ target: new Vector3(1, 2, Number.NEGATIVE_INFINITY) }, /target .* got \(1,2,-Infinity\)/],
  ])('refuses %o with a RangeError naming it', (options, message) => {
    expect(() => new Trackball(null, null, options)).toThrow(RangeError);
    expect(() => new Trackball(null, null, options)).toThrow(message);
  });

  it('refuses an unknown mapping with a TypeError, and bad limits, factors and deltas later', () => {
    expect(() => new Trackball(null, null, { mapping: 'disc' as 'bell' })).toThrow(TypeError);
    const tb = new Trackball();
    expect(() => {
      tb.minZoom = 1000;
    }).toThrow('minZoom (1000) must be ≤ maxZoom (100)');
    expect(() => {
      tb.maxZoom = 0.001;
    }).toThrow('minZoom (0.01) must be ≤ maxZoom (0.001)');
    expect(() => tb.zoomBy(0)).toThrow(/factor must be a number > 0/);
    expect(() => tb.update(-1)).toThrow(/delta must be a number ≥ 0/);
  });

  it('accepts any finite target, even one whose components sum to infinity', () => {
    for (const v of [
      [1e308, 1e308, 0],
      [-Number.MAX_VALUE, Number.MAX_VALUE, Number.MIN_VALUE],
    ]) {
      const tb = new Trackball(null, null, { target: new Vector3(...v) });
      expect(tb.target.toArray()).toEqual(v);
      expect(tb.getWorldMatrix().equals(new Matrix4())).toBe(true);
    }
  });

  it('uses a smaller ball with radius < 1: the rim moves in', () => {
    const element = makeElement();
    const tb = trackball(null, element, { mapping: 'arcball', radius: 0.5 });
    drag(element, [
      [CX, CY],
      [CX + 50, CY],
    ]);
    expect(Math.abs(tb.rotation.y)).toBeCloseTo(1, 12); // 50 px is the rim now: 180°
  });
});
