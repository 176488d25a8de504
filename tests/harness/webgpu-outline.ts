// Harness for tests/material-webgpu-outline.spec.ts: OutlineNodeMaterial (createOutlineNode) under WebGPURenderer,
// on its WebGPU backend and (forceWebGL) its WebGL2 backend, rendered offscreen into a RenderTarget and read back,
// against two references in the same scene: OutlineMaterial (createOutline) under WebGLRenderer, and the hull built
// on the CPU from three's own deformation (Mesh.getVertexPosition: morph targets and bones; the instance and object
// matrices; lib/outlineOracle.ts, which the WebGL outline's harness outline-impostor.ts shares) drawn by three's
// own MeshBasicNodeMaterial on the same WebGPURenderer.
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import { createOutlineNode, OutlineNodeMaterial } from '@shadelab/material/webgpu';
import {
  type Camera,
  type Material,
  Matrix4,
  MeshBasicMaterial,
  PerspectiveCamera,
  Scene,
  WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { MeshBasicNodeMaterial, RenderTarget } from 'three/webgpu';
import { thrown } from './lib/errors';
import {
  classify,
  compareClasses,
  cpuHull,
  type Instance,
  type OutlineConfig,
  outlinedObject,
  outlineGeometries,
} from './lib/outlineOracle';
import { type Backend, backendFlags, gpuRenderer, readTarget } from './lib/webgpu';

export type { Backend, Instance, OutlineConfig };

export interface OutlineStats {
  backend: { isWebGPUBackend: boolean; isWebGLBackend: boolean };
  /** Pixels of the outline's colour (pure black) in the node outline's picture, the CPU hull's and the GLSL one's. */
  ring: number;
  oracleRing: number;
  glRing: number;
  /** Pixels of the mesh (red) in the node outline's picture and the CPU hull's; in the GLSL one's. */
  body: number;
  glBody: number;
  /** Pixels whose 3 × 3 neighbourhood is one class (clear, outline, mesh) in the CPU hull's picture; how many differ. */
  compared: number;
  mismatches: number;
  /** The same against WebGLRenderer + OutlineMaterial's picture (its classes, its edges). */
  glCompared: number;
  glMismatches: number;
  /** The same comparison against the hull of the undeformed, uninstanced geometry (not vacuous). */
  staleMismatches: number;
  /** Pixels of a colour that is none of the three classes' (a NaN vertex, a stray triangle). */
  stray: number;
}

/** The geometries, one set per renderer. */
const geometrySets = { gpu: outlineGeometries(), gl: outlineGeometries() };

function makeCamera(): PerspectiveCamera {
  const camera = new PerspectiveCamera(60, 1, 0.1, 20);
  camera.position.set(0, 0.3, 6);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return camera;
}

async function drawGpu(backend: Backend, scene: Scene, camera: Camera, size: number): Promise<Uint8Array> {
  const renderer = await gpuRenderer(backend);
  const target = new RenderTarget(size, size, { depthBuffer: true });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x0000ff, 1);
  renderer.clear();
  renderer.render(scene, camera);
  const pixels = await readTarget(renderer, target, size);
  renderer.setRenderTarget(null);
  target.dispose();
  return pixels;
}

let gl: WebGLRenderer | null = null;
function drawGl(scene: Scene, camera: Camera, size: number): Uint8Array {
  gl ??= new WebGLRenderer({ antialias: false });
  const target = new WebGLRenderTarget(size, size);
  gl.setRenderTarget(target);
  gl.setClearColor(0x0000ff, 1);
  gl.clear();
  gl.render(scene, camera);
  const pixels = new Uint8Array(4 * size * size);
  gl.readRenderTargetPixels(target, 0, 0, size, size, pixels);
  gl.setRenderTarget(null);
  target.dispose();
  return pixels;
}

/**
 * A red object with `createOutlineNode`'s black hull on `backend`, against the same object with the CPU hull on
 * the same renderer (the oracle), with the hull of the raw geometry, and against WebGLRenderer drawing the object
 * with `createOutline`'s OutlineMaterial.
 */
