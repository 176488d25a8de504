/**
 * Temporary three.js stand-ins for the shadelab packages, used only until each package lands.
 * Everything here is reached through ./packages.ts, so switching to a real package is a one-file change.
 */
import * as THREE from 'three';
import type { SphereBase } from '../state/schema';

// ---- sphere ------------------------------------------------------------------------------------------------

/** three's polyhedra at the same triangle count as `level` subdivisions (non-indexed, with normals; ≤ level 6). */
export function standInSphere(base: SphereBase, level: number): THREE.BufferGeometry {
  const detail = 2 ** level;
  if (base === 'octahedron') return new THREE.OctahedronGeometry(1, Math.min(detail, 64) - 1);
  if (base === 'icosahedron') return new THREE.IcosahedronGeometry(1, Math.min(detail, 64) - 1);
  return new THREE.TetrahedronGeometry(1, Math.min(detail, 64) - 1);
}
