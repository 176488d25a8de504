/**
 * The playground's whole state, and a strict parser for state that comes from outside (the URL, localStorage).
 *
 * Untrusted text is never executed or merged blindly: it is size-limited before `JSON.parse`, every key is
 * checked against the schema (unknown keys and `__proto__` / `constructor` / `prototype` are refused), every
 * number is range-checked, every enum checked. Missing keys take their defaults, so short URLs stay valid.
 * The parser builds a fresh object from the defaults; nothing from the input is kept by reference.
 */

/** A 3-vector `[x, y, z]`. */
export type Vec3 = [number, number, number];
/** A linear-RGB colour `[r, g, b]`, each ≥ 0 (intensities may exceed 1). */
export type Rgb = [number, number, number];

/** Where the lighting equation is evaluated. */
export type Shading = 'flat' | 'gouraud' | 'phong';
/** Which specular equation. */
export type Lighting = 'phong' | 'blinn-phong';
/** The solid the sphere is subdivided from. */
export type SphereBase = 'tetrahedron' | 'octahedron' | 'icosahedron';
/** Pointer-to-ball mapping of the trackball. */
export type TrackballMapping = 'arcball' | 'bell';
/** Camera projection. */
export type Projection = 'perspective' | 'orthographic';
/**
 * How the renderer should store depth (@shadelab/camera's DepthModeRequest: 'reversed-or-logarithmic' is
 * reversed-Z where EXT_clip_control exists, else logarithmic); changing it makes a new renderer.
 */
export type DepthMode = 'standard' | 'logarithmic' | 'reversed' | 'reversed-or-logarithmic';
/** Every depth mode, in the order the controls list them. */
export const DEPTH_MODES: readonly DepthMode[] = [
  'standard',
  'logarithmic',
  'reversed',
  'reversed-or-logarithmic',
];
/** One view of the lit sphere, or the lecture's flat | Gouraud | Phong | cel slide. */
export type ViewMode = 'single' | 'compare';
/** How the sphere is drawn: a subdivided mesh, or a ray-cast impostor (exact, two triangles). */
export type SphereRender = 'mesh' | 'impostor';
/**
 * What is drawn: the lecture's sphere, or one of the three.js scenes that show the material's features (an
 * instanced field of spheres, a skinned and morphing mesh, a textured model with a normal map, a scene lit by
 * three's lights with fog and clipping).
 */
export type SceneName = 'sphere' | 'instanced' | 'skinned' | 'textured' | 'lights';
/** Every scene, in the order the picker lists them. */
export const SCENES: readonly SceneName[] = ['sphere', 'instanced', 'skinned', 'textured', 'lights'];

/** One light: the lecture's Ia, Id, Is and attenuation 1/(a + b·t + c·t²). */
export interface LightState {
  position: Vec3;
  ambient: Rgb;
  diffuse: Rgb;
  specular: Rgb;
  attenuation: { a: number; b: number; c: number };
}