async function outlineCompare(backend: Backend, config: OutlineConfig): Promise<OutlineStats> {
  const size = config.size ?? 192;
  const camera = makeCamera();
  const renderer = await gpuRenderer(backend);
  // WebGPURenderer: the node outline, then (hidden) the CPU hulls.
  const body = new MeshBasicNodeMaterial({ color: 0xff0000 });
  const { object, matrices } = outlinedObject(config, body, geometrySets.gpu);
  const scene = new Scene();
  scene.add(object);
  const outline = createOutlineNode(object, { thickness: config.thickness, color: 0 });
  scene.updateMatrixWorld();
  const ours = await drawGpu(backend, scene, camera, size);
  outline.visible = false;
  const oracleHull = cpuHull(
    object,
    matrices,
    config.thickness,
    true,
    new MeshBasicNodeMaterial({ color: 0 }),
  );
  scene.add(oracleHull);
  const theirs = await drawGpu(backend, scene, camera, size);
  scene.remove(oracleHull);
  const staleHull = cpuHull(
    object,
    [new Matrix4()],
    config.thickness,
    false,
    new MeshBasicNodeMaterial({ color: 0 }),
  );
  scene.add(staleHull);
  const stale = await drawGpu(backend, scene, camera, size);
  // WebGLRenderer: the same object with the GLSL outline.
  const glBody = new MeshBasicMaterial({ color: 0xff0000 });
  const glMade = outlinedObject(config, glBody, geometrySets.gl);
  const glScene = new Scene();
  glScene.add(glMade.object);
  const glOutline = createOutline(glMade.object, { thickness: config.thickness, color: 0 });
  glScene.updateMatrixWorld();
  const glPixels = drawGl(glScene, camera, size);
  const stats: OutlineStats = {
    backend: backendFlags(renderer),
    ring: 0,
    oracleRing: 0,
    glRing: 0,
    body: 0,
    glBody: 0,
    compared: 0,
    mismatches: 0,
    glCompared: 0,
    glMismatches: 0,
    staleMismatches: 0,
    stray: 0,
  };
  for (let i = 0; i < size * size; i++) {
    if (classify(ours, i) === 1) stats.ring++;
    if (classify(theirs, i) === 1) stats.oracleRing++;
    if (classify(glPixels, i) === 1) stats.glRing++;
    if (classify(ours, i) === 2 && classify(theirs, i) === 2) stats.body++;
    if (classify(glPixels, i) === 2) stats.glBody++;
    if (classify(ours, i) === 3) stats.stray++;
  }
  [stats.compared, stats.mismatches] = compareClasses(ours, theirs, size);
  [stats.glCompared, stats.glMismatches] = compareClasses(ours, glPixels, size);
  stats.staleMismatches = compareClasses(stale, theirs, size)[1];
  for (const mesh of [oracleHull, staleHull]) {
    mesh.geometry.dispose();
    (mesh.material as Material).dispose();
  }
  outline.material.dispose();
  glOutline.material.dispose();
  body.dispose();
  glBody.dispose();
  return stats;
}

/** `OutlineNodeMaterial`'s errors for bad options against `OutlineMaterial`'s, and its defaults against its. */
function errors(): { rows: { options: string; webgl: string; node: string }[]; defaults: string[] } {
  const bad: unknown[] = [
    { thickness: -1 },
    { thickness: Number.NaN },
    { thickness: Number.POSITIVE_INFINITY },
    { thickness: '0.1' },
    { thickness: 1e19 },
    { color: 0xff8000 },
    { color: 2 },
    { color: [Number.NaN, 0, 0] },
    { color: [1, 0] },
    { color: 'not a colour' },
    { color: {} },
  ];
  const rows = bad.map((options) => ({
    options: JSON.stringify(options, (_, v) =>
      typeof v === 'number' && !Number.isFinite(v) ? String(v) : v,
    ),
    webgl: thrown(() => new OutlineMaterial(options as never)),
    node: thrown(() => new OutlineNodeMaterial(options as never)),
  }));
  const a = new OutlineMaterial();
  const b = new OutlineNodeMaterial();
  const setter = thrown(() => {
    b.thickness = -2;
  });
  return {
    rows,
    defaults: [
      `${a.thickness} ${a.color.toArray()} ${a.side} ${a.fog}`,
      `${b.thickness} ${b.color.toArray()} ${b.side} ${b.fog}`,
      setter,
      `${b.clone().thickness} ${new OutlineNodeMaterial({ thickness: 0.2, color: '#ff0000' }).clone().color.getHexString()}`,
    ],
  };
}

async function backendInfo(backend: Backend) {
  return backendFlags(await gpuRenderer(backend));
}

const api = { backendInfo, outlineCompare, errors };
export type WebGPUOutlineHarness = typeof api;
(window as unknown as { harness: typeof api }).harness = api;
document.body.dataset.ready = '1';
