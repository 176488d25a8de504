/**
 * The object's bounding sphere in world units, for the attenuation plot's range of t: the lecture's sphere (its
 * mesh, whatever draws it: the impostor is the same sphere), or every visible mesh drawn with a ShadingMaterial in
 * a picked scene (three's bounding spheres: an InstancedMesh's covers its instances, a SkinnedMesh's its posed
 * bones), in world space, merged. Loaded with the plot.
 */
import * as THREE from 'three';
import type { Viewer } from '../engine/viewer/Viewer';
import type { BoundingSphere } from './attenuation';

/** The part of the viewer the bounds read. */
export type BoundsViewer = Pick<Viewer, 'mesh' | 'pivot' | 'state'>;

function worldSphere(mesh: THREE.Mesh): THREE.Sphere {
  let local: THREE.Sphere | null;
  if (mesh instanceof THREE.InstancedMesh || mesh instanceof THREE.SkinnedMesh) {
    mesh.computeBoundingSphere();
    local = mesh.boundingSphere;
  } else {
    if (!mesh.geometry.boundingSphere) mesh.geometry.computeBoundingSphere();
    local = mesh.geometry.boundingSphere;
  }
  return (local ?? new THREE.Sphere()).clone().applyMatrix4(mesh.matrixWorld);
}

function shown(object: THREE.Object3D): boolean {
  for (let o: THREE.Object3D | null = object; o; o = o.parent) if (!o.visible) return false;
  return true;
}

/**
 * The bounding sphere of what the view shows (see the module comment); null when a picked scene shows no mesh
 * (a model not loaded yet).
 *
 * @param viewer - The playground's viewer, with a state applied.
 */
export function objectBounds(viewer: BoundsViewer): BoundingSphere | null {
  viewer.pivot.updateMatrixWorld(true);
  let sphere: THREE.Sphere | null = null;
  if (!viewer.state || viewer.state.scene === 'sphere') {
    sphere = worldSphere(viewer.mesh);
  } else {
    viewer.pivot.traverse((object) => {
      const mesh = object as THREE.Mesh;
      if (!mesh.isMesh || mesh === viewer.mesh || !shown(mesh)) return;
      const materials = Array.isArray(mesh.material) ? mesh.material : [mesh.material];
      if (!materials.some((m) => (m as { isShadingMaterial?: boolean }).isShadingMaterial)) return;
      const s = worldSphere(mesh);
      sphere = sphere ? sphere.union(s) : s;
    });
  }
  if (!sphere) return null;
  const { center, radius } = sphere as THREE.Sphere;
  return { center: [center.x, center.y, center.z], radius };
}
