/**
 * The scene picker's scenes: a builder per scene (one file each), their labels in the panel, and what of the
 * panel applies to each.
 *
 * A scene is mounted as JSX (sceneRoot.tsx: a `<primitive>` under the trackball, its `enter`/`leave` in a layout
 * effect) but built in code, as an R3F app builds such content in a `useMemo`: its substance is numbers (40
 * instance matrices and colours, four posed bones and a morph target, textures computed pixel by pixel), and the
 * viewer needs its parts as objects to set the panel's material on them and each compare cell's shading. Unit
 * tests build them without a renderer (scenes.test.ts).
 */
import type { SceneName } from '../../state/schema';
import { createInstancedScene } from './instanced';
import { createLightsScene } from './lights';
import { createSkinnedScene } from './skinned';
import { createTexturedScene } from './textured';
import type { DemoScene } from './types';

export type { DemoScene, ScenePart } from './types';

/** The picker's label of each scene (leva select: label → value). */
export const SCENE_LABELS: Readonly<Record<SceneName, string>> = {
  sphere: "the lecture's sphere",
  instanced: 'instanced spheres',
  skinned: 'skinned + morphing mesh',
  textured: 'textured, normal map',
  lights: "three's lights, fog, clipping",
  model: 'your model (.glb / .gltf)',
};

/** Builds one of the scenes that replace the lecture's sphere. */
export function createScene(name: Exclude<SceneName, 'sphere' | 'model'>): DemoScene {
  switch (name) {
    case 'instanced':
      return createInstancedScene();
    case 'skinned':
      return createSkinnedScene();
    case 'textured':
      return createTexturedScene();
    case 'lights':
      return createLightsScene();
  }
}

/** Inputs of the panel (leva paths) that change only the lecture's sphere. */
export const SPHERE_ONLY_INPUTS = [
  'Sphere.render',
  'Sphere.base',
  'Sphere.level',
  'Sphere.auto',
  'Sphere.maxErrorPx',
  'Sphere.radius',
  'Sphere.scale',
] as const;

/** What the panel's note says about a scene: what it shows and which options do not apply to it. */
export function sceneNote(name: SceneName): string {
  const others =
    'Material (outline included), lights, camera, trackball and the compare view apply; the Sphere folder and the GLSL editor are for the lecture’s sphere only (greyed out).';
  switch (name) {
    case 'sphere':
      return 'The lecture’s sphere: every option applies.';
    case 'instanced':
      return `One InstancedMesh of 40 spheres; instanceColor tints ka and kd. ${others}`;
    case 'skinned':
      return `A cylinder on four bones, posed, with a morph target swelling its middle. ${others}`;
    case 'textured':
      return `A torus knot with a checker map (tints ka and kd) and a bump normal map (Phong shading only: gouraud and flat have no per-fragment normal), made in code. ${others}`;
    case 'lights':
      return `Lit by three's hemisphere, ambient, directional, point and spot lights (next to the panel's lights), with fog and a clipping plane. ${others}`;
    case 'model':
      return 'Your glTF model, its materials swapped for ShadingMaterials (they keep its colours and maps), lit by a rig of three’s lights: shading, lighting, cel bands, the outline, the camera, the trackball and the compare view apply; ka/kd/ks, shininess and the panel’s lights are the other scenes’; the Sphere folder and the GLSL editor are for the lecture’s sphere only (greyed out).';
  }
}
