// @vitest-environment happy-dom
import { Camera } from '@shadelab/camera';
import { Trackball } from '@shadelab/trackball';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { setTrackballRotation } from './applyState';

/** The lecture's camera, and a trackball on a pivot, listening on a 200 × 200 px element at (0, 0). */
function scene() {
  const camera = new Camera({ fovy: 90, aspect: 1, near: 0.1, far: 10 });
  camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
  camera.setPerspective(90, 1, 0.1, 10);
  const pivot = new THREE.Group();
  // The viewer's trackball: the package's defaults, turning the pivot in this camera's coordinates.
  const trackball = new Trackball(pivot, null, { camera });
  const element = document.createElement('canvas');
  document.body.appendChild(element);
  element.getBoundingClientRect = () =>
    ({ left: 0, top: 0, width: 200, height: 200, right: 200, bottom: 200, x: 0, y: 0 }) as DOMRect;
  trackball.connect(element);
  const pointer = (type: string, x: number, y: number) =>
    element.dispatchEvent(
      new PointerEvent(type, {
        pointerId: 1,
        pointerType: 'mouse',
        button: 0,
        clientX: x,
        clientY: y,
        bubbles: true,
      }),
    );
  const drag = (from: [number, number], to: [number, number]) => {
    pointer('pointerdown', ...from);
    pointer('pointermove', ...to);
    pointer('pointerup', ...to);
  };
  return { camera, pivot, trackball, drag };
}

const isIdentity = (m: THREE.Matrix4) =>
  m.elements.every((v, i) => Math.abs(v - new THREE.Matrix4().elements[i]!) < 1e-12);

describe('setTrackballRotation', () => {
  it('keeps the package default mapping (bell)', () => {
    expect(scene().trackball.mapping).toBe('bell');
  });

  it('resets through the trackball: its rotation and getMatrix() agree with the object again, and the zoom stays', () => {
    const { camera, pivot, trackball, drag } = scene();
    drag([100, 100], [150, 120]);
    expect(isIdentity(trackball.getMatrix())).toBe(false);
    expect(pivot.quaternion.w).toBeLessThan(1);
    // Zoom in by 2: the eye moves to 1.5 from the target.
    trackball.zoomBy(2);
    const eye = camera.position.clone();
    expect(eye.z).toBeCloseTo(1.5, 12);

    setTrackballRotation(trackball, [0, 0, 0, 1]);
    expect(pivot.quaternion.toArray()).toEqual([0, 0, 0, 1]);
    expect(isIdentity(trackball.getMatrix())).toBe(true);
    expect(trackball.zoom).toBeCloseTo(2, 12);
    expect(camera.position.distanceTo(eye)).toBeLessThan(1e-12);

    // The next drag starts from the identity on both sides: the trackball's world matrix turns the object's.
    drag([100, 100], [150, 120]);
    const world = trackball.getWorldMatrix();
    const object = new THREE.Matrix4().makeRotationFromQuaternion(pivot.quaternion);
    world.elements.forEach((v, i) => {
      expect(v).toBeCloseTo(object.elements[i]!, 9);
    });
  });

  it('puts the object at any rotation through the trackball, from a turned camera too: its matrices agree', () => {
    const { camera, pivot, trackball, drag } = scene();
    drag([100, 100], [150, 120]);
    camera.lookAt([2, 1, 2], [0, 0, 0], [0, 1, 0]);
    camera.updateMatrixWorld();
    setTrackballRotation(trackball, [0, 1.2, 0, 1.6]); // not normalised
    const q = new THREE.Quaternion(0, 0.6, 0, 0.8);
    expect(pivot.quaternion.angleTo(q)).toBeLessThan(1e-12);
    // getWorldMatrix is the object's rotation; getMatrix the same rotation in camera coordinates (C⁻¹ q C).
    const world = new THREE.Quaternion().setFromRotationMatrix(trackball.getWorldMatrix());
    expect(world.angleTo(q)).toBeLessThan(1e-12);
    const c = camera.getWorldQuaternion(new THREE.Quaternion());
    const inCamera = c.clone().invert().multiply(q).multiply(c);
    expect(
      new THREE.Quaternion().setFromRotationMatrix(trackball.getMatrix()).angleTo(inCamera),
    ).toBeLessThan(1e-12);
  });
});
