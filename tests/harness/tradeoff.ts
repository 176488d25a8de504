// Harness for tests/tradeoff.spec.ts and bench/tradeoff.bench.mjs: draws the sphere with one option of the
// trade (flat / Gouraud / Phong mesh at a base and level, or the ray-cast impostor), compares the pixels with
// renderReference computed here in the page, and times frames (1×1 readPixels after each).

import { SphereImpostor } from '@shadelab/material/impostor';
import { compareToReference } from '@shadelab/reference';
import { Mesh, MeshBasicMaterial, PlaneGeometry } from 'three';
import {
  optionCost,
  type TradeOption,
  TradeoffScene,
  type TradeView,
} from '../../playground/src/tradeoff/tradeoffScene';

const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const trade = new TradeoffScene(canvas);

/** The renderer's depth buffer for a check: three's default, logarithmic, or reversed-Z. */
export type DepthBuffer = 'standard' | 'logarithmic' | 'reversed';
const scenes = new Map<DepthBuffer, TradeoffScene>([['standard', trade]]);
/** A scene on its own canvas for each depth buffer (fixed for a renderer's life). */
function sceneFor(depth: DepthBuffer): TradeoffScene {
  let s = scenes.get(depth);
  if (s === undefined) {
    s = new TradeoffScene(document.createElement('canvas'), {
      logarithmicDepthBuffer: depth === 'logarithmic',
      reversedDepthBuffer: depth === 'reversed',
    });
    scenes.set(depth, s);
  }
  return s;
}
/** The exact image of `view`, from the standard scene (its camera is never switched to reversed depth). */
function referenceOf(view: TradeView) {
  trade.setView(view);
  return trade.reference();
}

export interface CompareResult {
  rmse: number;
  max: number;
  interiorPixels: number;
  silhouettePx: number;
  silhouetteMeanPx: number;
  mismatchedPixels: number;
  /** Mismatched pixels farther than 0.5 px from the exact silhouette. */
  mismatchedBeyondHalfPx: number;
  /** Pure black pixels (what a NaN colour writes; the lit scene never is black). */
  blackPixels: number;
}

function compare(view: TradeView, option: TradeOption, depth: DepthBuffer = 'standard'): CompareResult {
  const t = sceneFor(depth);
  t.setView(view);
  t.setOption(option);
  t.render();
  const pixels = t.readPixels();
  const reference = referenceOf(view);
  const e = compareToReference(pixels, reference);
  let beyond = 0;
  for (const s of e.silhouetteError) if (s > 0.5) beyond++;
  let black = 0;
  for (let k = 0; k < pixels.length; k += 4) if (pixels[k] + pixels[k + 1] + pixels[k + 2] === 0) black++;
  return {
    rmse: e.rmse,
    max: e.max,
    interiorPixels: e.interiorPixels,
    silhouettePx: e.silhouettePx,
    silhouetteMeanPx: e.silhouetteMeanPx,
    mismatchedPixels: e.mismatchedPixels,
    mismatchedBeyondHalfPx: beyond,
    blackPixels: black,
  };
}

/**
 * Depth check: a grey plane facing the camera at world z = planeZ cuts the sphere; the sphere must show
 * exactly where its exact depth (from the reference) is nearer than the plane's. Returns the pixels that
 * disagree, ignoring those within `eps` of equal depth.
 */
function depthCheck(
  view: TradeView,
  option: TradeOption,
  planeZ: number,
  eps = 1e-5,
  depth: DepthBuffer = 'standard',
): { wrong: number; sphere: number; plane: number } {
  const t = sceneFor(depth);
  t.setView(view);
  t.setOption(option);
  const plane = new Mesh(new PlaneGeometry(100, 100), new MeshBasicMaterial({ color: 0x808080 }));
  plane.position.z = planeZ;
  t.scene.add(plane);
  t.scene.updateMatrixWorld();
  t.render();
  const pixels = t.readPixels();
  t.scene.remove(plane);
  plane.geometry.dispose();
  plane.material.dispose();
  // Which is nearer, by the standard depth of the exact reference (every depth mode keeps the same order).
  const reference = referenceOf(view);
  const camera = trade.camera;
  const p = plane.position.clone().project(camera);
  const planeDepth = p.z * 0.5 + 0.5;
  let wrong = 0;
  let sphere = 0;
  let planeCount = 0;
  for (let k = 0; k < reference.depth.length; k++) {
    if (!reference.hit[k] || Math.abs(reference.edgeDistance[k]) < 1) continue;
    const d = reference.depth[k];
    if (Math.abs(d - planeDepth) < eps) continue;
    const grey = pixels[4 * k] === pixels[4 * k + 1] && pixels[4 * k + 1] === pixels[4 * k + 2];
    const expectSphere = d < planeDepth;
    if (expectSphere) sphere++;
    else planeCount++;
    if (grey === expectSphere) wrong++;
  }
  return { wrong, sphere, plane: planeCount };
}

