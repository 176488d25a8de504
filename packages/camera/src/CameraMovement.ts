import { Controls, type Object3D, Vector3 } from 'three';
import { checkCoordinates } from './readVector3.js';
import { check, finite } from './validateProjection.js';

/** Events of {@link CameraMovement}: `change` after every move or turn, `start`/`end` around a pointer drag. */
export interface CameraMovementEventMap {
  /** The camera moved or turned. */
  change: object;
  /** A pointer drag began (primary button down on the element). */
  start: object;
  /** The pointer drag ended (button up or pointer cancelled). */
  end: object;
}

/** Options for `new CameraMovement(camera, element?, options)`. */
export interface CameraMovementOptions {
  /** Distance moved per key press (each `keydown`, auto-repeat included), world units, ≥ 0. @defaultValue 0.1 */
  moveSpeed?: number;
  /** Turn per pixel of pointer drag, radians per CSS pixel, ≥ 0. @defaultValue 0.005 */
  turnSpeed?: number;
}

/** What each key does: a unit step along the camera's own axes (`KeyboardEvent.code`, layout-independent). */
export const MOVEMENT_KEYS: Readonly<Record<string, readonly [axis: 'u' | 'v' | 'w', sign: 1 | -1]>> = {
  KeyW: ['w', -1],
  ArrowUp: ['w', -1],
  KeyS: ['w', 1],
  ArrowDown: ['w', 1],
  KeyA: ['u', -1],
  ArrowLeft: ['u', -1],
  KeyD: ['u', 1],
  ArrowRight: ['u', 1],
  KeyE: ['v', 1],
  PageUp: ['v', 1],
  KeyQ: ['v', -1],
  PageDown: ['v', -1],
};

const speed = (v: number) => v >= 0 && v < Number.POSITIVE_INFINITY;

const _next = /* @__PURE__ */ new Vector3();

/**
 * The lecture's `addEventHandlers()` as a three.js `Controls`: keys move the camera along its own axes and a
 * pointer drag turns its gaze. Works on a shadelab {@link Camera} or any three.js camera (it moves the object
 * in its local frame: −z is the gaze `−w`, x is `u`, y is `v`).
 *
 * | keys | move |
 * | --- | --- |
 * | W / ↑ | forward, along −w |
 * | S / ↓ | back, along +w |
 * | A / ← | left, along −u |
 * | D / → | right, along +u |
 * | E / PageUp | up, along +v |
 * | Q / PageDown | down, along −v |
 *
 * Each `keydown` moves {@link CameraMovement.moveSpeed} world units. Dragging with the primary button turns the
 * gaze with the pointer: right/left about `v` (yaw), down/up about `u` (pitch), {@link CameraMovement.turnSpeed}
 * radians per pixel; the frame stays orthonormal (rotations about the camera's own axes). Keyboard listeners
 * go on the connected element, which is made focusable (`tabIndex = 0` if it had none) and focused on
 * pointer down. Only {@link CameraMovement.connect}/{@link CameraMovement.disconnect} touch the DOM; after
 * {@link CameraMovement.dispose} no listener is left.
 */
export class CameraMovement extends Controls<CameraMovementEventMap, Object3D> {
  /**
   * Distance moved per key press, world units, finite and ≥ 0 (checked by the constructor; a key press with a
   * bad value assigned later moves nothing). @defaultValue 0.1
   */
  moveSpeed: number;
  /**
   * Turn per pixel dragged, radians per CSS pixel, finite and ≥ 0 (checked by the constructor; a drag with a bad
   * value assigned later turns nothing). @defaultValue 0.005
   */
  turnSpeed: number;

  private _drag = -1;
  private _x = 0;
  private _y = 0;
  private _tab: string | null = null;
  private _touch = '';

  /**
   * @param camera - The camera (or any Object3D) to move.
   * @param element - Element to listen on; connects right away when given.
   * @param options - Speeds.
   */
  constructor(camera: Object3D, element: HTMLElement | null = null, options?: CameraMovementOptions | null) {
    super(camera, null);
    const { moveSpeed = 0.1, turnSpeed = 0.005 } = options ?? {};
    check(moveSpeed, speed, 'moveSpeed', 'finite and ≥ 0');
    check(turnSpeed, speed, 'turnSpeed', 'finite and ≥ 0');
    this.moveSpeed = moveSpeed;
    this.turnSpeed = turnSpeed;
    if (element !== null) this.connect(element);
  }

  /** Listen for keys and pointer drags on `element` (disconnecting from a previous one first). */
  override connect(element: HTMLElement | SVGElement): void {
    super.connect(element);
    const el = element as HTMLElement;
    this._tab = el.getAttribute('tabindex');
    if (this._tab === null) el.tabIndex = 0;
    this._touch = el.style.touchAction;
    el.style.touchAction = 'none';
    for (const [type, listener] of this._on) el.addEventListener(type, listener as EventListener);
  }

