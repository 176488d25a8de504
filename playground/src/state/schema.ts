/**
 * The playground's whole state, and a strict parser for state that comes from outside (the URL, localStorage),
 * both derived from the table of fields in `fields.ts`.
 *
 * Untrusted text is never executed or merged blindly: it is size-limited before `JSON.parse`, every key is
 * checked against the schema (unknown keys and `__proto__` / `constructor` / `prototype` are refused), every
 * number is range-checked, every enum checked. Missing keys take their defaults, so short URLs stay valid.
 * The parser builds a fresh object from the defaults; nothing from the input is kept by reference.
 */
import {
  DEPTH_MODES,
  defaultsOf,
  type FieldSpec,
  isField,
  LIGHT_FIELDS,
  MAX_LIGHTS,
  type Quat,
  type Rgb,
  SCENES,
  STATE_FIELDS,
  type StateOf,
  type Table,
  type Vec3,
} from './fields';

export type { Rgb, Vec3 };
export { DEPTH_MODES, MAX_LIGHTS, SCENES };

/** Everything the playground shows; `JSON.stringify` of it is what the URL carries. */
export type PlaygroundState = StateOf<typeof STATE_FIELDS>;
/** One light: the lecture's Ia, Id, Is and attenuation 1/(a + b·t + c·t²). */
export type LightState = StateOf<typeof LIGHT_FIELDS>;
/** Where the lighting equation is evaluated. */
export type Shading = PlaygroundState['material']['shading'];
/** Which specular equation. */
export type Lighting = PlaygroundState['material']['lighting'];
/** The solid the sphere is subdivided from. */
export type SphereBase = PlaygroundState['sphere']['base'];
/** Pointer-to-ball mapping of the trackball. */
export type TrackballMapping = PlaygroundState['trackball']['mapping'];
/** Camera projection. */
export type Projection = PlaygroundState['camera']['projection'];
/**
 * How the renderer should store depth (@shadelab/camera's DepthModeRequest: 'reversed-or-logarithmic' is
 * reversed-Z where EXT_clip_control exists, else logarithmic); changing it makes a new renderer.
 */
export type DepthMode = PlaygroundState['camera']['depth'];
/** One view of the lit sphere, or the lecture's flat | Gouraud | Phong | cel slide. */
export type ViewMode = PlaygroundState['view'];
/** How the sphere is drawn: a subdivided mesh, or a ray-cast impostor (exact, two triangles). */
export type SphereRender = PlaygroundState['sphere']['render'];
/**
 * What is drawn: the lecture's sphere, or one of the three.js scenes that show the material's features (an
 * instanced field of spheres, a skinned and morphing mesh, a textured model with a normal map, a scene lit by
 * three's lights with fog and clipping).
 */
export type SceneName = PlaygroundState['scene'];

/** Largest state text accepted, in UTF-16 code units (checked before parsing). */
export const STATE_MAX_CHARS = 16_384;

/** The lecture's demo light (see {@link LIGHT_FIELDS}). */
export function defaultLight(): LightState {
  return defaultsOf(LIGHT_FIELDS);
}

/** The lecture's demo scene (see {@link STATE_FIELDS}): a fresh object each call. */
export function defaultState(): PlaygroundState {
  return defaultsOf(STATE_FIELDS);
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

const quaternion: Parser<Quat> = (input, path, fallback) => {
  const q = tuple(4, num(-2, 2))(input, path, fallback);
  const length = Math.hypot(...q);
  if (Math.abs(length - 1) > 1e-3)
    throw new StateError(`${path}: length ${length} is not 1 (a unit quaternion)`);
  return q.map((c) => c / length) as Quat;
};

/** The parser of one row of the table. */
function fieldParser(field: FieldSpec<unknown>): Parser<unknown> {
  const kind = field.kind;
  switch (kind.type) {
    case 'enum':
      return oneOf(...kind.values) as Parser<unknown>;
    case 'number': {
      const range = num(kind.min, kind.max, kind);
      const refuse = kind.refuse;
      if (!refuse) return range as Parser<unknown>;
      return ((input, path, fallback: number) => {
        const n = range(input, path, fallback);
        if (n === refuse[0]) throw new StateError(`${path}: ${n} is not allowed (${refuse[1]})`);
        return n;
      }) as Parser<unknown>;
    }
    case 'boolean':
      return bool as Parser<unknown>;
    case 'vec3':
      return vec3(kind.limit) as Parser<unknown>;
    case 'rgb':
      return rgb as Parser<unknown>;
    case 'color':
      return hexColor as Parser<unknown>;
    case 'quaternion':
      return quaternion as Parser<unknown>;
    case 'list':
      return list(tableParser(kind.item), kind.max, () => defaultsOf(kind.item)) as Parser<unknown>;
  }
}

/** The parser of a group of rows: an object with exactly the table's keys. */
function tableParser(table: Table): Parser<Record<string, unknown>> {
  const shape = Object.fromEntries(
    Object.entries(table).map(([key, entry]) => [
      key,
      isField(entry) ? fieldParser(entry) : tableParser(entry),
    ]),
  ) as Shape<Record<string, unknown>>;
  return object(shape);
}

const stateParser = tableParser(STATE_FIELDS) as unknown as Parser<PlaygroundState>;

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
