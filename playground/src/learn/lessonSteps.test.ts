import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { defaultState, parseState } from '../state/schema';
import { applyStep, LESSON_LIGHT_POSITION, LESSON_STEPS } from './lessonSteps';

describe('the lesson’s steps', () => {
  it('the lecture’s thirteen steps, in its order, each with a title and a text', () => {
    expect(LESSON_STEPS.map((s) => s.id)).toEqual([
      'lights',
      'terms',
      'specular',
      'attenuation',
      'shadings',
      'mach-bands',
      'normal-matrix',
      'sphere',
      'camera',
      'trackball',
      'cel',
      'shader',
      'take-home',
    ]);
    for (const s of LESSON_STEPS) expect(s.title.length * s.text.length).toBeGreaterThan(0);
  });

  it('each step, from the default state and from the state the one before left, sets a state the page accepts', () => {
    let walked = defaultState();
    for (const step of LESSON_STEPS) {
      const fresh = defaultState();
      applyStep(fresh, step);
      applyStep(walked, step);
      for (const state of [fresh, walked]) {
        const parsed = parseState(JSON.stringify(state));
        expect(parsed.ok, `${step.id}: ${JSON.stringify(parsed)}`).toBe(true);
      }
      walked = structuredClone(walked);
    }
  });

  it('light 2 of the first step is in the default camera’s view and outside the lecture’s ellipsoid', () => {
    const state = defaultState();
    const camera = new PerspectiveCamera(state.camera.fovy, 460 / 600, state.camera.near, state.camera.far);
    camera.position.fromArray(state.camera.eye);
    camera.lookAt(new Vector3().fromArray(state.camera.at));
    camera.updateMatrixWorld();
    const ndc = new Vector3().fromArray(LESSON_LIGHT_POSITION).project(camera);
    for (const c of [ndc.x, ndc.y, ndc.z]) expect(Math.abs(c)).toBeLessThan(1);
    const [x, y, z] = LESSON_LIGHT_POSITION;
    const [a, b, c] = state.model.scale;
    expect((x / a) ** 2 + (y / b) ** 2 + (z / c) ** 2).toBeGreaterThan(1);
  });
});
