// The lecture's sphere for the material harness pages: @shadelab/sphere's tetrahedron subdivision, by default
// as a triangle soup (non-indexed: flat shading and the harness's per-pixel raycasting need it).
import { flatShadingGeometry } from '@shadelab/material';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import type { BufferGeometry } from 'three';

const geometries = new Map<string, BufferGeometry>();

/**
 * Unit tetrahedron sphere at `level`, non-indexed unless `indexed`. `normals: false` leaves out the normal
 * attribute, so ShadingMaterial uses the exact analytic normal (it recognises `SubdivisionSphereGeometry`).
 */
export function sphereGeometry(level: number, normals: boolean, indexed = false): BufferGeometry {
  const key = `${level}/${normals}/${indexed}`;
  let g = geometries.get(key);
  if (g === undefined) {
    g = new SubdivisionSphereGeometry({
      level,
      base: 'tetrahedron',
      normals: normals ? 'smooth' : 'none',
      indexed,
    });
    geometries.set(key, g);
  }
  return g;
}

const flatGeometries = new Map<number, BufferGeometry>();

/** The indexed sphere at `level` prepared for flat shading (each face's last vertex carries the face). */
export function flatSphereGeometry(level: number): BufferGeometry {
  let g = flatGeometries.get(level);
  if (g === undefined) {
    g = flatShadingGeometry(sphereGeometry(level, false, true));
    flatGeometries.set(level, g);
  }
  return g;
}
