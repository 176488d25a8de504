// Test helpers: independent mesh checks used by the sphere tests (not part of the package).

/** Triangle corner indices of a mesh, indexed or a soup. */
export function triangleIndices(positions: Float32Array, indices?: ArrayLike<number>): Uint32Array {
  if (indices) return Uint32Array.from(indices);
  return Uint32Array.from({ length: positions.length / 3 }, (_, i) => i);
}

/**
 * Vertex ids sorted by position (x, then y, then z, float32 values), ties by id: coincident vertices end up next
 * to each other, the smallest id first.
 */
function sortedByPosition(positions: Float32Array): Uint32Array {
  const order = new Uint32Array(positions.length / 3);
  for (let i = 0; i < order.length; i++) order[i] = i;
  return order.sort(
    (a, b) =>
      positions[3 * a] - positions[3 * b] ||
      positions[3 * a + 1] - positions[3 * b + 1] ||
      positions[3 * a + 2] - positions[3 * b + 2] ||
      a - b,
  );
}

function samePosition(positions: Float32Array, a: number, b: number): boolean {
  return (
    positions[3 * a] === positions[3 * b] &&
    positions[3 * a + 1] === positions[3 * b + 1] &&
    positions[3 * a + 2] === positions[3 * b + 2]
  );
}

/**
 * Merge coincident vertices (exact float equality) so a soup can be checked like an indexed mesh: the merged
 * vertices are numbered in order of first use, so a mesh without duplicates keeps its indices. Sorting, no hashing.
 */
export function weld(positions: Float32Array, indices: Uint32Array): Uint32Array {
  const order = sortedByPosition(positions);
  const first = new Uint32Array(order.length); // each vertex → the smallest id at its position
  for (let i = 0; i < order.length; i++) {
    first[order[i]] =
      i > 0 && samePosition(positions, order[i - 1], order[i]) ? first[order[i - 1]] : order[i];
  }
  const compact = new Uint32Array(order.length);
  for (let v = 0, next = 0; v < order.length; v++) compact[v] = first[v] === v ? next++ : compact[first[v]];
  return indices.map((i) => compact[i]);
}

/**
 * Watertight and oriented: every directed edge u→w appears once and w→u once. Typed arrays only (fast enough for
 * 12M corners): the directed edges are bucketed by their start vertex (a counting sort), so each vertex's
 * out-edges are a short list; a closed oriented surface has no repeat in a list, and w's list holds u for every
 * u→w. Returns V, E, F and the number of problems (degenerate edges, repeated directed edges, directed edges
 * without their reverse).
 */
export function checkClosedOriented(indices: ArrayLike<number>): {
  V: number;
  E: number;
  F: number;
  problems: number;
} {
  let V = 0;
  for (let i = 0; i < indices.length; i++) if (indices[i] >= V) V = indices[i] + 1;
  const next = (t: number, k: number) => indices[t + (k === 2 ? 0 : k + 1)];
  // start[u] … start[u + 1]: the ends w of the directed edges u→w.
  const start = new Uint32Array(V + 1);
  for (let i = 0; i < indices.length; i++) start[indices[i] + 1]++;
  for (let u = 0; u < V; u++) start[u + 1] += start[u];
  const fill = start.slice(0, V);
  const ends = new Uint32Array(indices.length);
  for (let t = 0; t < indices.length; t += 3) {
    for (let k = 0; k < 3; k++) ends[fill[indices[t + k]]++] = next(t, k);
  }
  const has = (u: number, w: number) => {
    for (let j = start[u]; j < start[u + 1]; j++) if (ends[j] === w) return true;
    return false;
  };
  let problems = 0;
  let distinct = 0;
  for (let u = 0; u < V; u++) {
    for (let j = start[u]; j < start[u + 1]; j++) {
      const w = ends[j];
      if (u === w) problems++;
      let repeated = false;
      for (let i = start[u]; i < j; i++) if (ends[i] === w) repeated = true;
      if (repeated) problems++;
      else distinct++;
      if (!has(w, u)) problems++;
    }
  }
  return { V, E: distinct / 2, F: indices.length / 3, problems };
}

/**
 * Vertices at exactly the same place as another (float32 equality, so −0 = 0), found with an open-addressing
 * hash table of the positions' bit patterns.
 */
