// The panel's leva settings, from the state's field table.
import { describe, expect, test } from 'vitest';
import { LIGHT_FIELDS } from '../state/fields';
import { levaInput, panelRows, stepDecimals } from './panelFields';

describe('panel fields', () => {
  test('stepDecimals: the decimals a step is written with', () => {
    expect([0.001, 0.005, 0.01, 0.05, 0.1, 0.5, 1, 5, 1e-7, 2.5].map(stepDecimals)).toEqual([
      3, 3, 2, 2, 1, 1, 0, 0, 7, 1,
    ]);
  });

  test("a number is shown with its step's decimals: attenuation c (step 0.001) keeps the docs' 0.002", () => {
    const c = panelRows(LIGHT_FIELDS).find((row) => row.path.join('.') === 'attenuation.c')!;
    expect(levaInput(c)).toMatchObject({ step: 0.001, pad: 3 });
    for (const row of panelRows(LIGHT_FIELDS)) {
      const input = levaInput(row);
      if (row.input.step !== undefined)
        expect(input['pad'], row.path.join('.')).toBe(stepDecimals(row.input.step));
      else expect(input, row.path.join('.')).not.toHaveProperty('pad');
    }
  });
});
