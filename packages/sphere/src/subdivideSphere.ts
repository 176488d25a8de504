import { bytesFor } from './estimateSphereBytes.js';
import { baseSolid, type SphereBase } from './SphereBase.js';
import { resolveSphereOptions, type SphereParameters, type SubdivideSphereOptions } from './SphereOptions.js';

/** The arrays of a subdivision sphere. */
export interface SphereMesh {
  /** Vertex positions in scene units, x, y, z per vertex; every vertex at `radius` from the origin. */
  positions: Float32Array;
  /** Unit normals, x, y, z per vertex; absent for `normals: 'none'`. */
  normals?: Float32Array;
  /**
   * Vertex indices, 3 per triangle, counter-clockwise seen from outside; Uint16 while the vertex count is at
   * most 65,536, else Uint32. Absent for `indexed: false`.
   */
  indices?: Uint16Array | Uint32Array;
}

/**
 * Build a sphere by recursive subdivision, as in the lecture: start from a base solid inscribed in the unit
 * sphere, split every triangle into four through its edge midpoints, push the midpoints out to the sphere, and
 * repeat `level` times. No three.js needed.
 *
 * The result has T = F0 · 4^level triangles (F0 = 4, 8, 20), all counter-clockwise seen from outside. Indexed
 * output makes every edge midpoint once, so it has V = 2 + T/2 shared vertices; non-indexed output has 3T.
 *
 * How: level by level on flat typed arrays, with no hashing. An edge table holds each edge's two endpoints and
 * every triangle holds its three edge ids, each with a bit saying which way the triangle runs along it. At each
 * level edge e gets the midpoint vertex V_old + e and splits into edges 2e and 2e + 1, and triangle t adds the
 * interior edges 2·E_old + 3t + 0‥2 and becomes triangles 4t‥4t + 3, so every new id is arithmetic. Every array
 * is allocated once, from the final counts; with Uint32 indices the scratch lives inside the index array (the last
 * pass expands per-triangle records into it in place), so the build allocates only its outputs
 * (`estimateSphereBytes` is exact).
 *
 * Positions are float32: the mesh's radial error is `radius · sphereError(base, level)` (exact for exact
 * vertices) plus at most about radius · 2^-24 from rounding (see `sphereError`).
 *
 * @example
 * ```ts
 * const { positions, normals, indices } = subdivideSphere({ level: 4, base: 'icosahedron', radius: 2 });
 * // 5120 triangles, 2562 vertices at distance 2 from the origin, Uint16 indices
 * ```
 * @throws RangeError / TypeError naming the option for a bad option (see {@link SubdivideSphereOptions}).
 * @throws RangeError with the estimated bytes when the build would allocate more than `maxBytes` (default
 * 512 MiB); nothing is allocated then.
 */
export function subdivideSphere(options: SubdivideSphereOptions = {}): SphereMesh {
  return buildSphere('subdivideSphere', resolveSphereOptions('subdivideSphere', options));
}

/**
 * {@link subdivideSphere} for resolved options; `caller` (the function or class the user called) starts the
 * memory error's message.
 * @internal
 */
export function buildSphere(caller: string, params: SphereParameters): SphereMesh {
  const { level, base, radius, normals, indexed, maxBytes } = params;
  const bytes = bytesFor(params);
  const needs = `${caller}: level ${level} of the ${base}`;
  // Infinity bytes is refused even with maxBytes: Infinity (its arrays cannot exist).
  if (!(bytes <= maxBytes && bytes < Number.POSITIVE_INFINITY)) {
    throw new RangeError(
      `${needs} (${indexed ? 'indexed' : 'non-indexed'}, normals '${normals}') needs about ${formatBytes(bytes)}, above maxBytes = ${formatBytes(maxBytes)}; lower the level or raise maxBytes`,
    );
  }
  let built: { positions: Float32Array; indices: IndexArray };
  try {
    built = buildIndexed(base, level, radius);
  } catch (cause) {
    // Only reachable with a raised maxBytes: the engine refused an array (too long, or out of memory).
    throw new RangeError(
      `${needs} needs about ${formatBytes(bytes)}, which could not be allocated (maxBytes = ${maxBytes}); lower the level`,
      { cause },
    );
  }
  const positions = indexed ? built.positions : expand(built.positions, built.indices);
  const mesh: SphereMesh = { positions };
  if (normals !== 'none') mesh.normals = (normals === 'smooth' ? smoothNormals : flatNormals)(positions);
  if (indexed) mesh.indices = built.indices;
  return mesh;
}

/** `1234567890` → `'1.23 GB (1234567890 bytes)'`. @internal */
export function formatBytes(bytes: number): string {
  if (!Number.isFinite(bytes)) return `${bytes} bytes`;
  let v = bytes;
  let u = 0;
  while (v >= 1000 && u < 6) {
    v /= 1000;
    u++;
  }
  return u === 0 ? `${bytes} bytes` : `${v.toPrecision(3)} ${'kMGTPE'[u - 1]}B (${bytes} bytes)`;
}