/** Everything the playground shows; `JSON.stringify` of it is what the URL carries. */
export interface PlaygroundState {
  view: ViewMode;
  /** The scene drawn (the lecture's sphere by default). */
  scene: SceneName;
  material: {
    shading: Shading;
    lighting: Lighting;
    /** 0 = off, N ≥ 2 discrete diffuse shades. */
    celBands: number;
    outline: boolean;
    /** Outline thickness along the normal, model units. */
    outlineWidth: number;
    /** Outline colour, CSS hex `#rrggbb` (sRGB, as a colour picker gives it). */
    outlineColor: string;
    ka: Rgb;
    kd: Rgb;
    ks: Rgb;
    shininess: number;
  };
  lights: LightState[];
  sphere: {
    render: SphereRender;
    base: SphereBase;
    level: number;
    auto: boolean;
    maxErrorPx: number;
    /** The sphere's radius before the model scale (@shadelab/sphere's `radius`), model units. */
    radius: number;
  };
  model: { scale: Vec3 };
  camera: {
    projection: Projection;
    /** Depth buffer mode (a new canvas and renderer when it changes). */
    depth: DepthMode;
    eye: Vec3;
    at: Vec3;
    up: Vec3;
    /** Vertical field of view, degrees. */
    fovy: number;
    near: number;
    far: number;
    /** Orthographic box (the lecture's r, l, t, b); r and l follow the aspect when `fitAspect`. */
    right: number;
    left: number;
    top: number;
    bottom: number;
    fitAspect: boolean;
    /** Zoom factor (the trackball's wheel zoom of an orthographic camera). */
    zoom: number;
    /** Movement keys' speed, world units per key press. */
    moveSpeed: number;
    /** A pointer drag turns the camera's gaze (instead of the trackball turning the sphere). */
    dragTurns: boolean;
    /** Gaze turn per pixel dragged, radians. */
    turnSpeed: number;
  };
  trackball: {
    mapping: TrackballMapping;
    rotateSpeed: number;
    zoomSpeed: number;
    /** Zoom limits (factors of the opening view). */
    minZoom: number;
    maxZoom: number;
    /** After a fling the sphere keeps turning and slows down (the trackball's `enableDamping`). */
    damping: boolean;
    /** Fraction of the spin lost per 1/60 s when damping, in (0, 1]. */
    dampingFactor: number;
    /** Ball radius as a fraction of half the canvas's shorter side (the trackball's `radius`). */
    radius: number;
    /** Accumulated rotation as a unit quaternion `[x, y, z, w]`. */
    rotation: [number, number, number, number];
  };
}

/** Largest state text accepted, in UTF-16 code units (checked before parsing). */
export const STATE_MAX_CHARS = 16_384;
/** Most lights the playground accepts. */
export const MAX_LIGHTS = 8;

/** The lecture's demo scene. */
export function defaultLight(): LightState {
  return {
    position: [-5, 10, 20],
    ambient: [0.2, 0.2, 0.2],
    diffuse: [1, 1, 1],
    specular: [0.8, 0.8, 0.8],
    attenuation: { a: 1, b: 0, c: 0 },
  };
}

/**
 * The lecture's demo scene: tetrahedron level 6, scale (2, 1, 2), eye (0, 0, 3), fovy 90, Phong shading with
 * Blinn-Phong lighting (the lecture's shader uses the half vector). The lecture never sets ka, kd, ks or the
 * shininess: those values are the playground's own. The trackball keeps its package defaults (Bell's mapping).
 */
export function defaultState(): PlaygroundState {
  return {
    view: 'single',
    scene: 'sphere',
    material: {
      shading: 'phong',
      lighting: 'blinn-phong',
      celBands: 0,
      outline: false,
      outlineWidth: 0.03,
      outlineColor: '#f2f2f2',
      ka: [0.8, 0.35, 0.15],
      kd: [0.8, 0.35, 0.15],
      ks: [1, 1, 1],
      shininess: 50,
    },
    lights: [defaultLight()],
    sphere: { render: 'mesh', base: 'tetrahedron', level: 6, auto: false, maxErrorPx: 0.5, radius: 1 },
    model: { scale: [2, 1, 2] },
    camera: {
      projection: 'perspective',
      depth: 'standard',
      eye: [0, 0, 3],
      at: [0, 0, 0],
      up: [0, 1, 0],
      fovy: 90,
      near: 0.1,
      far: 10,
      right: 2,
      left: -2,
      top: 1.5,
      bottom: -1.5,
      fitAspect: true,
      zoom: 1,
      moveSpeed: 0.1,
      dragTurns: false,
      turnSpeed: 0.005,
    },
    trackball: {
      mapping: 'bell',
      rotateSpeed: 1,
      zoomSpeed: 1,
      minZoom: 0.01,
      maxZoom: 100,
      damping: false,
      dampingFactor: 0.05,
      radius: 1,
      rotation: [0, 0, 0, 1],
    },
  };
}

// ---------------------------------------------------------------------------------------------------------
// A tiny strict schema language: each node parses `unknown` into a typed value or throws StateError.

/** A refusal: names the offending path, the value and what was allowed. */
export class StateError extends Error {
  override name = 'StateError';
}

type Parser<T> = (input: unknown, path: string, fallback: T) => T;

const FORBIDDEN_KEYS = new Set(['__proto__', 'constructor', 'prototype']);