export function duplicateVertices(positions: Float32Array): number {
  const count = positions.length / 3;
  const normalised = positions.map((x) => x + 0); // −0 + 0 = +0: equal floats, equal bits
  const bits = new Uint32Array(normalised.buffer);
  let size = 1;
  while (size < 2 * count) size *= 2;
  const table = new Int32Array(size).fill(-1);
  let duplicates = 0;
  for (let v = 0; v < count; v++) {
    const [x, y, z] = [bits[3 * v], bits[3 * v + 1], bits[3 * v + 2]];
    let slot = (Math.imul(x, 0x9e3779b1) ^ Math.imul(y, 0x85ebca77) ^ Math.imul(z, 0xc2b2ae3d)) & (size - 1);
    for (;;) {
      const other = table[slot];
      if (other < 0) {
        table[slot] = v;
        break;
      }
      if (bits[3 * other] === x && bits[3 * other + 1] === y && bits[3 * other + 2] === z) {
        duplicates++;
        break;
      }
      slot = (slot + 1) & (size - 1);
    }
  }
  return duplicates;
}

/** Count triangles whose face normal points inwards (n · centroid ≤ 0). */
export function inwardFaces(positions: Float32Array, indices: ArrayLike<number>): number {
  let inward = 0;
  for (let t = 0; t < indices.length; t += 3) {
    const a = 3 * indices[t];
    const b = 3 * indices[t + 1];
    const c = 3 * indices[t + 2];
    const ux = positions[b] - positions[a];
    const uy = positions[b + 1] - positions[a + 1];
    const uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a];
    const vy = positions[c + 1] - positions[a + 1];
    const vz = positions[c + 2] - positions[a + 2];
    const gx = positions[a] + positions[b] + positions[c];
    const gy = positions[a + 1] + positions[b + 1] + positions[c + 1];
    const gz = positions[a + 2] + positions[b + 2] + positions[c + 2];
    if ((uy * vz - uz * vy) * gx + (uz * vx - ux * vz) * gy + (ux * vy - uy * vx) * gz <= 0) inward++;
  }
  return inward;
}

/**
 * Run `build` while every Float32Array, Float64Array, Uint8Array, Uint16Array and Uint32Array it creates with
 * `new` or `from` is counted: the byte length of each distinct ArrayBuffer behind them (views such as
 * `subarray` share their buffer). During the call the globals are proxies whose construct trap makes a plain
 * typed array (so the build runs at full speed) and records its buffer.
 */
export function countAllocatedBytes<T>(build: () => T): { result: T; bytes: number } {
  const buffers = new Set<ArrayBufferLike>();
  const names = ['Float32Array', 'Float64Array', 'Uint8Array', 'Uint16Array', 'Uint32Array'] as const;
  const g = globalThis as unknown as Record<string, unknown>;
  const originals = names.map((name) => g[name] as new (...args: unknown[]) => ArrayBufferView);
  names.forEach((name, i) => {
    g[name] = new Proxy(originals[i], {
      construct(target, args) {
        const array = Reflect.construct(target, args) as ArrayBufferView;
        buffers.add(array.buffer);
        return array;
      },
    });
  });
  try {
    const result = build();
    let bytes = 0;
    for (const buffer of buffers) bytes += buffer.byteLength;
    return { result, bytes };
  } finally {
    names.forEach((name, i) => {
      g[name] = originals[i];
    });
  }
}

/** Largest | |p| / radius − 1 | over the vertices. */
export function maxRadialDeviation(positions: Float32Array, radius: number): number {
  let worst = 0;
  for (let i = 0; i < positions.length; i += 3) {
    const r = Math.hypot(positions[i], positions[i + 1], positions[i + 2]);
    worst = Math.max(worst, Math.abs(r / radius - 1));
  }
  return worst;
}

/** Float32 rounding of a vector's length: 3 components each off by half an ulp (2^-24), plus slack. */
export const FLOAT32_RADIUS_TOLERANCE = 2 ** -22;

type Vec = readonly [number, number, number];

/**
 * The lecture's `divideTriangle` recursion, in double precision: split (a, b, c) into (a, ab, ac), (ab, b, bc),
 * (bc, c, ac), (ab, bc, ac) with normalised midpoints, `level` times. Returns unit triangles.
 */
export function lectureSubdivision(triangles: readonly (readonly Vec[])[], level: number): Vec[][] {
  const out: Vec[][] = [];
  const mid = (p: Vec, q: Vec): Vec => {
    const m: Vec = [p[0] + q[0], p[1] + q[1], p[2] + q[2]];
    const l = Math.sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    return [m[0] / l, m[1] / l, m[2] / l];
  };
  const divide = (a: Vec, b: Vec, c: Vec, n: number): void => {
    if (n === 0) {
      out.push([a, b, c]);
      return;
    }
    const ab = mid(a, b);
    const ac = mid(a, c);
    const bc = mid(b, c);
    divide(a, ab, ac, n - 1);
    divide(ab, b, bc, n - 1);
    divide(bc, c, ac, n - 1);
    divide(ab, bc, ac, n - 1);
  };
  for (const [a, b, c] of triangles) divide(a, b, c, level);
  return out;
}