/**
 * Two impostors sharing one material, drawn in one frame, against each drawn alone: the per-object uniforms
 * (matrices, bounds) must be re-uploaded between the two draws. Returns the pixels that differ.
 */
function sharedMaterialCheck(): { differing: number; coveredA: number; coveredB: number } {
  const view: TradeView = { width: 320, height: 240, scale: [0.6, 0.4, 0.6] };
  trade.setView(view);
  trade.setOption({ shading: 'impostor' });
  const a = trade.impostor;
  const b = new SphereImpostor(trade.impostorMaterial);
  b.scale.set(0.5, 0.7, 0.5);
  b.position.set(1.2, 0.3, 0);
  a.position.set(-1, 0, 0);
  trade.scene.add(b);
  trade.scene.updateMatrixWorld();
  const draw = (showA: boolean, showB: boolean) => {
    a.visible = showA;
    b.visible = showB;
    trade.render();
    return trade.readPixels();
  };
  const onlyA = draw(true, false);
  const onlyB = draw(false, true);
  const both = draw(true, true);
  trade.scene.remove(b);
  b.geometry.dispose();
  a.position.set(0, 0, 0);
  a.visible = true;
  trade.scene.updateMatrixWorld();
  let differing = 0;
  let coveredA = 0;
  let coveredB = 0;
  const isBackground = (p: Uint8Array, k: number) => p[k] === 0 && p[k + 1] === 0 && p[k + 2] === 255;
  for (let k = 0; k < both.length; k += 4) {
    const inA = !isBackground(onlyA, k);
    const inB = !isBackground(onlyB, k);
    if (inA) coveredA++;
    if (inB) coveredB++;
    const expected = inA ? onlyA : onlyB;
    if (both[k] !== expected[k] || both[k + 1] !== expected[k + 1] || both[k + 2] !== expected[k + 2])
      differing++;
  }
  return { differing, coveredA, coveredB };
}

const gl = trade.renderer.getContext() as WebGL2RenderingContext; // three 0.163+ is WebGL2 only
const timer = gl.getExtension('EXT_disjoint_timer_query_webgl2') as { TIME_ELAPSED_EXT: number } | null;

/** GPU times (ms) of finished timer queries; empty when unavailable or disjoint. */
async function gpuTimes(queries: WebGLQuery[]): Promise<number[]> {
  if (timer === null || queries.length === 0) return [];
  const times: number[] = [];
  for (const q of queries) {
    for (let tries = 0; tries < 200 && !gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE); tries++) {
      await new Promise((r) => setTimeout(r, 5));
    }
    if (
      gl.getParameter(0x8fbb /* GPU_DISJOINT_EXT */) ||
      !gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE)
    ) {
      return [];
    }
    times.push(gl.getQueryParameter(q, gl.QUERY_RESULT) / 1e6);
    gl.deleteQuery(q);
  }
  return times;
}

/**
 * Frame times in ms: `warmup` untimed frames, then `frames` timed ones, each ended by a 1×1 readPixels; and
 * the GPU time of each timed frame (EXT_disjoint_timer_query_webgl2), empty without the extension.
 */
async function time(
  view: TradeView,
  option: TradeOption,
  frames: number,
  warmup: number,
): Promise<{ frames: number[]; gpu: number[] }> {
  trade.setView(view);
  trade.setOption(option);
  for (let i = 0; i < warmup; i++) {
    trade.render();
    trade.sync();
  }
  const out: number[] = [];
  const queries: WebGLQuery[] = [];
  for (let i = 0; i < frames; i++) {
    const query = timer === null ? null : gl.createQuery();
    if (timer !== null && query !== null) gl.beginQuery(timer.TIME_ELAPSED_EXT, query);
    const t0 = performance.now();
    trade.render();
    if (timer !== null && query !== null) {
      gl.endQuery(timer.TIME_ELAPSED_EXT);
      queries.push(query);
    }
    trade.sync();
    out.push(performance.now() - t0);
  }
  return { frames: out, gpu: await gpuTimes(queries) };
}

function referenceMs(view: TradeView): number {
  trade.setView({ ...view, width: view.width, height: view.height });
  const t0 = performance.now();
  trade.reference();
  return performance.now() - t0;
}

const api = {
  compare,
  depthCheck,
  sharedMaterialCheck,
  time,
  cost: optionCost,
  referenceMs,
  hasTimer: timer !== null,
};
declare global {
  interface Window {
    tradeoff: typeof api;
  }
}
window.tradeoff = api;
document.body.dataset.ready = '1';
