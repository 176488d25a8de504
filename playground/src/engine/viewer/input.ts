/**
 * Pointer and keyboard input on the viewer's canvas: the trackball (drag, wheel, its damped spin), the camera's
 * movement keys, and the turn keys (the keyboard's trackball). Each reports the new view to the app.
 */
import * as THREE from 'three';
import type { Vec3 } from '../../state/schema';
import type { ViewerEvents, ViewerHost } from './host';

/** Keys that move the camera (documented on the page; @shadelab/camera's MOVEMENT_KEYS). */
export const MOVE_KEYS = 'W/S or ↑/↓ forward/back, A/D or ←/→ left/right, E/Q up/down';

/**
 * Keys that turn the sphere (the keyboard's trackball), by `KeyboardEvent.code`: an axis of the camera's frame
 * and a sign. None is one of @shadelab/camera's MOVEMENT_KEYS (WASD, arrows, E/Q, PageUp/PageDown).
 */
export const TURN_KEYS: Readonly<Record<string, readonly [axis: 'u' | 'v', sign: 1 | -1]>> = {
  KeyJ: ['v', -1],
  KeyL: ['v', 1],
  KeyI: ['u', -1],
  KeyK: ['u', 1],
};

/** The turn keys as the page documents them. */
export const TURN_KEYS_TEXT = 'J/L, I/K';

/** One turn key press, radians (times the trackball's rotate speed). */
export const TURN_STEP = Math.PI / 36;

/** The object's rotation (what the trackball turned) as [x, y, z, w]. */
export function rotationOf(object: THREE.Object3D): [number, number, number, number] {
  return object.quaternion.toArray() as [number, number, number, number];
}

const _axis = /* @__PURE__ */ new THREE.Vector3();
const _turn = /* @__PURE__ */ new THREE.Quaternion();

export class ViewInput {
  /** Reports the view once the wheel or a damped spin rests (neither has a drag to end). */
  private viewTimer = 0;
  /** A drag turns the camera's gaze: its view is reported when the drag ends. */
  private moverDragging = false;

  /** Listens to the host's trackball and camera movement, and connects them (and the turn keys) to its canvas. */
  constructor(
    private readonly host: ViewerHost,
    private readonly events: ViewerEvents,
  ) {
    const { trackball, mover, canvas } = host;
    trackball.addEventListener('change', this.onTrackballChange);
    trackball.addEventListener('end', this.onTrackballEnd);
    mover.addEventListener('change', this.onMoverChange);
    mover.addEventListener('start', this.onMoverStart);
    mover.addEventListener('end', this.onMoverEnd);
    trackball.connect(canvas);
    mover.connect(canvas);
    canvas.addEventListener('keydown', this.onKeyDown);
  }

  /**
   * J/L turn the sphere about the camera's up axis v, I/K about its right axis u (as a drag right or down
   * would), {@link TURN_STEP} · rotate speed per press.
   */
  private readonly onKeyDown = (event: KeyboardEvent) => {
    const key = TURN_KEYS[event.code];
    const { state } = this.host;
    if (!key || event.ctrlKey || event.metaKey || event.altKey || !state) return;
    event.preventDefault();
    // The camera's u or v axis in camera coordinates, through the trackball (as a drag): its rotation and
    // matrices stay those of the picture, and the next drag continues from here.
    _axis.set(key[0] === 'u' ? 1 : 0, key[0] === 'u' ? 0 : 1, 0);
    this.host.trackball.rotate(
      _turn.setFromAxisAngle(_axis, key[1] * TURN_STEP * state.trackball.rotateSpeed),
    );
    this.onViewEnd();
  };

  private readonly onTrackballChange = () => {
    this.host.requestRender();
    window.clearTimeout(this.viewTimer);
    this.viewTimer = window.setTimeout(this.onViewEnd, 250);
  };

  /**
   * A drag ended: report the view, and render once more. With damping on, that frame steps the spin
   * (`useTrackball`'s `useFrame`, see sceneRoot.tsx), whose `change` asks for the next, until it rests; the view
   * is reported again once it is quiet.
   */
  private readonly onTrackballEnd = () => {
    this.onViewEnd();
    this.host.requestRender();
  };

  /** The movement keys translate the camera: `at` moves with the eye. */
  private readonly onMoverStart = () => {
    this.moverDragging = true;
  };
  private readonly onMoverEnd = () => {
    this.moverDragging = false;
    this.reportCamera();
  };
  private readonly onMoverChange = () => {
    this.host.requestRender();
    if (!this.moverDragging) this.reportCamera();
  };

  /** The movement keys moved the camera or a drag turned its gaze: `at` stays at the same distance ahead. */
  private reportCamera() {
    const { state, camera, pivot } = this.host;
    if (!state) return;
    const { e, v, w } = camera.getFrame();
    const c = state.camera;
    const distance = Math.hypot(...c.eye.map((x, i) => x - c.at[i]!)) || 1;
    const eye: Vec3 = [e.x, e.y, e.z];
    const at = eye.map((x, i) => x - [w.x, w.y, w.z][i]! * distance) as Vec3;
    this.events.onView?.({
      eye,
      at,
      up: c.dragTurns ? [v.x, v.y, v.z] : c.up,
      zoom: c.zoom,
      rotation: rotationOf(pivot),
    });
  }

  /** The trackball turned the sphere or zoomed (perspective: the eye moves towards `at`; orthographic: zoom). */
  private readonly onViewEnd = () => {
    window.clearTimeout(this.viewTimer);
    const { state, camera, pivot } = this.host;
    if (!state) return;
    const { e } = camera.getFrame();
    const c = state.camera;
    const ortho = c.projection === 'orthographic';
    this.events.onView?.({
      eye: ortho ? c.eye : [e.x, e.y, e.z],
      at: c.at,
      zoom: ortho ? camera.zoom : c.zoom,
      rotation: rotationOf(pivot),
    });
  };

  dispose(): void {
    const { trackball, mover, canvas } = this.host;
    canvas.removeEventListener('keydown', this.onKeyDown);
    trackball.removeEventListener('change', this.onTrackballChange);
    trackball.removeEventListener('end', this.onTrackballEnd);
    mover.removeEventListener('change', this.onMoverChange);
    mover.removeEventListener('start', this.onMoverStart);
    mover.removeEventListener('end', this.onMoverEnd);
    window.clearTimeout(this.viewTimer);
  }
}
