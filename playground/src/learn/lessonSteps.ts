/**
 * The lecture as a walk through the playground: one step per idea, each with the state it sets and what to look at
 * (the Learn panel, Lesson.tsx, shows them; the playground README's "Learn the lecture" is the same path in
 * prose). A step ({@link applyStep}) sets the lecture's sphere and what it talks about, and leaves the rest (the
 * camera, the trackball's turn, other lights) as the student left it.
 */
import type { PlaygroundState } from '../state/schema';
import { defaultLight } from '../state/schema';

export interface LessonStep {
  /** A short name, for tests and links. */
  id: string;
  title: string;
  /** What to look at and how, in the page's words (the controls named as **Folder → input**). */
  text: string;
  /** The state the step is about beyond the lecture's sphere ({@link applyStep}), set on the state shown. */
  set?(d: PlaygroundState): void;
}

/** Light 2 of the lesson: beside the sphere, in the view, so that its gizmo can be dragged. */
export const LESSON_LIGHT_POSITION: [number, number, number] = [-1.8, 1.5, 0.5];

/** What every step starts from: the lecture's sphere in the single view, the lit colour, Phong shading. */
function lectureSphere(d: PlaygroundState): void {
  d.scene = 'sphere';
  d.view = 'single';
  d.material.output = 'color';
  d.material.shading = 'phong';
  d.material.lighting = 'blinn-phong';
  d.material.celBands = 0;
  d.material.normalMatrix = 'inverse-transpose';
  d.sphere.render = 'mesh';
  d.sphere.auto = false;
  d.sphere.base = 'tetrahedron';
  d.sphere.level = 6;
}

/** Two lights: the lecture's light 1, behind the eye, and light 2 in the view. */
function twoLights(d: PlaygroundState): void {
  if (d.lights.length === 0) d.lights.push(defaultLight());
  if (d.lights.length === 1) d.lights.push({ ...defaultLight(), position: [...LESSON_LIGHT_POSITION] });
}

