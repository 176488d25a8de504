// The notice for a light's gizmo that would be off the view.
import { describe, expect, test } from 'vitest';
import { defaultState } from '../state/schema';
import { gizmoNotice } from './gizmoNotice';

describe('gizmoNotice', () => {
  test("the lecture's light 1 (z = 20, behind the eye at z = 3) is named, with what to do instead", () => {
    expect(gizmoNotice(defaultState(), 0)).toBe(
      'Light 1 is behind the eye, so its gizmo is off the view: type its position (Light 1 → position), or add a light in front of the object (Lights → add light) and move that one.',
    );
  });

  test('a light in front of the eye, or none at that index: no notice', () => {
    const state = defaultState();
    state.lights[0]!.position = [0.4, 0.3, 2.4];
    expect(gizmoNotice(state, 0)).toBeNull();
    expect(gizmoNotice(state, 5)).toBeNull();
    // The eye turned round (looking at z = 30 from z = 3): light 1 at z = 20 is in front.
    const turned = defaultState();
    turned.camera.at = [0, 0, 30];
    expect(gizmoNotice(turned, 0)).toBeNull();
  });
});
