import { BufferAttribute, BufferGeometry, type InterleavedBufferAttribute } from 'three';
import { FLAT_CORNER_INDEX, FLAT_CORNERS, FLAT_PROVOKING_VERTEX, SPHERE_FLAG } from './geometryFlags.js';
import { checkOneOf } from './validate.js';

/** The vertex of a triangle whose flat varyings the rasteriser uses. */
export type ProvokingVertex = 'first' | 'last';

const PROVOKING_VERTICES: readonly ProvokingVertex[] = ['last', 'first'];

/** Options of {@link flatShadingGeometry}. */
export interface FlatShadingGeometryOptions {
  /**
   * Which vertex of each triangle carries its face: `'last'`, WebGL's provoking vertex (`WebGLRenderer`, and
   * `WebGPURenderer` on its WebGL2 backend), or `'first'`, WebGPU's (`WebGPURenderer` on its WebGPU backend:
   * `renderer.backend.isWebGPUBackend`, known after `await renderer.init()`). A material that draws a
   * geometry made for the other one lights it per fragment with the face normal, and warns once.
   * @default 'last'
   */
  provokingVertex?: ProvokingVertex;
}

/**
 * An indexed geometry on which {@link ShadingMaterial}'s flat shading lights every face **once per vertex it
 * owns** instead of once per vertex of a triangle soup: about a third of the vertex-shader runs, and a third
 * less memory.
 *
 * WebGL takes a flat varying from the last vertex of each triangle (its provoking vertex), WebGPU from the
 * first. This gives every triangle a provoking vertex of its own: the triangle's corners are rotated (which
 * keeps its winding) so that an unclaimed corner comes last (or first, see `provokingVertex`), and a corner is
 * duplicated only when all three are taken. Each vertex carries
 * the other two corners of the face it provokes (`flatCornerA`, `flatCornerB`, object space), so the vertex
 * shader has the whole face without a texture. Faces keep their order and winding; the colours equal those of
 * the soup path to float rounding.
 *
 * Memory, for T triangles and V′ ≥ T vertices (a subdivision sphere, V = T/2 + 2, gets exactly V′ = T): 36
 * bytes per vertex (position and the two corners) plus the index, about 48 bytes per triangle (42 with Uint16
 * indices), against 72 for a soup (positions and the face-position texture).
 *
 * A skinned or morphed source keeps what three needs to move it: `skinIndex` and `skinWeight`, the position
 * morph targets (`morphAttributes.position`, `morphTargetsRelative`), and each vertex gets `flatCornerIndex`,
 * the vertex indices of its two corners (8 more bytes per vertex), so that flat shading moves them too.
 *
 * @param geometry - Any triangle geometry with a `position` attribute (indexed or not). Not modified.
 * @param options - The renderer's provoking vertex (see {@link FlatShadingGeometryOptions}).
 * @returns A new indexed geometry with `position`, `flatCornerA` and `flatCornerB` (Uint16 indices while V′
 *   fits, else Uint32), and for a skinned or morphed source the attributes above; flagged as a sphere
 *   (`userData.isSphere`) when the source is one; `userData.flatProvokingVertex` says which vertex provokes.
 * @throws TypeError when `provokingVertex` is not `'first'` or `'last'`, when `geometry` has no 3-component `position` attribute or its index count is not a
 *   multiple of 3.
 */
