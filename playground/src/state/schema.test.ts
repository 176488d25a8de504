import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Trackball } from '@shadelab/trackball';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  defaultLight,
  defaultState,
  MAX_LIGHTS,
  type PlaygroundState,
  parseState,
  SCENES,
  STATE_MAX_CHARS,
  serializeState,
  validateState,
} from './schema';

const refused = (text: string) => {
  const result = parseState(text);
  expect(result.ok).toBe(false);
  return result.ok ? '' : result.error;
};

describe('parseState', () => {
  it('reads back what serializeState wrote', () => {
    const state = defaultState();
    state.camera.projection = 'orthographic';
    state.lights.push({ ...defaultLight(), position: [1, 2, 3] });
    const result = parseState(serializeState(state));
    expect(result).toEqual({ ok: true, state });
  });

  it('opens on the lecture scene', () => {
    const state = defaultState();
    expect(state.sphere).toMatchObject({ base: 'tetrahedron', level: 6 });
    expect(state.model.scale).toEqual([2, 1, 2]);
    expect(state.camera).toMatchObject({
      eye: [0, 0, 3],
      at: [0, 0, 0],
      up: [0, 1, 0],
      fovy: 90,
      near: 0.1,
      far: 10,
    });
    expect(state.lights).toEqual([
      {
        position: [-5, 10, 20],
        ambient: [0.2, 0.2, 0.2],
        diffuse: [1, 1, 1],
        specular: [0.8, 0.8, 0.8],
        attenuation: { a: 1, b: 0, c: 0 },
      },
    ]);
    // The lecture's shader: per-fragment (Phong) shading, and the half vector (Blinn-Phong) in its specular.
    expect(state.material).toMatchObject({ shading: 'phong', lighting: 'blinn-phong' });
    expect(state.trackball.rotation).toEqual([0, 0, 0, 1]);
  });

  it("keeps the packages' own defaults where the lecture sets nothing", () => {
    const state = defaultState();
    const trackball = new Trackball();
    expect(state.trackball).toMatchObject({
      mapping: trackball.mapping,
      rotateSpeed: trackball.rotateSpeed,
      zoomSpeed: trackball.zoomSpeed,
      minZoom: trackball.minZoom,
      maxZoom: trackball.maxZoom,
      damping: trackball.enableDamping,
      dampingFactor: trackball.dampingFactor,
      radius: trackball.radius,
    });
    expect(state.trackball.mapping).toBe('bell');
    expect(state.sphere.radius).toBe(new SubdivisionSphereGeometry().parameters.radius);
  });

  it('reads an outline colour #rrggbb (lower-cased) and refuses anything else, naming it', () => {
    const result = parseState('{"material":{"outlineColor":"#FF8000"}}');
    expect(result.ok && result.state.material.outlineColor).toBe('#ff8000');
    for (const bad of ['"red"', '"#fff"', '"#ff800g"', '16711680', 'null']) {
      expect(refused(`{"material":{"outlineColor":${bad}}}`)).toMatch(
        /^state\.material\.outlineColor: .* is not a colour #rrggbb$/,
      );
    }
  });

  it('refuses a sphere or trackball radius ≤ 0, naming it and the range', () => {
    expect(refused('{"sphere":{"radius":0}}')).toBe('state.sphere.radius: 0 is outside (0, 1000]');
    expect(refused('{"sphere":{"radius":-2}}')).toBe('state.sphere.radius: -2 is outside (0, 1000]');
    expect(refused('{"trackball":{"radius":0}}')).toBe('state.trackball.radius: 0 is outside (0, 100]');
    expect(refused('{"trackball":{"radius":"1"}}')).toBe(
      'state.trackball.radius: "1" is not a finite number',
    );
  });

  it('fills missing keys with defaults', () => {
    const result = parseState('{"material":{"shading":"flat"}}');
    expect(result.ok).toBe(true);
    if (!result.ok) return;
    const expected = defaultState();
    expected.material.shading = 'flat';
    expect(result.state).toEqual(expected);
  });

  it('refuses malformed JSON', () => {
    expect(refused('{"view":')).toMatch(/^state: malformed JSON/);
    expect(refused('')).toMatch(/malformed JSON/);
    expect(refused('undefined')).toMatch(/malformed JSON/);
  });

  it('refuses a non-object root', () => {
    expect(refused('[]')).toBe('state: an array is not an object');
    expect(refused('null')).toBe('state: null is not an object');
    expect(refused('"x"')).toBe('state: "x" is not an object');
  });

  it('refuses oversized text before parsing it', () => {
    const text = `{"view":"single"${' '.repeat(STATE_MAX_CHARS)}}`;
    expect(refused(text)).toBe(
      `state: ${text.length} characters is more than the limit of ${STATE_MAX_CHARS}`,
    );
  });

  it('refuses prototype-polluting keys anywhere, and leaves Object.prototype alone', () => {
    expect(refused('{"__proto__":{"polluted":1}}')).toBe('state: key "__proto__" is refused');
    expect(refused('{"material":{"constructor":{"prototype":{"x":1}}}}')).toBe(
      'state.material: key "constructor" is refused',
    );
    expect(refused('{"lights":[{"prototype":1}]}')).toBe('state.lights[0]: key "prototype" is refused');
    expect(({} as Record<string, unknown>)['polluted']).toBeUndefined();
  });

  it('refuses unknown keys, naming them', () => {
    expect(refused('{"camera":{"fov":60}}')).toMatch(
      /^state\.camera: unknown key "fov" \(allowed: projection,/,
    );
  });

  it('refuses out-of-range numbers, naming the parameter, the value and the range', () => {
    expect(refused('{"camera":{"fovy":180}}')).toBe('state.camera.fovy: 180 is outside (0, 180)');
    expect(refused('{"camera":{"fovy":0}}')).toBe('state.camera.fovy: 0 is outside (0, 180)');
    expect(refused('{"camera":{"near":-1}}')).toBe('state.camera.near: -1 is outside (0, 1000000]');
    expect(refused('{"material":{"shininess":10001}}')).toBe(
      'state.material.shininess: 10001 is outside [0, 10000]',
    );
    expect(refused('{"sphere":{"level":2.5}}')).toBe('state.sphere.level: 2.5 is not an integer');
    expect(refused('{"material":{"celBands":1}}')).toMatch(/^state\.material\.celBands: 1 is not allowed/);
    expect(refused('{"lights":[{"position":[0,1e300,0]}]}')).toBe(
      'state.lights[0].position[1]: 1e+300 is outside [-10000, 10000]',
    );
    expect(refused('{"lights":[{"attenuation":{"a":-1}}]}')).toBe(
      'state.lights[0].attenuation.a: -1 is outside [0, 1000]',
    );
  });

  it('refuses wrong types and enums', () => {
    expect(refused('{"material":{"shading":"smooth"}}')).toBe(
      'state.material.shading: "smooth" is not one of flat, gouraud, phong',
    );
    expect(refused('{"material":{"outline":"yes"}}')).toBe(
      'state.material.outline: "yes" is not true or false',
    );
    expect(refused('{"model":{"scale":[1,2]}}')).toBe(
      'state.model.scale: an array is not an array of 3 numbers',
    );
    expect(refused('{"model":{"scale":["1",2,3]}}')).toBe('state.model.scale[0]: "1" is not a finite number');
    expect(refused('{"lights":{}}')).toBe('state.lights: object is not an array');
  });

  it('refuses script in strings without running it', () => {
    const error = refused('{"view":"<img src=x onerror=alert(1)>"}');
    expect(error).toMatch(
      /^state\.view: "<img src=x onerror=alert\(1\)>" is not one of single, compare, parity$/,
    );
  });

  it('takes every scene name, defaults to the sphere and refuses any other scene value', () => {
    expect(defaultState().scene).toBe('sphere');
    expect(parseState('{}')).toMatchObject({ ok: true, state: { scene: 'sphere' } });
    for (const scene of SCENES) {
      expect(parseState(JSON.stringify({ scene }))).toMatchObject({ ok: true, state: { scene } });
    }
    const allowed = SCENES.join(', ');
    expect(refused('{"scene":"Sphere"}')).toBe(`state.scene: "Sphere" is not one of ${allowed}`);
    expect(refused('{"scene":"__proto__"}')).toBe(`state.scene: "__proto__" is not one of ${allowed}`);
    expect(refused('{"scene":0}')).toBe(`state.scene: 0 is not one of ${allowed}`);
    expect(refused('{"scene":["sphere"]}')).toBe(`state.scene: an array is not one of ${allowed}`);
    expect(refused('{"scene":{"name":"sphere"}}')).toBe(`state.scene: object is not one of ${allowed}`);
  });

  it('refuses more lights than the limit', () => {
    const lights = Array.from({ length: MAX_LIGHTS + 1 }, () => ({}));
    expect(refused(JSON.stringify({ lights }))).toBe(
      `state.lights: ${MAX_LIGHTS + 1} items is more than ${MAX_LIGHTS}`,
    );
    expect(parseState(JSON.stringify({ lights: [] }))).toMatchObject({ ok: true, state: { lights: [] } });
  });

  it('renormalises a nearly-unit quaternion and refuses a zero one', () => {
    const result = parseState('{"trackball":{"rotation":[0,0,0,1.0005]}}');
    expect(result.ok && result.state.trackball.rotation).toEqual([0, 0, 0, 1]);
    expect(refused('{"trackball":{"rotation":[0,0,0,0]}}')).toMatch(/length 0 is not 1/);
  });

  it('returns a fresh object each time (no shared references with the input or the defaults)', () => {
    const a = validateState({});
    const b = validateState({});
    expect(a.ok && b.ok && a.state !== b.state && a.state.lights !== b.state.lights).toBe(true);
  });
});

describe('parseState properties', () => {
  // JSON has no −0: compare with +0.
  const finite = fc.double({ noNaN: true, min: -1e3, max: 1e3 }).map((x) => x + 0);
  const validState = fc.record({
    view: fc.constantFrom('single', 'compare'),
    scene: fc.constantFrom(...SCENES),
    shading: fc.constantFrom('flat', 'gouraud', 'phong'),
    celBands: fc.oneof(fc.constant(0), fc.integer({ min: 2, max: 16 })),
    shininess: fc.double({ noNaN: true, min: 0, max: 1e4 }).map((x) => x + 0),
    scale: fc.tuple(finite, finite, finite),
    lights: fc.integer({ min: 0, max: MAX_LIGHTS }),
  });

  it('round-trips every valid state exactly', () => {
    fc.assert(
      fc.property(validState, (v) => {
        const state: PlaygroundState = defaultState();
        state.view = v.view as PlaygroundState['view'];
        state.scene = v.scene;
        state.material.shading = v.shading as PlaygroundState['material']['shading'];
        state.material.celBands = v.celBands;
        state.material.shininess = v.shininess;
        state.model.scale = v.scale;
        state.lights = Array.from({ length: v.lights }, defaultLight);
        expect(parseState(serializeState(state))).toEqual({ ok: true, state });
      }),
    );
  });

  it('never throws and never accepts a non-finite or out-of-range number', () => {
    const bad = fc.oneof(
      fc.constant(Number.NaN),
      fc.constant(Number.POSITIVE_INFINITY),
      fc.double({ min: 1e10, noNaN: true }),
      fc.string(),
      fc.constant(null),
      fc.boolean(),
    );
    const field = fc.constantFrom('fovy', 'near', 'far', 'moveSpeed');
    fc.assert(
      fc.property(field, bad, (key, value) => {
        const result = validateState({ camera: { [key]: value } });
        expect(result.ok).toBe(false);
        if (!result.ok) expect(result.error.startsWith(`state.camera.${key}: `)).toBe(true);
      }),
    );
  });

  it('never throws on arbitrary JSON text', () => {
    fc.assert(
      fc.property(fc.oneof(fc.json(), fc.string()), (text) => {
        const result = parseState(text);
        expect(typeof result.ok).toBe('boolean');
      }),
    );
  });
});