/** Triangles of a non-indexed three.js position array (9 numbers per triangle), normalised to the unit sphere. */
export function unitTriangles(soup: ArrayLike<number>): Vec[][] {
  const out: Vec[][] = [];
  for (let i = 0; i < soup.length; i += 9) {
    const t: Vec[] = [];
    for (let k = 0; k < 9; k += 3) {
      const l = Math.hypot(soup[i + k], soup[i + k + 1], soup[i + k + 2]);
      t.push([soup[i + k] / l, soup[i + k + 1] / l, soup[i + k + 2] / l]);
    }
    out.push(t);
  }
  return out;
}

/** The triangles of a mesh as sorted keys, each triangle rotated (not reflected) to start at its least vertex. */
export function triangleKeys(triangles: readonly (readonly Vec[])[], digits = 5): string[] {
  const key = (v: Vec) => v.map((x) => (Math.abs(x) < 10 ** -digits ? 0 : x).toFixed(digits)).join(',');
  return triangles
    .map((t) => {
      const ks = t.map(key);
      let first = 0;
      for (let k = 1; k < 3; k++) if (ks[k] < ks[first]) first = k;
      return [ks[first], ks[(first + 1) % 3], ks[(first + 2) % 3]].join(' | ');
    })
    .sort();
}

/** The triangles of an indexed float32 mesh, scaled to the unit sphere. */
export function meshTriangles(positions: Float32Array, indices: ArrayLike<number>, radius = 1): Vec[][] {
  const out: Vec[][] = [];
  for (let t = 0; t < indices.length; t += 3) {
    const tri: Vec[] = [];
    for (let k = 0; k < 3; k++) {
      const a = 3 * indices[t + k];
      tri.push([positions[a] / radius, positions[a + 1] / radius, positions[a + 2] / radius]);
    }
    out.push(tri);
  }
  return out;
}

/**
 * 1 − min |p| over a flat triangle: the closest point of the triangle to the origin by the textbook
 * region test (Ericson, Real-Time Collision Detection 5.1.5), not assuming unit vertices.
 */
export function closestPointError(a: Vec, b: Vec, c: Vec): number {
  const sub = (p: Vec, q: Vec): Vec => [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
  const dot = (p: Vec, q: Vec) => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  const p: Vec = [0, 0, 0];
  const ab = sub(b, a);
  const ac = sub(c, a);
  const ap = sub(p, a);
  const at = (v: number, w: number): Vec => [
    a[0] + ab[0] * v + ac[0] * w,
    a[1] + ab[1] * v + ac[1] * w,
    a[2] + ab[2] * v + ac[2] * w,
  ];
  const len = (q: Vec) => Math.sqrt(dot(q, q));
  const d1 = dot(ab, ap);
  const d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return 1 - len(a);
  const bp = sub(p, b);
  const d3 = dot(ab, bp);
  const d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return 1 - len(b);
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return 1 - len(at(d1 / (d1 - d3), 0));
  const cp = sub(p, c);
  const d5 = dot(ab, cp);
  const d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return 1 - len(c);
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return 1 - len(at(0, d2 / (d2 - d6)));
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const w = (d4 - d3) / (d4 - d3 + (d5 - d6));
    const q: Vec = [b[0] + (c[0] - b[0]) * w, b[1] + (c[1] - b[1]) * w, b[2] + (c[2] - b[2]) * w];
    return 1 - len(q);
  }
  const denom = 1 / (va + vb + vc);
  return 1 - len(at(vb * denom, vc * denom));
}

/** The lecture's tetrahedron: vertices a, b, c, d and its faces (d, c, b), (a, b, c), (a, d, b), (a, c, d). */
export function lectureTetrahedron(): [Vec, Vec, Vec][] {
  const s2 = Math.SQRT2;
  const s6 = Math.sqrt(6);
  const a: Vec = [0, 0, 1];
  const b: Vec = [0, (2 * s2) / 3, -1 / 3];
  const c: Vec = [-s6 / 3, -s2 / 3, -1 / 3];
  const d: Vec = [s6 / 3, -s2 / 3, -1 / 3];
  return [
    [d, c, b],
    [a, b, c],
    [a, d, b],
    [a, c, d],
  ];
}

