import { Camera } from '@shadelab/camera';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { renderReference } from '@shadelab/reference';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Group, Mesh, MeshBasicMaterial, PerspectiveCamera, Scene } from 'three';
import { describe, expect, it } from 'vitest';
import { referenceSceneOf } from './referenceSceneOf.js';

/** The lecture's scene as an app builds it: the light in a group, the sphere scaled (2, 1, 2). */
function lecture() {
  const scene = new Scene();
  const light = new PhongLight({
    ambient: 0.2,
    diffuse: 1,
    specular: 0.8,
    attenuation: { a: 1, b: 0.1, c: 0 },
  });
  const rig = new Group();
  rig.position.set(-1, 0, 0);
  light.position.set(-4, 10, 20); // world (−5, 10, 20)
  rig.add(light);
  const material = new ShadingMaterial({
    shading: 'phong',
    lighting: 'blinn-phong',
    shininess: 40,
    celBands: 3,
  });
  const sphere = new Mesh(new SubdivisionSphereGeometry({ level: 3, radius: 1.2 }), material);
  sphere.scale.set(2, 1, 2);
  scene.add(rig, sphere);
  const camera = new Camera();
  camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
  camera.setPerspective(90, 4 / 3, 0.1, 10);
  return { scene, light, material, sphere, camera };
}

describe('referenceSceneOf', () => {
  it("reads the camera's matrices, the sphere's world matrix and radius, the material and the PhongLights in the scene", () => {
    const { sphere, camera, material } = lecture();
    const scene = referenceSceneOf({ camera, sphere, background: [0, 0, 1] });
    expect(scene.projectionMatrix).toEqual(Array.from(camera.projectionMatrix.elements));
    expect(scene.viewMatrix).toEqual(Array.from(camera.matrixWorldInverse.elements));
    expect(scene.modelMatrix).toEqual([2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]);
    expect(scene.radius).toBe(1.2);
    expect(scene.material).toEqual({
      ka: [material.ka.r, material.ka.g, material.ka.b],
      kd: [material.kd.r, material.kd.g, material.kd.b],
      ks: [material.ks.r, material.ks.g, material.ks.b],
      shininess: 40,
      lighting: 'blinn-phong',
      celBands: 3,
    });
    expect(scene.lights).toEqual([
      {
        position: [-5, 10, 20],
        ambient: [0.2, 0.2, 0.2],
        diffuse: [1, 1, 1],
        specular: [0.8, 0.8, 0.8],
        attenuation: { a: 1, b: 0.1, c: 0 },
      },
    ]);
    expect(scene.background).toEqual([0, 0, 1]);
    // What renderReference draws from it: the centre pixel lit, a corner the background.
    const image = renderReference({ ...scene, width: 40, height: 30 });
    expect(image.hit[15 * 40 + 20]).toBe(1);
    expect(image.hit[0]).toBe(0);
  });

  it("prefers the lights given, then the material's phongLights, to the scene's", () => {
    const { sphere, camera, material } = lecture();
    const other = new PhongLight({ diffuse: 0.5 });
    other.position.set(1, 2, 3);
    expect(referenceSceneOf({ camera, sphere, lights: [other] }).lights.map((l) => l.position)).toEqual([
      [1, 2, 3],
    ]);
    material.phongLights = [other];
    expect(referenceSceneOf({ camera, sphere }).lights.map((l) => l.diffuse)).toEqual([[0.5, 0.5, 0.5]]);
  });

  it('reads a SphereImpostor (radius 1) and a three camera; background defaults to black', () => {
    const light = new PhongLight();
    const impostor = new SphereImpostor(new SphereImpostorMaterial({ lights: [light], shininess: 7 }));
    const camera = new PerspectiveCamera(60, 1, 0.1, 10);
    camera.position.set(0, 0, 4);
    const scene = referenceSceneOf({ camera, sphere: impostor });
    expect(scene.radius).toBe(1);
    expect(scene.material.shininess).toBe(7);
    expect(scene.background).toEqual([0, 0, 0]);
    expect(scene.viewMatrix[14]).toBeCloseTo(-4, 12);
  });

  it('refuses a sphere without a shadelab material, or without a PhongLight, saying what to pass', () => {
    const { camera } = lecture();
    const plain = new Mesh(new SubdivisionSphereGeometry(), new MeshBasicMaterial());
    expect(() => referenceSceneOf({ camera, sphere: plain })).toThrow(
      /the sphere must have a material with ka, kd and ks .* or pass material/,
    );
    const unlit = new Mesh(new SubdivisionSphereGeometry(), new ShadingMaterial());
    new Scene().add(unlit);
    expect(() => referenceSceneOf({ camera, sphere: unlit })).toThrow(
      /no PhongLight lights the sphere .*: pass lights/,
    );
  });
});