type IndexArray = Uint16Array | Uint32Array;

/**
 * Positions (scaled by `radius`) and indices of the indexed sphere.
 *
 * Scratch lives in one Uint32Array of 3T entries (12n, with n = T/4 the triangles of level L − 1): the Uint32
 * index array itself when the indices are Uint32, so the large levels allocate nothing but their outputs.
 * Layout: [0, 3n) the edge table of level L − 1; [3n, 4.5n) and [4.5n, 6n) two regions for levels L − 2,
 * L − 3, … (alternating, each level's edge table then its triangle edge ids); [6n, 12n) one record per
 * triangle of level L − 1, its three corners and the level-L midpoint vertices of its three edges. The last
 * pass turns record t (entries 6n + 6t …) into the four output triangles 12t … 12t + 11 in place: it reads a
 * record before writing, and 12t + 11 < 6n + 6(t + 1) for every t < n, so no unread record is overwritten.
 */
function buildIndexed(
  base: SphereBase,
  level: number,
  radius: number,
): { positions: Float32Array; indices: IndexArray } {
  const { vertices, faces } = baseSolid(base);
  const f0 = faces.length / 3;
  const triangles = f0 * 4 ** level;
  const vertexCount = 2 + triangles / 2;
  const positions = new Float32Array(3 * vertexCount);
  for (let i = 0; i < vertices.length; i++) positions[i] = vertices[i] * radius;
  if (level === 0) return { positions, indices: Uint16Array.from(faces) };

  const n = triangles / 4;
  const wide = vertexCount > 65536;
  const indices = wide ? new Uint32Array(3 * triangles) : new Uint16Array(3 * triangles);
  const scratch = wide ? (indices as Uint32Array) : new Uint32Array(3 * triangles);
  const lastEdges = scratch.subarray(0, 3 * n);
  const records = scratch.subarray(6 * n);
  let vertexBase = vertices.length / 3;

  // Level 0 state: edge table and triangle edge ids. With level 1 it is level L − 1 (edges straight into
  // lastEdges); else it is level L − 2 − j, in region A = [3n, 4.5n) when j is even, B = [4.5n, 6n) when odd.
  const regionA = 3 * n;
  const regionB = 4.5 * n;
  let at = level % 2 === 0 ? regionA : regionB;
  let edges = level === 1 ? lastEdges : scratch.subarray(at, at + 3 * f0);
  let tris =
    level === 1 ? scratch.subarray(regionA, regionA + 3 * f0) : scratch.subarray(at + 3 * f0, at + 6 * f0);
  // Each triangle edge gets an id, ×2, + 1 when the triangle runs against the stored direction.
  let edgeCount = 0;
  for (let c = 0; c < faces.length; c++) {
    const u = faces[c];
    const w = faces[c % 3 === 2 ? c - 2 : c + 1];
    let id = -1;
    for (let e = 0; e < edgeCount; e++) {
      if (edges[2 * e] === w && edges[2 * e + 1] === u) id = 2 * e + 1;
    }
    if (id < 0) {
      edges[2 * edgeCount] = u;
      edges[2 * edgeCount + 1] = w;
      id = 2 * edgeCount++;
    }
    tris[c] = id;
  }
  midpoints(positions, edges, edgeCount, vertexBase, radius);

  if (level === 1) {
    for (let t = 0; t < f0; t++) {
      for (let k = 0; k < 3; k++) {
        records[6 * t + k] = faces[3 * t + k];
        records[6 * t + 3 + k] = vertexBase + (tris[3 * t + k] >>> 1);
      }
    }
  } else {
    let triangleCount = f0;
    for (let k = 0; k < level - 2; k++) {
      // Level k (in one region) → level k + 1 (in the other).
      at = at === regionA ? regionB : regionA;
      const nextEdgeCount = 2 * edgeCount + 3 * triangleCount;
      const nextEdges = scratch.subarray(at, at + 2 * nextEdgeCount);
      const nextTris = scratch.subarray(at + 2 * nextEdgeCount, at + 2 * nextEdgeCount + 12 * triangleCount);
      refine(edges, tris, edgeCount, triangleCount, vertexBase, nextEdges, nextTris);
      vertexBase += edgeCount;
      edgeCount = nextEdgeCount;
      triangleCount *= 4;
      edges = nextEdges;
      tris = nextTris;
      midpoints(positions, edges, edgeCount, vertexBase, radius);
    }
    // Level L − 2 → the edge table and the records of level L − 1.
    refineLast(edges, tris, edgeCount, triangleCount, vertexBase, lastEdges, records);
    vertexBase += edgeCount;
    edgeCount = 2 * edgeCount + 3 * triangleCount;
    midpoints(positions, lastEdges, edgeCount, vertexBase, radius);
  }
  finalTriangles(records, n, indices);
  return { positions, indices };
}

