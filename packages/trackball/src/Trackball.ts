import { type Camera, Controls, type ControlsEventMap, Matrix4, Object3D, Quaternion, Vector3 } from 'three';
import { arcRotation } from './arcRotation.js';
import { projectToBall } from './projectToBall.js';
import { trackballWorldMatrix } from './trackballWorldMatrix.js';
import type { BallMapping, Quat, Vec3 } from './types.js';

/** Events a {@link Trackball} dispatches. */
export interface TrackballEventMap extends ControlsEventMap {
  /** The rotation or the zoom changed (fired on every pointer move, wheel step and damped update). */
  change: object;
  /** A drag, pinch or wheel step began. */
  start: object;
  /** A drag, pinch or wheel step ended. */
  end: object;
}

/**
 * Any camera the trackball can zoom: three's PerspectiveCamera and OrthographicCamera, and any
 * `THREE.Camera` (such as `@shadelab/camera`'s) that says which it is through these flags.
 */
export type TrackballCamera = Camera & {
  /** True for a perspective camera: zoom moves it toward or away from the target. */
  readonly isPerspectiveCamera?: boolean;
  /** True for an orthographic camera: zoom scales its view (its `zoom`, or its projection). */
  readonly isOrthographicCamera?: boolean;
  /** three's zoom factor, used for orthographic cameras when present. */
  zoom?: number;
  /** three's projection refresh, called after `zoom` changes. */
  updateProjectionMatrix?: () => void;
};

/** Options of {@link Trackball}; every one is also a property of the same name. */
export interface TrackballOptions {
  /** The camera whose frame the rotation axes are fixed in, and which wheel/pinch zooms. @defaultValue null */
  camera?: TrackballCamera | null;
  /** How the pointer is lifted onto the ball. @defaultValue 'bell' */
  mapping?: BallMapping;
  /** Multiplies the rotation angle (1 = Shoemake: twice the arc on the ball). ≥ 0. @defaultValue 1 */
  rotateSpeed?: number;
  /** Exponent on each zoom step (0 disables zoom). ≥ 0. @defaultValue 1 */
  zoomSpeed?: number;
  /** Smallest accumulated zoom factor (zoomed out). > 0. @defaultValue 0.01 */
  minZoom?: number;
  /** Largest accumulated zoom factor (zoomed in). ≥ minZoom, finite. @defaultValue 100 */
  maxZoom?: number;
  /** Keep spinning after release, slowing down, while {@link Trackball.update} is called. @defaultValue false */
  enableDamping?: boolean;
  /** Fraction of the spin lost per 1/60 s when damping. In (0, 1]. @defaultValue 0.05 */
  dampingFactor?: number;
  /** Ball radius as a fraction of half the element's shorter side. > 0, finite. @defaultValue 1 */
  radius?: number;
  /** Pivot in world coordinates; x, y and z finite. @defaultValue the object's world position, or the origin */
  target?: Vector3;
}

const _changeEvent = { type: 'change' } as const;
const _startEvent = { type: 'start' } as const;
const _endEvent = { type: 'end' } as const;

/** A pointer release later than this after the last move leaves no spin (milliseconds). */
const SPIN_STALE_MS = 100;
/** Spins slower than this (radians per 1/60 s) stop. */
const SPIN_MIN = 1e-6;
/** Wheel `deltaY` per zoom e-fold, in pixels. */
const WHEEL_PIXELS_PER_EFOLD = 500;
/** Pixels per wheel `deltaY` unit, by `deltaMode`: pixel, line, page. */
const WHEEL_MODE_PIXELS = [1, 16, 800];

const _delta = /* @__PURE__ */ new Quaternion();
const _turn = /* @__PURE__ */ new Quaternion();
const _frame = /* @__PURE__ */ new Quaternion();
const _parent = /* @__PURE__ */ new Quaternion();
const _eye = /* @__PURE__ */ new Vector3();
const _parentInverse = /* @__PURE__ */ new Quaternion();
const _identity = /* @__PURE__ */ new Quaternion();
const _ball: Vec3 = [0, 0, 0];
const _arc: Quat = [0, 0, 0, 1];

