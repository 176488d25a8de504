// @vitest-environment happy-dom
import { LIGHTINGS, MAX_CEL_BANDS, SHADINGS } from '@shadelab/material';
import { SPHERE_BASES } from '@shadelab/sphere';
import { Leva } from 'leva';
import { act, createElement } from 'react';
import { createRoot } from 'react-dom/client';
import { describe, expect, it } from 'vitest';
import { getPath, type PanelRow, panelRows, setPath } from '../ui/panelFields';
import { type FieldSpec, FOLDER_OF, isField, LIGHT_FIELDS, STATE_FIELDS, type Table } from './fields';
import { readUrlState, stateUrl } from './persist';
import { defaultState, parseState, serializeState } from './schema';

/** Every row of a table with its path (the lights' rows under `lights[0]`). */
function rows(table: Table, prefix: string[] = []): { path: string[]; field: FieldSpec<unknown> }[] {
  return Object.entries(table).flatMap(([key, entry]) => {
    const path = [...prefix, key];
    if (!isField(entry)) return rows(entry, path);
    if (entry.kind.type === 'list') return rows(entry.kind.item, [...path, '0']);
    return [{ path, field: entry }];
  });
}

/** A valid value of the row's type that is not its default. */
function otherValue(field: FieldSpec<unknown>): unknown {
  const kind = field.kind;
  switch (kind.type) {
    case 'enum':
      return kind.values.find((v) => v !== field.default);
    case 'number': {
      const middle = (kind.min + kind.max) / 2;
      const value = kind.integer ? Math.round(middle) : middle;
      return value === field.default ? (value + kind.max) / 2 : value;
    }
    case 'boolean':
      return !field.default;
    case 'vec3':
      return [kind.limit / 2, -kind.limit / 4, 0.125];
    case 'rgb':
      return [0.5, 0.25, 2];
    case 'color':
      return '#0a1b2c';
    case 'quaternion':
      return [0, 1, 0, 0];
    case 'list':
      throw new Error('a list has rows');
  }
}

const all = rows(STATE_FIELDS);
// React's act() for the panel render.
(globalThis as { IS_REACT_ACT_ENVIRONMENT?: boolean }).IS_REACT_ACT_ENVIRONMENT = true;

describe('the table of fields', () => {
  it('has every field of the state, and the state has nothing else', () => {
    const state = defaultState();
    const leaves = (value: unknown, path: string[]): string[] =>
      typeof value === 'object' && value !== null && !Array.isArray(value)
        ? Object.entries(value).flatMap(([k, v]) => leaves(v, [...path, k]))
        : Array.isArray(value) && typeof value[0] === 'object'
          ? leaves(value[0], [...path, '0'])
          : [path.join('.')];
    expect(leaves(state, []).sort()).toEqual(all.map((r) => r.path.join('.')).sort());
    expect(all.length).toBeGreaterThan(45);
  });

  it.each(all.map((r) => [r.path.join('.'), r] as const))(
    'round-trips %s through the URL',
    (_, { path, field }) => {
      const state = defaultState();
      const value = otherValue(field);
      expect(value).not.toEqual(field.default);
      setPath(state, path, value);
      // A valid value the parser takes as it is, and nothing else changes.
      expect(parseState(serializeState(state))).toEqual({ ok: true, state });
      window.history.replaceState(null, '', '/');
      window.location.hash = new URL(stateUrl(state)).hash;
      const result = readUrlState();
      expect(result).toEqual({ ok: true, state });
      expect(result?.ok && getPath(result.state, path)).toEqual(value);
    },
  );

  it('takes its options and limits from the packages', () => {
    const kind = (field: FieldSpec<unknown>) => field.kind as Record<string, unknown>;
    expect(kind(STATE_FIELDS.material.shading)['values']).toBe(SHADINGS);
    expect(kind(STATE_FIELDS.material.lighting)['values']).toBe(LIGHTINGS);
    expect(kind(STATE_FIELDS.sphere.base)['values']).toBe(SPHERE_BASES);
    expect(kind(STATE_FIELDS.material.celBands)['max']).toBeLessThanOrEqual(MAX_CEL_BANDS);
  });

  it('has the renderer switch: WebGL by default, WebGPU in the View folder', () => {
    expect(STATE_FIELDS.renderer.kind).toEqual({ type: 'enum', values: ['webgl', 'webgpu'] });
    expect(defaultState().renderer).toBe('webgl');
    expect(FOLDER_OF.renderer).toBe('View');
    const state = { ...defaultState(), renderer: 'webgpu' as const };
    expect(parseState(serializeState(state))).toEqual({ ok: true, state });
    expect(parseState('{"renderer":"vulkan"}')).toEqual({
      ok: false,
      error: 'state.renderer: "vulkan" is not one of webgl, webgpu',
    });
  });

  it('lists in the panel exactly the values the parser takes', () => {
    for (const { field, input } of [...panelRows(STATE_FIELDS), ...panelRows(LIGHT_FIELDS)]) {
      if (field.kind.type !== 'enum' || !input.options) continue;
      const listed = Array.isArray(input.options) ? input.options : Object.values(input.options);
      expect([...listed].sort()).toEqual([...field.kind.values].sort());
    }
  });

  it('says why a field is not in the panel', () => {
    const hidden = all.filter((r) => !('label' in r.field.panel)).map((r) => r.path.join('.'));
    expect(hidden).toEqual(['camera.zoom', 'trackball.rotation']);
  });
});

describe('the panel', () => {
  it('shows every labelled row, with its label, in the folders the table gives', async () => {
    const { LightControls, SceneControls } = await import('../ui/Controls');
    const host = document.createElement('div');
    document.body.append(host);
    const state = defaultState();
    const noop = () => {};
    const actions = { exportPng: noop, copyLink: noop, reset: noop, addLight: noop };
    const root = createRoot(host);
    await act(async () => {
      root.render(
        createElement(
          'div',
          null,
          createElement(Leva, { fill: true, flat: true, titleBar: false }),
          createElement(SceneControls, { state, update: noop, actions }),
          createElement(LightControls, { index: 0, state, update: noop, onGizmo: noop }),
        ),
      );
    });
    const labels = new Set(
      [...document.querySelectorAll('label')].map((label) => label.textContent?.trim() ?? ''),
    );
    const expected = [...panelRows(STATE_FIELDS), ...panelRows(LIGHT_FIELDS)].map(
      (r: PanelRow) => r.input.label,
    );
    expect(labels.size).toBeGreaterThanOrEqual(new Set(expected).size);
    expect(expected.filter((label) => !labels.has(label))).toEqual([]);
    for (const folder of ['View', 'Material', 'Sphere', 'Camera', 'Trackball', 'Light 1']) {
      expect(document.body.textContent).toContain(folder);
    }
    await act(async () => root.unmount());
    host.remove();
  });
});