/** Vertex `vertexBase + e` = the midpoint of edge e pushed out to the sphere of `radius`. */
function midpoints(
  positions: Float32Array,
  edges: Uint32Array,
  edgeCount: number,
  vertexBase: number,
  radius: number,
): void {
  for (let e = 0, o = 3 * vertexBase; e < edgeCount; e++, o += 3) {
    const a = 3 * edges[2 * e];
    const b = 3 * edges[2 * e + 1];
    const x = positions[a] + positions[b];
    const y = positions[a + 1] + positions[b + 1];
    const z = positions[a + 2] + positions[b + 2];
    const s = radius / Math.sqrt(x * x + y * y + z * z);
    positions[o] = x * s;
    positions[o + 1] = y * s;
    positions[o + 2] = z * s;
  }
}

/** Edge e (u → w) with midpoint m = vertexBase + e becomes edges 2e (u → m) and 2e + 1 (m → w). */
function splitEdges(edges: Uint32Array, edgeCount: number, vertexBase: number, nextEdges: Uint32Array): void {
  for (let e = 0; e < edgeCount; e++) {
    const m = vertexBase + e;
    nextEdges[4 * e] = edges[2 * e];
    nextEdges[4 * e + 1] = m;
    nextEdges[4 * e + 2] = m;
    nextEdges[4 * e + 3] = edges[2 * e + 1];
  }
}

/**
 * The edge table and triangle edge ids of the next level. Edge e (u → w) with midpoint m becomes 2e (u → m)
 * and 2e + 1 (m → w); triangle t with midpoints m0, m1, m2 (of its edges 0, 1, 2) adds interior edges
 * m0 → m1, m1 → m2, m2 → m0 and becomes the corner triangles (a, m0, m2), (m0, b, m1), (m2, m1, c) and the
 * centre (m0, m1, m2). A triangle's edge id p = 2·edge + flip; running along edge p, the first half is
 * 2p + flip and the second 2p + 2 − 3·flip, with the same flip.
 */
function refine(
  edges: Uint32Array,
  tris: Uint32Array,
  edgeCount: number,
  triangleCount: number,
  vertexBase: number,
  nextEdges: Uint32Array,
  nextTris: Uint32Array,
): void {
  splitEdges(edges, edgeCount, vertexBase, nextEdges);
  for (let t = 0, interior = 2 * edgeCount; t < triangleCount; t++, interior += 3) {
    const p0 = tris[3 * t];
    const p1 = tris[3 * t + 1];
    const p2 = tris[3 * t + 2];
    const f0 = p0 & 1;
    const f1 = p1 & 1;
    const f2 = p2 & 1;
    const m0 = vertexBase + (p0 >>> 1);
    const m1 = vertexBase + (p1 >>> 1);
    const m2 = vertexBase + (p2 >>> 1);
    const o = 2 * interior;
    nextEdges[o] = m0;
    nextEdges[o + 1] = m1;
    nextEdges[o + 2] = m1;
    nextEdges[o + 3] = m2;
    nextEdges[o + 4] = m2;
    nextEdges[o + 5] = m0;
    const q0 = 2 * interior; // interior edges, forward
    const c = 12 * t;
    nextTris[c] = 2 * p0 + f0; // (a, m0, m2)
    nextTris[c + 1] = q0 + 5;
    nextTris[c + 2] = 2 * p2 + 2 - 3 * f2;
    nextTris[c + 3] = 2 * p0 + 2 - 3 * f0; // (m0, b, m1)
    nextTris[c + 4] = 2 * p1 + f1;
    nextTris[c + 5] = q0 + 1;
    nextTris[c + 6] = q0 + 3; // (m2, m1, c)
    nextTris[c + 7] = 2 * p1 + 2 - 3 * f1;
    nextTris[c + 8] = 2 * p2 + f2;
    nextTris[c + 9] = q0; // (m0, m1, m2)
    nextTris[c + 10] = q0 + 2;
    nextTris[c + 11] = q0 + 4;
  }
}

/**
 * As {@link refine}, but each child triangle is written as a record: its corners, then the vertices the next
 * (final) level puts at its edges' midpoints. A child's edge id x gives that vertex as next base + (x >>> 1):
 * along parent edge p the first half is p and the second p ^ 1; interior edge i gives interior + i.
 */
