/**
 * The panel's inputs that change nothing in the picture of a state, greyed out (leva's disabled inputs; the
 * scene's note beside the panel says why): the Sphere folder's outside the lecture's sphere, the mesh's detail
 * where the impostor (no mesh) or automatic detail (the stats name the level it drew) decides it, and what a
 * loaded model keeps of its own (its materials' ka/kd/ks and α) or is lit by instead (a rig of three's lights, not
 * the panel's).
 */
import { SPHERE_ONLY_INPUTS } from '../engine/scenes';
import type { PlaygroundState } from '../state/schema';

/** The mesh's detail: the impostor draws the exact sphere on two triangles. */
const MESH_DETAIL_INPUTS = ['Sphere.base', 'Sphere.level', 'Sphere.auto', 'Sphere.maxErrorPx'];
/** Chosen by automatic detail. */
const AUTO_DETAIL_INPUTS = ['Sphere.base', 'Sphere.level'];
/** A loaded model's own, from its materials. */
const MODEL_OWN_INPUTS = ['Material.ka', 'Material.kd', 'Material.ks', 'Material.shininess'];

/** Whether the panel input at leva path `path` (`Folder.key`) changes nothing in `state`'s picture. */
export function isIdleInput(state: PlaygroundState, path: string): boolean {
  if (state.scene !== 'sphere') {
    if ((SPHERE_ONLY_INPUTS as readonly string[]).includes(path)) return true;
  } else if (state.sphere.render === 'impostor') {
    if (MESH_DETAIL_INPUTS.includes(path)) return true;
  } else if (state.sphere.auto && AUTO_DETAIL_INPUTS.includes(path)) return true;
  if (state.scene !== 'model') return false;
  return MODEL_OWN_INPUTS.includes(path) || path.startsWith('Light ') || path.startsWith('Lights.');
}