export const LESSON_STEPS: readonly LessonStep[] = [
  {
    id: 'lights',
    title: 'Light sources: Ia, Id, Is',
    text: 'Light 1 sits at (-5, 10, 20), behind the eye: its gizmo is out of the view. This step adds light 2 beside the sphere: press **Light 2 → move light 2 with the gizmo** and drag it. **Alt+click** the sphere: the probe lists, for each light, l, its distance t and the terms it adds. Halve **Light 2 → Id (diffuse)** and probe again: its att·kd·Id·max(l·n, 0) line halves.',
    set: twoLights,
  },
  {
    id: 'terms',
    title: 'The terms: ka·Ia, kd·Id·max(l·n, 0), ks·Is·spec',
    text: '**Material → output** draws one term of I = ka·Ia + att·(kd·Id·max(l·n, 0) + ks·Is·spec) alone: the diffuse term now (back to **color** for the sum). **Alt+click** the sphere: the probe shows each light’s terms, their sum and the GPU’s pixel beside it. Change **Material → kd** and the picture and the probe follow.',
    set(d) {
      d.material.output = 'diffuse';
    },
  },
  {
    id: 'specular',
    title: 'Phong and Blinn-Phong',
    text: 'Phong lighting: r = 2(l·n)n − l and spec = max(v·r, 0)^α; the specular term alone is drawn. **Alt+click** the highlight: the probe shows r and v·r, and draws l, n, v and r at the point. Switch **Material → lighting** to blinn-phong: h = normalize(l + v), spec = max(n·h, 0)^α, a wider highlight at the same **shininess** α.',
    set(d) {
      d.material.lighting = 'phong';
      d.material.output = 'specular';
    },
  },
  {
    id: 'attenuation',
    title: 'Attenuation: 1 / (a + b·t + c·t²)',
    text: 'Light 1 is attenuated with c = 0.002: its diffuse and specular terms are scaled by 1/(a + b·t + c·t²), its ambient term is not. Press **attenuation curve** among the tools: the factor against the distance t, the sphere’s range of t drawn thick. **Alt+click**: the probe gives t and att at the pixel.',
    set(d) {
      if (d.lights.length === 0) d.lights.push(defaultLight());
      d.lights[0]!.attenuation = { a: 1, b: 0, c: 0.002 };
    },
  },
  {
    id: 'shadings',
    title: 'Flat, Gouraud and Phong shading',
    text: 'The compare view draws the lecture’s slide: flat, Gouraud, Phong and cel side by side on a coarse sphere (**Sphere → level** 2), one trackball turning all four. **Alt+click** a cell: the probe says where the equation is evaluated: the face’s centroid (flat), the three vertices and their barycentric weights (Gouraud), the point itself (Phong).',
    set(d) {
      d.view = 'compare';
      d.sphere.level = 2;
    },
  },
  {
    id: 'mach-bands',
    title: 'Mach bands',
    text: 'Gouraud shading on a coarse sphere. Press **intensity profile** among the tools and drag a line across the sphere: the plot shows the displayed intensity along it for flat, Gouraud and Phong shading, and marks where a profile’s slope jumps. Gouraud’s slope changes at every triangle edge: the eye sees a bright or dark band there that the pixels do not hold.',
    set(d) {
      d.material.shading = 'gouraud';
      d.sphere.level = 2;
    },
  },
  {
    id: 'normal-matrix',
    title: 'The normal matrix under a non-uniform scale',
    text: 'The sphere is scaled (2, 1, 2). **Alt+click** a point off the centre, then press **normal matrix** among the tools: the sphere shaded with (M⁻¹)ᵀ and with M side by side, a tangent and both normals at the point. Only (M⁻¹)ᵀ keeps the normal perpendicular to the surface; **Material → normal matrix** = M (wrong) draws the whole view the wrong way.',
    set(d) {
      if (d.model.scale.every((s) => s === d.model.scale[0])) d.model.scale = [2, 1, 2];
    },
  },
  {
    id: 'sphere',
    title: 'The subdivided sphere',
    text: 'An icosahedron divided twice. Raise **Sphere → level**: each level divides every triangle in four, and the stats count the triangles and bound the silhouette’s error in pixels. **auto detail** picks the level for the sphere’s size on screen; **draw as** = ray-cast impostor draws the exact sphere with two triangles.',
    set(d) {
      d.sphere.base = 'icosahedron';
      d.sphere.level = 2;
    },
  },
  {
    id: 'camera',
    title: 'The camera: lookAt and the projection',
    text: '**Camera → eye**, **at** and **up** are the lecture’s lookAt (its u, v, w); **projection**, **fovy °**, **near** and **far** the frustum, and **ortho r, l, t, b** the orthographic box. Click the view, then the movement keys move the eye along u, v and w.',
  },
  {
    id: 'trackball',
    title: 'The trackball',
    text: 'Drag the view (or press J/L, I/K) to turn the sphere. **Trackball → mapping** switches between Bell’s trackball and the arcball; **rotate speed**, **ball radius** and **damping** change the feel, **reset rotation** turns it back. The probe and the normal-matrix figure follow the turn.',
  },
  {
    id: 'cel',
    title: 'Cel shading',
    text: 'Four cel bands: the diffuse factor max(l·n, 0) is rounded to 4 shades and the highlight switched on or off. **Alt+click**: the probe names the band of each light. Change **Material → cel bands**; 0 turns it off.',
    set(d) {
      d.material.celBands = 4;
    },
  },
  {
    id: 'shader',
    title: 'The shader',
    text: 'The side column’s GLSL editor holds the program that draws the picture: only the lines this state compiles (**full source** shows every #if branch). Edit it: after a pause a program that compiles replaces the drawn one; one that does not is listed with the compiler’s errors by line, and the drawn one stays. **reset to generated** goes back.',
  },
  {
    id: 'take-home',
    title: 'Take the code home',
    text: 'Press **three.js** or **R3F** among the tools: the program that draws this picture, with its install line, ready to paste into an app. Every step above lives in the URL: **View → copy link** shares what you reached.',
  },
];

/** Sets step `step`'s state on `d`: the lecture's sphere in the single view, then what the step is about. */
export function applyStep(d: PlaygroundState, step: LessonStep): void {
  lectureSphere(d);
  step.set?.(d);
}
