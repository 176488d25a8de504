/**
 * The meshes the playground builds from the packages, for the viewer's sphere and the picked scenes alike: the
 * unit sphere prepared for a shading, and the cel outline drawn light on the lecture's black background.
 */
import { flatShadingGeometry } from '@shadelab/material';
import { createOutline, type OutlineMaterial } from '@shadelab/material/outline';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import type * as THREE from 'three';
import type { Shading, SphereBase } from '../state/schema';

/**
 * The sphere for `shading`, indexed with no normal attribute (analytic normals); for flat shading prepared by
 * `flatShadingGeometry` (each face lit once, on a last vertex of its own).
 */
export function createSphere(
  base: SphereBase,
  level: number,
  shading: Shading,
  radius = 1,
): THREE.BufferGeometry {
  const sphere = new SubdivisionSphereGeometry({ base, level, radius, normals: 'none' });
  if (shading !== 'flat') return sphere;
  const flat = flatShadingGeometry(sphere);
  sphere.dispose();
  return flat;
}

/** Names the geometry {@link createSphere} builds: it differs only between flat and the other shadings. */
export function sphereKey(base: SphereBase, level: number, shading: Shading, radius = 1): string {
  return `${base}:${level}:${radius}:${shading === 'flat' ? 'faces' : 'shared'}`;
}

/** Outline thickness along the normal, in model units (before the model scale). */
export const OUTLINE_THICKNESS = 0.03;

/** A cel outline: an inverted hull sharing its mesh's geometry. */
export type Outline = THREE.Mesh<THREE.BufferGeometry, OutlineMaterial>;

/**
 * The material package's inverted-hull outline for cel shading, as a child of `mesh` sharing its geometry;
 * drawn light so that it shows on the lecture's black background.
 */
export function createOutlineMesh(mesh: THREE.Mesh): Outline {
  return createOutline(mesh, { thickness: OUTLINE_THICKNESS, color: '#f2f2f2' });
}