function positive(name: string, value: number, allowZero: boolean): number {
  if (
    !(typeof value === 'number' && (allowZero ? value >= 0 : value > 0) && value < Number.POSITIVE_INFINITY)
  ) {
    throw new RangeError(
      `Trackball: ${name} must be a number ${allowZero ? '≥' : '>'} 0 and finite, got ${String(value)}`,
    );
  }
  return value;
}

/**
 * A virtual trackball as three.js {@link Controls}: dragging rotates about axes fixed in the camera's frame,
 * the wheel and a two-finger pinch zoom.
 *
 * - `object` is the object being rotated (a mesh or group): it turns about its own origin, and keeps
 *   whatever orientation it had before. Without one, `object` is a detached `Object3D` that turns the same
 *   way (put meshes under it, or ignore it and use {@link Trackball.getWorldMatrix}).
 * - `camera` gives the frame: a drag to the right turns the object about the camera's up axis as the camera
 *   is during that drag. Turning the camera later does not turn the object (it stays where the user left
 *   it). Without a camera the frame is the world (x right, y up, z toward the viewer).
 * - The rotation of one drag depends only on where the drag started and where the pointer is now
 *   (`rotation = q(start → now) · rotationAtStart`), so a closed drag restores the start orientation exactly.
 * - Zoom is one factor, {@link Trackball.zoom}, clamped to [{@link Trackball.minZoom},
 *   {@link Trackball.maxZoom}] and applied to the camera relative to how it was when the trackball was made:
 *   a perspective camera moves along the line to {@link Trackball.target} (distance = initial / zoom); an
 *   orthographic one multiplies its `zoom` (or, without one, scales its projection's x and y). Without a
 *   camera only {@link Trackball.zoom} changes: {@link Trackball.getMatrix} stays a pure rotation.
 *
 * Only {@link Trackball.connect} and {@link Trackball.disconnect} touch the DOM.
 */
export class Trackball extends Controls<TrackballEventMap, Object3D> {
  /** The camera whose frame the axes are fixed in, and which zoom moves; null for none. */
  camera: TrackballCamera | null;
  /** Pivot in world coordinates: what a perspective zoom approaches and {@link Trackball.getWorldMatrix} turns about. */
  readonly target: Vector3;
  /** Keep spinning after release while {@link Trackball.update} is called. @defaultValue false */
  enableDamping: boolean;

  private _mapping: BallMapping = 'bell';
  private _rotateSpeed = 1;
  private _zoomSpeed = 1;
  private _minZoom = 0.01;
  private _maxZoom = 100;
  private _dampingFactor = 0.05;
  private _radius = 1;

  private readonly _rotation = new Quaternion();
  private readonly _rotationAtStart = new Quaternion();
  private readonly _objectAtStart = new Quaternion();
  private readonly _objectHome = new Quaternion();
  private readonly _world = new Quaternion();
  private readonly _worldAtStart = new Quaternion();
  private readonly _ballStart: Vec3 = [0, 0, 1];
  private _hasBallStart = false;
  private _zoom = 1;

  private readonly _pointers = new Map<number, { x: number; y: number }>();
  private _pinchDistance = 0;
  private _listening: Document | null = null;

  private readonly _spin = new Quaternion();
  private readonly _spinAxis = new Vector3(0, 0, 1);
  private _spinAngle = 0;
  private _lastMove = Number.NEGATIVE_INFINITY;

