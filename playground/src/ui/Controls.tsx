import { button, levaStore } from 'leva';
import { useEffect } from 'react';
import { SCENE_LABELS, SPHERE_ONLY_INPUTS } from '../engine/scenes';
import type { PlaygroundState, Rgb, Vec3 } from '../state/schema';
import { DEPTH_MODES, defaultLight, MAX_LIGHTS, SCENES } from '../state/schema';
import { type Field, type Update, useFolder } from './useFolder';

const vec3 = (label: string, step = 0.1): Record<string, unknown> => ({ label, step });
const rgb = (label: string): Record<string, unknown> => ({ label, step: 0.05 });

/** Material, sphere, model, camera, trackball and view controls. */
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
    {
      view: {
        input: {
          label: 'view',
          options: { 'single sphere': 'single', 'flat | Gouraud | Phong | cel': 'compare' },
        },
        read: (s) => s.view,
        write: (d, v: PlaygroundState['view']) => {
          d.view = v;
        },
      },
      scene: {
        input: {
          label: 'scene',
          options: Object.fromEntries(SCENES.map((name) => [SCENE_LABELS[name], name])),
        },
        read: (s) => s.scene,
        write: (d, v: PlaygroundState['scene']) => {
          d.scene = v;
        },
      },
    },
    state,
    update,
    {
      'export PNG': button(actions.exportPng),
      'copy link': button(actions.copyLink),
      'reset scene': button(actions.reset),
    },
    0,
  );

  useFolder(
    'Material',
    {
      shading: {
        input: { label: 'shading', options: ['flat', 'gouraud', 'phong'] },
        read: (s) => s.material.shading,
        write: (d, v: PlaygroundState['material']['shading']) => {
          d.material.shading = v;
        },
      },
      lighting: {
        input: { label: 'lighting', options: ['phong', 'blinn-phong'] },
        read: (s) => s.material.lighting,
        write: (d, v: PlaygroundState['material']['lighting']) => {
          d.material.lighting = v;
        },
      },
      celBands: {
        input: { label: 'cel bands', step: 1 },
        read: (s) => s.material.celBands,
        write: (d, v: number) => {
          d.material.celBands = v;
        },
      },
      outline: {
        input: { label: 'outline' },
        read: (s) => s.material.outline,
        write: (d, v: boolean) => {
          d.material.outline = v;
        },
      },
      outlineWidth: {
        input: { label: 'outline width', step: 0.005 },
        read: (s) => s.material.outlineWidth,
        write: (d, v: number) => {
          d.material.outlineWidth = v;
        },
      },
      outlineColor: {
        input: { label: 'outline colour' },
        read: (s) => s.material.outlineColor,
        write: (d, v: string) => {
          d.material.outlineColor = v;
        },
      },
      ka: {
        input: rgb('ka'),
        read: (s) => s.material.ka,
        write: (d, v: Rgb) => {
          d.material.ka = v;
        },
      },
      kd: {
        input: rgb('kd'),
        read: (s) => s.material.kd,
        write: (d, v: Rgb) => {
          d.material.kd = v;
        },
      },
      ks: {
        input: rgb('ks'),
        read: (s) => s.material.ks,
        write: (d, v: Rgb) => {
          d.material.ks = v;
        },
      },
      shininess: {
        input: { label: 'shininess', step: 1 },
        read: (s) => s.material.shininess,
        write: (d, v: number) => {
          d.material.shininess = v;
        },
      },
    },
    state,
    update,
    {},
    1,
  );

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

  useFolder(
    'Sphere',
    {
      render: {
        input: { label: 'draw as', options: { 'subdivided mesh': 'mesh', 'ray-cast impostor': 'impostor' } },
        read: (s) => s.sphere.render,
        write: (d, v: PlaygroundState['sphere']['render']) => {
          d.sphere.render = v;
        },
      },
      base: {
        input: { label: 'base', options: ['tetrahedron', 'octahedron', 'icosahedron'] },
        read: (s) => s.sphere.base,
        write: (d, v: PlaygroundState['sphere']['base']) => {
          d.sphere.base = v;
        },
      },
      level: {
        input: { label: 'level', step: 1 },
        read: (s) => s.sphere.level,
        write: (d, v: number) => {
          d.sphere.level = v;
        },
      },
      auto: {
        input: { label: 'auto detail' },
        read: (s) => s.sphere.auto,
        write: (d, v: boolean) => {
          d.sphere.auto = v;
        },
      },
      maxErrorPx: {
        input: { label: 'max error px', step: 0.05 },
        read: (s) => s.sphere.maxErrorPx,
        write: (d, v: number) => {
          d.sphere.maxErrorPx = v;
        },
      },
      radius: {
        input: { label: 'radius', step: 0.1 },
        read: (s) => s.sphere.radius,
        write: (d, v: number) => {
          d.sphere.radius = v;
        },
      },
      scale: {
        input: vec3('model scale'),
        read: (s) => s.model.scale,
        write: (d, v: Vec3) => {
          d.model.scale = v;
        },
      },
    },
    state,
    update,
    {},
    3,
  );

  const camera: Record<string, Field> = {
    projection: {
      input: { label: 'projection', options: ['perspective', 'orthographic'] },
      read: (s) => s.camera.projection,
      write: (d, v: PlaygroundState['camera']['projection']) => {
        d.camera.projection = v;
      },
    },
    depth: {
      input: { label: 'depth buffer', options: [...DEPTH_MODES] },
      read: (s) => s.camera.depth,
      write: (d, v: PlaygroundState['camera']['depth']) => {
        d.camera.depth = v;
      },
    },
    eye: {
      input: vec3('eye'),
      read: (s) => s.camera.eye,
      write: (d, v: Vec3) => {
        d.camera.eye = v;
      },
    },
    at: {
      input: vec3('at'),
      read: (s) => s.camera.at,
      write: (d, v: Vec3) => {
        d.camera.at = v;
      },
    },
    up: {
      input: vec3('up'),
      read: (s) => s.camera.up,
      write: (d, v: Vec3) => {
        d.camera.up = v;
      },
    },
    fovy: {
      input: { label: 'fovy °', step: 1 },
      read: (s) => s.camera.fovy,
      write: (d, v: number) => {
        d.camera.fovy = v;
      },
    },
    near: {
      input: { label: 'near', step: 0.01 },
      read: (s) => s.camera.near,
      write: (d, v: number) => {
        d.camera.near = v;
      },
    },
    far: {
      input: { label: 'far', step: 1 },
      read: (s) => s.camera.far,
      write: (d, v: number) => {
        d.camera.far = v;
      },
    },
    right: {
      input: { label: 'ortho r', step: 0.1 },
      read: (s) => s.camera.right,
      write: (d, v: number) => {
        d.camera.right = v;
      },
    },
    left: {
      input: { label: 'ortho l', step: 0.1 },
      read: (s) => s.camera.left,
      write: (d, v: number) => {
        d.camera.left = v;
      },
    },
    top: {
      input: { label: 'ortho t', step: 0.1 },
      read: (s) => s.camera.top,
      write: (d, v: number) => {
        d.camera.top = v;
      },
    },
    bottom: {
      input: { label: 'ortho b', step: 0.1 },
      read: (s) => s.camera.bottom,
      write: (d, v: number) => {
        d.camera.bottom = v;
      },
    },
    fitAspect: {
      input: { label: 'ortho fits aspect' },
      read: (s) => s.camera.fitAspect,
      write: (d, v: boolean) => {
        d.camera.fitAspect = v;
      },
    },
    dragTurns: {
      input: { label: 'drag turns camera' },
      read: (s) => s.camera.dragTurns,
      write: (d, v: boolean) => {
        d.camera.dragTurns = v;
      },
    },
    turnSpeed: {
      input: { label: 'turn speed rad/px', step: 0.001 },
      read: (s) => s.camera.turnSpeed,
      write: (d, v: number) => {
        d.camera.turnSpeed = v;
      },
    },
    moveSpeed: {
      input: { label: 'move speed', step: 0.01 },
      read: (s) => s.camera.moveSpeed,
      write: (d, v: number) => {
        d.camera.moveSpeed = v;
      },
    },
  };
  useFolder('Camera', camera, state, update, {}, 4);

  useFolder(
    'Trackball',
    {
      mapping: {
        input: { label: 'mapping', options: ['bell', 'arcball'] },
        read: (s) => s.trackball.mapping,
        write: (d, v: PlaygroundState['trackball']['mapping']) => {
          d.trackball.mapping = v;
        },
      },
      rotateSpeed: {
        input: { label: 'rotate speed', step: 0.1 },
        read: (s) => s.trackball.rotateSpeed,
        write: (d, v: number) => {
          d.trackball.rotateSpeed = v;
        },
      },
      zoomSpeed: {
        input: { label: 'zoom speed', step: 0.1 },
        read: (s) => s.trackball.zoomSpeed,
        write: (d, v: number) => {
          d.trackball.zoomSpeed = v;
        },
      },
      minZoom: {
        input: { label: 'min zoom', step: 0.01 },
        read: (s) => s.trackball.minZoom,
        write: (d, v: number) => {
          d.trackball.minZoom = v;
        },
      },
      maxZoom: {
        input: { label: 'max zoom', step: 0.1 },
        read: (s) => s.trackball.maxZoom,
        write: (d, v: number) => {
          d.trackball.maxZoom = v;
        },
      },
      radius: {
        input: { label: 'ball radius', step: 0.1 },
        read: (s) => s.trackball.radius,
        write: (d, v: number) => {
          d.trackball.radius = v;
        },
      },
      damping: {
        input: { label: 'damping (spin on)' },
        read: (s) => s.trackball.damping,
        write: (d, v: boolean) => {
          d.trackball.damping = v;
        },
      },
      dampingFactor: {
        input: { label: 'damping factor', step: 0.01, min: 0.01, max: 1 },
        read: (s) => s.trackball.dampingFactor,
        write: (d, v: number) => {
          d.trackball.dampingFactor = v;
        },
      },
    },
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
  const at = (s: PlaygroundState) => s.lights[index] ?? defaultLight();
  const edit = (d: PlaygroundState, f: (l: PlaygroundState['lights'][number]) => void) => {
    const light = d.lights[index];
    if (light) f(light);
  };
  const n = index + 1;
  useFolder(
    `Light ${n}`,
    {
      [`light${n}Position`]: {
        input: vec3('position', 0.5),
        read: (s) => at(s).position,
        write: (d, v: Vec3) =>
          edit(d, (l) => {
            l.position = v;
          }),
      },
      [`light${n}Ia`]: {
        input: rgb('Ia (ambient)'),
        read: (s) => at(s).ambient,
        write: (d, v: Rgb) =>
          edit(d, (l) => {
            l.ambient = v;
          }),
      },
      [`light${n}Id`]: {
        input: rgb('Id (diffuse)'),
        read: (s) => at(s).diffuse,
        write: (d, v: Rgb) =>
          edit(d, (l) => {
            l.diffuse = v;
          }),
      },
      [`light${n}Is`]: {
        input: rgb('Is (specular)'),
        read: (s) => at(s).specular,
        write: (d, v: Rgb) =>
          edit(d, (l) => {
            l.specular = v;
          }),
      },
      [`light${n}A`]: {
        input: { label: 'attenuation a', step: 0.1 },
        read: (s) => at(s).attenuation.a,
        write: (d, v: number) =>
          edit(d, (l) => {
            l.attenuation.a = v;
          }),
      },
      [`light${n}B`]: {
        input: { label: 'attenuation b', step: 0.01 },
        read: (s) => at(s).attenuation.b,
        write: (d, v: number) =>
          edit(d, (l) => {
            l.attenuation.b = v;
          }),
      },
      [`light${n}C`]: {
        input: { label: 'attenuation c', step: 0.001 },
        read: (s) => at(s).attenuation.c,
        write: (d, v: number) =>
          edit(d, (l) => {
            l.attenuation.c = v;
          }),
      },
    },
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