export function flatShadingGeometry(
  geometry: BufferGeometry,
  { provokingVertex = 'last' }: FlatShadingGeometryOptions = {},
): BufferGeometry {
  checkOneOf('flatShadingGeometry.provokingVertex', provokingVertex, PROVOKING_VERTICES);
  const position = geometry?.getAttribute?.('position');
  if (position === undefined || position.itemSize !== 3) {
    throw new TypeError('flatShadingGeometry: geometry must have a position attribute with 3 components');
  }
  const source = geometry.index;
  const count = source === null ? position.count : source.count;
  if (count % 3 !== 0) {
    throw new TypeError(
      `flatShadingGeometry: the geometry's vertex count must be a multiple of 3, got ${count}`,
    );
  }
  const vertices = position.count;
  const corner = (k: number): number => (source === null ? k : source.getX(k));
  // Worst case: every triangle duplicates one corner.
  const capacity = vertices + count / 3;
  const positions = new Float32Array(3 * capacity);
  for (let i = 0; i < vertices; i++) {
    positions[3 * i] = position.getX(i);
    positions[3 * i + 1] = position.getY(i);
    positions[3 * i + 2] = position.getZ(i);
  }
  const a = new Float32Array(3 * capacity);
  const b = new Float32Array(3 * capacity);
  const taken = new Uint8Array(capacity);
  const index = new Uint32Array(count);
  const origin = new Uint32Array(capacity); // the source vertex of each vertex
  const cornerIndex = new Float32Array(2 * capacity);
  for (let i = 0; i < vertices; i++) origin[i] = i;
  let next = vertices;
  for (let k = 0; k < count; k += 3) {
    let i0 = corner(k);
    let i1 = corner(k + 1);
    let i2 = corner(k + 2);
    // Rotate (i0, i1, i2) → (i1, i2, i0) until the last corner is free; duplicate it when none is.
    if (taken[i2]) {
      const t = i0;
      if (!taken[i0]) {
        i0 = i1;
        i1 = i2;
        i2 = t;
      } else if (!taken[i1]) {
        i0 = i2;
        i2 = i1;
        i1 = t;
      } else {
        positions.copyWithin(3 * next, 3 * i2, 3 * i2 + 3);
        origin[next] = i2;
        i2 = next++;
      }
    }
    taken[i2] = 1;
    for (let c = 0; c < 3; c++) {
      a[3 * i2 + c] = positions[3 * i0 + c];
      b[3 * i2 + c] = positions[3 * i1 + c];
    }
    cornerIndex[2 * i2] = i0;
    cornerIndex[2 * i2 + 1] = i1;
    // A cyclic rotation keeps the winding: (i2, i0, i1) puts the owned corner first.
    const first = provokingVertex === 'first';
    index[k] = first ? i2 : i0;
    index[k + 1] = first ? i0 : i1;
    index[k + 2] = first ? i1 : i2;
  }
  const out = new BufferGeometry();
  out.setIndex(new BufferAttribute(next <= 65536 ? Uint16Array.from(index) : index, 1));
  out.setAttribute('position', new BufferAttribute(positions.slice(0, 3 * next), 3));
  out.setAttribute(FLAT_CORNERS[0], new BufferAttribute(a.slice(0, 3 * next), 3));
  out.setAttribute(FLAT_CORNERS[1], new BufferAttribute(b.slice(0, 3 * next), 3));
  // What three moves a vertex by, per new vertex (a duplicate copies its source vertex).
  // Float32, denormalised: three reads skinIndex, skinWeight and morph targets as floats.
  const copy = (source: BufferAttribute | InterleavedBufferAttribute): BufferAttribute => {
    const n = source.itemSize;
    const array = new Float32Array(n * next);
    for (let i = 0; i < next; i++) {
      for (let c = 0; c < n; c++) array[n * i + c] = source.getComponent(origin[i], c);
    }
    return new BufferAttribute(array, n);
  };
  const morphs = geometry.morphAttributes.position;
  const skinned = geometry.getAttribute('skinIndex') !== undefined;
  if (skinned || morphs !== undefined) {
    for (const name of ['skinIndex', 'skinWeight']) {
      const attribute = geometry.getAttribute(name);
      if (attribute !== undefined) out.setAttribute(name, copy(attribute));
    }
    if (morphs !== undefined) {
      out.morphAttributes.position = morphs.map(copy);
      out.morphTargetsRelative = geometry.morphTargetsRelative;
    }
    out.setAttribute(FLAT_CORNER_INDEX, new BufferAttribute(cornerIndex.slice(0, 2 * next), 2));
  }
  // Still a sphere centred at its origin when the source was one: ShadingMaterial and OutlineMaterial may use
  // the analytic normal = position.
  if (geometry.type === 'SubdivisionSphereGeometry' || geometry.userData[SPHERE_FLAG] === true) {
    out.userData[SPHERE_FLAG] = true;
  }
  out.userData[FLAT_PROVOKING_VERTEX] = provokingVertex;
  out.computeBoundingSphere();
  return out;
}
