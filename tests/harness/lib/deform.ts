// Three's vertex deformation as the harness pages share it: a normal moved by the morph targets and the skin as
// three's vertex chunks move it (the CPU side of their references), the stretched morph target, the skinned
// cylinder and its two bones, and an instanced SkinnedMesh.
import {
  Bone,
  type BufferGeometry,
  CylinderGeometry,
  Float32BufferAttribute,
  InstancedBufferAttribute,
  Matrix4,
  type Mesh,
  Skeleton,
  type SkinnedMesh,
  Uint16BufferAttribute,
  Vector3,
} from 'three';

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

/** The stretch of {@link stretchMorph}'s morph target, per axis. */
const STRETCH = [1.6, 0.8, 1.2] as const;

/**
 * A copy of `source` (a unit sphere) with one morph target: its positions stretched to (1.6, 0.8, 1.2) and the
 * normals of that ellipsoid.
 */
export function stretchMorph(source: BufferGeometry): BufferGeometry {
  const g = source.clone();
  const position = g.getAttribute('position');
  const [kx, ky, kz] = STRETCH;
  const p = new Float32Array(3 * position.count);
  const n = new Float32Array(3 * position.count);
  for (let i = 0; i < position.count; i++) {
    const [x, y, z] = [position.getX(i), position.getY(i), position.getZ(i)];
    p.set([x * kx, y * ky, z * kz], 3 * i);
    const [nx, ny, nz] = [x / kx, y / ky, z / kz];
    const l = Math.hypot(nx, ny, nz);
    n.set([nx / l, ny / l, nz / l], 3 * i);
  }
  g.morphAttributes.position = [new Float32BufferAttribute(p, 3)];
  g.morphAttributes.normal = [new Float32BufferAttribute(n, 3)];
  return g;
}

/**
 * Binds {@link skinnedCylinder}'s two bones to `mesh` (the root at y = −1.5, the joint 3 above it, at rest when
 * bound), then bends the joint by `bend` radians about z; returns the joint.
 */
export function bindTwoBones(mesh: SkinnedMesh, bend: number): Bone {
  const root = new Bone();
  root.position.set(0, -1.5, 0);
  const joint = new Bone();
  joint.position.set(0, 1.5, 0);
  root.add(joint);
  mesh.add(root);
  mesh.bind(new Skeleton([root, joint]));
  joint.rotation.z = bend;
  return joint;
}

/**
 * The bone-weighted cylinder the skinning references use: 3 high, bones at y = −1.5 (root) and y = 0, the two
 * blended by smoothstep over |y| < 0.5 (skinIndex Uint16, skinWeight float).
 */
export function skinnedCylinder(
  radius: number,
  radialSegments: number,
  heightSegments: number,
): BufferGeometry {
  const g = new CylinderGeometry(radius, radius, 3, radialSegments, heightSegments);
  const position = g.getAttribute('position');
  const index = new Uint16Array(4 * position.count);
  const weight = new Float32Array(4 * position.count);
  for (let i = 0; i < position.count; i++) {
    const t = Math.min(Math.max(position.getY(i) + 0.5, 0), 1);
    const w = t * t * (3 - 2 * t);
    index.set([0, 1, 0, 0], 4 * i);
    weight.set([1 - w, w, 0, 0], 4 * i);
  }
  g.setAttribute('skinIndex', new Uint16BufferAttribute(index, 4));
  g.setAttribute('skinWeight', new Float32BufferAttribute(weight, 4));
  return g;
}

/**
 * Gives a SkinnedMesh an InstancedMesh's instance matrices. three has no InstancedSkinnedMesh class; its program
 * parameters and chunks combine both when a SkinnedMesh has an InstancedMesh's instanceMatrix (what such classes
 * in apps do).
 */
export function instanceSkinned(mesh: SkinnedMesh, matrices: readonly Matrix4[]): void {
  const attribute = new InstancedBufferAttribute(new Float32Array(16 * matrices.length), 16);
  matrices.forEach((m, i) => {
    m.toArray(attribute.array, 16 * i);
  });
  Object.assign(mesh, {
    isInstancedMesh: true,
    instanceMatrix: attribute,
    instanceColor: null,
    morphTexture: null,
    count: matrices.length,
  });
}
