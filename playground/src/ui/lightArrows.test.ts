import { PerspectiveCamera } from 'three';
import { describe, expect, it } from 'vitest';
import { lightArrows } from './lightArrows';

/** The playground's default camera: eye (0, 0, 3) looking at the origin, 90°, in a 460 × 600 view. */
function camera() {
  const c = new PerspectiveCamera(90, 460 / 600, 0.1, 10);
  c.position.set(0, 0, 3);
  c.lookAt(0, 0, 0);
  c.updateMatrixWorld();
  return c;
}

describe('arrows to the lights the view does not show', () => {
  it('the lecture’s light 1 behind the eye, up and to the left: an arrow on the border, up-left of the centre', () => {
    const [arrow] = lightArrows(camera(), [[-5, 10, 20]], 460, 600);
    expect(arrow).toMatchObject({ index: 0, behind: true });
    expect(arrow!.x).toBeLessThan(230);
    expect(arrow!.y).toBeLessThan(300);
    // On the border, 14 px in: the top edge here (the light is more up than left).
    expect(arrow!.y).toBeCloseTo(14, 6);
    expect(arrow!.angle).toBeCloseTo(Math.atan2(-10, -5), 6);
  });

  it('a light in the view gets none; one beside it gets one on the border towards its projection', () => {
    const arrows = lightArrows(
      camera(),
      [
        [-1.8, 1.5, 0.5],
        [40, 0, 0],
      ],
      460,
      600,
    );
    expect(arrows).toHaveLength(1);
    expect(arrows[0]).toMatchObject({ index: 1, behind: false });
    expect(arrows[0]!.x).toBeCloseTo(460 - 14, 6);
    expect(arrows[0]!.y).toBeCloseTo(300, 6);
  });

  it('a light straight behind the eye points down; every arrow stays inside the view', () => {
    const arrows = lightArrows(
      camera(),
      [
        [0, 0, 50],
        [3, -7, 9],
        [-100, 0.1, -2],
      ],
      460,
      600,
    );
    expect(arrows[0]).toMatchObject({ x: 230, behind: true });
    expect(arrows[0]!.y).toBeCloseTo(600 - 14, 6);
    for (const a of arrows) {
      expect(a.x).toBeGreaterThanOrEqual(14 - 1e-9);
      expect(a.x).toBeLessThanOrEqual(446 + 1e-9);
      expect(a.y).toBeGreaterThanOrEqual(14 - 1e-9);
      expect(a.y).toBeLessThanOrEqual(586 + 1e-9);
    }
  });

  it('a light without a finite position is passed over', () => {
    expect(lightArrows(camera(), [null, undefined, [Number.NaN, 0, 0], [0, 0, 50]], 460, 600)).toMatchObject([
      { index: 3, behind: true },
    ]);
  });
});