/**
 * How many triangles of `ours` have no partner in `reference` with the same vertices in the same cyclic order
 * (any rotation, no reflection), each vertex within `tolerance`; partners are used once. Matches through a grid
 * on the centroids, so rounding never splits a pair.
 */
export function unmatchedTriangles(
  ours: readonly (readonly Vec[])[],
  reference: readonly (readonly Vec[])[],
  tolerance = 1e-6,
): number {
  const cell = 1e-3;
  const key = (x: number, y: number, z: number) => `${x},${y},${z}`;
  const grid = new Map<string, number[]>();
  const centroid = (t: readonly Vec[]) => [0, 1, 2].map((k) => (t[0][k] + t[1][k] + t[2][k]) / 3 / cell);
  reference.forEach((t, i) => {
    const [x, y, z] = centroid(t).map(Math.floor);
    const list = grid.get(key(x, y, z)) ?? [];
    list.push(i);
    grid.set(key(x, y, z), list);
  });
  const used = new Uint8Array(reference.length);
  const close = (p: Vec, q: Vec) =>
    Math.abs(p[0] - q[0]) <= tolerance &&
    Math.abs(p[1] - q[1]) <= tolerance &&
    Math.abs(p[2] - q[2]) <= tolerance;
  let unmatched = 0;
  for (const t of ours) {
    const [cx, cy, cz] = centroid(t).map(Math.floor);
    let found = false;
    for (let dx = -1; dx <= 1 && !found; dx++) {
      for (let dy = -1; dy <= 1 && !found; dy++) {
        for (let dz = -1; dz <= 1 && !found; dz++) {
          for (const i of grid.get(key(cx + dx, cy + dy, cz + dz)) ?? []) {
            const r = reference[i];
            if (used[i]) continue;
            for (let s = 0; s < 3 && !found; s++) {
              if (close(t[0], r[s]) && close(t[1], r[(s + 1) % 3]) && close(t[2], r[(s + 2) % 3])) {
                used[i] = 1;
                found = true;
              }
            }
            if (found) break;
          }
        }
      }
    }
    if (!found) unmatched++;
  }
  return unmatched + Math.max(0, reference.length - ours.length);
}

/**
 * The radial error of a float32 indexed mesh as built: the largest 1 − |p| / radius over every point p of every
 * face, by the same closest-point region test as {@link closestPointError}, in scalars (millions of faces).
 */
export function meshRadialError(positions: Float32Array, indices: ArrayLike<number>, radius: number): number {
  let worst = Number.NEGATIVE_INFINITY;
  for (let t = 0; t < indices.length; t += 3) {
    const i = 3 * indices[t];
    const j = 3 * indices[t + 1];
    const k = 3 * indices[t + 2];
    const ax = positions[i] / radius;
    const ay = positions[i + 1] / radius;
    const az = positions[i + 2] / radius;
    const abx = positions[j] / radius - ax;
    const aby = positions[j + 1] / radius - ay;
    const abz = positions[j + 2] / radius - az;
    const acx = positions[k] / radius - ax;
    const acy = positions[k + 1] / radius - ay;
    const acz = positions[k + 2] / radius - az;
    // Closest point a + v·ab + w·ac to the origin (Ericson 5.1.5 with p = 0).
    const d1 = -(abx * ax + aby * ay + abz * az);
    const d2 = -(acx * ax + acy * ay + acz * az);
    const d3 = d1 - (abx * abx + aby * aby + abz * abz);
    const d4 = d2 - (acx * abx + acy * aby + acz * abz);
    const d5 = d1 - (abx * acx + aby * acy + abz * acz);
    const d6 = d2 - (acx * acx + acy * acy + acz * acz);
    let v: number;
    let w: number;
    const va = d3 * d6 - d5 * d4;
    const vb = d5 * d2 - d1 * d6;
    const vc = d1 * d4 - d3 * d2;
    if (d1 <= 0 && d2 <= 0) [v, w] = [0, 0];
    else if (d3 >= 0 && d4 <= d3) [v, w] = [1, 0];
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) [v, w] = [d1 / (d1 - d3), 0];
    else if (d6 >= 0 && d5 <= d6) [v, w] = [0, 1];
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) [v, w] = [0, d2 / (d2 - d6)];
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
      const s = (d4 - d3) / (d4 - d3 + (d5 - d6));
      [v, w] = [1 - s, s];
    } else [v, w] = [vb / (va + vb + vc), vc / (va + vb + vc)];
    const e = 1 - Math.hypot(ax + v * abx + w * acx, ay + v * aby + w * acy, az + v * abz + w * acz);
    if (e > worst) worst = e;
  }
  return worst;
}
