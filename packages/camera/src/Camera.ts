import { Matrix4, Quaternion, Camera as ThreeCamera, Vector3 } from 'three';
import type { CameraFrame } from './CameraFrame.js';
import { createPoleMemory, lookAtFrame, type PoleMemory } from './lookAtFrame.js';
import { checkCoordinates, readVector3, type Vec3Input } from './readVector3.js';
import { check, finite, positive, validateOrthographic, validatePerspective } from './validateProjection.js';

/** Which projection a {@link Camera} uses. */
export type ProjectionType = 'perspective' | 'orthographic';

/** Options for `new Camera(options)`: a perspective projection (three.js's PerspectiveCamera defaults). */
export interface CameraOptions {
  /** Vertical field of view, degrees, in (0, 180). @defaultValue 50 */
  fovy?: number;
  /** Width / height of the viewport, > 0. @defaultValue 1 */
  aspect?: number;
  /** Distance to the near plane, world units, > 0. @defaultValue 0.1 */
  near?: number;
  /** Distance to the far plane, world units, > near. @defaultValue 2000 */
  far?: number;
}

const newFrame = (): CameraFrame => ({
  e: new Vector3(),
  u: new Vector3(),
  v: new Vector3(),
  w: new Vector3(),
});
const _frame = /* @__PURE__ */ newFrame();
const _m = /* @__PURE__ */ new Matrix4();
const _p = /* @__PURE__ */ new Matrix4();
const _pi = /* @__PURE__ */ new Matrix4();
const _q = /* @__PURE__ */ new Quaternion();
const _eye = /* @__PURE__ */ new Vector3();
const _change = { type: 'change' } as const;

/**
 * The lecture's camera as a three.js camera: `renderer.render(scene, camera)` and three's controls use it as is.
 *
 * The frame (`e`, `u`, `v`, `w`) is never stored apart from the Object3D state: `position`, `quaternion` and
 * `matrixWorld` *are* the camera transformation, so every way of moving the camera (the lecture's
 * `lookAt(eye, at, up)`, three's `lookAt(target)`, `position.set`, controls, {@link CameraMovement}) keeps
 * {@link Camera.getFrame}, {@link Camera.getCameraTransformationMatrix} and `matrixWorldInverse` consistent.
 *
 * The projection is perspective or orthographic; `isPerspectiveCamera` / `isOrthographicCamera` follow it, so
 * three's shaders and controls treat the camera as the matching kind. Matrices equal three's
 * `PerspectiveCamera` / `OrthographicCamera` ones, including the reversed-depth variant the renderer switches
 * on (`WebGLRenderer({ reversedDepthBuffer: true })` sets `reversedDepth` and calls
 * {@link Camera.updateProjectionMatrix}).
 *
 * Dispatches `{ type: 'change' }` after `lookAt`, `setPerspective`, `setOrthographic` and `setAspect`.
 *
 * @example
 * ```ts
 * const camera = new Camera();
 * camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
 * camera.setPerspective(90, 1, 0.1, 10);
 * renderer.render(scene, camera);
 * ```
 */
export class Camera extends ThreeCamera {
  /** Vertical field of view of the perspective projection, degrees, in (0, 180). @defaultValue 50 */
  fovy: number;
  /** Viewport width / height, > 0. Call {@link Camera.updateProjectionMatrix} after setting it, or use {@link Camera.setAspect}. @defaultValue 1 */
  aspect: number;
  /** Near plane distance, world units (> 0 for perspective, any finite value for orthographic). @defaultValue 0.1 */
  near: number;
  /** Far plane distance, world units, > near. @defaultValue 2000 */
  far: number;
  /** Zoom factor (as three's cameras): divides the view extent. > 0. @defaultValue 1 */
  zoom: number;
  /** Orthographic left plane, camera-space x, world units. @defaultValue -1 */
  left: number;
  /** Orthographic right plane, camera-space x, world units. @defaultValue 1 */
  right: number;
  /** Orthographic top plane, camera-space y, world units. @defaultValue 1 */
  top: number;
  /** Orthographic bottom plane, camera-space y, world units. @defaultValue -1 */
  bottom: number;

  private _kind: ProjectionType = 'perspective';
  private readonly _pole: PoleMemory = createPoleMemory();
  /** Orientation written by the last lookAt: when another API has turned the camera since, the pole anchor resets. */
  private readonly _poleQ = new Quaternion(Number.NaN, 0, 0, 0);

