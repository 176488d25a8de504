// Automatic detail over a zoom sweep of the lecture scene (Node only: no browser, no timing). Ellipsoid
// (2, 1, 2) at the origin, eye on +z, 90° perspective, 1280×720, 25 distances from 2.25 to about 64 units.
// At each distance: the triangles and the silhouette error of a fixed tetrahedron level 6 (the lecture's),
// of AutoDetailSphere at a 0.5 px budget, of the choice the projected-radius model made before (for the
// cost of the bound), and of AutoDetailSphere at equal error, two ways: its budget is level 6's worst measured
// error over the sweep (this orientation of the sphere), or level 6's worst bound (any orientation: a rotated
// tetrahedron sphere shows its worst faces on the outline; measured below over seeded rotations). Every error is measured in the image the auditor's way (bench/lib/silhouetteGap.mjs:
// projected mesh vertices, their hull, against the ray-cast exact outline, on screen only); "bound" is what
// AutoDetailSphere budgets (silhouetteErrorScalePx · sphereError).
//
//   node bench/autodetail.bench.mjs [--json PATH] [--distances 25] [--samples 2048] [--rotations 24]
import { sphereCounts } from '@shadelab/sphere';
import {
  AutoDetailSphere,
  chooseSphereDetail,
  projectedRadiusPx,
  silhouetteErrorScalePx,
  sphereError,
} from '@shadelab/sphere/detail';
import { Euler, Matrix4, MeshBasicMaterial, PerspectiveCamera, Quaternion, Vector3 } from 'three';
import { arg, writeResults } from './lib/bench.mjs';
import { silhouetteGapPx, sphereMesh } from './lib/silhouetteGap.mjs';

const WIDTH = 1280;
const HEIGHT = 720;
const BUDGET = 0.5;
const count = Number(arg('--distances', '25'));
const samples = Number(arg('--samples', '2048'));
// 2.25 … 2.25·1.15^24 ≈ 63.8 (fewer distances span the same range).
const distances = Array.from({ length: count }, (_, i) => 2.25 * 1.15 ** ((24 * i) / Math.max(1, count - 1)));
const FIXED = /** @type {const} */ ({ base: 'tetrahedron', level: 6 });
const matrixWorld = new Matrix4().makeScale(2, 1, 2);
const material = new MeshBasicMaterial();

/** @param {number} d */
function cameraAt(d) {
  const camera = new PerspectiveCamera(90, WIDTH / HEIGHT, 0.01, 1000);
  camera.position.set(0, 0, d);
  camera.updateMatrixWorld();
  return camera;
}

/** @param {PerspectiveCamera} camera @param {import('@shadelab/sphere').SphereBase} base @param {number} level */
function measured(camera, base, level) {
  return silhouetteGapPx(
    sphereMesh(base, level),
    { camera, matrixWorld, widthPx: WIDTH, heightPx: HEIGHT },
    samples,
  );
}

/** AutoDetailSphere's choice at `budget`. @param {PerspectiveCamera} camera @param {number} budget */
function auto(camera, budget) {
  const sphere = new AutoDetailSphere(material, { maxErrorPx: budget, maxLevel: 10 });
  sphere.scale.set(2, 1, 2);
  sphere.update(camera, HEIGHT);
  const { base, level, triangles, errorPx, meetsBudget } = sphere.detail;
  sphere.disposeGeometries();
  return { base, level, triangles, boundPx: errorPx, meetsBudget, measuredPx: measured(camera, base, level) };
}

const fixedTriangles = sphereCounts(FIXED.base, FIXED.level).triangles;
const points = distances.map((d) => {
  const camera = cameraAt(d);
  const view = { camera, matrixWorld, viewportHeightPx: HEIGHT };
  const radiusPx = projectedRadiusPx(view);
  const errorScalePx = silhouetteErrorScalePx(view);
  const old = chooseSphereDetail({ radiusPx, maxErrorPx: BUDGET, maxLevel: 10 });
  return {
    distance: d,
    radiusPx,
    errorScalePx,
    fixed: {
      ...FIXED,
      triangles: fixedTriangles,
      boundPx: errorScalePx * sphereError(FIXED.base, FIXED.level),
      measuredPx: measured(camera, FIXED.base, FIXED.level),
    },
    auto: auto(camera, BUDGET),
    radiusModel: {
      base: old.base,
      level: old.level,
      triangles: old.triangles,
      modelPx: old.errorPx,
      measuredPx: measured(camera, old.base, old.level),
    },
  };
});
const equalBudgetPx = Math.max(...points.map((p) => p.fixed.measuredPx));
const equalBoundPx = Math.max(...points.map((p) => p.fixed.boundPx));
for (const p of points) {
  Object.assign(p, {
    autoEqual: auto(cameraAt(p.distance), equalBudgetPx),
    autoEqualBound: auto(cameraAt(p.distance), equalBoundPx),
  });
}
// Level 6 turned: the worst measured error at the nearest distance over seeded random rotations.
let seed = 1;
const random = () => {
  seed = (seed * 48271) % 2147483647;
  return seed / 2147483647;
};
const rotations = Number(arg('--rotations', '24'));
let fixedRotatedPx = 0;
for (let i = 0; i < rotations; i++) {
  const q = new Quaternion().setFromEuler(new Euler(7 * random(), 7 * random(), 7 * random()));
  const m = new Matrix4().compose(new Vector3(), q, new Vector3(2, 1, 2));
  const camera = cameraAt(distances[0]);
  const gap = silhouetteGapPx(
    sphereMesh(FIXED.base, FIXED.level),
    { camera, matrixWorld: m, widthPx: WIDTH, heightPx: HEIGHT },
    samples,
  );
  fixedRotatedPx = Math.max(fixedRotatedPx, gap);
}

