// @vitest-environment happy-dom
import { Camera, CameraMovement, MOVEMENT_KEYS } from '@shadelab/camera';
import fc from 'fast-check';
import { PerspectiveCamera, Vector3 } from 'three';
import { afterEach, describe, expect, it } from 'vitest';

/** An element whose add/removeEventListener calls are counted (live listeners by type). */
function countedElement(): { el: HTMLDivElement; live: Map<string, number> } {
  const el = document.createElement('div');
  document.body.appendChild(el);
  const live = new Map<string, number>();
  const add = el.addEventListener.bind(el);
  const remove = el.removeEventListener.bind(el);
  el.addEventListener = ((type: string, fn: EventListener, opts?: boolean | AddEventListenerOptions) => {
    live.set(type, (live.get(type) ?? 0) + 1);
    add(type, fn, opts);
  }) as typeof el.addEventListener;
  el.removeEventListener = ((type: string, fn: EventListener, opts?: boolean | EventListenerOptions) => {
    live.set(type, (live.get(type) ?? 0) - 1);
    remove(type, fn, opts);
  }) as typeof el.removeEventListener;
  return { el, live };
}

const total = (live: Map<string, number>) => [...live.values()].reduce((a, b) => a + b, 0);

const key = (el: Element, code: string, init: KeyboardEventInit = {}) =>
  el.dispatchEvent(new KeyboardEvent('keydown', { code, bubbles: true, cancelable: true, ...init }));

const pointer = (el: Element, type: string, x: number, y: number, init: PointerEventInit = {}) =>
  el.dispatchEvent(
    new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, button: 0, bubbles: true, ...init }),
  );

afterEach(() => {
  document.body.innerHTML = '';
});

describe('CameraMovement keyboard', () => {
  it.each(Object.entries(MOVEMENT_KEYS))(
    '%s moves moveSpeed along its axis of the frame',
    (code, [axis, sign]) => {
      const camera = new Camera().lookAt([1, 2, 3], [-2, 0, 1], [0, 1, 0]);
      const before = camera.getFrame();
      const { el } = countedElement();
      const movement = new CameraMovement(camera, el, { moveSpeed: 0.5 });
      key(el, code);
      const after = camera.getFrame();
      const expected = before.e.clone().addScaledVector(before[axis], 0.5 * sign);
      expect(after.e.distanceTo(expected)).toBeLessThan(1e-12);
      expect(after.w.distanceTo(before.w)).toBeLessThan(1e-12); // moving never turns
      movement.dispose();
    },
  );

  it("W moves towards the gaze (−w), dispatches 'change', and other keys do nothing", () => {
    const camera = new Camera().lookAt([0, 0, 5], [0, 0, 0], [0, 1, 0]);
    const { el } = countedElement();
    const movement = new CameraMovement(camera, el);
    let changes = 0;
    movement.addEventListener('change', () => changes++);
    key(el, 'KeyW');
    expect(camera.position.z).toBeCloseTo(4.9, 12);
    key(el, 'KeyX');
    key(el, 'KeyW', { ctrlKey: true }); // browser shortcuts are left alone
    expect(camera.position.z).toBeCloseTo(4.9, 12);
    expect(changes).toBe(1);
    movement.enabled = false;
    key(el, 'KeyW');
    expect(camera.position.z).toBeCloseTo(4.9, 12);
    movement.dispose();
  });

  it('works on a plain three.js PerspectiveCamera too', () => {
    const camera = new PerspectiveCamera();
    const { el } = countedElement();
    const movement = new CameraMovement(camera, el, { moveSpeed: 2 });
    key(el, 'KeyD');
    expect(camera.position.toArray()).toEqual([2, 0, 0]);
    movement.dispose();
  });
});

