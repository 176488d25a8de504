// The instance matrix of an InstancedMesh in the node materials (ShadingNodeMaterial, OutlineNodeMaterial): read
// as three's instancing node reads it, and its normal transform sign(det A)·cof(A) of its linear part A, A scaled
// by its largest entry first (ShadingMaterial's and OutlineMaterial's `shadingCofactor`): finite for a singular or
// 1e20 instance matrix and outward for a mirrored one, where three's inverse transpose is not.
import {
  abs,
  buffer,
  float,
  instanceColor,
  instancedBufferAttribute,
  instancedDynamicBufferAttribute,
  instanceIndex,
  mat4,
  max,
  nodeObject,
  positionLocal,
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
 * `node` computed once, as a constant (`let`) where it is first used (and where three copies that code to): not
 * added to the stack being set up as `toVar()` adds it (which would compute a vertex-stage value in the fragment
 * stage too), and not a variable (a copy into a `var` made the lecture's phong shading 1–2 % slower on
 * WebGPURenderer).
 */
export function once(node: N): N {
  return nodeObject(new VarNode(node, null, true) as never);
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
  const columns = [vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0)].map((e) => once(matrix.mul(e).xyz));
  const e = columns.map((c: N) => max(max(abs(c.x), abs(c.y)), abs(c.z)));
  const s = float(1).div(max(max(max(e[0], e[1]), e[2]), 1e-30));
  const a = columns.map((c: N) => once(c.mul(s)));
  const k = [a[1].cross(a[2]), a[2].cross(a[0]), a[0].cross(a[1])];
  const sign = select(a[0].dot(k[0]).lessThan(0), float(-1), float(1));
  return k[0].mul(n.x).add(k[1].mul(n.y)).add(k[2].mul(n.z)).mul(sign);
}

/** three's limit of the vertex buffers a draw binds, for its instance data (WebGPU's default). */
const MAX_VERTEX_BUFFERS = 8;

/** The instance matrix node a build reads for every use (see instanceThroughReference). */
const _referenced = /* @__PURE__ */ new WeakMap<object, N>();

/**
 * Where three would share the build between instanced meshes (their instance data bound per mesh as vertex
 * attributes: room for them beside the geometry's, no previous matrices for motion vectors), moves the vertex as
 * three's `instancedMesh` moves it (the position by the instance matrix, the instance colour), with one instance
 * matrix node that the normal and exact flat shading read too ({@link instanceMatrixOf}), and without three's
 * inverse transpose of the normal (which ShadingNodeMaterial replaces). Returns false, doing nothing, elsewhere: call
 * three's `instancedMesh` then. One node instead of two saves four vertex attributes and their reads, so exact
 * flat shading reads the instance matrix from them too, not from a uniform array indexed per vertex as in a build
 * of its own: flat shading of a flatShadingGeometry in the realistic scene, 0.99–1.01 → 0.76–0.77×
 * MeshPhongNodeMaterial on the WebGL2 backend, 0.98–0.99 → 0.93–0.94 on WebGPU (bench/webgpu.bench.mjs).
 */
export function instanceThroughReference(builder: N, mesh: N): boolean {
  const buffers = Object.keys(builder.geometry.attributes).length + 1 + (mesh.instanceColor != null ? 1 : 0);
  // (An older three has no needsPreviousData, nor motion vectors of instances to keep.)
  const previous = typeof builder.needsPreviousData === 'function' && builder.needsPreviousData() === true;
  if (builder.renderer?.isRenderer !== true || previous || buffers > MAX_VERTEX_BUFFERS) {
    return false;
  }
  const matrix: N = (referenceAttribute as N)('instanceMatrix', 'mat4');
  (positionLocal as N).assign(matrix.mul(vec4(positionLocal, 1)).xyz);
  if (mesh.instanceColor != null) {
    (instanceColor as N).assign((referenceAttribute as N)('instanceColor', 'vec3'));
  }
  _referenced.set(builder, matrix);
  return true;
}

/**
 * An InstancedMesh's instance matrix of the instance being drawn, bound as three's instancing node binds it
 * (call it after the material's `setupPosition`): the node the position was moved by, where
 * {@link instanceThroughReference} moved it; a reference to the drawn mesh's `instanceMatrix` in a build three
 * shares between instanced meshes; in a build of this object only (`builder.objectSpecific`), its storage, uniform
 * buffer or instanced attribute.
 */
export function instanceMatrixOf(builder: N, mesh: N): N {
  const referenced = _referenced.get(builder);
  if (referenced !== undefined) return referenced;
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