function refineLast(
  edges: Uint32Array,
  tris: Uint32Array,
  edgeCount: number,
  triangleCount: number,
  vertexBase: number,
  nextEdges: Uint32Array,
  records: Uint32Array,
): void {
  splitEdges(edges, edgeCount, vertexBase, nextEdges);
  const next = vertexBase + edgeCount; // first vertex of the final level
  for (let t = 0, interior = 2 * edgeCount; t < triangleCount; t++, interior += 3) {
    const p0 = tris[3 * t];
    const p1 = tris[3 * t + 1];
    const p2 = tris[3 * t + 2];
    const a = edges[p0];
    const b = edges[p1];
    const c = edges[p2];
    const m0 = vertexBase + (p0 >>> 1);
    const m1 = vertexBase + (p1 >>> 1);
    const m2 = vertexBase + (p2 >>> 1);
    const o = 2 * interior;
    nextEdges[o] = m0;
    nextEdges[o + 1] = m1;
    nextEdges[o + 2] = m1;
    nextEdges[o + 3] = m2;
    nextEdges[o + 4] = m2;
    nextEdges[o + 5] = m0;
    const i0 = next + interior;
    const r = 24 * t;
    records[r] = a; // (a, m0, m2)
    records[r + 1] = m0;
    records[r + 2] = m2;
    records[r + 3] = next + p0;
    records[r + 4] = i0 + 2;
    records[r + 5] = next + (p2 ^ 1);
    records[r + 6] = m0; // (m0, b, m1)
    records[r + 7] = b;
    records[r + 8] = m1;
    records[r + 9] = next + (p0 ^ 1);
    records[r + 10] = next + p1;
    records[r + 11] = i0;
    records[r + 12] = m2; // (m2, m1, c)
    records[r + 13] = m1;
    records[r + 14] = c;
    records[r + 15] = i0 + 1;
    records[r + 16] = next + (p1 ^ 1);
    records[r + 17] = next + p2;
    records[r + 18] = m0; // (m0, m1, m2)
    records[r + 19] = m1;
    records[r + 20] = m2;
    records[r + 21] = i0;
    records[r + 22] = i0 + 1;
    records[r + 23] = i0 + 2;
  }
}

/**
 * The output: record (a, b, c, m0, m1, m2) becomes triangles (a, m0, m2), (m0, b, m1), (m2, m1, c),
 * (m0, m1, m2). `out` may be the array `records` views (in place; see {@link buildIndexed}).
 */
function finalTriangles(records: Uint32Array, count: number, out: IndexArray): void {
  for (let t = 0; t < count; t++) {
    const r = 6 * t;
    const a = records[r];
    const b = records[r + 1];
    const c = records[r + 2];
    const m0 = records[r + 3];
    const m1 = records[r + 4];
    const m2 = records[r + 5];
    const o = 12 * t;
    out[o] = a;
    out[o + 1] = m0;
    out[o + 2] = m2;
    out[o + 3] = m0;
    out[o + 4] = b;
    out[o + 5] = m1;
    out[o + 6] = m2;
    out[o + 7] = m1;
    out[o + 8] = c;
    out[o + 9] = m0;
    out[o + 10] = m1;
    out[o + 11] = m2;
  }
}

/** The triangle soup of an indexed mesh. */
function expand(positions: Float32Array, indices: IndexArray): Float32Array {
  const out = new Float32Array(3 * indices.length);
  for (let i = 0, o = 0; i < indices.length; i++, o += 3) {
    const a = 3 * indices[i];
    out[o] = positions[a];
    out[o + 1] = positions[a + 1];
    out[o + 2] = positions[a + 2];
  }
  return out;
}

/** position / |position|: the exact normal of a sphere centred at the origin. */
function smoothNormals(positions: Float32Array): Float32Array {
  const out = new Float32Array(positions.length);
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i];
    const y = positions[i + 1];
    const z = positions[i + 2];
    const s = 1 / Math.sqrt(x * x + y * y + z * z);
    out[i] = x * s;
    out[i + 1] = y * s;
    out[i + 2] = z * s;
  }
  return out;
}

/** Each triangle's unit face normal on its three corners (a triangle soup). */
function flatNormals(soup: Float32Array): Float32Array {
  const out = new Float32Array(soup.length);
  for (let i = 0; i < soup.length; i += 9) {
    const ux = soup[i + 3] - soup[i];
    const uy = soup[i + 4] - soup[i + 1];
    const uz = soup[i + 5] - soup[i + 2];
    const vx = soup[i + 6] - soup[i];
    const vy = soup[i + 7] - soup[i + 1];
    const vz = soup[i + 8] - soup[i + 2];
    const nx = uy * vz - uz * vy;
    const ny = uz * vx - ux * vz;
    const nz = ux * vy - uy * vx;
    const s = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz);
    for (let k = 0; k < 9; k += 3) {
      out[i + k] = nx * s;
      out[i + k + 1] = ny * s;
      out[i + k + 2] = nz * s;
    }
  }
  return out;
}