  /**
   * Remove every listener and restore the element's `tabindex` and `touch-action`. A drag in progress ends
   * (pointer capture released, `end` dispatched).
   */
  override disconnect(): void {
    const el = this.domElement as HTMLElement | null;
    if (el === null) return;
    if (this._drag !== -1) this._end({ pointerId: this._drag } as PointerEvent);
    for (const [type, listener] of this._on) el.removeEventListener(type, listener as EventListener);
    if (this._tab === null) el.removeAttribute('tabindex');
    el.style.touchAction = this._touch;
    this.domElement = null;
  }

  /** Disconnect; the controls can be connected again afterwards. */
  override dispose(): void {
    this.disconnect();
  }

  /**
   * Move along the camera's axes by a step in each (world units): `+w` is backwards, `−w` forwards.
   * Dispatches `change` when anything moved.
   * @throws RangeError naming du, dv, dw when one is not a finite number, or when the move would take
   * a coordinate beyond ±1e30 world units, where float32 view matrices overflow (the object then stays put).
   */
  move(du: number, dv: number, dw: number): void {
    for (const d of [du, dv, dw]) check(d, finite, 'du, dv, dw', 'finite');
    if (du === 0 && dv === 0 && dw === 0) return;
    // Along the object's own axes (as translateX/Y/Z), checked before anything moves.
    const object = this.object;
    object.position.copy(
      checkCoordinates(
        _next.set(du, dv, dw).applyQuaternion(object.quaternion).add(object.position),
        'du, dv, dw',
      ),
    );
    object.updateMatrixWorld();
    this.dispatchEvent({ type: 'change' });
  }

  /**
   * Turn the gaze: `yaw` radians about `v` (positive turns left), then `pitch` radians about `u` (positive turns up).
   * Dispatches `change` when anything turned.
   * @throws RangeError naming yaw, pitch when one is not a finite number.
   */
  turn(yaw: number, pitch: number): void {
    for (const a of [yaw, pitch]) check(a, finite, 'yaw, pitch', 'finite');
    if (yaw === 0 && pitch === 0) return;
    const object = this.object;
    object.rotateY(yaw);
    object.rotateX(pitch);
    object.quaternion.normalize();
    object.updateMatrixWorld();
    this.dispatchEvent({ type: 'change' });
  }

  private readonly _key = (event: KeyboardEvent): void => {
    if (!this.enabled || event.ctrlKey || event.metaKey || event.altKey) return;
    const step = MOVEMENT_KEYS[event.code];
    if (step === undefined) return;
    event.preventDefault();
    try {
      check(this.moveSpeed, speed, 'moveSpeed', 'finite and ≥ 0');
      const d = step[1] * this.moveSpeed;
      this.move(step[0] === 'u' ? d : 0, step[0] === 'v' ? d : 0, step[0] === 'w' ? d : 0);
    } catch {
      // A bad moveSpeed, or ±1e30 world units reached: the camera stays where it is.
    }
  };

  private readonly _down = (event: PointerEvent): void => {
    if (!this.enabled || event.button !== 0 || this._drag !== -1) return;
    const el = this.domElement as HTMLElement;
    el.focus?.();
    el.setPointerCapture?.(event.pointerId);
    this._drag = event.pointerId;
    this._x = event.clientX;
    this._y = event.clientY;
    this.dispatchEvent({ type: 'start' });
  };

  private readonly _move = (event: PointerEvent): void => {
    if (event.pointerId !== this._drag) return;
    const dx = event.clientX - this._x;
    const dy = event.clientY - this._y;
    this._x = event.clientX;
    this._y = event.clientY;
    try {
      check(this.turnSpeed, speed, 'turnSpeed', 'finite and ≥ 0');
      if (this.enabled) this.turn(-dx * this.turnSpeed, -dy * this.turnSpeed);
    } catch {
      // A bad or huge turnSpeed (the angle overflowed): this move turns nothing.
    }
  };

  private readonly _end = (event: PointerEvent): void => {
    if (event.pointerId !== this._drag) return;
    this._drag = -1;
    const el = this.domElement as HTMLElement;
    if (el.hasPointerCapture?.(event.pointerId)) el.releasePointerCapture(event.pointerId);
    this.dispatchEvent({ type: 'end' });
  };

  /** Every DOM listener, added by `connect` and removed by `disconnect`. */
  private readonly _on = [
    ['keydown', this._key],
    ['pointerdown', this._down],
    ['pointermove', this._move],
    ['pointerup', this._end],
    ['pointercancel', this._end],
  ] as const;
}
