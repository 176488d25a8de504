import { BufferAttribute, BufferGeometry, Mesh, Sphere, Vector3 } from 'three';
import { SPHERE_FLAG } from './geometryFlags.js';
import type { SphereImpostorMaterial } from './SphereImpostorMaterial.js';

/**
 * The impostor's geometry: one quad, 4 vertices with `position` (x, y = ±1, z = 0) and 6 Uint16 indices:
 * 48 + 12 bytes. Flagged as a sphere (`userData.isSphere`) with the unit sphere as its bounding sphere, so
 * three's frustum culling uses the real extent. It is also the geometry of an `InstancedMesh` of impostors (one
 * sphere per instance, see {@link SphereImpostorMaterial}), whose bounding sphere three builds from it.
 *
 * @example
 * const field = new InstancedMesh(createImpostorQuad(), new SphereImpostorMaterial({ lights: [light] }), 1000);
 * field.setMatrixAt(0, new Matrix4().makeTranslation(2, 0, 0)); // instance 0: a unit sphere at x = 2
 */
export function createImpostorQuad(): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute(
    'position',
    new BufferAttribute(new Float32Array([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]), 3),
  );
  geometry.setIndex(new BufferAttribute(new Uint16Array([0, 1, 2, 0, 2, 3]), 1));
  geometry.userData[SPHERE_FLAG] = true;
  geometry.boundingSphere = new Sphere(new Vector3(), 1);
  return geometry;
}

/**
 * The unit sphere drawn by ray casting (see {@link SphereImpostorMaterial}): a mesh of 2 triangles. Scale,
 * rotate and move it like any object; a non-uniform scale makes an ellipsoid, exactly.
 *
 * @example
 * const impostor = new SphereImpostor(new SphereImpostorMaterial({ lights: [light] }));
 * impostor.scale.set(2, 1, 2);
 */
export class SphereImpostor extends Mesh<BufferGeometry, SphereImpostorMaterial> {
  /** Always true. */
  readonly isSphereImpostor = true;
  /** three's type name: `'SphereImpostor'`. */
  override type = 'SphereImpostor';

  /** @param material - the impostor material (shared freely between impostors). */
  constructor(material: SphereImpostorMaterial) {
    super(createImpostorQuad(), material);
  }
}
