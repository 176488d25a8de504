/**
 * Where to point at a light the view does not show: for each light outside the view (beside it, or behind the
 * eye, as the lecture's light 1 is), the point on the view's border, `margin` in from it, in the light's direction
 * from the view's centre, and that direction's angle. A light in front of the eye is pointed at through its
 * projection; one behind the eye through its sideways offset in view space (where the viewer would turn to see it).
 */
import { type Camera, Vector3 } from 'three';

export interface LightArrow {
  /** The light's index in the state (0-based). */
  index: number;
  /** The arrow's place on the view, CSS pixels from its top left. */
  x: number;
  y: number;
  /** Its direction on the screen, radians from +x, clockwise (y down). */
  angle: number;
  /** Whether the light is behind the eye (else beside the view). */
  behind: boolean;
}

const _v = new Vector3();

/**
 * The arrows for the lights at `positions` (world space; an entry that is not three finite numbers is passed over)
 * seen by `camera` (matrices current) in a w × h view.
 */
export function lightArrows(
  camera: Camera,
  positions: readonly (readonly [number, number, number] | null | undefined)[],
  w: number,
  h: number,
  margin = 14,
): LightArrow[] {
  const out: LightArrow[] = [];
  for (const [index, p] of positions.entries()) {
    if (p?.length !== 3 || !p.every(Number.isFinite)) continue;
    _v.set(p[0], p[1], p[2]).applyMatrix4(camera.matrixWorldInverse);
    const behind = _v.z >= 0;
    let dx: number;
    let dy: number;
    if (behind) {
      dx = _v.x;
      dy = -_v.y;
    } else {
      _v.applyMatrix4(camera.projectionMatrix);
      if (Math.abs(_v.x) <= 1 && Math.abs(_v.y) <= 1) continue;
      dx = _v.x * (w / 2);
      dy = -_v.y * (h / 2);
    }
    // Straight behind the eye: no sideways direction; point down, where the eye would turn round.
    if (Math.hypot(dx, dy) < 1e-9) dy = 1;
    const t = Math.min((w / 2 - margin) / Math.abs(dx || 1e-12), (h / 2 - margin) / Math.abs(dy || 1e-12));
    out.push({ index, x: w / 2 + dx * t, y: h / 2 + dy * t, angle: Math.atan2(dy, dx), behind });
  }
  return out;
}