function show(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value.length > 40 ? `${value.slice(0, 40)}…` : value);
  if (typeof value === 'number' || typeof value === 'boolean' || value === null) return String(value);
  return Array.isArray(value) ? 'an array' : typeof value;
}

const num =
  (min: number, max: number, { integer = false, openMin = false, openMax = false } = {}): Parser<number> =>
  (input, path) => {
    if (typeof input !== 'number' || !Number.isFinite(input)) {
      throw new StateError(`${path}: ${show(input)} is not a finite number`);
    }
    const range = `${openMin ? '(' : '['}${min}, ${max}${openMax ? ')' : ']'}`;
    if (input < min || input > max || (openMin && input === min) || (openMax && input === max)) {
      throw new StateError(`${path}: ${input} is outside ${range}`);
    }
    if (integer && !Number.isInteger(input)) throw new StateError(`${path}: ${input} is not an integer`);
    return input;
  };

const oneOf =
  <T extends string>(...values: T[]): Parser<T> =>
  (input, path) => {
    if (typeof input !== 'string' || !(values as string[]).includes(input)) {
      throw new StateError(`${path}: ${show(input)} is not one of ${values.join(', ')}`);
    }
    return input as T;
  };

const bool: Parser<boolean> = (input, path) => {
  if (typeof input !== 'boolean') throw new StateError(`${path}: ${show(input)} is not true or false`);
  return input;
};

function tuple<N extends number>(n: N, item: Parser<number>): Parser<number[]> {
  return (input, path, fallback) => {
    if (!Array.isArray(input) || input.length !== n) {
      throw new StateError(`${path}: ${show(input)} is not an array of ${n} numbers`);
    }
    return input.map((v, i) => item(v, `${path}[${i}]`, fallback[i]!));
  };
}

const vec3 = (limit: number) => tuple(3, num(-limit, limit)) as unknown as Parser<Vec3>;
const rgb = tuple(3, num(0, 100)) as unknown as Parser<Rgb>;

function checkKeys(input: unknown, path: string, allowed: readonly string[]): Record<string, unknown> {
  if (typeof input !== 'object' || input === null || Array.isArray(input)) {
    throw new StateError(`${path}: ${show(input)} is not an object`);
  }
  for (const key of Object.keys(input)) {
    if (FORBIDDEN_KEYS.has(key)) throw new StateError(`${path}: key ${JSON.stringify(key)} is refused`);
    if (!allowed.includes(key)) {
      throw new StateError(`${path}: unknown key ${show(key)} (allowed: ${allowed.join(', ')})`);
    }
  }
  return input as Record<string, unknown>;
}

type Shape<T> = { [K in keyof T]: Parser<T[K]> };

function object<T extends object>(shape: Shape<T>): Parser<T> {
  const keys = Object.keys(shape);
  return (input, path, fallback) => {
    const record = checkKeys(input, path, keys);
    const out = {} as T;
    for (const key of keys as (keyof T & string)[]) {
      const value = Object.hasOwn(record, key) ? record[key] : undefined;
      out[key] =
        value === undefined
          ? structuredClone(fallback[key])
          : shape[key](value, `${path}.${key}`, fallback[key]);
    }
    return out;
  };
}

function list<T>(item: Parser<T>, max: number, makeDefault: () => T): Parser<T[]> {
  return (input, path) => {
    if (!Array.isArray(input)) throw new StateError(`${path}: ${show(input)} is not an array`);
    if (input.length > max) throw new StateError(`${path}: ${input.length} items is more than ${max}`);
    return input.map((v, i) => item(v, `${path}[${i}]`, makeDefault()));
  };
}

const hexColor: Parser<string> = (input, path) => {
  if (typeof input !== 'string' || !/^#[0-9a-f]{6}$/i.test(input)) {
    throw new StateError(`${path}: ${show(input)} is not a colour #rrggbb`);
  }
  return input.toLowerCase();
};

const celBands: Parser<number> = (input, path, fallback) => {
  const n = num(0, 16, { integer: true })(input, path, fallback);
  if (n === 1) throw new StateError(`${path}: 1 is not allowed (0 = off, or 2 … 16 bands)`);
  return n;
};

