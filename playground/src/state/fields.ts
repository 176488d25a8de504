/**
 * The one table of the playground's options. Each row is one field of the state: its type and range (what the
 * strict parser accepts), its default, its panel input (label, step, options) and, where the values come from a
 * package, the package constant. The default state and the parser (`schema.ts`) and the leva panel
 * (`ui/panelFields.ts`) are derived from it: adding an option is one row here.
 */
import type { DepthModeRequest, ProjectionType } from '@shadelab/camera';
import { LIGHTINGS, MAX_CEL_BANDS, NORMAL_MATRIX_MODES, SHADING_OUTPUTS, SHADINGS } from '@shadelab/material';
import { SPHERE_BASES } from '@shadelab/sphere';
import type { BallMapping } from '@shadelab/trackball';

/** A 3-vector `[x, y, z]`. */
export type Vec3 = [number, number, number];
/** A linear-RGB colour `[r, g, b]`, each ≥ 0 (intensities may exceed 1). */
export type Rgb = [number, number, number];
/** A unit quaternion `[x, y, z, w]`. */
export type Quat = [number, number, number, number];

/** What the parser accepts for one field. */
export type Kind =
  | { type: 'enum'; values: readonly string[] }
  | {
      type: 'number';
      min: number;
      max: number;
      integer?: boolean;
      openMin?: boolean;
      openMax?: boolean;
      /** A value inside the range that is still refused, and why. */
      refuse?: readonly [value: number, why: string];
    }
  | { type: 'boolean' }
  | { type: 'vec3'; limit: number }
  | { type: 'rgb' }
  | { type: 'color' }
  | { type: 'quaternion' }
  | { type: 'list'; item: Table; max: number };

/** The field's leva input: its label and settings (its folder is its group's, see {@link FOLDER_OF}). */
export interface PanelInput {
  label: string;
  step?: number;
  /** Slider bounds (leva draws a slider only when both are given). */
  min?: number;
  max?: number;
  /**
   * The select's entries when they are not the values in their order: label → value, or the values in the
   * panel's order (the same set: a test checks it).
   */
  options?: Readonly<Record<string, string>> | readonly string[];
  /** The leva key when it is not the field's name (a light's inputs: `light<n><key>`). */
  key?: string;
}

/** One row of the table; `T` is the field's type in the state. */
export interface FieldSpec<T> {
  readonly kind: Kind;
  readonly default: T;
  /** The panel input, or why the field is not in the panel. */
  readonly panel: PanelInput | { hidden: string };
  /** The package constant its values or range come from. */
  readonly from?: string;
}

/** A group of rows (an object of the state). */
export interface Table {
  readonly [key: string]: FieldSpec<unknown> | Table;
}

/** The state type a table describes. */
export type StateOf<S> = {
  -readonly [K in keyof S]: S[K] extends FieldSpec<infer T> ? T : StateOf<S[K]>;
};

const row = <T>(kind: Kind, value: T, panel: FieldSpec<T>['panel'], from?: string): FieldSpec<T> =>
  from === undefined ? { kind, default: value, panel } : { kind, default: value, panel, from };
const choice = <T extends string>(values: readonly T[], value: T, panel: PanelInput, from?: string) =>
  row<T>({ type: 'enum', values }, value, panel, from);
type Range = Omit<Extract<Kind, { type: 'number' }>, 'type'>;
const num = (value: number, range: Range, panel: PanelInput | { hidden: string }, from?: string) =>
  row<number>({ type: 'number', ...range }, value, panel, from);
const flag = (value: boolean, panel: PanelInput) => row<boolean>({ type: 'boolean' }, value, panel);
const vec3 = (value: Vec3, limit: number, panel: PanelInput) =>
  row<Vec3>({ type: 'vec3', limit }, value, panel);
const rgb = (value: Rgb, label: string, key?: string) =>
  row<Rgb>({ type: 'rgb' }, value, key === undefined ? { label, step: 0.05 } : { label, step: 0.05, key });

/** Largest number of cel bands the panel offers (the material takes up to `MAX_CEL_BANDS`). */
const CEL_BANDS = Math.min(16, MAX_CEL_BANDS);

