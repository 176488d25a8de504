import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import {
  BufferAttribute,
  BufferGeometry,
  IcosahedronGeometry,
  InstancedMesh,
  Matrix4,
  Mesh,
  MeshPhongMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  Vector3,
} from 'three';
import { describe, expect, it } from 'vitest';
import { AdaptiveShading } from './AdaptiveShading.js';
import { allocateShading } from './allocateShading.js';
import { linearToSrgb8Channel } from './linearToSrgb8.js';
import { ShadingMaterial } from './ShadingMaterial.js';
import { shade } from './shade.js';
import {
  ERROR_BUDGETS,
  fibonacciDirections,
  measureShadingError,
  overFraction,
} from './shadingErrorModel.js';

const FAST = { resolution: 24, views: 2, lights: 3 };
const VIEW = { width: 800, height: 600 };

function camera(z: number): PerspectiveCamera {
  const c = new PerspectiveCamera(50, 800 / 600, 0.1, 1000);
  c.position.set(0, 0, z);
  c.lookAt(0, 0, 0);
  c.updateMatrixWorld();
  return c;
}

describe('measureShadingError', () => {
  it('equals shade() evaluated directly at the cell centres of one triangle (Gouraud and flat against Phong)', () => {
    // One view and one light, both along fibonacciDirections(1)[0]; the triangle faces it, its vertex normals tilt.
    const [v] = fibonacciDirections(1);
    const helper = Math.abs(v[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
    const u = new Vector3().crossVectors(new Vector3(...helper), new Vector3(...v)).normalize();
    const w = new Vector3().crossVectors(new Vector3(...v), u);
    const corners = [0, 1, 2].map((k) => {
      const a = (2 * Math.PI * k) / 3 + 0.2;
      return u.clone().multiplyScalar(Math.cos(a)).addScaledVector(w, Math.sin(a));
    });
    const normals = corners.map((c) =>
      c
        .clone()
        .multiplyScalar(0.8)
        .add(new Vector3(...v)),
    );
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(new Float32Array(corners.flatMap((c) => c.toArray())), 3));
    g.setAttribute('normal', new BufferAttribute(new Float32Array(normals.flatMap((c) => c.toArray())), 3));
    const res = 32;
    const table = measureShadingError(g, { resolution: res, views: 1, lights: 1 });
    // Direct: the same cells (the disc of the farthest vertex, the same screen axes), shade() at each.
    const P = (i: number) =>
      new Vector3().fromBufferAttribute(g.getAttribute('position') as BufferAttribute, i);
    const N = (i: number) =>
      new Vector3().fromBufferAttribute(g.getAttribute('normal') as BufferAttribute, i);
    const radius = Math.max(P(0).length(), P(1).length(), P(2).length()) * 1.0001;
    const eye = [...v, 0];
    const light = {
      position: v.map((x) => x * 1e6 * radius),
      ambient: [0, 0, 0],
      diffuse: [1, 1, 1],
      specular: [1, 1, 1],
    };
    const material = { ka: [0.6, 0.35, 0.2], kd: [0.6, 0.35, 0.2], ks: [0.5, 0.5, 0.5], shininess: 32 };
    const lv = (a: number[], b: number[]) =>
      Math.max(...[0, 1, 2].map((j) => Math.abs(linearToSrgb8Channel(a[j]) - linearToSrgb8Channel(b[j]))));
    const s2 = [0, 1, 2].map((i) =>
      [P(i).dot(u), P(i).dot(w)].map((x) => ((x + radius) * res) / (2 * radius)),
    );
    const area =
      (s2[1][0] - s2[0][0]) * (s2[2][1] - s2[0][1]) - (s2[2][0] - s2[0][0]) * (s2[1][1] - s2[0][1]);
    const vertex = [0, 1, 2].map((i) =>
      shade({ position: P(i).toArray(), normal: N(i).toArray(), eye }, material, [light]),
    );
    const faceNormal = new Vector3().crossVectors(P(1).sub(P(0)), P(2).sub(P(0)));
    const centroid = P(0).add(P(1)).add(P(2)).divideScalar(3);
    const flatColour = shade({ position: centroid.toArray(), normal: faceNormal.toArray(), eye }, material, [
      light,
    ]);
    let covered = 0;
    const gouraudOver = ERROR_BUDGETS.map(() => 0);
    const flatOver = ERROR_BUDGETS.map(() => 0);
    let gouraudMax = 0;
    for (let y = 0; y < res; y++) {
      for (let x = 0; x < res; x++) {
        const cx = x + 0.5;
        const cy = y + 0.5;
        const b0 = ((s2[1][0] - cx) * (s2[2][1] - cy) - (s2[2][0] - cx) * (s2[1][1] - cy)) / area;
        const b1 = ((s2[2][0] - cx) * (s2[0][1] - cy) - (s2[0][0] - cx) * (s2[2][1] - cy)) / area;
        const b = [b0, b1, 1 - b0 - b1];
        if (b.some((t) => t < -1e-9)) continue;
        covered++;
        const p = [0, 1, 2].reduce((s, i) => s.addScaledVector(P(i), b[i]), new Vector3());
        const n = [0, 1, 2].reduce((s, i) => s.addScaledVector(N(i), b[i]), new Vector3());
        const phong = shade({ position: p.toArray(), normal: n.toArray(), eye }, material, [light]);
        const gouraud = [0, 1, 2].map((j) => b[0] * vertex[0][j] + b[1] * vertex[1][j] + b[2] * vertex[2][j]);
        const flatHere = shade({ position: p.toArray(), normal: faceNormal.toArray(), eye }, material, [
          light,
        ]);
        const eg = lv(gouraud, phong);
        const ef = Math.max(lv(flatColour, phong), lv(flatHere, phong));
        gouraudMax = Math.max(gouraudMax, eg);
        ERROR_BUDGETS.forEach((budget, k) => {
          if (eg > budget) gouraudOver[k]++;
          if (ef > budget) flatOver[k]++;
        });
      }
    }
    expect(covered).toBeGreaterThan(100);
    const row = (s: string) => table.rows.find((r) => r.shading === s && r.level === null);
    expect(row('phong')?.over.every((x) => x === 0)).toBe(true);
    expect(row('gouraud')?.max).toBe(gouraudMax);
    expect(gouraudMax).toBeGreaterThan(2);
    row('gouraud')?.over.forEach((f, k) => {
      expect(f).toBeCloseTo(gouraudOver[k] / covered, 5);
    });
    row('flat')?.over.forEach((f, k) => {
      expect(f).toBeCloseTo(flatOver[k] / covered, 5);
    });
  });

  it('records fractions that fall with the budget, 0 at 255, and for a subdivision sphere every level', () => {
    const sphere = new SubdivisionSphereGeometry({ level: 3 });
    const table = measureShadingError(sphere, {
      ...FAST,
      levels: [{ geometry: new SubdivisionSphereGeometry({ level: 2 }), level: 2, silhouetteError: 0.1 }],
    });
    expect(table.rows.map((r) => `${r.shading} ${r.level}`)).toEqual([
      'phong null',
      'gouraud null',
      'flat null',
      'phong 2',
      'gouraud 2',
      'flat 2',
    ]);
    for (const r of table.rows) {
      for (let k = 1; k < r.over.length; k++) expect(r.over[k]).toBeLessThanOrEqual(r.over[k - 1]);
      expect(r.over[r.over.length - 1]).toBe(0);
      expect(overFraction(table, r, 255)).toBe(0);
    }
    expect(table.coverageMin).toBeGreaterThan(0.9); // a sphere covers its disc
    expect(JSON.parse(JSON.stringify(table))).toEqual(table);
  });
});

describe('AdaptiveShading: bad input', () => {
  it('refuses a budget ≤ 0 or NaN, once, naming maxError', () => {
    for (const maxError of [0, -1, Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => new AdaptiveShading({ maxError })).toThrow(/maxError must be a finite number > 0/);
    }
    expect(() => new AdaptiveShading({ maxError: 255 })).not.toThrow();
  });

  it('refuses an object without a ShadingMaterial and leaves it as it was', () => {
    const a = new AdaptiveShading({ maxError: 8 });
    const phong = new MeshPhongMaterial();
    const mesh = new Mesh(new IcosahedronGeometry(1, 2), phong);
    expect(() => a.add(mesh)).toThrow(TypeError);
    expect(() => a.add(mesh)).toThrow(/must have one ShadingMaterial, got MeshPhongMaterial/);
    expect(() => a.add(new Mesh(new IcosahedronGeometry(), [new ShadingMaterial()]))).toThrow(
      /an array of materials/,
    );
    expect(() => a.add({} as Mesh)).toThrow(/must be a THREE.Mesh/);
    expect(mesh.material).toBe(phong);
    expect(a.objects).toEqual([]);
  });
});

/** Two objects: a large one in front and a small one dollied along z. */
function pair(budget: number) {
  const a = new AdaptiveShading({ maxError: budget, model: FAST });
  const big = new Mesh(new SubdivisionSphereGeometry({ level: 4 }), new ShadingMaterial());
  const small = new Mesh(new SubdivisionSphereGeometry({ level: 4 }), new ShadingMaterial());
  big.position.set(-1.2, 0, 0);
  a.add(big).add(small);
  return { a, big, small };
}

const rank = (a: AdaptiveShading, o: Mesh, budget: number) => {
  const c = a.choiceOf(o);
  const t = a.tableOf(o);
  if (!c || !t) throw new Error('not managed');
  const row = t.rows.find((r) => r.shading === c.shading && r.level === c.level);
  return overFraction(t, row as never, budget) + (row?.silhouetteError ?? 0);
};

describe('AdaptiveShading: choices', () => {
  it('never picks a less accurate choice for a larger object, nor a more accurate one for a larger budget', () => {
    const { a, small } = pair(8);
    const cam = camera(4);
    let last = Number.POSITIVE_INFINITY;
    // Growing: the small sphere comes from far away towards the camera (fresh allocation each step).
    for (let z = -60; z <= 1; z += 1) {
      small.position.set(1.5, 0, z);
      const fresh = new AdaptiveShading({ maxError: 8, model: FAST });
      fresh.add(a.objects[0], { table: a.tableOf(a.objects[0]) as never });
      fresh.add(small, { table: a.tableOf(small) as never });
      fresh.update(cam, VIEW);
      const r = rank(fresh, small, 8);
      expect(r).toBeLessThanOrEqual(last + 1e-12);
      last = r;
      fresh.dispose();
    }
    // Budgets: the estimated over-budget fraction of the choice, at a fixed size, never rises with the budget.
    small.position.set(1.5, 0, -10);
    let previousCost = Number.POSITIVE_INFINITY;
    for (const budget of [1, 2, 4, 8, 16, 32, 64, 128, 255]) {
      const fresh = new AdaptiveShading({ maxError: budget, model: FAST });
      fresh.add(small, { table: a.tableOf(small) as never });
      fresh.update(cam, VIEW);
      const c = fresh.choiceOf(small);
      const t = fresh.tableOf(small);
      const tri = t?.rows.find((r) => r.shading === c?.shading && r.level === c?.level)?.triangles ?? 0;
      // Cheaper or equal: fewer triangles or a cheaper shading.
      const cost = tri * (c?.shading === 'phong' ? 1 : 0.9);
      expect(cost).toBeLessThanOrEqual(previousCost);
      previousCost = cost;
      fresh.dispose();
    }
  });

  it('hysteresis: a dolly back and forth across a threshold changes the choice once', () => {
    const { a, small } = pair(8);
    const cam = camera(4);
    // Find a threshold: the distance at which the small sphere's choice first changes as it recedes.
    let threshold = Number.NaN;
    let before: string | null = null;
    for (let z = 1; z >= -200; z -= 0.5) {
      small.position.set(1.5, 0, z);
      const fresh = new AdaptiveShading({ maxError: 8, model: FAST });
      fresh.add(a.objects[0], { table: a.tableOf(a.objects[0]) as never });
      fresh.add(small, { table: a.tableOf(small) as never });
      fresh.update(cam, VIEW);
      const c = JSON.stringify(fresh.choiceOf(small));
      fresh.dispose();
      if (before !== null && c !== before) {
        threshold = z;
        break;
      }
      before = c;
    }
    expect(Number.isFinite(threshold)).toBe(true);
    // Dolly across it, 1% either way, for 100 frames.
    const seen: string[] = [];
    for (let f = 0; f < 100; f++) {
      small.position.set(1.5, 0, threshold * (f % 2 === 0 ? 0.99 : 1.01));
      a.update(cam, VIEW);
      const c = JSON.stringify(a.choiceOf(small));
      if (seen[seen.length - 1] !== c) seen.push(c);
    }
    expect(seen.length).toBeLessThanOrEqual(2);
  });

  it("update's cache: a still frame computes nothing again; what moved is computed again, as a fresh one would", () => {
    // No hysteresis, so that the choice of a fresh AdaptiveShading (no last frame) is the oracle.
    const a = new AdaptiveShading({ maxError: 8, model: FAST, hysteresis: 0 });
    const sphere = new SubdivisionSphereGeometry({ level: 4 });
    const big = new Mesh(sphere, new ShadingMaterial());
    const small = new Mesh(sphere, new ShadingMaterial());
    big.position.set(-1.2, 0, 0);
    a.add(big).add(small);
    const cam = camera(4);
    small.position.set(1.5, 0, -2);
    a.update(cam, VIEW);
    expect(a.stats).toEqual({ units: 2, recomputed: 2, allocated: true });
    const first = [a.choiceOf(big), a.choiceOf(small)];
    // Nothing moved: nothing computed, every choice kept.
    a.update(cam, VIEW);
    a.update(cam);
    expect(a.stats).toEqual({ units: 2, recomputed: 0, allocated: false });
    expect([a.choiceOf(big), a.choiceOf(small)]).toEqual(first);
    // One object moved far away: only it is computed again, and it gets what a fresh AdaptiveShading gives it.
    small.position.set(1.5, 0, -150);
    a.update(cam, VIEW);
    expect(a.stats).toEqual({ units: 2, recomputed: 1, allocated: true });
    const fresh = new AdaptiveShading({ maxError: 8, model: FAST, hysteresis: 0 });
    // Its own meshes: the managed ones wear a's variants and geometries.
    const [bigF, smallF] = [big, small].map((o) => {
      const copy = new Mesh(sphere, new ShadingMaterial());
      copy.position.copy(o.position);
      return copy;
    });
    fresh.add(bigF, { table: a.tableOf(big) as never }).add(smallF, { table: a.tableOf(small) as never });
    fresh.update(cam, VIEW);
    expect(a.choiceOf(small)).toEqual(fresh.choiceOf(smallF));
    expect(a.choiceOf(big)).toEqual(fresh.choiceOf(bigF));
    expect(a.choiceOf(small)).not.toEqual(first[1]);
    fresh.dispose();
    // The camera (its matrix or its projection) or the viewport: everything again.
    cam.position.x = 0.01;
    a.update(cam, VIEW);
    expect(a.stats.recomputed).toBe(2);
    cam.fov = 40;
    cam.updateProjectionMatrix();
    a.update(cam, VIEW);
    expect(a.stats.recomputed).toBe(2);
    a.update(cam, { width: 400, height: 300 });
    expect(a.stats.recomputed).toBe(2);
    a.update(cam);
    expect(a.stats.recomputed).toBe(0);
    // Adding an object spends the allowance again (the new one computed, the others from the cache).
    const third = new Mesh(sphere, new ShadingMaterial());
    a.add(third, { table: a.tableOf(small) as never });
    a.update(cam);
    expect(a.stats).toEqual({ units: 3, recomputed: 1, allocated: true });
    a.remove(third);
    a.update(cam);
    expect(a.stats).toEqual({ units: 2, recomputed: 0, allocated: true });
    a.dispose();
  });

  it("update's cache, instances: flagged matrices or a new count compute every instance again, a still frame none", () => {
    const n = 200;
    const a = new AdaptiveShading({ maxError: 8, model: FAST });
    const im = new InstancedMesh(new SubdivisionSphereGeometry({ level: 3 }), new ShadingMaterial(), n);
    const m = new Matrix4();
    for (let i = 0; i < n; i++) im.setMatrixAt(i, m.makeTranslation(i % 10, Math.floor(i / 10), -i));
    a.add(im);
    const cam = camera(20);
    a.update(cam, VIEW);
    expect(a.stats).toEqual({ units: n, recomputed: n, allocated: true });
    a.update(cam);
    expect(a.stats).toEqual({ units: n, recomputed: 0, allocated: false });
    const before = Array.from({ length: n }, (_, i) => a.choiceOf(im, i));
    // Written but not flagged: three would not upload it either, and the cache keeps the old choices.
    im.setMatrixAt(0, m.makeTranslation(0, 0, -400));
    a.update(cam);
    expect(a.stats.recomputed).toBe(0);
    im.instanceMatrix.needsUpdate = true;
    a.update(cam);
    expect(a.stats).toEqual({ units: n, recomputed: n, allocated: true });
    expect(a.choiceOf(im, 0)).not.toEqual(before[0]);
    // Moving the InstancedMesh itself moves every instance.
    im.position.x = 1;
    a.update(cam);
    expect(a.stats.recomputed).toBe(n);
    im.count = 100;
    a.update(cam);
    expect(a.stats).toEqual({ units: 100, recomputed: 100, allocated: true });
    a.dispose();
  });

  it('draws only the material variants: one per shading, shared, with the source options', () => {
    const a = new AdaptiveShading({ maxError: 32, model: FAST });
    const source = new ShadingMaterial({ ka: 0.2, kd: 0.7, ks: 0.3, shininess: 16 });
    const meshes = [0, 1, 2, 3].map((i) => {
      const m = new Mesh(new SubdivisionSphereGeometry({ level: 3 }), source);
      m.position.set(i * 3, 0, -i * 30);
      return m;
    });
    for (const m of meshes) a.add(m);
    a.update(camera(5), VIEW);
    source.kd = 0.1;
    a.update(camera(5), VIEW);
    for (const m of meshes) {
      const v = m.material as ShadingMaterial;
      expect(v).toBeInstanceOf(ShadingMaterial);
      expect(v.shading).toBe(a.choiceOf(m)?.shading);
      expect(v.kd.r).toBeCloseTo(0.1);
      expect(v.ks.r).toBeCloseTo(0.3);
    }
    a.dispose();
    for (const m of meshes) expect(m.material).toBe(source);
  });
});

describe('AdaptiveShading: extremes', () => {
  const choices = (a: AdaptiveShading, objects: Mesh[]) =>
    objects.map((o) => {
      const c = a.choiceOf(o);
      expect(c).not.toBeNull();
      return c;
    });

  it('an object behind the camera, zero scale, near = far, a budget of 255: finite choices, no throw', () => {
    for (const budget of [0.5, 8, 255]) {
      const a = new AdaptiveShading({ maxError: budget, model: FAST });
      const behind = new Mesh(new SubdivisionSphereGeometry({ level: 3 }), new ShadingMaterial());
      behind.position.set(0, 0, 50);
      const zero = new Mesh(new IcosahedronGeometry(1, 2), new ShadingMaterial());
      zero.scale.set(0, 0, 0);
      const huge = new Mesh(new IcosahedronGeometry(1, 2), new ShadingMaterial());
      huge.scale.setScalar(1e20);
      a.add(behind).add(zero).add(huge);
      a.update(camera(10), VIEW);
      choices(a, [behind, zero, huge]);
      // The huge one covers the screen: it gets the reference unless the budget allows anything.
      if (budget < 255) expect(a.choiceOf(huge)?.shading).toBe('phong');
      const degenerate = new PerspectiveCamera(50, 1, 5, 5);
      degenerate.position.set(0, 0, 10);
      degenerate.updateMatrixWorld();
      degenerate.projectionMatrix.makePerspective(-1, 1, 1, -1, 5, 5);
      a.update(degenerate, VIEW);
      choices(a, [behind, zero, huge]);
      const ortho = new OrthographicCamera(-5, 5, 5, -5, 1, 1);
      ortho.position.set(0, 0, 10);
      ortho.updateMatrixWorld();
      a.update(ortho, VIEW);
      choices(a, [behind, zero, huge]);
      a.dispose();
    }
  });

  it('an instance with a 1e20 scale and one with zero scale among ordinary ones', () => {
    const a = new AdaptiveShading({ maxError: 8, model: FAST });
    const im = new InstancedMesh(new SubdivisionSphereGeometry({ level: 3 }), new ShadingMaterial(), 3);
    im.setMatrixAt(0, new Matrix4().makeScale(1e20, 1e20, 1e20));
    im.setMatrixAt(1, new Matrix4().makeScale(0, 0, 0));
    im.setMatrixAt(2, new Matrix4().makeTranslation(0, 0, -40));
    a.add(im);
    a.update(camera(10), VIEW);
    for (let i = 0; i < 3; i++) expect(a.choiceOf(im, i)).not.toBeNull();
    expect(a.choiceOf(im, 0)?.shading).toBe('phong');
    for (const g of a.groupsOf(im)) {
      for (const x of g.instanceMatrix.array.slice(0, 16 * g.count)) expect(Number.isNaN(x)).toBe(false);
    }
  });
});

describe('AdaptiveShading: instances', () => {
  it('1,000 moving instances: a bounded number of groups, one update range per group per frame, none when still', () => {
    const n = 1000;
    const a = new AdaptiveShading({ maxError: 8, model: FAST });
    const im = new InstancedMesh(new SubdivisionSphereGeometry({ level: 3 }), new ShadingMaterial(), n);
    const m = new Matrix4();
    const place = (t: number) => {
      for (let i = 0; i < n; i++) {
        m.makeTranslation(
          ((i % 10) - 4.5) * 3,
          ((Math.floor(i / 10) % 10) - 4.5) * 3,
          -Math.floor(i / 100) * 3 - 20 * Math.sin(t + i),
        );
        im.setMatrixAt(i, m);
      }
    };
    place(0);
    a.add(im);
    const cam = camera(20);
    a.update(cam, VIEW);
    const candidates = 3 * 4 + 1; // shadings × levels (+ flat's second path)
    // Still: nothing uploaded.
    const versions = () => a.groupsOf(im).map((g) => g.instanceMatrix.version);
    const v0 = versions();
    a.update(cam, VIEW);
    expect(versions()).toEqual(v0);
    // Moving: every frame the user flags the matrices; each group gets one update range.
    let moved = 0;
    for (let f = 1; f <= 60; f++) {
      place(f * 0.05);
      im.instanceMatrix.needsUpdate = true;
      a.update(cam, VIEW);
      const groups = a.groupsOf(im);
      expect(groups.length).toBeLessThanOrEqual(candidates);
      for (const g of groups) expect(g.instanceMatrix.updateRanges.length).toBeLessThanOrEqual(1);
      expect(groups.reduce((s, g) => s + g.count, 0)).toBe(n);
      moved += groups.length;
    }
    expect(moved).toBeGreaterThan(0);
    expect(im.count).toBe(0);
    // Only the camera moves: instances change group only when their choice changes.
    const before = Array.from({ length: n }, (_, i) => JSON.stringify(a.choiceOf(im, i)));
    cam.position.z = 21;
    cam.updateMatrixWorld();
    a.update(cam, VIEW);
    const changed = before.filter((c, i) => c !== JSON.stringify(a.choiceOf(im, i))).length;
    const ranges = a.groupsOf(im).reduce((s, g) => s + g.instanceMatrix.updateRanges.length, 0);
    expect(ranges).toBeLessThanOrEqual(a.groupsOf(im).length);
    expect(changed).toBeLessThan(n);
    a.remove(im);
    expect(im.count).toBe(n);
    expect(im.children.length).toBe(0);
  });

  it('allocateShading: within the allowance, cheapest when the allowance is large', () => {
    const units = [0, 1, 2].map((i) => ({ costs: [10, 4, 1], overs: [0, 1 + i, 5 + i], previous: -1 }));
    expect(Array.from(allocateShading(units, 1e9, 0))).toEqual([2, 2, 2]);
    expect(Array.from(allocateShading(units, 0, 0))).toEqual([0, 0, 0]);
    const mid = allocateShading(units, 4, 0);
    expect(units.reduce((s, u, i) => s + u.overs[mid[i]], 0)).toBeLessThanOrEqual(4);
  });
});
