// ShadingNodeMaterial's exact flat shading: the face each vertex lights (its three corners in object space, moved
// as three moves its vertices: morph targets, then skinning), and the instance matrix that places it, as
// ShadingMaterial's flat chunks do. A triangle soup's corners (and their morph targets, skin indices and weights)
// are read from float textures (one texel a vertex, built once per geometry and attribute version); a
// flatShadingGeometry's from its corner attributes (and, deformed, the corners' vertex indices into textures).
import {
  attribute,
  int,
  ivec2,
  OnObjectUpdate,
  positionGeometry,
  reference,
  referenceBuffer,
  textureLoad,
  uniform,
  uniformArray,
  vec4,
  vertexIndex,
} from 'three/tsl';
import {
  type BufferAttribute,
  type BufferGeometry,
  DataTexture,
  FloatType,
  type InterleavedBufferAttribute,
  NearestFilter,
  RGBAFormat,
} from 'three/webgpu';
import { FLAT_CORNER_INDEX, FLAT_CORNERS, FLAT_PROVOKING_VERTEX } from './geometryFlags.js';
import { instanceMatrixOf } from './nodeInstance.js';
import { provokingVertexOf } from './provokingVertexOf.js';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

/** Texels per row of the face textures. */
const FACE_TEXTURE_WIDTH = 2048;
const _faceTextures = /* @__PURE__ */ new WeakMap<
  BufferGeometry,
  Map<string, { texture: DataTexture; version: number }>
>();

/**
 * Vertex i's `attribute` (xyz, w = 1 for three components; four as they are) at texel i (RGBA float: WebGPU has
 * no RGB float textures), cached per geometry, `key` and attribute version; disposed with the geometry.
 */
export function faceTexture(
  geometry: BufferGeometry,
  key: string,
  attribute: BufferAttribute | InterleavedBufferAttribute = geometry.getAttribute(key),
): DataTexture {
  const version = 'version' in attribute ? (attribute.version as number) : 0;
  let textures = _faceTextures.get(geometry);
  if (textures === undefined) {
    const created = new Map<string, { texture: DataTexture; version: number }>();
    textures = created;
    _faceTextures.set(geometry, created);
    geometry.addEventListener('dispose', () => {
      for (const { texture } of created.values()) texture.dispose();
    });
  }
  const cached = textures.get(key);
  if (cached !== undefined && cached.version === version) return cached.texture;
  const height = Math.max(1, Math.ceil(attribute.count / FACE_TEXTURE_WIDTH));
  const data = new Float32Array(4 * FACE_TEXTURE_WIDTH * height);
  const four = attribute.itemSize > 3;
  for (let i = 0; i < attribute.count; i++) {
    data[4 * i] = attribute.getX(i);
    data[4 * i + 1] = attribute.itemSize > 1 ? attribute.getY(i) : 0;
    data[4 * i + 2] = attribute.itemSize > 2 ? attribute.getZ(i) : 0;
    data[4 * i + 3] = four ? attribute.getW(i) : 1;
  }
  const texture = cached?.texture ?? new DataTexture(data, FACE_TEXTURE_WIDTH, height, RGBAFormat, FloatType);
  if (cached !== undefined) texture.image = { data, width: FACE_TEXTURE_WIDTH, height } as never;
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  textures.set(key, { texture, version });
  return texture;
}

/** Vertex `i`'s texel of a face texture. */
export function faceTexel(texture: DataTexture, i: N): N {
  return textureLoad(texture, ivec2(i.mod(FACE_TEXTURE_WIDTH), i.div(FACE_TEXTURE_WIDTH))) as N;
}

/** The face a vertex lights in exact flat shading. */
export interface FlatFace {
  /** Its corners, object space, winding order, moved by the morph targets and the skin. */
  corners: [N, N, N];
  /** The instance matrix (mat4) of an InstancedMesh, else null. */
  instance: N;
}

/** The geometries already warned about their provoking vertex. */
const _warnedProvoking = /* @__PURE__ */ new WeakSet<BufferGeometry>();

/** three's morph base influence: 1 − Σ influences for absolute targets, 1 for relative ones. */
const morphBase = /* @__PURE__ */ uniform(1).onObjectUpdate(({ object }) => {
  const o = object as unknown as { geometry: BufferGeometry; morphTargetInfluences: number[] };
  return o.geometry.morphTargetsRelative ? 1 : 1 - o.morphTargetInfluences.reduce((a, b) => a + b, 0);
});

/**
 * The face of the vertex being drawn, or null where flat shading lights per fragment with the face normal from
 * screen-space derivatives: a BatchedMesh, an instanced mesh with per-instance morph weights, a skeleton too big
 * for a uniform buffer, an indexed geometry that is not a flatShadingGeometry made for this backend's provoking
 * vertex (one warning per geometry), or a deformed one made without its corners' vertex indices.
 */