  /**
   * Build a perspective camera at the origin looking down −z (frame e = 0, u = x, v = y, w = z).
   * @param options - Projection parameters (`null` or omitted: all defaults).
   * @throws RangeError / TypeError naming the first bad option, as {@link Camera.setPerspective}.
   */
  constructor(options?: CameraOptions | null) {
    super();
    const { fovy = 50, aspect = 1, near = 0.1, far = 2000 } = options ?? {};
    this.fovy = fovy;
    this.aspect = aspect;
    this.near = near;
    this.far = far;
    this.zoom = 1;
    this.left = -1;
    this.right = 1;
    this.top = 1;
    this.bottom = -1;
    this.updateProjectionMatrix();
  }

  /** The current projection. Change it with {@link Camera.setPerspective} / {@link Camera.setOrthographic}. */
  get projection(): ProjectionType {
    return this._kind;
  }

  /** `true` while the projection is perspective (three's shaders and controls read this). */
  get isPerspectiveCamera(): boolean {
    return this._kind === 'perspective';
  }

  /** `true` while the projection is orthographic (three sets the `isOrthographic` uniform from this). */
  get isOrthographicCamera(): boolean {
    return this._kind === 'orthographic';
  }

  /**
   * Whether `projectionMatrix` maps near → 1 and far → 0 (reversed-Z, clip z in [0, 1]), as three's cameras.
   * A `WebGLRenderer` created with `reversedDepthBuffer: true` switches it on by itself before drawing and never
   * off again; set it back to `false` (this setter updates the matrix) before using the camera with a standard
   * renderer, or it renders with the depth order inverted.
   * @defaultValue false
   */
  override get reversedDepth(): boolean {
    return (this as unknown as { _reversedDepth: boolean })._reversedDepth;
  }
  override set reversedDepth(value: boolean) {
    (this as unknown as { _reversedDepth: boolean })._reversedDepth = value;
    this.updateProjectionMatrix();
  }

  /** Alias of {@link Camera.fovy} (degrees) under three's name, for code written for `PerspectiveCamera`. */
  get fov(): number {
    return this.fovy;
  }
  set fov(degrees: number) {
    this.fovy = degrees;
  }

  /**
   * Aim the camera. Three forms:
   * - `lookAt(eye, at, up)` — the lecture's: place the eye, look at `at`, with `up` giving the roll (world space).
   *   `up` is also stored in `this.up` for later three-style calls.
   * - `lookAt(target)` / `lookAt(x, y, z)` — three's `Object3D.lookAt` for cameras: look from the current
   *   world position towards the target with `this.up`.
   *
   * The frame is the one three.js builds (`w = normalize(eye − at)`, `u = normalize(up × w)`, `v = w × u`); with
   * `up` parallel to the gaze (or within {@link POLE_CAP_RAD}) it stays finite, orthonormal and continuous
   * (see {@link lookAtFrame}). With a parent, eye/at/up are world-space and position/quaternion are set so the
   * world frame is the requested one (uniformly-scaled parents, as three).
   *
   * @throws RangeError when eye = at, up is zero, any component is NaN/infinite, or an eye component is beyond
   * ±1e30 (the view matrix must stay finite in float32); TypeError for non-vectors, and for `lookAt(x, y, z)`
   * with a missing or non-number component (named `at`).
   */
  override lookAt(target: Vec3Input): this;
  override lookAt(x: number, y: number, z: number): this;
  override lookAt(eye: Vec3Input, at: Vec3Input, up?: Vec3Input): this;
  override lookAt(a: Vec3Input | number, b?: Vec3Input | number, c?: Vec3Input | number): this {
    // three's forms look from the current world position with this.up.
    let eye: Vec3Input = this.getWorldPosition(_eye);
    // lookAt(x, y, z) is read as the vector [x, y, z], so a missing or non-number component is refused naming
    // `at` (three's Vector3.set would keep the old component and aim at a point nobody asked for).
    let at = (typeof a === 'number' ? [a, b, c] : a) as Vec3Input;
    let up: Vec3Input = this.up;
    if (typeof a !== 'number' && b !== undefined) {
      eye = a;
      at = b as Vec3Input;
      if (c !== undefined) up = c as Vec3Input;
    }
    if (!this._poleQ.equals(this.quaternion)) {
      // Someone else turned the camera since our last lookAt: the pole anchor is its current right vector.
      this.updateWorldMatrix(true, false);
      this._pole.anchor.setFromMatrixColumn(this.matrixWorld, 0).normalize();
      this._pole.turn = 0;
    }
    const frame = lookAtFrame(eye, at, up, _frame, this._pole);
    checkCoordinates(frame.e, 'eye');
    if (up !== this.up) readVector3(up, 'up', this.up);
    _m.makeBasis(frame.u, frame.v, frame.w);
    this.quaternion.setFromRotationMatrix(_m);
    this.position.copy(frame.e);
    const parent = this.parent;
    if (parent) {
      parent.updateWorldMatrix(true, false);
      parent.worldToLocal(this.position);
      _q.setFromRotationMatrix(_m.extractRotation(parent.matrixWorld));
      this.quaternion.premultiply(_q.invert());
    }
    this.updateMatrixWorld(true);
    this._poleQ.copy(this.quaternion);
    this.dispatchEvent(_change as never);
    return this;
  }

