// The instance matrix of an InstancedMesh in the node materials (ShadingNodeMaterial, OutlineNodeMaterial): read
// as three's instancing node reads it, and its normal transform sign(det A)·cof(A) of its linear part A, A scaled
// by its largest entry first (ShadingMaterial's and OutlineMaterial's `shadingCofactor`): finite for a singular or
// 1e20 instance matrix and outward for a mirrored one, where three's inverse transpose is not.
import {
  abs,
  buffer,
  float,
  instancedBufferAttribute,
  instancedDynamicBufferAttribute,
  instanceIndex,
  mat4,
  max,
  nodeObject,
  referenceAttribute,
  select,
  storage,
  vec3,
  vec4,
} from 'three/tsl';
import { DynamicDrawUsage, InterleavedBufferAttribute, VarNode } from 'three/webgpu';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

/**
 * `node` as a variable: computed once where it is first used (and where three copies that code to), not added to
 * the stack being set up as `toVar()` adds it (which would compute a vertex-stage value in the fragment stage too).
 */
export function variable(node: N): N {
  return nodeObject(new VarNode(node) as never);
}

/** `v` divided by its largest absolute component (zero stays zero): direction kept, magnitude in range. */
export function rescale(v: N): N {
  const m = max(max(abs(v.x), abs(v.y)), abs(v.z));
  return select(m.greaterThan(0), v.div(max(m, 1e-30)), vec3(0));
}

/**
 * sign(det A)·cof(A)·n for the linear part A of `matrix` (a mat4 node), A scaled by its largest entry first so
 * that nothing overflows at a scale of 1e20 (`shadingCofactorTimes` of the GLSL materials): the normal of a face
 * whose object-space normal is `n`, unnormalised; a zero scale gives the flattened surface's normal, or zero.
 */
export function cofactorTimes(matrix: N, n: N): N {
  // The columns as products, each computed once (a matrix reference cannot always be indexed: element(i) of a
  // referenced attribute reads it as an array of matrices; a mat3 variable indexed measured slower on the WebGL2
  // backend), scaled by one reciprocal.
  const columns = [vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0)].map((e) =>
    variable(matrix.mul(e).xyz),
  );
  const e = columns.map((c: N) => max(max(abs(c.x), abs(c.y)), abs(c.z)));
  const s = float(1).div(max(max(max(e[0], e[1]), e[2]), 1e-30));
  const a = columns.map((c: N) => variable(c.mul(s)));
  const k = [a[1].cross(a[2]), a[2].cross(a[0]), a[0].cross(a[1])];
  const sign = select(a[0].dot(k[0]).lessThan(0), float(-1), float(1));
  return k[0].mul(n.x).add(k[1].mul(n.y)).add(k[2].mul(n.z)).mul(sign);
}

/**
 * An InstancedMesh's instance matrix of the instance being drawn, bound as three's instancing node binds it
 * (call it after three's `instancedMesh` node was set up for this build): a reference to the drawn mesh's
 * `instanceMatrix` in a build three shares between instanced meshes; in a build of this object only
 * (`builder.objectSpecific`), its storage, uniform buffer or instanced attribute.
 */
export function instanceMatrixOf(builder: N, mesh: N): N {
  if (builder.objectSpecific !== true) return (referenceAttribute as N)('instanceMatrix', 'mat4');
  const matrices = mesh.instanceMatrix;
  const count = Math.max(matrices.count, 1);
  if (matrices.isStorageInstancedBufferAttribute === true) {
    return (storage(matrices, 'mat4', count) as N).element(instanceIndex);
  }
  if (count * 64 <= builder.getUniformBufferLimit()) {
    return (buffer(matrices.array, 'mat4', count) as N).element(instanceIndex);
  }
  const read =
    matrices.usage === DynamicDrawUsage ? instancedDynamicBufferAttribute : instancedBufferAttribute;
  const [c0, c1, c2, c3] = [0, 4, 8, 12].map((offset) =>
    read(new InterleavedBufferAttribute(matrices, 4, offset) as never),
  );
  return (mat4 as N)(c0, c1, c2, c3);
}
