import { button } from 'leva';
import { SCENE_LABELS } from '../engine/scenes';
import type { PlaygroundState } from '../state/schema';
import { MAX_LIGHTS, SCENES } from '../state/schema';
import { isIdleInput } from './idleInputs';
import { folderFields, lightFields } from './panelFields';
import { type Update, useFolder } from './useFolder';

/** The View folder's inputs; the scene picker's labels live beside the scene builders (`SCENE_LABELS`). */
function viewFields() {
  const fields = folderFields('View');
  const scene = fields['scene']!;
  scene.input = {
    ...scene.input,
    options: Object.fromEntries(SCENES.map((name) => [SCENE_LABELS[name], name])),
  };
  return fields;
}

/** Material, sphere, model, camera, trackball and view controls (their inputs: `state/fields.ts`). */
export function SceneControls({
  state,
  update,
  actions,
}: {
  state: PlaygroundState;
  update: Update;
  actions: { exportPng: () => void; copyLink: () => void; reset: () => void; addLight: () => void };
}) {
  useFolder(
    'View',
    viewFields(),
    state,
    update,
    {
      'export PNG': button(actions.exportPng),
      'copy link': button(actions.copyLink),
      'reset scene': button(actions.reset),
    },
    0,
  );
  // Inputs that change nothing in this state's picture are greyed out (idleInputs.ts).
  const idle = (path: string) => isIdleInput(state, path);
  useFolder('Material', folderFields('Material'), state, update, {}, 1, idle);
  useFolder(
    'Lights',
    {},
    state,
    update,
    {
      'add light': button(actions.addLight, { disabled: false }),
    },
    2,
    idle,
  );

  useFolder('Sphere', folderFields('Sphere'), state, update, {}, 3, idle);
  useFolder('Camera', folderFields('Camera'), state, update, {}, 4);
  useFolder(
    'Trackball',
    folderFields('Trackball'),
    state,
    update,
    {
      'reset rotation': button(() =>
        update((d) => {
          d.trackball.rotation = [0, 0, 0, 1];
        }),
      ),
    },
    5,
  );

  return null;
}

/** One light's folder: position, Ia/Id/Is, attenuation, remove. */
export function LightControls({
  index,
  state,
  update,
  onGizmo,
}: {
  index: number;
  state: PlaygroundState;
  update: Update;
  /** Toggles the move gizmo on this light. */
  onGizmo: (index: number) => void;
}) {
  const n = index + 1;
  useFolder(
    `Light ${n}`,
    lightFields(index),
    state,
    update,
    {
      [`move light ${n} with the gizmo`]: button(() => onGizmo(index)),
      [`remove light ${n}`]: button(() =>
        update((d) => {
          d.lights.splice(index, 1);
        }),
      ),
    },
    2 + (index + 1) / 100,
    (path) => isIdleInput(state, path),
  );
  return null;
}

export { MAX_LIGHTS };
