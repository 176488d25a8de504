// @vitest-environment happy-dom
import { Camera } from '@shadelab/camera';
import { OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { describe, expect, it } from 'vitest';

/** Drive three's OrbitControls the same way on a shadelab Camera and on three's own camera. */
function orbit<C extends Camera | PerspectiveCamera | OrthographicCamera>(camera: C): C {
  const el = document.createElement('div');
  document.body.appendChild(el);
  const controls = new OrbitControls(camera, el);
  controls.target.set(1, 0, -1);
  controls.update();
  // rotateLeft/dollyIn are public since three r183; older releases (our oldest is r179) name them _rotateLeft/_dollyIn.
  const c = controls as unknown as Record<string, ((x: number) => void) | undefined>;
  (c.rotateLeft ?? c._rotateLeft)!.call(controls, 0.4);
  (c.dollyIn ?? c._dollyIn)!.call(controls, 1.5);
  controls.update();
  controls.dispose();
  camera.updateMatrixWorld();
  return camera;
}

describe("three's OrbitControls drive the Camera like three's own cameras", () => {
  it('perspective: same position, orientation and frame', () => {
    const ours = orbit(new Camera({ fovy: 45, aspect: 1, near: 0.1, far: 100 }).lookAt([0, 2, 5], [0, 0, 0]));
    const theirs = new PerspectiveCamera(45, 1, 0.1, 100);
    theirs.position.set(0, 2, 5);
    theirs.lookAt(0, 0, 0);
    orbit(theirs);
    expect(ours.position.distanceTo(theirs.position)).toBeLessThan(1e-9);
    expect(ours.quaternion.angleTo(theirs.quaternion)).toBeLessThan(1e-7);
    const { e, w } = ours.getFrame();
    expect(e.distanceTo(theirs.position)).toBeLessThan(1e-9);
    // The gaze points at the orbit target.
    expect(w.dot(new Vector3(1, 0, -1).sub(e).normalize())).toBeCloseTo(-1, 9);
  });

  it('orthographic: OrbitControls zooms through camera.zoom and updateProjectionMatrix', () => {
    const ours = new Camera().setOrthographic(2, -2, 1.5, -1.5, 0.1, 100).lookAt([0, 0, 5], [0, 0, 0]);
    orbit(ours);
    const theirs = new OrthographicCamera(-2, 2, 1.5, -1.5, 0.1, 100);
    theirs.position.set(0, 0, 5);
    theirs.lookAt(0, 0, 0);
    orbit(theirs);
    expect(ours.zoom).toBeCloseTo(theirs.zoom, 12);
    expect(ours.zoom).not.toBe(1);
    for (let i = 0; i < 16; i++) {
      expect(ours.projectionMatrix.elements[i]).toBeCloseTo(theirs.projectionMatrix.elements[i], 12);
    }
  });
});