/** Every depth mode, in the order the controls list them (@shadelab/camera's `DepthModeRequest`). */
export const DEPTH_MODES = [
  'standard',
  'logarithmic',
  'reversed',
  'reversed-or-logarithmic',
] as const satisfies readonly DepthModeRequest[];
/**
 * Every scene, in the order the picker lists them. `'model'` is the user's own glTF: the URL says only that it
 * is shown; the file's bytes are this browser's (IndexedDB, `engine/modelStore.ts`).
 */
export const SCENES = ['sphere', 'instanced', 'skinned', 'textured', 'lights', 'model'] as const;
/** The renderers the playground switches between (WebGPURenderer runs its WebGL2 backend without WebGPU). */
export const RENDERERS = ['webgl', 'webgpu'] as const;
const PROJECTIONS = ['perspective', 'orthographic'] as const satisfies readonly ProjectionType[];
const MAPPINGS = ['arcball', 'bell'] as const satisfies readonly BallMapping[];

/** One light: the lecture's Ia, Id, Is and attenuation 1/(a + b·t + c·t²); the lecture's demo light. */
export const LIGHT_FIELDS = {
  position: vec3([-5, 10, 20], 1e4, { label: 'position', step: 0.5, key: 'Position' }),
  ambient: rgb([0.2, 0.2, 0.2], 'Ia (ambient)', 'Ia'),
  diffuse: rgb([1, 1, 1], 'Id (diffuse)', 'Id'),
  specular: rgb([0.8, 0.8, 0.8], 'Is (specular)', 'Is'),
  attenuation: {
    a: num(1, { min: 0, max: 1e3 }, { label: 'attenuation a', step: 0.1, key: 'A' }),
    b: num(0, { min: 0, max: 1e3 }, { label: 'attenuation b', step: 0.01, key: 'B' }),
    c: num(0, { min: 0, max: 1e3 }, { label: 'attenuation c', step: 0.001, key: 'C' }),
  },
} as const satisfies Table;

/** The defaults of a table: a fresh object (nothing shared with the table). */
export function defaultsOf<S extends Table>(table: S): StateOf<S> {
  const out: Record<string, unknown> = {};
  for (const [key, entry] of Object.entries(table)) {
    out[key] = isField(entry) ? structuredClone(entry.default) : defaultsOf(entry);
  }
  return out as StateOf<S>;
}

/** Whether a table entry is a row (else it is a group). */
export function isField(entry: FieldSpec<unknown> | Table): entry is FieldSpec<unknown> {
  return 'kind' in entry && 'panel' in entry;
}

/** Most lights the playground accepts. */
export const MAX_LIGHTS = 8;

/**
 * The lecture's demo scene: tetrahedron level 6, scale (2, 1, 2), eye (0, 0, 3), fovy 90, Phong shading with
 * Blinn-Phong lighting (the lecture's shader uses the half vector). The lecture never sets ka, kd, ks or the
 * shininess: those values are the playground's own. The trackball keeps its package defaults (Bell's mapping).
 * Within a group, rows are in the panel's order.
 */
