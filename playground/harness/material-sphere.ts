// The lecture's sphere for the material harness pages (kept here so the harness does not depend on the
// @shadelab/sphere package while it is being written).
import { BufferGeometry, Float32BufferAttribute } from 'three';

/** The lecture's sphere: a tetrahedron subdivided `level` times, vertices pushed to the unit sphere. */
export function tetrahedronSphere(level: number): Float32Array {
  const s2 = Math.SQRT2;
  const s6 = Math.sqrt(6);
  const a = [0, 0, 1];
  const b = [0, (2 * s2) / 3, -1 / 3];
  const c = [-s6 / 3, -s2 / 3, -1 / 3];
  const d = [s6 / 3, -s2 / 3, -1 / 3];
  const out: number[] = [];
  const mid = (p: number[], q: number[]) => {
    const m = [p[0] + q[0], p[1] + q[1], p[2] + q[2]];
    const l = Math.hypot(m[0], m[1], m[2]);
    return [m[0] / l, m[1] / l, m[2] / l];
  };
  const divide = (p: number[], q: number[], r: number[], n: number): void => {
    if (n === 0) {
      out.push(...p, ...q, ...r);
      return;
    }
    const pq = mid(p, q);
    const pr = mid(p, r);
    const qr = mid(q, r);
    divide(p, pq, pr, n - 1);
    divide(pq, q, qr, n - 1);
    divide(qr, r, pr, n - 1);
    divide(pq, qr, pr, n - 1);
  };
  divide(d, c, b, level);
  divide(a, b, c, level);
  divide(a, d, b, level);
  divide(a, c, d, level);
  return new Float32Array(out);
}

const geometries = new Map<string, BufferGeometry>();
/** Non-indexed sphere; `normals: false` drops the normal attribute and flags it for analytic normals. */
export function sphereGeometry(level: number, normals: boolean): BufferGeometry {
  const key = `${level}/${normals}`;
  let g = geometries.get(key);
  if (g === undefined) {
    g = new BufferGeometry();
    const positions = tetrahedronSphere(level);
    g.setAttribute('position', new Float32BufferAttribute(positions, 3));
    if (normals) g.setAttribute('normal', new Float32BufferAttribute(positions.slice(), 3));
    else g.userData.isSphere = true;
    geometries.set(key, g);
  }
  return g;
}