export function flatFace(builder: N, geometry: BufferGeometry, owner: string): FlatFace | null {
  const object = builder.object ?? {};
  if (object.isBatchedMesh === true) return null;
  const skinned = object.isSkinnedMesh === true && object.skeleton != null;
  const morphs = geometry.morphAttributes.position ?? [];
  const morphed = morphs.length > 0 && Array.isArray(object.morphTargetInfluences);
  if (morphed && object.morphTexture != null) return null;
  if (skinned && object.skeleton.bones.length * 64 > builder.getUniformBufferLimit()) return null;
  let corners: [N, N, N];
  let indices: [N, N, N];
  if (geometry.index === null) {
    // A triangle soup: every vertex of a triangle reads the triangle's three corners from the face texture,
    // so whichever vertex provokes gives the same colour.
    const texture = faceTexture(geometry, 'position');
    const first = (vertexIndex as N).div(3).mul(3);
    indices = [first, first.add(1), first.add(2)];
    corners = indices.map((i) => faceTexel(texture, i).xyz) as [N, N, N];
  } else {
    if (geometry.getAttribute(FLAT_CORNERS[0]) === undefined) return null;
    // A flatShadingGeometry: each triangle's provoking vertex carries the face's other two corners.
    const wanted = provokingVertexOf(builder.renderer ?? {});
    const made = geometry.userData[FLAT_PROVOKING_VERTEX] ?? 'last';
    if (made !== wanted) {
      if (!_warnedProvoking.has(geometry)) {
        _warnedProvoking.add(geometry);
        console.warn(
          `${owner}: this flatShadingGeometry was made with provokingVertex '${made}', but this backend's is the ${wanted}: flat shading lights it per fragment with the face normal. Make it with flatShadingGeometry(geometry, { provokingVertex: '${wanted}' })`,
        );
      }
      return null;
    }
    if ((skinned || morphed) && geometry.getAttribute(FLAT_CORNER_INDEX) === undefined) return null;
    corners = [attribute(FLAT_CORNERS[0], 'vec3'), attribute(FLAT_CORNERS[1], 'vec3'), positionGeometry];
    const index: N = skinned || morphed ? attribute(FLAT_CORNER_INDEX, 'vec2') : null;
    indices = index === null ? [null, null, null] : [int(index.x), int(index.y), vertexIndex];
  }
  if (morphed) corners = corners.map((c, k) => morph(object, geometry, c, indices[k])) as [N, N, N];
  if (skinned) corners = corners.map((c, k) => skin(object, geometry, c, indices[k])) as [N, N, N];
  // An instanced mesh's build is its own (not shared with other instanced meshes); its instance matrix is the node
  // setupPosition moved the vertices by, where that read it as three shares it (see instanceMatrixOf).
  if (object.isInstancedMesh === true) builder.objectSpecific = true;
  return { corners, instance: object.isInstancedMesh === true ? instanceMatrixOf(builder, object) : null };
}

/** Corner `c` (vertex `i`) moved by the mesh's position morph targets, as three's morph node moves a vertex. */
function morph(mesh: N, geometry: BufferGeometry, c: N, i: N): N {
  const targets = geometry.morphAttributes.position ?? [];
  const influences: N = uniformArray(mesh.morphTargetInfluences, 'float');
  OnObjectUpdate(({ object }) => {
    influences.array = (object as unknown as { morphTargetInfluences: number[] }).morphTargetInfluences;
    influences.update();
  });
  let moved: N = c.mul(morphBase);
  targets.forEach((target, t) => {
    const texel = faceTexel(faceTexture(geometry, `morph ${t}`, target), i).xyz;
    moved = moved.add(texel.mul(influences.element(t)));
  });
  return moved;
}

/** Corner `c` (vertex `i`) skinned by the mesh's bones, as three's skinning node skins a vertex. */
function skin(mesh: N, geometry: BufferGeometry, c: N, i: N): N {
  const bones: N = (referenceBuffer as N)('skeleton.boneMatrices', 'mat4', mesh.skeleton.bones.length);
  const bindMatrix: N = (reference as N)('bindMatrix', 'mat4');
  const bindMatrixInverse: N = (reference as N)('bindMatrixInverse', 'mat4');
  const index = faceTexel(faceTexture(geometry, 'skinIndex'), i);
  const weight = faceTexel(faceTexture(geometry, 'skinWeight'), i);
  const bound = bindMatrix.mul(vec4(c, 1));
  const skinned = (['x', 'y', 'z', 'w'] as const)
    .map((k) => bones.element(int(index[k])).mul(weight[k]).mul(bound))
    .reduce((a, b) => a.add(b));
  return bindMatrixInverse.mul(skinned).xyz;
}
