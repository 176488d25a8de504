// @shadelab/trackball: speed of the rotation core and of one pointer move through Trackball, and the accuracy
// the design choices buy (atan2 against acos for tiny drags, renormalising the quaternion against not).
//
//   npx tsc -b packages/trackball && node bench/trackball.bench.mjs [--json bench/results/trackball.json] [--quick]
//
// --quick only checks that the script runs (few points, few runs, drift up to 10³ drags): its numbers mean nothing.
//
// Runs in Node against the built package (dist). The pointer-move timing drives the real handlers through a
// minimal EventTarget stand-in for the canvas and its document (no browser, no layout): it is the cost of the
// trackball's own work, not of the browser's event dispatch.
import { Mesh, PerspectiveCamera, Quaternion } from 'three';
import { arcRotation, projectToBall, Trackball } from '../packages/trackball/dist/index.js';
import { measure, writeResults } from './lib/bench.mjs';

const quick = process.argv.includes('--quick');
const N = quick ? 2_000 : 200_000;
const RUNS = quick ? { warmup: 1, runs: 3 } : { warmup: 5, runs: 21 };
/** Compose and renormalise as Trackball does: three's Quaternion (premultiply, normalize). */
const _dq = new Quaternion();

/** Deterministic pointer positions in ball radii, spread over the ball and beyond its rim. */
const points = new Float64Array(2 * N);
{
  let s = 12345;
  const rand = () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return s / 2147483648;
  };
  for (let i = 0; i < 2 * N; i++) points[i] = (rand() - 0.5) * 3;
}

// ── speed: the core, one drag step = 2 × projectToBall + arcRotation + three's multiply + normalise ──
/** @typedef {import('../packages/trackball/dist/index.js').BallMapping} BallMapping */
/** @typedef {import('../packages/trackball/dist/index.js').Vec3} Vec3 */
/** @typedef {import('../packages/trackball/dist/index.js').Quat} Quat */
/** @type {BallMapping[]} */
const MAPPINGS = ['arcball', 'bell'];

/** @type {Record<string, { medianNs: number, minNs: number, maxNs: number }>} */
const core = {};
for (const mapping of MAPPINGS) {
  /** @type {Vec3} */
  const a = [0, 0, 1];
  /** @type {Vec3} */
  const b = [0, 0, 1];
  /** @type {Quat} */
  const dq = [0, 0, 0, 1];
  const q = new Quaternion();
  const t = measure(() => {
    for (let i = 0; i + 3 < 2 * N; i += 2) {
      projectToBall(points[i], points[i + 1], mapping, a);
      projectToBall(points[i + 2], points[i + 3], mapping, b);
      arcRotation(a, b, 1, dq);
      q.premultiply(_dq.set(dq[0], dq[1], dq[2], dq[3])).normalize();
    }
  }, RUNS);
  const per = (/** @type {number} */ ms) => (ms * 1e6) / (N - 1);
  core[mapping] = { medianNs: per(t.median), minNs: per(t.min), maxNs: per(t.max) };
}

// ── speed: one pointermove through Trackball (with an object and a camera) ──
class FakeTarget extends EventTarget {}
const doc = new FakeTarget();
const element = Object.assign(new FakeTarget(), {
  ownerDocument: doc,
  style: {},
  getBoundingClientRect: () => ({ left: 0, top: 0, width: 500, height: 500 }),
  setPointerCapture() {},
  releasePointerCapture() {},
  hasPointerCapture: () => true,
});
const pointerEvent = (/** @type {string} */ type, /** @type {number} */ x, /** @type {number} */ y) =>
  Object.assign(new Event(type), { pointerId: 1, pointerType: 'mouse', button: 0, clientX: x, clientY: y });
const camera = new PerspectiveCamera();
camera.position.set(1, 2, 5);
camera.lookAt(0, 0, 0);
const mesh = new Mesh();
/** @type {Event[]} */
const moves = [];
for (let i = 0; i < 1000; i++)
  moves.push(pointerEvent('pointermove', 250 + 200 * Math.cos(i / 50), 250 + 150 * Math.sin(i / 30)));