  /**
   * @param object - The object to rotate, or null for a detached placeholder. @defaultValue null
   * @param domElement - The element to listen on (connected at once), or null to call `connect` later.
   *   @defaultValue null
   * @param options - See {@link TrackballOptions}.
   */
  constructor(
    object: Object3D | null = null,
    domElement: HTMLElement | SVGElement | null = null,
    {
      camera = null,
      mapping = 'bell',
      rotateSpeed = 1,
      zoomSpeed = 1,
      minZoom = 0.01,
      maxZoom = 100,
      enableDamping = false,
      dampingFactor = 0.05,
      radius = 1,
      target,
    }: TrackballOptions = {},
  ) {
    super(object ?? new Object3D(), domElement);
    this.camera = camera;
    this.mapping = mapping;
    this.rotateSpeed = rotateSpeed;
    this.zoomSpeed = zoomSpeed;
    this._setLimits(minZoom, maxZoom);
    this.enableDamping = enableDamping;
    this.dampingFactor = dampingFactor;
    this.radius = radius;
    this.target = target ? target.clone() : object ? object.getWorldPosition(new Vector3()) : new Vector3();
    if (!this.target.toArray().every(Number.isFinite)) {
      throw new RangeError(`Trackball: target must have finite x, y and z, got (${this.target.toArray()})`);
    }
    this._objectHome.copy(this.object.quaternion);
    if (domElement !== null) this.connect(domElement);
  }

  /** How the pointer is lifted onto the ball: `'bell'` (smooth at the rim) or `'arcball'`. @defaultValue 'bell' */
  get mapping(): BallMapping {
    return this._mapping;
  }
  set mapping(value: BallMapping) {
    if (value !== 'arcball' && value !== 'bell') {
      throw new TypeError(`Trackball: mapping must be 'arcball' or 'bell', got ${String(value)}`);
    }
    this._mapping = value;
  }

  /** Multiplies the rotation angle; 1 turns the object by twice the arc swept on the ball. ≥ 0, finite. @defaultValue 1 */
  get rotateSpeed(): number {
    return this._rotateSpeed;
  }
  set rotateSpeed(value: number) {
    this._rotateSpeed = positive('rotateSpeed', value, true);
  }

  /**
   * Zoom sensitivity: each wheel step or pinch multiplies {@link Trackball.zoom} by `step ^ zoomSpeed`
   * (a pinch's step is the ratio of finger distances; a wheel step is `exp(−deltaY / 500 px)`).
   * 0 disables zoom. ≥ 0, finite. @defaultValue 1
   */
  get zoomSpeed(): number {
    return this._zoomSpeed;
  }
  set zoomSpeed(value: number) {
    this._zoomSpeed = positive('zoomSpeed', value, true);
  }

  /** Smallest zoom factor (furthest out). > 0 and ≤ {@link Trackball.maxZoom}. @defaultValue 0.01 */
  get minZoom(): number {
    return this._minZoom;
  }
  set minZoom(value: number) {
    this._setLimits(value, this._maxZoom);
  }

  /** Largest zoom factor (furthest in). Finite and ≥ {@link Trackball.minZoom}. @defaultValue 100 */
  get maxZoom(): number {
    return this._maxZoom;
  }
  set maxZoom(value: number) {
    this._setLimits(this._minZoom, value);
  }

  /** Fraction of the spin lost per 1/60 s after release when damping. In (0, 1]. @defaultValue 0.05 */
  get dampingFactor(): number {
    return this._dampingFactor;
  }
  set dampingFactor(value: number) {
    if (!(typeof value === 'number' && value > 0 && value <= 1)) {
      throw new RangeError(`Trackball: dampingFactor must be in (0, 1], got ${String(value)}`);
    }
    this._dampingFactor = value;
  }

  /** Ball radius as a fraction of half the element's shorter side; the ball is centred on the element. @defaultValue 1 */
  get radius(): number {
    return this._radius;
  }
  set radius(value: number) {
    this._radius = positive('radius', value, false);
  }

  /**
   * The accumulated zoom factor (1 = as the camera was when the trackball was made). Without a camera this
   * is all that zoom changes: scale your view by it (the rotation matrices stay pure rotations).
   * @defaultValue 1
   */
  get zoom(): number {
    return this._zoom;
  }

  /**
   * The trackball rotation in camera coordinates, a unit quaternion. Read-only: change it with
   * {@link Trackball.rotate}, {@link Trackball.setRotation} or {@link Trackball.reset}.
   */
  get rotation(): Quaternion {
    return this._rotation;
  }