const quaternion: Parser<[number, number, number, number]> = (input, path, fallback) => {
  const q = tuple(4, num(-2, 2))(input, path, fallback);
  const length = Math.hypot(...q);
  if (Math.abs(length - 1) > 1e-3)
    throw new StateError(`${path}: length ${length} is not 1 (a unit quaternion)`);
  return q.map((c) => c / length) as [number, number, number, number];
};

const lightParser = object<LightState>({
  position: vec3(1e4),
  ambient: rgb,
  diffuse: rgb,
  specular: rgb,
  attenuation: object({ a: num(0, 1e3), b: num(0, 1e3), c: num(0, 1e3) }),
});

const stateParser = object<PlaygroundState>({
  view: oneOf('single', 'compare'),
  scene: oneOf(...SCENES),
  material: object({
    shading: oneOf('flat', 'gouraud', 'phong'),
    lighting: oneOf('phong', 'blinn-phong'),
    celBands,
    outline: bool,
    outlineWidth: num(0, 1),
    outlineColor: hexColor,
    ka: rgb,
    kd: rgb,
    ks: rgb,
    shininess: num(0, 1e4),
  }),
  lights: list(lightParser, MAX_LIGHTS, defaultLight),
  sphere: object({
    render: oneOf('mesh', 'impostor'),
    base: oneOf('tetrahedron', 'octahedron', 'icosahedron'),
    level: num(0, 16, { integer: true }),
    auto: bool,
    maxErrorPx: num(0.01, 100),
    radius: num(0, 1e3, { openMin: true }),
  }),
  model: object({ scale: vec3(1e3) }),
  camera: object({
    projection: oneOf('perspective', 'orthographic'),
    depth: oneOf(...DEPTH_MODES),
    eye: vec3(1e4),
    at: vec3(1e4),
    up: vec3(1e4),
    fovy: num(0, 180, { openMin: true, openMax: true }),
    near: num(0, 1e6, { openMin: true }),
    far: num(0, 1e9, { openMin: true }),
    right: num(-1e4, 1e4),
    left: num(-1e4, 1e4),
    top: num(-1e4, 1e4),
    bottom: num(-1e4, 1e4),
    fitAspect: bool,
    zoom: num(0.01, 100),
    moveSpeed: num(0, 100, { openMin: true }),
    dragTurns: bool,
    turnSpeed: num(0, 1),
  }),
  trackball: object({
    mapping: oneOf('arcball', 'bell'),
    rotateSpeed: num(0, 100),
    zoomSpeed: num(0, 100),
    minZoom: num(1e-3, 1e3, { openMin: true }),
    maxZoom: num(1e-3, 1e3, { openMin: true }),
    damping: bool,
    dampingFactor: num(0, 1, { openMin: true }),
    radius: num(0, 100, { openMin: true }),
    rotation: quaternion,
  }),
});

/** What {@link parseState} returns: a fresh state, or a message naming what was refused. */
export type ParseResult = { ok: true; state: PlaygroundState } | { ok: false; error: string };

/**
 * Parses untrusted state text (JSON). Refuses text longer than {@link STATE_MAX_CHARS}, malformed JSON,
 * unknown or prototype-polluting keys, wrong types and out-of-range numbers; missing keys take defaults.
 * Never throws.
 */
export function parseState(text: string): ParseResult {
  if (typeof text !== 'string') return { ok: false, error: 'state: not text' };
  if (text.length > STATE_MAX_CHARS) {
    return {
      ok: false,
      error: `state: ${text.length} characters is more than the limit of ${STATE_MAX_CHARS}`,
    };
  }
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (error) {
    return { ok: false, error: `state: malformed JSON (${(error as Error).message})` };
  }
  return validateState(json);
}

/** Validates an already-parsed value against the schema (see {@link parseState}). Never throws. */
export function validateState(value: unknown): ParseResult {
  try {
    return { ok: true, state: stateParser(value, 'state', defaultState()) };
  } catch (error) {
    if (error instanceof StateError) return { ok: false, error: error.message };
    throw error;
  }
}

/** The state as compact JSON text (what {@link parseState} reads back). */
export function serializeState(state: PlaygroundState): string {
  return JSON.stringify(state);
}