  /**
   * Use a perspective projection (the lecture's `setPerspective`).
   * @param fovy - Vertical field of view, degrees, in (0, 180).
   * @param aspect - Viewport width / height, > 0.
   * @param near - Near plane distance, world units, > 0.
   * @param far - Far plane distance, world units, > near. Any finite far/near works; see the README for the depth
   *   precision each depth mode keeps up to far/near = 1e9.
   * @throws RangeError naming the first bad parameter (NaN included), or when the matrix would not be finite; the
   * camera is then unchanged. TypeError for a non-number.
   */
  setPerspective(fovy: number, aspect: number, near: number, far: number): this {
    return this._set({ _kind: 'perspective', fovy, aspect, near, far });
  }

  /**
   * Use an orthographic projection, in the lecture's argument order (three's `OrthographicCamera` takes
   * `left, right, top, bottom, near, far`). Planes are camera-space, world units.
   * @param r - Right plane, camera-space x, world units.
   * @param l - Left plane, camera-space x, ≠ r (r < l mirrors the picture, as in three).
   * @param t - Top plane, camera-space y.
   * @param b - Bottom plane, camera-space y, ≠ t.
   * @param n - Near plane distance along the gaze (any finite value, 0 and negative included).
   * @param f - Far plane distance along the gaze, > n.
   * Also sets {@link Camera.aspect} to |r − l| / |t − b|.
   * @throws RangeError naming the first bad parameter (NaN included), or when the matrix would not be finite; the
   * camera is then unchanged. TypeError for a non-number.
   */
  setOrthographic(r: number, l: number, t: number, b: number, n: number, f: number): this {
    validateOrthographic(r, l, t, b, n, f, this.zoom);
    const aspect = Math.abs(r - l) / Math.abs(t - b);
    return this._set({
      _kind: 'orthographic',
      right: r,
      left: l,
      top: t,
      bottom: b,
      near: n,
      far: f,
      aspect,
    });
  }

  /**
   * Follow a viewport resize. Perspective: keeps `fovy` (the vertical view), sets `aspect`. Orthographic: keeps
   * the vertical extent `top − bottom` and the horizontal centre, and sets `right − left` to
   * `aspect · |top − bottom|` (keeping its sign).
   * @param aspect - Viewport width / height (e.g. `canvas.clientWidth / canvas.clientHeight`), finite and > 0.
   * @throws RangeError when aspect is not finite and > 0.
   */
  setAspect(aspect: number): this {
    check(aspect, positive, 'aspect', 'finite and > 0');
    if (this._kind !== 'orthographic') return this._set({ aspect });
    const cx = (this.left + this.right) / 2;
    const half = (Math.sign(this.right - this.left) * aspect * Math.abs(this.top - this.bottom)) / 2;
    return this._set({ aspect, left: cx - half, right: cx + half });
  }

  /**
   * Update the matrices for `fields` (validated on a view of this camera that has them: a refusal throws before
   * anything changes), then assign them: all or nothing.
   */
  private _set(
    fields: Partial<
      Record<'_kind' | 'fovy' | 'aspect' | 'near' | 'far' | 'left' | 'right' | 'top' | 'bottom', unknown>
    >,
  ): this {
    this.updateProjectionMatrix.call(Object.assign(Object.create(this) as this, fields));
    Object.assign(this, fields);
    this.dispatchEvent(_change as never);
    return this;
  }