describe('CameraMovement pointer drag', () => {
  it('turns the gaze with the pointer: right → about v towards +u, down → about u towards −v', () => {
    const camera = new Camera().lookAt([0, 0, 0], [0, 0, -1], [0, 1, 0]);
    const { el } = countedElement();
    const movement = new CameraMovement(camera, el, { turnSpeed: 0.01 });
    const events: string[] = [];
    for (const type of ['start', 'change', 'end'] as const)
      movement.addEventListener(type, () => events.push(type));
    pointer(el, 'pointerdown', 100, 100);
    pointer(el, 'pointermove', 110, 100); // 10 px right → 0.1 rad
    const gaze = camera.getFrame().w.negate();
    expect(gaze.x).toBeCloseTo(Math.sin(0.1), 12);
    expect(gaze.z).toBeCloseTo(-Math.cos(0.1), 12);
    pointer(el, 'pointermove', 110, 120); // 20 px down → 0.2 rad about u
    const frame = camera.getFrame();
    expect(frame.w.negate().y).toBeCloseTo(-Math.sin(0.2), 12);
    expect(frame.e.toArray()).toEqual([0, 0, 0]); // turning never moves the eye
    pointer(el, 'pointerup', 110, 120);
    pointer(el, 'pointermove', 300, 300); // not dragging any more
    expect(camera.getFrame().w.distanceTo(frame.w.negate())).toBeLessThan(1e-12);
    expect(events).toEqual(['start', 'change', 'change', 'end']);
    movement.dispose();
  });

  it('zero-length drags and non-primary buttons change nothing', () => {
    const camera = new Camera().lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
    const { el } = countedElement();
    const movement = new CameraMovement(camera, el);
    let changes = 0;
    movement.addEventListener('change', () => changes++);
    pointer(el, 'pointerdown', 5, 5, { button: 2 });
    pointer(el, 'pointermove', 50, 50);
    pointer(el, 'pointerdown', 5, 5);
    pointer(el, 'pointermove', 5, 5);
    pointer(el, 'pointerup', 5, 5);
    expect(changes).toBe(0);
    movement.dispose();
  });

  it('any sequence of drags keeps the frame orthonormal (property)', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: -500, max: 500 }), fc.integer({ min: -500, max: 500 })), {
          maxLength: 60,
        }),
        (moves) => {
          const camera = new Camera();
          const { el } = countedElement();
          const movement = new CameraMovement(camera, el, { turnSpeed: 0.013 });
          let x = 0;
          let y = 0;
          pointer(el, 'pointerdown', x, y);
          for (const [dx, dy] of moves) {
            x += dx;
            y += dy;
            pointer(el, 'pointermove', x, y);
          }
          pointer(el, 'pointerup', x, y);
          const { u, v, w } = camera.getFrame();
          expect(Math.abs(u.dot(v)) + Math.abs(u.dot(w)) + Math.abs(v.dot(w))).toBeLessThan(1e-9);
          expect(new Vector3().crossVectors(u, v).distanceTo(w)).toBeLessThan(1e-9);
          movement.dispose();
          el.remove();
        },
      ),
      { numRuns: 50 },
    );
  });
});