export const STATE_FIELDS = {
  /**
   * One view, the lecture's flat | Gouraud | Phong | cel slide, or the parity view: WebGL mode's and WebGPU
   * mode's pictures of the state side by side with a heat map of their difference and its numbers.
   */
  view: choice(['single', 'compare', 'parity'], 'single', {
    label: 'view',
    options: {
      'single sphere': 'single',
      'flat | Gouraud | Phong | cel': 'compare',
      'WebGL vs WebGPU parity': 'parity',
    },
  }),
  /** The scene drawn (the lecture's sphere by default); the picker's labels are `SCENE_LABELS`. */
  scene: choice(SCENES, 'sphere', { label: 'scene' }),
  /**
   * three's WebGLRenderer with ShadingMaterial, or WebGPURenderer with ShadingNodeMaterial (its WebGPU backend, or
   * its WebGL2 backend where WebGPU is missing); `engine/webgpu/` says what WebGPU mode draws.
   */
  renderer: choice(RENDERERS, 'webgl', {
    label: 'renderer',
    options: { WebGL: 'webgl', 'WebGPU (WebGL2 fallback)': 'webgpu' },
  }),
  material: {
    shading: choice(SHADINGS, 'phong', { label: 'shading' }, '@shadelab/material SHADINGS'),
    lighting: choice(LIGHTINGS, 'blinn-phong', { label: 'lighting' }, '@shadelab/material LIGHTINGS'),
    /** 0 = off, N ≥ 2 discrete diffuse shades. */
    celBands: num(
      0,
      { min: 0, max: CEL_BANDS, integer: true, refuse: [1, `0 = off, or 2 … ${CEL_BANDS} bands`] },
      { label: 'cel bands', step: 1 },
      '@shadelab/material MAX_CEL_BANDS',
    ),
    outline: flag(false, { label: 'outline' }),
    /** Outline thickness along the normal, model units. */
    outlineWidth: num(0.03, { min: 0, max: 1 }, { label: 'outline width', step: 0.005 }),
    /** Outline colour, CSS hex `#rrggbb` (sRGB, as a colour picker gives it). */
    outlineColor: row<string>({ type: 'color' }, '#f2f2f2', { label: 'outline colour' }),
    ka: rgb([0.8, 0.35, 0.15], 'ka'),
    kd: rgb([0.8, 0.35, 0.15], 'kd'),
    ks: rgb([1, 1, 1], 'ks'),
    shininess: num(50, { min: 0, max: 1e4 }, { label: 'shininess', step: 1 }),
    /** What the material draws: the lit colour, or one term of the lecture's equation alone (a term view). */
    output: choice(SHADING_OUTPUTS, 'color', { label: 'output' }, '@shadelab/material SHADING_OUTPUTS'),
    /** How normals go to world space: (M⁻¹)ᵀ, or M itself (the lecture's wrong way, a teaching aid). */
    normalMatrix: choice(
      NORMAL_MATRIX_MODES,
      'inverse-transpose',
      { label: 'normal matrix', options: { '(M⁻¹)ᵀ': 'inverse-transpose', 'M (wrong)': 'model' } },
      '@shadelab/material NORMAL_MATRIX_MODES',
    ),
  },
  lights: row<StateOf<typeof LIGHT_FIELDS>[]>(
    { type: 'list', item: LIGHT_FIELDS, max: MAX_LIGHTS },
    [defaultsOf(LIGHT_FIELDS)],
    { hidden: 'each light has its own folder (LIGHT_FIELDS)' },
  ),
  sphere: {
    /** A subdivided mesh, or a ray-cast impostor (exact, two triangles). */
    render: choice(['mesh', 'impostor'], 'mesh', {
      label: 'draw as',
      options: { 'subdivided mesh': 'mesh', 'ray-cast impostor': 'impostor' },
    }),
    base: choice(SPHERE_BASES, 'tetrahedron', { label: 'base' }, '@shadelab/sphere SPHERE_BASES'),
    level: num(6, { min: 0, max: 16, integer: true }, { label: 'level', step: 1 }),
    auto: flag(false, { label: 'auto detail' }),
    maxErrorPx: num(0.5, { min: 0.01, max: 100 }, { label: 'max error px', step: 0.05 }),
    /** The sphere's radius before the model scale (@shadelab/sphere's `radius`), model units. */
    radius: num(1, { min: 0, max: 1e3, openMin: true }, { label: 'radius', step: 0.1 }),
  },
  model: { scale: vec3([2, 1, 2], 1e3, { label: 'model scale', step: 0.1 }) },
  camera: {
    projection: choice(
      PROJECTIONS,
      'perspective',
      { label: 'projection' },
      '@shadelab/camera ProjectionType',
    ),
    /** Depth buffer mode (a new canvas and renderer when it changes). */
    depth: choice(DEPTH_MODES, 'standard', { label: 'depth buffer' }, '@shadelab/camera DepthModeRequest'),
    eye: vec3([0, 0, 3], 1e4, { label: 'eye', step: 0.1 }),
    at: vec3([0, 0, 0], 1e4, { label: 'at', step: 0.1 }),
    up: vec3([0, 1, 0], 1e4, { label: 'up', step: 0.1 }),
    /** Vertical field of view, degrees. */
    fovy: num(90, { min: 0, max: 180, openMin: true, openMax: true }, { label: 'fovy °', step: 1 }),
    near: num(0.1, { min: 0, max: 1e6, openMin: true }, { label: 'near', step: 0.01 }),
    far: num(10, { min: 0, max: 1e9, openMin: true }, { label: 'far', step: 1 }),
    /** Orthographic box (the lecture's r, l, t, b); r and l follow the aspect when `fitAspect`. */
    right: num(2, { min: -1e4, max: 1e4 }, { label: 'ortho r', step: 0.1 }),
    left: num(-2, { min: -1e4, max: 1e4 }, { label: 'ortho l', step: 0.1 }),
    top: num(1.5, { min: -1e4, max: 1e4 }, { label: 'ortho t', step: 0.1 }),
    bottom: num(-1.5, { min: -1e4, max: 1e4 }, { label: 'ortho b', step: 0.1 }),
    fitAspect: flag(true, { label: 'ortho fits aspect' }),
    /** A pointer drag turns the camera's gaze (instead of the trackball turning the sphere). */
    dragTurns: flag(false, { label: 'drag turns camera' }),
    /** Gaze turn per pixel dragged, radians. */
    turnSpeed: num(0.005, { min: 0, max: 1 }, { label: 'turn speed rad/px', step: 0.001 }),
    /** Movement keys' speed, world units per key press. */
    moveSpeed: num(0.1, { min: 0, max: 100, openMin: true }, { label: 'move speed', step: 0.01 }),
    /** Zoom factor (the trackball's wheel zoom of an orthographic camera). */
    zoom: num(1, { min: 0.01, max: 100 }, { hidden: 'set by the trackball (wheel zoom)' }),
  },
  trackball: {
    mapping: choice(
      MAPPINGS,
      'bell',
      { label: 'mapping', options: ['bell', 'arcball'] },
      '@shadelab/trackball BallMapping',
    ),
    rotateSpeed: num(1, { min: 0, max: 100 }, { label: 'rotate speed', step: 0.1 }),
    zoomSpeed: num(1, { min: 0, max: 100 }, { label: 'zoom speed', step: 0.1 }),
    /** Zoom limits (factors of the opening view). */
    minZoom: num(0.01, { min: 1e-3, max: 1e3, openMin: true }, { label: 'min zoom', step: 0.01 }),
    maxZoom: num(100, { min: 1e-3, max: 1e3, openMin: true }, { label: 'max zoom', step: 0.1 }),
    /** Ball radius as a fraction of half the canvas's shorter side (the trackball's `radius`). */
    radius: num(1, { min: 0, max: 100, openMin: true }, { label: 'ball radius', step: 0.1 }),
    /** After a fling the sphere keeps turning and slows down (the trackball's `enableDamping`). */
    damping: flag(false, { label: 'damping (spin on)' }),
    /** Fraction of the spin lost per 1/60 s when damping, in (0, 1]. */
    dampingFactor: num(
      0.05,
      { min: 0, max: 1, openMin: true },
      { label: 'damping factor', step: 0.01, min: 0.01, max: 1 },
    ),
    /** Accumulated rotation as a unit quaternion `[x, y, z, w]`. */
    rotation: row<Quat>({ type: 'quaternion' }, [0, 0, 0, 1], { hidden: 'set by the trackball (drag)' }),
  },
} as const satisfies Table;

/** The panel folder of each group of {@link STATE_FIELDS} (lights have a folder each). */
export const FOLDER_OF = {
  view: 'View',
  scene: 'View',
  renderer: 'View',
  material: 'Material',
  lights: 'Lights',
  sphere: 'Sphere',
  model: 'Sphere',
  camera: 'Camera',
  trackball: 'Trackball',
} as const satisfies Record<keyof typeof STATE_FIELDS, string>;