const sum = (/** @type {number[]} */ a) => a.reduce((s, x) => s + x, 0);
const worst = (/** @type {number[]} */ a) => Math.max(...a);
/** @param {(p: any) => { triangles: number, measuredPx: number }} pick */
const total = (pick) => ({
  triangles: sum(points.map((p) => pick(p).triangles)),
  worstMeasuredPx: worst(points.map((p) => pick(p).measuredPx)),
  overBudget: points.filter((p) => pick(p).measuredPx > BUDGET).length,
});
const totals = {
  fixed: total((p) => p.fixed),
  auto: total((p) => p.auto),
  radiusModel: total((p) => p.radiusModel),
  autoEqual: total((p) => p.autoEqual),
  autoEqualBound: total((p) => p.autoEqualBound),
};

const results = {
  width: WIDTH,
  height: HEIGHT,
  fovy: 90,
  scale: [2, 1, 2],
  budgetPx: BUDGET,
  outlineSamples: samples,
  fixed: { ...FIXED, triangles: fixedTriangles },
  equalBudgetPx,
  equalBoundPx,
  fixedRotated: { distance: distances[0], rotations, worstMeasuredPx: fixedRotatedPx },
  points,
  totals,
};

const show = (/** @type {{ base: string, level: number, triangles: number }} */ a) =>
  `${a.base} ${a.level} (${a.triangles})`;
console.log(
  `lecture zoom sweep, ${points.length} distances from ${distances[0]} to ${distances.at(-1)?.toFixed(1)}, ${WIDTH}×${HEIGHT}, 90°; errors measured in the image (px), bound in brackets`,
);
console.log(
  '| distance | radius px | tetrahedron 6 | auto 0.5 px | radius model (before) | auto at equal error | auto at equal bound |',
);
console.log('| ---: | ---: | --- | --- | --- | --- | --- |');
for (const p of points) {
  const q = /** @type {any} */ (p);
  console.log(
    `| ${p.distance.toFixed(2)} | ${p.radiusPx.toFixed(1)} | ${p.fixed.measuredPx.toFixed(3)} [${p.fixed.boundPx.toFixed(3)}] | ${show(p.auto)}: ${p.auto.measuredPx.toFixed(3)} [${p.auto.boundPx.toFixed(3)}] | ${show(p.radiusModel)}: ${p.radiusModel.measuredPx.toFixed(3)} | ${show(q.autoEqual)}: ${q.autoEqual.measuredPx.toFixed(3)} | ${show(q.autoEqualBound)}: ${q.autoEqualBound.measuredPx.toFixed(3)} |`,
  );
}
const pct = (/** @type {number} */ n) => `${((1 - n / totals.fixed.triangles) * 100).toFixed(1)} % saved`;
console.log(
  '\n| | triangles over the sweep | vs fixed level 6 | worst measured error | distances over 0.5 px |',
);
console.log('| --- | ---: | ---: | ---: | ---: |');
for (const [name, t] of /** @type {const} */ ([
  ['fixed tetrahedron 6', totals.fixed],
  ['auto, 0.5 px (bound)', totals.auto],
  ['radius model, 0.5 px (before)', totals.radiusModel],
  [`auto, ${equalBudgetPx.toFixed(3)} px (equal measured error)`, totals.autoEqual],
  [`auto, ${equalBoundPx.toFixed(3)} px (equal bound)`, totals.autoEqualBound],
])) {
  console.log(
    `| ${name} | ${t.triangles} | ${t === totals.fixed ? '—' : pct(t.triangles)} | ${t.worstMeasuredPx.toFixed(3)} px | ${t.overBudget} |`,
  );
}
console.log(
  `the bound costs ${totals.auto.triangles - totals.radiusModel.triangles} triangles more than the radius model over the sweep (${((totals.auto.triangles / totals.radiusModel.triangles - 1) * 100).toFixed(1)} %)`,
);
console.log(
  `tetrahedron 6 at ${distances[0]} turned ${rotations} random ways: worst ${fixedRotatedPx.toFixed(3)} px measured (bound ${points[0].fixed.boundPx.toFixed(3)} px)`,
);
writeResults(results);