  /**
   * Recompute `projectionMatrix` (and its inverse) from the fields, exactly as three's `PerspectiveCamera` /
   * `OrthographicCamera` do, honouring `zoom`, `coordinateSystem` and `reversedDepth`. Call it after assigning
   * fields directly.
   * @throws RangeError when the fields are out of range (see {@link Camera.setPerspective}/{@link Camera.setOrthographic}),
   * or when together they give a matrix (or inverse) that is not finite in float32, as uniforms are (e.g. near =
   * 1e-320); the matrices are then left unchanged.
   */
  updateProjectionMatrix(): void {
    const { near, far, zoom } = this;
    if (this._kind === 'perspective') {
      validatePerspective(this.fovy, this.aspect, near, far, zoom);
      // three's top, left = −0.5 · aspect · 2 · top, right = left + width, bottom = top − height: the same doubles.
      const top = (near * Math.tan((Math.PI / 360) * this.fovy)) / zoom;
      const right = this.aspect * top;
      _p.makePerspective(-right, right, top, -top, near, far, this.coordinateSystem, this.reversedDepth);
    } else {
      validateOrthographic(this.right, this.left, this.top, this.bottom, near, far, zoom);
      const dx = (this.right - this.left) / (2 * zoom);
      const dy = (this.top - this.bottom) / (2 * zoom);
      const cx = (this.right + this.left) / 2;
      const cy = (this.top + this.bottom) / 2;
      _p.makeOrthographic(
        cx - dx,
        cx + dx,
        cy + dy,
        cy - dy,
        near,
        far,
        this.coordinateSystem,
        this.reversedDepth,
      );
    }
    _pi.copy(_p).invert();
    if (![..._p.elements, ..._pi.elements].every((x) => finite(Math.fround(x)))) {
      throw new RangeError(
        `near, far, zoom (${near}, ${far}, ${zoom}), aspect, fovy or extent give a non-finite float32 matrix`,
      );
    }
    this.projectionMatrix.copy(_p);
    this.projectionMatrixInverse.copy(_pi);
  }

  /**
   * The camera frame in world space (the lecture's `getFrame()`), read from `matrixWorld` so it always matches
   * what is rendered.
   * @param target - Frame to write; a new one when omitted.
   */
  getFrame(target: CameraFrame = newFrame()): CameraFrame {
    this.updateWorldMatrix(true, false);
    target.e.setFromMatrixPosition(this.matrixWorld);
    this.matrixWorld.extractBasis(target.u, target.v, target.w);
    target.u.normalize();
    target.v.normalize();
    target.w.normalize();
    return target;
  }

  /**
   * The camera transformation `Mcam` (world → camera), i.e. three's view matrix `matrixWorldInverse`, brought up
   * to date first. The returned matrix is the camera's own: copy it to keep it.
   */
  getCameraTransformationMatrix(): Matrix4 {
    this.updateWorldMatrix(true, false);
    return this.matrixWorldInverse;
  }

  /** The projection matrix `P` (the camera's own `projectionMatrix`: copy it to keep it). */
  getProjectionMatrix(): Matrix4 {
    return this.projectionMatrix;
  }

  /**
   * `P · Mcam` (world → clip), the lecture's `getMatrix()`.
   * @param target - Matrix to write; a new one when omitted.
   */
  getMatrix(target: Matrix4 = new Matrix4()): Matrix4 {
    return target.multiplyMatrices(this.projectionMatrix, this.getCameraTransformationMatrix());
  }

  /** Copy projection, frame (Object3D state) and pole memory from `source`. */
  override copy(source: Camera, recursive?: boolean): this {
    super.copy(source, recursive);
    this._kind = source._kind;
    this.fovy = source.fovy;
    this.aspect = source.aspect;
    this.near = source.near;
    this.far = source.far;
    this.zoom = source.zoom;
    this.left = source.left;
    this.right = source.right;
    this.top = source.top;
    this.bottom = source.bottom;
    this._pole.anchor.copy(source._pole.anchor);
    this._pole.turn = source._pole.turn;
    this._poleQ.copy(source._poleQ);
    this.updateProjectionMatrix();
    return this;
  }
}
