/**
 * A skinned and morphing mesh built in code (no downloads): a capped cylinder on a chain of four bones, bent
 * into a fixed pose, with one morph target that swells its middle (positions and normals, so the morphed
 * surface is lit with its own normals). The pose and the morph weight are constants: the picture is the same
 * on every run.
 */
import { ShadingMaterial } from '@shadelab/material';
import * as THREE from 'three';
import { type DemoScene, disposeParts, scenePart } from './types';

/** The cylinder's height (model units) and its bones (evenly spaced along it). */
const HEIGHT = 2.8;
const BONES = 4;
/** Bone turns about z (radians) and the morph target's weight: the fixed pose. */
export const POSE = { bend: [0, 0.4, 0.45, 0.35], twist: 0.35, swell: 1 } as const;

/** The swell morph target: positions pushed out along the radius (most at mid-height, in rings), and their normals. */
function swellTarget(geometry: THREE.BufferGeometry): {
  position: THREE.BufferAttribute;
  normal: THREE.BufferAttribute;
} {
  const morphed = geometry.clone();
  const position = morphed.getAttribute('position') as THREE.BufferAttribute;
  for (let i = 0; i < position.count; i++) {
    const x = position.getX(i);
    const y = position.getY(i);
    const z = position.getZ(i);
    const t = y / HEIGHT + 0.5; // 0 at the bottom, 1 at the top
    // Swollen in the middle, with rings.
    const k = 1 + 0.45 * Math.sin(Math.PI * t) ** 2 + 0.1 * Math.sin(8 * Math.PI * t) ** 2;
    position.setXYZ(i, x * k, y, z * k);
  }
  morphed.deleteAttribute('normal');
  morphed.computeVertexNormals();
  const out = {
    position: position.clone(),
    normal: (morphed.getAttribute('normal') as THREE.BufferAttribute).clone(),
  };
  morphed.dispose();
  return out;
}

export function createSkinnedScene(): DemoScene {
  const geometry = new THREE.CylinderGeometry(0.36, 0.36, HEIGHT, 48, 56, false);
  // Skin: each vertex follows the two bones around its height, weighted linearly between them.
  const position = geometry.getAttribute('position');
  const skinIndex: number[] = [];
  const skinWeight: number[] = [];
  const segment = HEIGHT / (BONES - 1);
  for (let i = 0; i < position.count; i++) {
    const s = Math.min(BONES - 1 - 1e-6, (position.getY(i) + HEIGHT / 2) / segment);
    const bone = Math.floor(s);
    const w = s - bone;
    skinIndex.push(bone, bone + 1, 0, 0);
    skinWeight.push(1 - w, w, 0, 0);
  }
  geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(skinIndex, 4));
  geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(skinWeight, 4));
  const swell = swellTarget(geometry);
  geometry.morphAttributes['position'] = [swell.position];
  geometry.morphAttributes['normal'] = [swell.normal];

  const bones: THREE.Bone[] = [];
  for (let b = 0; b < BONES; b++) {
    const bone = new THREE.Bone();
    bone.name = `bone ${b}`;
    bone.position.y = b === 0 ? -HEIGHT / 2 : segment;
    bones[b - 1]?.add(bone);
    bones.push(bone);
  }
  const material = new ShadingMaterial();
  const mesh = new THREE.SkinnedMesh(geometry, material);
  mesh.name = 'skinned mesh';
  mesh.add(bones[0]!);
  mesh.bind(new THREE.Skeleton(bones));
  // The pose, after binding (the bind pose is the straight cylinder).
  bones.forEach((bone, b) => {
    bone.rotation.z = POSE.bend[b]!;
  });
  bones[BONES - 1]!.rotation.y = POSE.twist;
  mesh.morphTargetInfluences = [POSE.swell];
  // Skinning moves the vertices outside the rest bounds: never cull (the geometry also changes with the shading).
  mesh.frustumCulled = false;
  // Centre the bent shape in the view.
  const root = new THREE.Group();
  root.position.set(0.45, 0.1, 0);
  root.add(mesh);
  const parts = [scenePart(mesh, material)];
  return {
    root,
    parts,
    dispose: () => {
      mesh.skeleton.dispose();
      disposeParts(parts);
    },
  };
}
