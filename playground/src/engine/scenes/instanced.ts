/**
 * An instanced field of spheres: one InstancedMesh of an icosahedron sphere (analytic normals through each
 * instance matrix), in two rows of depth, each instance with its own size and an instanceColor that tints ka
 * and kd (the highlight keeps the light's colour). Deterministic: positions, sizes and colours follow the
 * instance's index.
 */
import { ShadingMaterial } from '@shadelab/material';
import * as THREE from 'three';
import { createSphere } from '../meshes';
import { type DemoScene, disposeParts, scenePart } from './types';

/** Instances per row and column, and rows of depth. */
export const FIELD = { columns: 5, rows: 4, layers: 2 } as const;

export function createInstancedScene(): DemoScene {
  const material = new ShadingMaterial();
  const geometry = createSphere('icosahedron', 3, 'phong', 1);
  const count = FIELD.columns * FIELD.rows * FIELD.layers;
  const mesh = new THREE.InstancedMesh(geometry, material, count);
  mesh.name = 'instanced spheres';
  const matrix = new THREE.Matrix4();
  const position = new THREE.Vector3();
  const rotation = new THREE.Quaternion();
  const scale = new THREE.Vector3();
  const color = new THREE.Color();
  const spacing = 0.95;
  let i = 0;
  for (let layer = 0; layer < FIELD.layers; layer++) {
    for (let row = 0; row < FIELD.rows; row++) {
      for (let column = 0; column < FIELD.columns; column++) {
        // The back layer is shifted by half a cell, so it shows between the front spheres.
        const shift = layer * 0.5;
        position.set(
          (column - (FIELD.columns - 1) / 2 + shift) * spacing,
          (row - (FIELD.rows - 1) / 2 + shift) * spacing,
          -layer * 1.2,
        );
        // Sizes 0.26 … 0.42 and slightly squashed, from the index alone.
        const r = 0.26 + 0.16 * (((i * 7) % 11) / 10);
        scale.set(r, r * (0.8 + 0.2 * ((i * 3) % 5) * 0.25), r);
        rotation.setFromAxisAngle(position.clone().normalize(), 0.3 * i);
        mesh.setMatrixAt(i, matrix.compose(position, rotation, scale));
        mesh.setColorAt(i, color.setHSL((i * 0.137) % 1, 0.65, 0.55));
        i++;
      }
    }
  }
  mesh.instanceMatrix.needsUpdate = true;
  if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
  mesh.computeBoundingSphere();
  const parts = [scenePart(mesh, material)];
  return {
    root: mesh,
    parts,
    dispose: () => {
      mesh.dispose();
      disposeParts(parts);
    },
  };
}
