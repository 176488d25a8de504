// Test helpers: independent mesh checks used by the sphere tests (not part of the package).

/** Triangle corner indices of a mesh, indexed or a soup. */
export function triangleIndices(positions: Float32Array, indices?: ArrayLike<number>): Uint32Array {
  if (indices) return Uint32Array.from(indices);
  return Uint32Array.from({ length: positions.length / 3 }, (_, i) => i);
}

/** Merge coincident vertices (exact float equality) so a soup can be checked like an indexed mesh. */
export function weld(positions: Float32Array, indices: Uint32Array): Uint32Array {
  const ids = new Map<string, number>();
  const remap = new Uint32Array(positions.length / 3);
  for (let v = 0; v < remap.length; v++) {
    const key = `${positions[3 * v]},${positions[3 * v + 1]},${positions[3 * v + 2]}`;
    let id = ids.get(key);
    if (id === undefined) {
      id = ids.size;
      ids.set(key, id);
    }
    remap[v] = id;
  }
  return indices.map((i) => remap[i]);
}

/** Watertight and oriented: every directed edge u→w appears once and w→u once. Returns V, E, F. */
export function checkClosedOriented(indices: Uint32Array): {
  V: number;
  E: number;
  F: number;
  problems: number;
} {
  const directed = new Map<number, number>();
  let V = 0;
  for (const i of indices) V = Math.max(V, i + 1);
  let problems = 0;
  for (let t = 0; t < indices.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const u = indices[t + k];
      const w = indices[t + ((k + 1) % 3)];
      if (u === w) problems++;
      const key = u * V + w;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  }
  for (const [key, count] of directed) {
    const u = Math.floor(key / V);
    const w = key % V;
    if (count !== 1 || directed.get(w * V + u) !== 1) problems++;
  }
  return { V, E: directed.size / 2, F: indices.length / 3, problems };
}

/** Count triangles whose face normal points inwards (n · centroid ≤ 0). */
export function inwardFaces(positions: Float32Array, indices: Uint32Array): number {
  let inward = 0;
  for (let t = 0; t < indices.length; t += 3) {
    const a = 3 * indices[t];
    const b = 3 * indices[t + 1];
    const c = 3 * indices[t + 2];
    const u = [
      positions[b] - positions[a],
      positions[b + 1] - positions[a + 1],
      positions[b + 2] - positions[a + 2],
    ];
    const v = [
      positions[c] - positions[a],
      positions[c + 1] - positions[a + 1],
      positions[c + 2] - positions[a + 2],
    ];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const g = [0, 1, 2].map((k) => positions[a + k] + positions[b + k] + positions[c + k]);
    if (n[0] * g[0] + n[1] * g[1] + n[2] * g[2] <= 0) inward++;
  }
  return inward;
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