  /** True while a pointer is down on the element. */
  get dragging(): boolean {
    return this._pointers.size > 0;
  }

  /**
   * The trackball matrix, as the lecture's `getMatrix()`: the accumulated rotation in camera coordinates
   * (a pure rotation, with or without a camera: zoom is applied to the camera, or only kept in
   * {@link Trackball.zoom}).
   *
   * @param out - Where to write it. @defaultValue a new Matrix4
   */
  getMatrix(out: Matrix4 = new Matrix4()): Matrix4 {
    return out.makeRotationFromQuaternion(this._rotation);
  }

  /**
   * The rotation the object received, as a world transform about {@link Trackball.target}:
   * `T(target) · W · T(−target)`, W the product of every drag's `C · R_drag · C⁻¹` with C the camera's world
   * orientation during that drag. Use it when there is no object to rotate (for example as a shader uniform).
   *
   * While the camera has not turned since the first drag this is the lecture's
   * `trackballWorldMatrix(trackball, camera)` = `T(target) · C · R · C⁻¹ · T(−target)`. After it turns they
   * differ: the lecture's formula turns every past drag about the new camera's axes (the object would turn in
   * the world when only the camera moved); this keeps each drag about the axes the user saw while dragging.
   *
   * @param out - Where to write it. @defaultValue a new Matrix4
   */
  getWorldMatrix(out: Matrix4 = new Matrix4()): Matrix4 {
    return trackballWorldMatrix({ rotation: this._world, target: this.target }, null, out);
  }

  /** Listen for pointer and wheel input on `element` (disconnecting from any previous element first). */
  override connect(element: HTMLElement | SVGElement): void {
    super.connect(element);
    element.addEventListener('pointerdown', this._onPointerDown as EventListener);
    element.addEventListener('wheel', this._onWheel as EventListener, { passive: false });
    element.style.touchAction = 'none';
  }

  /** Remove every listener this trackball added; a drag in progress ends (an `end` event is sent). */
  override disconnect(): void {
    const element = this.domElement;
    if (element) {
      element.removeEventListener('pointerdown', this._onPointerDown as EventListener);
      element.removeEventListener('wheel', this._onWheel as EventListener);
      element.style.touchAction = '';
    }
    const wasDragging = this._pointers.size > 0;
    for (const id of this._pointers.keys()) this._release(id);
    this._pointers.clear();
    this._unlistenDocument();
    if (wasDragging) this.dispatchEvent(_endEvent);
  }

  /** Disconnect and stop any spin. The trackball can be connected again afterwards. */
  override dispose(): void {
    this.disconnect();
    this._spinAngle = 0;
  }

  /**
   * Back to the start: identity rotation, the object's original orientation, zoom 1 (clamped to the
   * limits; the camera moved or rescaled back), no spin. Sends `change`.
   */
  reset(): void {
    this._rotation.identity();
    this._world.identity();
    this.object.quaternion.copy(this._objectHome);
    this._spinAngle = 0;
    this._hasBallStart = false;
    this._setZoom(1);
    this.dispatchEvent(_changeEvent);
  }

  /**
   * Turn as a drag would: by `q`, a rotation in camera coordinates (`rotation = q · rotation`), the object
   * about the camera's current axes. For keyboard turns and scripted motion. Stops any spin; sends `change`.
   *
   * @param q - A finite, non-zero quaternion (normalised here).
   */
  rotate(q: Quaternion): void {
    this._turnBy(q, this._rotation, this.object.quaternion, this._world);
  }

  /**
   * Set the rotation to `q` (camera coordinates, as {@link Trackball.rotation} reads it; for example a saved
   * view): the object is put at its original orientation turned by `q` about the camera's current axes, and
   * {@link Trackball.getWorldMatrix} becomes the lecture's `trackballWorldMatrix`. Zoom is kept. Stops any
   * spin; sends `change`.
   *
   * @param q - A finite, non-zero quaternion (normalised here).
   */
  setRotation(q: Quaternion): void {
    this._turnBy(q, _identity, this._objectHome, _identity);
  }

