// useAdaptiveShading on a bare R3F root in node (as useSwapMaterials.test.ts: stand-in canvas and renderer, frames
// advanced by hand): the objects get the variant materials before a frame and their own back on unmount.
import { act, advance, createRoot, type ReconcilerRoot } from '@react-three/fiber';
import { ShadingMaterial } from '@shadelab/material';
import type { AdaptiveShading } from '@shadelab/material/adaptive';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { createElement } from 'react';
import { InstancedMesh, Mesh, PerspectiveCamera, Scene } from 'three';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { useAdaptiveShading } from './useAdaptiveShading.js';

(globalThis as { IS_REACT_ACT_ENVIRONMENT?: boolean }).IS_REACT_ACT_ENVIRONMENT = true;

let root: ReconcilerRoot<HTMLCanvasElement>;
beforeEach(async () => {
  const canvas = Object.assign(new EventTarget(), { style: { touchAction: '' } });
  const gl = { render: () => {}, domElement: canvas, setSize: () => {}, setPixelRatio: () => {} };
  root = createRoot(canvas as never);
  const camera = new PerspectiveCamera(50, 1, 0.1, 100);
  camera.position.set(0, 0, 5);
  await root.configure({
    gl: gl as never,
    camera,
    scene: new Scene(),
    frameloop: 'never',
    dpr: 1,
    size: { width: 200, height: 200, top: 0, left: 0 },
  });
});
afterEach(async () => {
  await act(async () => root.unmount());
});

const FAST = { resolution: 16, views: 1, lights: 2 };

function Probe(props: { objects: Mesh[]; maxError: number; out: { adaptive?: AdaptiveShading } }) {
  props.out.adaptive = useAdaptiveShading(props.objects, { maxError: props.maxError, model: FAST });
  return null;
}

describe('useAdaptiveShading', () => {
  it('manages the objects each frame and puts them back on unmount', async () => {
    const source = new ShadingMaterial();
    const mesh = new Mesh(new SubdivisionSphereGeometry({ level: 2 }), source);
    const im = new InstancedMesh(new SubdivisionSphereGeometry({ level: 2 }), source, 4);
    const out: { adaptive?: AdaptiveShading } = {};
    await act(async () => root.render(createElement(Probe, { objects: [mesh, im], maxError: 8, out })));
    expect(out.adaptive?.objects).toEqual([mesh, im]);
    await act(async () => {
      // R3F's frame: the hook's useFrame runs adaptive.update with the canvas size.
      advance(0);
    });
    expect(mesh.material).not.toBe(source);
    expect((mesh.material as ShadingMaterial).shading).toBe(out.adaptive?.choiceOf(mesh)?.shading);
    expect(im.count).toBe(0);
    expect(out.adaptive?.groupsOf(im).reduce((s, g) => s + g.count, 0)).toBe(4);
    await act(async () => root.render(createElement(Probe, { objects: [], maxError: 8, out })));
    expect(mesh.material).toBe(source);
    expect(im.count).toBe(4);
  });

  it('makes a new AdaptiveShading when the budget changes, and moves the objects to it', async () => {
    const source = new ShadingMaterial();
    const mesh = new Mesh(new SubdivisionSphereGeometry({ level: 2 }), source);
    const out: { adaptive?: AdaptiveShading } = {};
    await act(async () => root.render(createElement(Probe, { objects: [mesh], maxError: 8, out })));
    const first = out.adaptive;
    await act(async () => root.render(createElement(Probe, { objects: [mesh], maxError: 32, out })));
    expect(out.adaptive).not.toBe(first);
    expect(first?.objects).toEqual([]);
    expect(out.adaptive?.objects).toEqual([mesh]);
    expect(out.adaptive?.parameters.maxError).toBe(32);
  });
});