describe('CameraMovement DOM hygiene', () => {
  it('connect adds listeners, dispose removes every one, and restores tabindex and touch-action', () => {
    const { el, live } = countedElement();
    el.style.touchAction = 'pan-y';
    const movement = new CameraMovement(new Camera(), el);
    expect(total(live)).toBeGreaterThan(0);
    expect(el.tabIndex).toBe(0);
    expect(el.style.touchAction).toBe('none');
    movement.dispose();
    expect(total(live)).toBe(0);
    for (const n of live.values()) expect(n).toBe(0);
    expect(el.hasAttribute('tabindex')).toBe(false);
    expect(el.style.touchAction).toBe('pan-y');
    movement.dispose(); // twice is harmless
    expect(total(live)).toBe(0);
  });

  it('after dispose, keys and drags do nothing; reconnecting moves to the new element', () => {
    const camera = new Camera();
    const a = countedElement();
    const b = countedElement();
    const movement = new CameraMovement(camera);
    expect(total(a.live)).toBe(0); // nothing touched the DOM before connect
    movement.connect(a.el);
    movement.connect(b.el);
    expect(total(a.live)).toBe(0);
    movement.dispose();
    key(a.el, 'KeyW');
    key(b.el, 'KeyW');
    pointer(b.el, 'pointerdown', 0, 0);
    pointer(b.el, 'pointermove', 40, 0);
    expect(camera.position.toArray()).toEqual([0, 0, 0]);
    expect(camera.quaternion.toArray()).toEqual([0, 0, 0, 1]);
    expect(total(b.live)).toBe(0);
  });

  it("disconnect() during a drag releases the pointer capture and dispatches 'end'; later moves turn nothing", () => {
    const camera = new Camera().lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
    const { el, live } = countedElement();
    const captured = new Set<number>();
    el.setPointerCapture = (id: number) => void captured.add(id);
    el.releasePointerCapture = (id: number) => void captured.delete(id);
    el.hasPointerCapture = (id: number) => captured.has(id);
    const movement = new CameraMovement(camera, el);
    const events: string[] = [];
    for (const type of ['start', 'change', 'end'] as const)
      movement.addEventListener(type, () => events.push(type));
    pointer(el, 'pointerdown', 10, 10, { pointerId: 7 });
    pointer(el, 'pointermove', 20, 10, { pointerId: 7 });
    expect(captured.has(7)).toBe(true);
    movement.disconnect();
    expect(captured.size).toBe(0);
    expect(events).toEqual(['start', 'change', 'end']);
    expect(total(live)).toBe(0);
    const turned = camera.quaternion.clone();
    pointer(el, 'pointermove', 80, 40, { pointerId: 7 });
    pointer(el, 'pointerup', 80, 40, { pointerId: 7 });
    expect(camera.quaternion.equals(turned)).toBe(true);
    expect(events).toEqual(['start', 'change', 'end']); // no second 'end'
    // Reconnected, a new drag works again (the drag state was cleared), and disconnecting idle sends no 'end'.
    movement.connect(el);
    pointer(el, 'pointerdown', 0, 0, { pointerId: 8 });
    pointer(el, 'pointerup', 0, 0, { pointerId: 8 });
    movement.dispose();
    expect(events).toEqual(['start', 'change', 'end', 'start', 'end']);
  });

  it('a bad speed assigned after construction moves and turns nothing (negative, NaN, infinite)', () => {
    for (const bad of [-0.5, Number.NaN, Number.POSITIVE_INFINITY]) {
      const camera = new Camera().lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
      const { el } = countedElement();
      const movement = new CameraMovement(camera, el);
      movement.moveSpeed = bad;
      movement.turnSpeed = bad;
      const before = camera.matrixWorld.clone();
      key(el, 'KeyW');
      pointer(el, 'pointerdown', 0, 0);
      pointer(el, 'pointermove', 30, 10);
      pointer(el, 'pointerup', 30, 10);
      expect(camera.matrixWorld.equals(before)).toBe(true);
      movement.dispose();
    }
  });

  it('null options are the defaults, like no options', () => {
    const movement = new CameraMovement(new Camera(), null, null);
    expect([movement.moveSpeed, movement.turnSpeed]).toEqual([0.1, 0.005]);
  });

  it('keeps an existing tabindex and refuses negative or NaN speeds', () => {
    const { el } = countedElement();
    el.setAttribute('tabindex', '3');
    const movement = new CameraMovement(new Camera(), el);
    movement.dispose();
    expect(el.getAttribute('tabindex')).toBe('3');
    expect(() => new CameraMovement(new Camera(), null, { moveSpeed: -1 })).toThrow(/^moveSpeed must be/);
    expect(() => new CameraMovement(new Camera(), null, { turnSpeed: Number.NaN })).toThrow(RangeError);
  });

  it('a camera moved by the handlers then aimed at the pole starts its pole anchor from where it is', () => {
    const camera = new Camera().lookAt([0, 0, 5], [0, 0, 0], [0, 1, 0]);
    const { el } = countedElement();
    const movement = new CameraMovement(camera, el);
    movement.turn(0.7, 0);
    const u = camera.getFrame().u.clone();
    camera.lookAt([0, 5, 0], [0, 0, 0], [0, 1, 0]); // up exactly along the gaze: anchor = current u, projected
    const frame = camera.getFrame();
    const expected = u.clone().setY(0).normalize();
    expect(frame.u.distanceTo(expected)).toBeLessThan(1e-12);
    movement.dispose();
  });
});