  private _turnBy(q: Quaternion, rotation: Quaternion, object: Quaternion, world: Quaternion): void {
    const n = q.length();
    if (!(n > 0 && n < Infinity)) {
      throw new RangeError(`Trackball: rotation must be a finite, non-zero quaternion, got (${q.toArray()})`);
    }
    _delta.copy(q).normalize();
    this._spinAngle = 0;
    this._rotation.multiplyQuaternions(_delta, rotation).normalize();
    this._rotateObject(_delta, object, world);
    this.dispatchEvent(_changeEvent);
  }

  /**
   * Advance the damped spin (call once per frame when {@link Trackball.enableDamping} is on). After a
   * release the last pointer move's rotation repeats once per 1/60 s, losing
   * {@link Trackball.dampingFactor} of its angle each time, until it is below 1e-6 rad. A longer `delta`
   * turns by the sum of the frames it covers.
   *
   * @param delta - Seconds since the last call. ≥ 0, finite. @defaultValue 1/60
   * @returns Whether anything moved (a `change` was sent).
   */
  override update(delta = 1 / 60): boolean {
    positive('delta', delta, true);
    if (!this.enableDamping || this._pointers.size > 0 || this._spinAngle <= SPIN_MIN) return false;
    const frames = delta * 60;
    const keep = 1 - this._dampingFactor;
    // The sum of the per-frame angles over `frames` frames (a geometric series), so one update(k/60) turns
    // as far as k updates of 1/60 s.
    const angle =
      this._spinAngle * (keep === 0 ? Math.min(frames, 1) : (1 - keep ** frames) / this._dampingFactor);
    _delta.setFromAxisAngle(this._spinAxis, angle);
    this._rotation.premultiply(_delta).normalize();
    this._rotateObject(_delta, this.object.quaternion, this._world);
    this._spinAngle *= keep ** frames;
    if (this._spinAngle <= SPIN_MIN) this._spinAngle = 0;
    this.dispatchEvent(_changeEvent);
    return true;
  }

  /**
   * Multiply the zoom by `factor` (clamped to the limits) and apply it to the camera, as a wheel step does.
   *
   * @param factor - > 1 zooms in, < 1 out. > 0, finite.
   * @returns Whether the zoom changed (a `change` was sent).
   */
  zoomBy(factor: number): boolean {
    positive('factor', factor, false);
    const changed = this._setZoom(this._zoom * factor);
    if (changed) this.dispatchEvent(_changeEvent);
    return changed;
  }

  // ── internals ──

  /** Validate and set both zoom limits. */
  private _setLimits(min: number, max: number): void {
    if (!(positive('minZoom', min, false) <= positive('maxZoom', max, false))) {
      throw new RangeError(`Trackball: minZoom (${min}) must be ≤ maxZoom (${max})`);
    }
    this._minZoom = min;
    this._maxZoom = max;
  }

  /** Clamp and apply a zoom factor; returns whether it changed. */
  private _setZoom(value: number): boolean {
    const next = Math.min(this._maxZoom, Math.max(this._minZoom, value));
    const ratio = next / this._zoom;
    if (!(ratio > 0 && ratio < Number.POSITIVE_INFINITY) || ratio === 1) return false;
    const camera = this.camera;
    if (camera?.isOrthographicCamera) {
      // A zoom whose projection would overflow is refused (three's update computes 2 · zoom: ∞ above 9e307).
      const e = camera.projectionMatrix.elements;
      const zoom = camera.zoom;
      if (typeof zoom === 'number' && typeof camera.updateProjectionMatrix === 'function') {
        camera.zoom = zoom * ratio;
        camera.updateProjectionMatrix();
        if (!e.every(Number.isFinite)) {
          camera.zoom = zoom;
          camera.updateProjectionMatrix();
          return false;
        }
      } else {
        // Scale NDC x and y (rows 0 and 1 of the column-major projection) about the view centre.
        const xy = [0, 4, 8, 12, 1, 5, 9, 13];
        if (!xy.every((i) => Number.isFinite(e[i] * ratio))) return false;
        for (const i of xy) e[i] *= ratio;
        camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
      }
    } else if (camera?.isPerspectiveCamera) {
      camera.getWorldPosition(_eye).sub(this.target).divideScalar(ratio).add(this.target);
      if (camera.parent) camera.parent.worldToLocal(_eye);
      // An extreme minZoom would put the eye at infinity: that step is refused.
      if (!Number.isFinite(_eye.x + _eye.y + _eye.z)) return false;
      camera.position.copy(_eye);
      camera.updateMatrixWorld();
    }
    this._zoom = next;
    return true;
  }

