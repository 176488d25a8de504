// The lecture's sphere for the material harness pages: @shadelab/sphere's tetrahedron subdivision, as a
// triangle soup (non-indexed: flat shading and the harness's per-pixel raycasting need it).
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import type { BufferGeometry } from 'three';

const geometries = new Map<string, BufferGeometry>();

/**
 * Non-indexed unit tetrahedron sphere at `level`. `normals: false` leaves out the normal attribute, so
 * ShadingMaterial uses the exact analytic normal (it recognises `SubdivisionSphereGeometry`).
 */
export function sphereGeometry(level: number, normals: boolean): BufferGeometry {
  const key = `${level}/${normals}`;
  let g = geometries.get(key);
  if (g === undefined) {
    g = new SubdivisionSphereGeometry({
      level,
      base: 'tetrahedron',
      normals: normals ? 'smooth' : 'none',
      indexed: false,
    });
    geometries.set(key, g);
  }
  return g;
}
