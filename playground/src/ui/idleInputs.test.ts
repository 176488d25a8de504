// Which panel inputs are greyed out: those that change nothing in the state's picture.
import { describe, expect, test } from 'vitest';
import { SPHERE_ONLY_INPUTS } from '../engine/scenes';
import { defaultState, type PlaygroundState, SCENES } from '../state/schema';
import { isIdleInput } from './idleInputs';

function state(change: (s: PlaygroundState) => void = () => {}): PlaygroundState {
  const s = defaultState();
  change(s);
  return s;
}

/** The greyed-out inputs among `paths` in `s`. */
const idle = (s: PlaygroundState, paths: readonly string[]) => paths.filter((p) => isIdleInput(s, p));

const SOME = [
  ...SPHERE_ONLY_INPUTS,
  'Material.shading',
  'Material.ka',
  'Material.shininess',
  'Lights.add light',
  'Light 1.light1Position',
  'Camera.eye',
];

describe('idle inputs', () => {
  test("the lecture's sphere, a mesh of a chosen level: every input applies", () => {
    expect(idle(state(), SOME)).toEqual([]);
  });

  test('the impostor: the mesh detail goes (base, level, auto detail and its bound), render, radius and scale stay', () => {
    expect(
      idle(
        state((s) => Object.assign(s.sphere, { render: 'impostor', auto: true })),
        SOME,
      ),
    ).toEqual(['Sphere.base', 'Sphere.level', 'Sphere.auto', 'Sphere.maxErrorPx']);
  });

  test('automatic detail chooses the base and level; its bound applies', () => {
    expect(
      idle(
        state((s) => Object.assign(s.sphere, { auto: true })),
        SOME,
      ),
    ).toEqual(['Sphere.base', 'Sphere.level']);
  });

  test('another scene: the Sphere folder; a loaded model also keeps its own ka/kd/ks and α and its own lights', () => {
    for (const scene of SCENES.filter((name) => name !== 'sphere')) {
      const expected: string[] = [...SPHERE_ONLY_INPUTS];
      if (scene === 'model')
        expected.push('Material.ka', 'Material.shininess', 'Lights.add light', 'Light 1.light1Position');
      expect(
        idle(
          state((s) => Object.assign(s, { scene })),
          SOME,
        ),
        scene,
      ).toEqual(expected);
    }
  });
});
