/**
 * A scene lit by three's own lights, with fog and clipping: a hemisphere, an ambient, a directional, a point
 * and a spot light (the material reads them through the lecture's equation) over a ground plane, a clipped
 * sphere (its cut shows the inside, lit with the flipped normal: DoubleSide), a box, a torus and spheres
 * going back into the fog. The lights and the clipping plane are fixed: the picture is the same on every run.
 */
import { ShadingMaterial } from '@shadelab/material';
import * as THREE from 'three';
import { createSphere } from '../meshes';
import { type DemoScene, disposeParts, type ScenePart, scenePart } from './types';

/** The fog (colour also the background), linear from `near` to `far` (world units from the eye). */
export const FOG = { color: 0x1a2233, near: 3.5, far: 9.5 } as const;
/**
 * The clipping plane (world space): drops the clipped sphere's cap that faces the camera and the sky, so its
 * inside shows.
 */
export const CLIP_PLANE = { normal: [0.15, -0.25, -1] as const, constant: 0.39 };

export function createLightsScene(): DemoScene {
  const root = new THREE.Group();
  root.name = "three's lights";
  // Looked at from slightly above, so the ground shows.
  root.rotation.x = 0.38;

  const plane = new THREE.Plane(new THREE.Vector3(...CLIP_PLANE.normal).normalize(), CLIP_PLANE.constant);
  const solid = new ShadingMaterial();
  const clipped = new ShadingMaterial();
  clipped.clippingPlanes = [plane];
  clipped.side = THREE.DoubleSide;
  const ground = new ShadingMaterial();

  const parts: ScenePart[] = [];
  const add = (mesh: THREE.Mesh, material: typeof solid, x: number, y: number, z: number) => {
    mesh.material = material;
    mesh.position.set(x, y, z);
    root.add(mesh);
    parts.push(scenePart(mesh, material));
  };
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(7, 14, 14, 28));
  floor.rotation.x = -Math.PI / 2;
  add(floor, ground, 0, -1, -4);
  add(new THREE.Mesh(createSphere('icosahedron', 4, 'phong', 0.8)), clipped, -1.05, -0.2, 0);
  const box = new THREE.Mesh(new THREE.BoxGeometry(0.9, 0.9, 0.9, 4, 4, 4));
  box.rotation.set(0.3, 0.6, 0);
  add(box, solid, 1.15, -0.45, 0.2);
  const torus = new THREE.Mesh(new THREE.TorusGeometry(0.55, 0.2, 24, 64));
  torus.rotation.x = -0.5;
  add(torus, solid, 0.2, -0.1, -2.2);
  for (let i = 0; i < 3; i++) {
    add(
      new THREE.Mesh(createSphere('icosahedron', 3, 'phong', 0.45)),
      solid,
      -1.6 + 1.6 * i,
      -0.55,
      -4.5 - 1.8 * i,
    );
  }

  // Intensities as three's own materials need them for this look (three's lights carry three's 1/π).
  const hemisphere = new THREE.HemisphereLight(0x8899ff, 0x332211, 0.15 * Math.PI);
  const ambient = new THREE.AmbientLight(0xffffff, 0.05 * Math.PI);
  const sun = new THREE.DirectionalLight(0xfff2dd, 0.25 * Math.PI);
  sun.position.set(3, 5, 4);
  const point = new THREE.PointLight(0xff44aa, 1.2 * Math.PI, 0, 2);
  point.position.set(-0.2, 0.6, 1.2);
  const spot = new THREE.SpotLight(0x33ccff, 10 * Math.PI, 0, 0.35, 0.4, 2);
  spot.position.set(1.6, 2.6, 1.6);
  spot.target.position.set(1.15, -0.45, 0.2);
  root.add(hemisphere, ambient, sun, sun.target, point, spot, spot.target);

  const fog = new THREE.Fog(FOG.color, FOG.near, FOG.far);
  const background = new THREE.Color(FOG.color);
  let saved: { background: THREE.Scene['background']; clipping: boolean } | null = null;
  return {
    root,
    parts,
    enter(scene, renderer) {
      saved = { background: scene.background, clipping: renderer.localClippingEnabled };
      scene.fog = fog;
      scene.background = background;
      renderer.localClippingEnabled = true;
    },
    leave(scene, renderer) {
      scene.fog = null;
      if (saved) {
        scene.background = saved.background;
        renderer.localClippingEnabled = saved.clipping;
      }
      saved = null;
    },
    dispose: () => disposeParts(parts),
  };
}