  /**
   * Apply a camera-frame rotation `q`: world rotation = (C q C⁻¹) · worldFrom, object = P⁻¹ · (C q C⁻¹) · P ·
   * from (C the camera's, P the parent's world orientation).
   */
  private _rotateObject(q: Quaternion, from: Quaternion, worldFrom: Quaternion): void {
    if (this.camera) this.camera.getWorldQuaternion(_frame);
    else _frame.identity();
    _turn.copy(_frame).multiply(q).multiply(_frame.invert());
    // multiplyQuaternions reads both factors first, so worldFrom may be this._world itself.
    this._world.multiplyQuaternions(_turn, worldFrom).normalize();
    const parent = this.object.parent;
    if (parent) {
      parent.getWorldQuaternion(_parent);
      _parentInverse.copy(_parent).invert();
      _turn.premultiply(_parentInverse).multiply(_parent);
    }
    this.object.quaternion.copy(_turn.multiply(from)).normalize();
  }

  /** The pointer's position on the ball, or false while the element has no size. */
  private _toBall(clientX: number, clientY: number, out: Vec3): boolean {
    const element = this.domElement;
    if (!element) return false;
    const rect = element.getBoundingClientRect();
    const half = (Math.min(rect.width, rect.height) / 2) * this._radius;
    const x = (clientX - (rect.left + rect.width / 2)) / half;
    const y = (rect.top + rect.height / 2 - clientY) / half;
    // NaN, infinite and absurd (synthetic) coordinates, or an element without size: no rotation.
    if (!(Math.abs(x) + Math.abs(y) < 1e150)) return false;
    projectToBall(x, y, this._mapping, out);
    return true;
  }

  /** Begin (or restart) a rotation from a pointer position. */
  private _beginRotation(clientX: number, clientY: number): void {
    this._hasBallStart = this._toBall(clientX, clientY, this._ballStart);
    this._rotationAtStart.copy(this._rotation);
    this._objectAtStart.copy(this.object.quaternion);
    this._worldAtStart.copy(this._world);
    this._spinAngle = 0;
    this._spin.identity();
  }

  private _rotateTo(clientX: number, clientY: number): void {
    if (!this._hasBallStart) {
      this._beginRotation(clientX, clientY);
      return;
    }
    if (!this._toBall(clientX, clientY, _ball)) return;
    arcRotation(this._ballStart, _ball, this._rotateSpeed, _arc);
    _delta.set(_arc[0], _arc[1], _arc[2], _arc[3]);
    // The increment since the previous move, kept for the damped spin: new · old⁻¹.
    this._spin.copy(this._rotation).invert();
    this._rotation.copy(_delta).multiply(this._rotationAtStart).normalize();
    this._spin.premultiply(this._rotation).normalize();
    this._rotateObject(_delta, this._objectAtStart, this._worldAtStart);
    this._lastMove = performance.now();
    this.dispatchEvent(_changeEvent);
  }

  private _listenDocument(): void {
    const doc = this.domElement?.ownerDocument ?? null;
    if (!doc || this._listening === doc) return;
    this._unlistenDocument();
    doc.addEventListener('pointermove', this._onPointerMove);
    doc.addEventListener('pointerup', this._onPointerUp);
    doc.addEventListener('pointercancel', this._onPointerUp);
    this._listening = doc;
  }

