// The CPU side of three's vertex deformation that the harness pages' references share: a normal moved by the
// morph targets and the skin as three's vertex chunks move it.
import { type BufferGeometry, Matrix4, type Mesh, type SkinnedMesh, Vector3 } from 'three';

/**
 * Moves the object-space normal `target` of `vertex` as three's vertex chunks do: by the morph targets' normals
 * (when `morph`), then by the skin matrix (a SkinnedMesh); `target` comes in as the undeformed normal. `geometry`
 * holds the attributes (the object's own). The result is a direction, not normalised.
 */
export function deformNormal(
  object: Mesh,
  geometry: BufferGeometry,
  vertex: number,
  target: Vector3,
  morph = true,
): Vector3 {
  const morphs = geometry.morphAttributes.normal;
  const influences = object.morphTargetInfluences;
  if (morph && morphs !== undefined && influences !== undefined) {
    const sum = influences.reduce((a, b) => a + b, 0);
    target.multiplyScalar(geometry.morphTargetsRelative ? 1 : 1 - sum);
    const m = new Vector3();
    morphs.forEach((attribute, i) => {
      if (influences[i] !== 0)
        target.addScaledVector(m.fromBufferAttribute(attribute, vertex), influences[i]);
    });
  }
  const skinned = object as SkinnedMesh;
  if (skinned.isSkinnedMesh) {
    const index = geometry.getAttribute('skinIndex');
    const weight = geometry.getAttribute('skinWeight');
    const sum = new Matrix4().set(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    const bone = new Matrix4();
    for (let j = 0; j < 4; j++) {
      const w = weight.getComponent(vertex, j);
      if (w === 0) continue;
      const b = index.getComponent(vertex, j);
      bone.multiplyMatrices(skinned.skeleton.bones[b].matrixWorld, skinned.skeleton.boneInverses[b]);
      for (let e = 0; e < 16; e++) sum.elements[e] += w * bone.elements[e];
    }
    const skin = new Matrix4().multiplyMatrices(skinned.bindMatrixInverse, sum).multiply(skinned.bindMatrix);
    target.transformDirection(skin);
  }
  return target;
}