/** @type {Record<string, { medianUs: number, minUs: number, maxUs: number }>} */
const handler = {};
for (const mapping of MAPPINGS) {
  const tb = new Trackball(mesh, /** @type {HTMLElement} */ (/** @type {unknown} */ (element)), {
    camera,
    mapping,
  });
  let changes = 0;
  tb.addEventListener('change', () => changes++);
  element.dispatchEvent(pointerEvent('pointerdown', 250, 250));
  const t = measure(() => {
    for (const e of moves) doc.dispatchEvent(e);
  }, RUNS);
  doc.dispatchEvent(pointerEvent('pointerup', 250, 250));
  tb.dispose();
  if (changes === 0) throw new Error('the trackball did not react to the synthetic moves');
  const per = (/** @type {number} */ ms) => (ms * 1e3) / moves.length;
  handler[mapping] = { medianUs: per(t.median), minUs: per(t.min), maxUs: per(t.max) };
}

// ── accuracy: the angle of a tiny drag from the centre, atan2 (ours) against acos(a·b) ──
// Exact: the arcball point (x, 0, √(1 − x²)) is at angle asin(x) from the pole.
const tiny = [];
for (const px of [1, 0.1, 0.01, 1e-3, 1e-4]) {
  const x = px / 250; // on a 500 px ball (radius 250 px)
  const a = projectToBall(0, 0, 'arcball');
  const b = projectToBall(x, 0, 'arcball');
  const exact = Math.asin(x);
  const q = arcRotation(a, b, 0.5);
  const ours = 2 * Math.atan2(Math.hypot(q[0], q[1], q[2]), q[3]);
  const acos = Math.acos(Math.min(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]));
  tiny.push({
    dragPx: px,
    exactRad: exact,
    atan2RelError: Math.abs(ours / exact - 1),
    acosRelError: Math.abs(acos / exact - 1),
  });
}

// ── feel: rotation of a one-pixel radial move at distance r from the centre, 500 px ball (radius 250 px) ──
const RADIUS_PX = 250;
const perPixel = [];
for (const rPx of [0, 125, 176, 200, 240, 248, 249, 250, 300, 500]) {
  /** @type {Record<string, number>} */
  const row = { rPx };
  for (const mapping of MAPPINGS) {
    const a = projectToBall(rPx / RADIUS_PX, 0, mapping);
    const b = projectToBall((rPx + 1) / RADIUS_PX, 0, mapping);
    const q = arcRotation(a, b);
    row[`${mapping}Deg`] = (2 * Math.atan2(Math.hypot(q[0], q[1], q[2]), Math.abs(q[3])) * 180) / Math.PI;
  }
  perPixel.push(row);
}

// ── accuracy: drift of the accumulated rotation over many drags, renormalised or not ──
/** @param {Quaternion} q */
function orthonormalError(q) {
  const { x, y, z, w } = q;
  // Columns of the rotation matrix of a possibly non-unit quaternion, as three would build it.
  const c0 = [1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)];
  const c1 = [2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)];
  const c2 = [2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)];
  const dot = (/** @type {number[]} */ u, /** @type {number[]} */ v) =>
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  return Math.max(
    Math.abs(dot(c0, c0) - 1),
    Math.abs(dot(c1, c1) - 1),
    Math.abs(dot(c2, c2) - 1),
    Math.abs(dot(c0, c1)),
    Math.abs(dot(c1, c2)),
    Math.abs(dot(c2, c0)),
  );
}
const drift = [];
for (const drags of quick ? [1e3] : [1e3, 1e5, 1e6]) {
  const row = { drags, renormalised: 0, notRenormalised: 0 };
  for (const renormalise of [true, false]) {
    const q = new Quaternion();
    /** @type {Vec3} */
    const a = [0, 0, 1];
    /** @type {Vec3} */
    const b = [0, 0, 1];
    /** @type {Quat} */
    const dq = [0, 0, 0, 1];
    for (let i = 0; i < drags; i++) {
      const j = (2 * i) % (2 * N - 4);
      projectToBall(points[j], points[j + 1], 'bell', a);
      projectToBall(points[j + 2], points[j + 3], 'bell', b);
      arcRotation(a, b, 0.9, dq);
      q.premultiply(_dq.set(dq[0], dq[1], dq[2], dq[3]));
      if (renormalise) q.normalize();
    }
    row[renormalise ? 'renormalised' : 'notRenormalised'] = orthonormalError(q);
  }
  drift.push(row);
}

const results = {
  node: process.version,
  quick,
  coreNsPerDragStep: core,
  pointerMoveUs: handler,
  tinyDragAngle: tiny,
  degreesPerRadialPixel: perPixel,
  orthonormalityAfterDrags: drift,
};
console.log('core drag step (ns):', core);
console.log('Trackball pointermove (µs):', handler);
console.table(tiny);
console.table(perPixel);
console.table(drift);
writeResults(results);