  private _unlistenDocument(): void {
    const doc = this._listening;
    if (!doc) return;
    doc.removeEventListener('pointermove', this._onPointerMove);
    doc.removeEventListener('pointerup', this._onPointerUp);
    doc.removeEventListener('pointercancel', this._onPointerUp);
    this._listening = null;
  }

  private _release(pointerId: number): void {
    const element = this.domElement;
    try {
      if (element?.hasPointerCapture?.(pointerId)) element.releasePointerCapture(pointerId);
    } catch {
      // The pointer is already gone: nothing to release.
    }
  }

  private _pinchSpan(): number {
    const [a, b] = [...this._pointers.values()];
    return Math.hypot(a.x - b.x, a.y - b.y);
  }

  private readonly _onPointerDown = (event: PointerEvent): void => {
    if (!this.enabled) return;
    if (event.pointerType === 'mouse' && event.button !== 0) return;
    if (this._pointers.has(event.pointerId) || this._pointers.size >= 2) return;
    const first = this._pointers.size === 0;
    this._pointers.set(event.pointerId, { x: event.clientX, y: event.clientY });
    try {
      this.domElement?.setPointerCapture?.(event.pointerId);
    } catch {
      // Synthetic or already-ended pointers cannot be captured; the document listeners still see them.
    }
    this._listenDocument();
    if (first) {
      this._beginRotation(event.clientX, event.clientY);
      this.dispatchEvent(_startEvent);
    } else {
      // A second finger: stop rotating, start pinching.
      this._hasBallStart = false;
      this._pinchDistance = this._pinchSpan();
    }
  };

  private readonly _onPointerMove = (event: PointerEvent): void => {
    const pointer = this._pointers.get(event.pointerId);
    if (!pointer || !this.enabled) return;
    pointer.x = event.clientX;
    pointer.y = event.clientY;
    if (this._pointers.size === 1) {
      this._rotateTo(event.clientX, event.clientY);
    } else {
      const span = this._pinchSpan();
      if (this._pinchDistance > 0 && span > 0 && this._zoomSpeed > 0) {
        // _setZoom clamps, so an extreme ratio (0 or ∞) lands on a limit instead of throwing.
        if (this._setZoom(this._zoom * (span / this._pinchDistance) ** this._zoomSpeed)) {
          this.dispatchEvent(_changeEvent);
        }
      }
      this._pinchDistance = span;
    }
  };

  private readonly _onPointerUp = (event: PointerEvent): void => {
    if (!this._pointers.delete(event.pointerId)) return;
    this._release(event.pointerId);
    if (this._pointers.size === 1) {
      // One finger left after a pinch: rotate from where it is now, without a jump.
      const [rest] = [...this._pointers.values()];
      this._beginRotation(rest.x, rest.y);
      return;
    }
    this._unlistenDocument();
    this._hasBallStart = false;
    if (this.enableDamping && performance.now() - this._lastMove <= SPIN_STALE_MS) {
      const w = Math.min(1, Math.abs(this._spin.w));
      const angle = 2 * Math.atan2(Math.hypot(this._spin.x, this._spin.y, this._spin.z), w);
      if (angle > SPIN_MIN) {
        const sign = this._spin.w < 0 ? -1 : 1;
        this._spinAxis.set(this._spin.x * sign, this._spin.y * sign, this._spin.z * sign).normalize();
        this._spinAngle = angle;
      }
    }
    this.dispatchEvent(_endEvent);
  };

  private readonly _onWheel = (event: WheelEvent): void => {
    if (!this.enabled || this._zoomSpeed === 0) return;
    event.preventDefault();
    // deltaMode 0 is pixels, 1 lines, 2 pages.
    const dy = event.deltaY * (WHEEL_MODE_PIXELS[event.deltaMode] ?? 1);
    if (!Number.isFinite(dy) || dy === 0) return;
    this.dispatchEvent(_startEvent);
    if (this._setZoom(this._zoom * Math.exp((-dy / WHEEL_PIXELS_PER_EFOLD) * this._zoomSpeed))) {
      this.dispatchEvent(_changeEvent);
    }
    this.dispatchEvent(_endEvent);
  };
}
