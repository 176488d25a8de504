import { button, levaStore } from 'leva';
import { useEffect } from 'react';
import { SCENE_LABELS, SPHERE_ONLY_INPUTS } from '../engine/scenes';
import type { PlaygroundState } from '../state/schema';
import { MAX_LIGHTS, SCENES } from '../state/schema';
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
  useFolder('Material', folderFields('Material'), state, update, {}, 1);
  useFolder(
    'Lights',
    {},
    state,
    update,
    {
      'add light': button(actions.addLight, { disabled: false }),
    },
    2,
  );

  useFolder('Sphere', folderFields('Sphere'), state, update, {}, 3);
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

  // The sphere's own inputs are greyed out while another scene is shown (the note beside the panel says why).
  const sphereOnly = state.scene !== 'sphere';
  useEffect(() => {
    const data = levaStore.getData();
    for (const path of SPHERE_ONLY_INPUTS) {
      if (data[path]) levaStore.disableInputAtPath(path, sphereOnly);
    }
  }, [sphereOnly]);
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
  );
  return null;
}

export { MAX_LIGHTS };
