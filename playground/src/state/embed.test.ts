// @vitest-environment happy-dom
import { beforeEach, describe, expect, it } from 'vitest';
import { parseEmbedFlag } from './embed';
import { loadInitialState, saveState } from './persist';
import { defaultState, serializeState } from './schema';

describe('parseEmbedFlag', () => {
  it('is off without the flag, on for ?embed and ?embed=1, off for ?embed=0', () => {
    expect(parseEmbedFlag('')).toEqual({ embed: false, error: null });
    expect(parseEmbedFlag('?other=2')).toEqual({ embed: false, error: null });
    expect(parseEmbedFlag('?embed')).toEqual({ embed: true, error: null });
    expect(parseEmbedFlag('embed=')).toEqual({ embed: true, error: null });
    expect(parseEmbedFlag('?x=1&embed=1')).toEqual({ embed: true, error: null });
    expect(parseEmbedFlag('?embed=0')).toEqual({ embed: false, error: null });
  });

  it('refuses any other value, and the flag given twice, naming it', () => {
    expect(parseEmbedFlag('?embed=yes')).toEqual({
      embed: false,
      error: '?embed="yes" is not understood: use ?embed (or ?embed=1, ?embed=0)',
    });
    expect(parseEmbedFlag('?embed&embed=1')).toEqual({
      embed: false,
      error: '?embed is given 2 times: give it once (?embed)',
    });
    const long = parseEmbedFlag(`?embed=${'x'.repeat(500)}`);
    expect(long.embed).toBe(false);
    expect(long.error).toContain(`"${'x'.repeat(40)}…"`);
    expect(long.error!.length).toBeLessThan(120);
  });
});

describe('embed mode and the saved state', () => {
  const stored = defaultState();
  stored.material.shininess = 7;
  beforeEach(() => {
    window.localStorage.clear();
    window.localStorage.setItem('shadelab.state', serializeState(stored));
  });

  it('an embed opens on the URL state or the lecture scene, never on what this browser saved', () => {
    window.history.replaceState(null, '', '/?embed');
    expect(loadInitialState()).toEqual({ state: defaultState(), source: 'default', refused: [] });
    window.history.replaceState(
      null,
      '',
      `/?embed#${new URLSearchParams({ s: '{"material":{"shininess":9}}' })}`,
    );
    const initial = loadInitialState();
    expect([initial.source, initial.state.material.shininess]).toEqual(['url', 9]);
  });

  it('an embed writes the URL but not localStorage; the playground writes both', () => {
    const next = defaultState();
    next.material.shininess = 3;
    window.history.replaceState(null, '', '/?embed');
    saveState(next);
    expect(window.location.search).toBe('?embed');
    expect(new URLSearchParams(window.location.hash.slice(1)).get('s')).toBe(serializeState(next));
    expect(window.localStorage.getItem('shadelab.state')).toBe(serializeState(stored));
    window.history.replaceState(null, '', '/');
    saveState(next);
    expect(window.localStorage.getItem('shadelab.state')).toBe(serializeState(next));
  });

  it('a refused flag is reported and the page opens as the playground (with the saved state)', () => {
    window.history.replaceState(null, '', '/?embed=please');
    const initial = loadInitialState();
    expect(initial.source).toBe('storage');
    expect(initial.refused).toEqual([
      '?embed="please" is not understood: use ?embed (or ?embed=1, ?embed=0)',
    ]);
  });
});
