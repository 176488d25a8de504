// @vitest-environment happy-dom
// The trackball with @shadelab/camera's Camera (a THREE.Camera with isPerspectiveCamera/isOrthographicCamera
// getters): axes in its frame, and zoom in and out for both of its projections.
import { Camera } from '@shadelab/camera';
import { Trackball } from '@shadelab/trackball';
import { Mesh, Quaternion, Vector3 } from 'three';
import { afterEach, describe, expect, it } from 'vitest';

function makeElement(): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  canvas.getBoundingClientRect = () =>
    ({ left: 0, top: 0, width: 200, height: 200, right: 200, bottom: 200, x: 0, y: 0 }) as DOMRect;
  return canvas;
}

function pointer(target: EventTarget, type: string, x: number, y: number): void {
  target.dispatchEvent(
    new PointerEvent(type, {
      pointerId: 1,
      pointerType: 'mouse',
      button: 0,
      clientX: x,
      clientY: y,
      bubbles: true,
    }),
  );
}

const made: Trackball[] = [];
afterEach(() => {
  for (const t of made.splice(0)) t.dispose();
  document.body.innerHTML = '';
});

describe('Trackball with @shadelab/camera', () => {
  it('rotates about the camera frame’s v (up) axis for a horizontal drag', () => {
    const camera = new Camera();
    camera.lookAt([3, 2, 5], [0, 0, 0], [0, 1, 0]);
    const mesh = new Mesh();
    const element = makeElement();
    made.push(new Trackball(mesh, element, { camera, mapping: 'arcball' }));
    pointer(element, 'pointerdown', 100, 100);
    pointer(element, 'pointermove', 150, 100);
    pointer(element, 'pointerup', 150, 100);
    const { v } = camera.getFrame();
    const expected = new Quaternion().setFromAxisAngle(new Vector3(v.x, v.y, v.z), Math.PI / 3);
    expect(1 - Math.abs(mesh.quaternion.dot(expected))).toBeLessThan(1e-12);
  });

  it('zooms a perspective Camera by moving its eye toward the target, keeping the frame consistent', () => {
    const camera = new Camera();
    camera.lookAt([0, 0, 5], [0, 0, 0], [0, 1, 0]);
    const tb = new Trackball(null, makeElement(), { camera });
    made.push(tb);
    tb.zoomBy(2);
    expect(camera.getFrame().e.z).toBeCloseTo(2.5, 12);
    expect(camera.getCameraTransformationMatrix().elements[14]).toBeCloseTo(-2.5, 12);
    tb.zoomBy(0.25);
    expect(camera.getFrame().e.z).toBeCloseTo(10, 12);
  });

  it('zooms an orthographic Camera in and out through its zoom', () => {
    const camera = new Camera();
    camera.setOrthographic(2, -2, 2, -2, 0.1, 10);
    const sx = camera.projectionMatrix.elements[0];
    const tb = new Trackball(null, makeElement(), { camera });
    made.push(tb);
    tb.zoomBy(4);
    expect(camera.projectionMatrix.elements[0]).toBeCloseTo(sx * 4, 12);
    tb.zoomBy(1 / 8);
    expect(camera.projectionMatrix.elements[0]).toBeCloseTo(sx / 2, 12);
    expect(camera.zoom).toBeCloseTo(0.5, 12);
  });
});
