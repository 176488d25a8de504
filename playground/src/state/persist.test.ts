// @vitest-environment happy-dom
import { beforeEach, describe, expect, it } from 'vitest';
import {
  loadInitialState,
  loadShaderEdit,
  readUrlState,
  saveShaderEdit,
  saveState,
  stateUrl,
} from './persist';
import { defaultState, STATE_MAX_CHARS, serializeState } from './schema';

const setHash = (text: string | null) => {
  const params = new URLSearchParams();
  if (text !== null) params.set('s', text);
  window.history.replaceState(null, '', text === null ? '/' : `/#${params}`);
};

beforeEach(() => {
  window.localStorage.clear();
  setHash(null);
});

describe('loadInitialState', () => {
  it('opens on the lecture scene when nothing is stored', () => {
    expect(loadInitialState()).toEqual({ state: defaultState(), source: 'default', refused: [] });
  });

  it('prefers the URL over localStorage', () => {
    const stored = defaultState();
    stored.material.shininess = 7;
    window.localStorage.setItem('shadelab.state', serializeState(stored));
    setHash('{"material":{"shininess":9}}');
    const initial = loadInitialState();
    expect(initial.source).toBe('url');
    expect(initial.state.material.shininess).toBe(9);
  });

  it('refuses a hostile URL with a message and falls back to localStorage', () => {
    const stored = defaultState();
    stored.material.shininess = 7;
    window.localStorage.setItem('shadelab.state', serializeState(stored));
    setHash('{"__proto__":{"x":1}}');
    const initial = loadInitialState();
    expect(initial.source).toBe('storage');
    expect(initial.state.material.shininess).toBe(7);
    expect(initial.refused).toEqual(['The state in the URL was refused: state: key "__proto__" is refused']);
  });

  it('refuses a URL state longer than STATE_MAX_CHARS, naming the limit, and opens the saved state', () => {
    const stored = defaultState();
    stored.material.shininess = 7;
    window.localStorage.setItem('shadelab.state', serializeState(stored));
    const huge = `{"material":{"shininess":9},"pad":"${'x'.repeat(STATE_MAX_CHARS)}"}`;
    setHash(huge);
    const initial = loadInitialState();
    expect(initial.source).toBe('storage');
    expect(initial.state.material.shininess).toBe(7);
    expect(initial.refused).toEqual([
      `The state in the URL was refused: state: ${huge.length} characters is more than the limit of ${STATE_MAX_CHARS}`,
    ]);
    // Pasted into the tab later: refused the same way (the page keeps the state it shows).
    expect(readUrlState()).toEqual({
      ok: false,
      error: `state: ${huge.length} characters is more than the limit of ${STATE_MAX_CHARS}`,
    });
    // At the limit it is parsed.
    const padded = serializeState(stored);
    setHash(padded + ' '.repeat(STATE_MAX_CHARS - padded.length));
    expect(readUrlState()).toEqual({ ok: true, state: stored });
  });

  it('refuses corrupt storage too, and opens on the defaults', () => {
    window.localStorage.setItem('shadelab.state', '{"camera":{"near":-1}}');
    const initial = loadInitialState();
    expect(initial.source).toBe('default');
    expect(initial.refused).toEqual([
      'The saved state was refused: state.camera.near: -1 is outside (0, 1000000]',
    ]);
  });
});

describe('saveState', () => {
  it('writes the state to the URL hash and to localStorage, readable back', () => {
    const state = defaultState();
    state.view = 'compare';
    saveState(state);
    expect(readUrlState()).toEqual({ ok: true, state });
    expect(window.localStorage.getItem('shadelab.state')).toBe(serializeState(state));
    expect(stateUrl(state)).toBe(`${window.location.origin}/${window.location.hash}`);
  });
});

describe('shader edits', () => {
  it('are kept per variant, and malformed or foreign entries are ignored', () => {
    saveShaderEdit('A', { vertexShader: 'v', fragmentShader: 'broken(' });
    expect(loadShaderEdit('A')).toEqual({ vertexShader: 'v', fragmentShader: 'broken(' });
    expect(loadShaderEdit('B')).toBeNull();
    window.localStorage.setItem('shadelab.glsl.C', '{"vertexShader":1}');
    window.localStorage.setItem('shadelab.glsl.D', 'not json');
    expect(loadShaderEdit('C')).toBeNull();
    expect(loadShaderEdit('D')).toBeNull();
    saveShaderEdit('A', null);
    expect(loadShaderEdit('A')).toBeNull();
  });
});
