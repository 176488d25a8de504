/**
 * What the panel says when a light's move gizmo is turned on where it cannot be seen: a light behind the eye (the
 * lecture's light 1 at (-5, 10, 20), with the eye at (0, 0, 3) looking at the origin) has its gizmo off the view.
 */
import type { PlaygroundState } from '../state/schema';

/** The notice for light `index`'s gizmo in `state`, or null when the light is in front of the eye. */
export function gizmoNotice(state: PlaygroundState, index: number): string | null {
  const light = state.lights[index];
  if (!light) return null;
  const { eye, at } = state.camera;
  const ahead = [0, 1, 2].reduce((sum, k) => sum + (light.position[k]! - eye[k]!) * (at[k]! - eye[k]!), 0);
  if (ahead > 0) return null;
  const n = index + 1;
  return `Light ${n} is behind the eye, so its gizmo is off the view: type its position (Light ${n} → position), or add a light in front of the object (Lights → add light) and move that one.`;
}
