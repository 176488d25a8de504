// <Adaptive> on a bare R3F root in node (as useAdaptiveShading.test.ts: stand-in canvas and renderer, frames
// advanced by hand): the meshes under the group get AdaptiveShading's choices, as a vanilla AdaptiveShading
// given the same objects, camera and viewport chooses; children that come and go are added and removed;
// unmounting puts everything back.
import { act, advance, createRoot, extend, type ReconcilerRoot } from '@react-three/fiber';
import { ShadingMaterial } from '@shadelab/material';
import { AdaptiveShading } from '@shadelab/material/adaptive';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Component, createElement, type ReactNode } from 'react';
import {
  BufferGeometry,
  Float32BufferAttribute,
  Group,
  InstancedMesh,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  PerspectiveCamera,
  Scene,
} from 'three';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { Adaptive } from './Adaptive.js';

(globalThis as { IS_REACT_ACT_ENVIRONMENT?: boolean }).IS_REACT_ACT_ENVIRONMENT = true;
// <Canvas> registers three's classes; a bare root does not: <Adaptive> renders a <group>.
extend({ Group });

/** Catches what its children throw at render. */
class Boundary extends Component<
  { children?: ReactNode; onError: (e: unknown) => void },
  { failed: boolean }
> {
  override state = { failed: false };
  static getDerivedStateFromError() {
    return { failed: true };
  }
  override componentDidCatch(error: unknown) {
    this.props.onError(error);
  }
  override render() {
    return this.state.failed ? null : this.props.children;
  }
}

const SIZE = { width: 300, height: 200 };
let root: ReconcilerRoot<HTMLCanvasElement>;
let camera: PerspectiveCamera;
beforeEach(async () => {
  const canvas = Object.assign(new EventTarget(), { style: { touchAction: '' } });
  const gl = { render: () => {}, domElement: canvas, setSize: () => {}, setPixelRatio: () => {} };
  root = createRoot(canvas as never);
  camera = new PerspectiveCamera(50, SIZE.width / SIZE.height, 0.1, 500);
  camera.position.set(0, 0, 5);
  await root.configure({
    gl: gl as never,
    camera,
    scene: new Scene(),
    frameloop: 'never',
    dpr: 2,
    size: { ...SIZE, top: 0, left: 0 },
  });
});
afterEach(async () => {
  await act(async () => root.unmount());
});

const FAST = { resolution: 16, views: 1, lights: 2 };
const sphere = new SubdivisionSphereGeometry({ level: 4 });

/** Meshes at increasing depths (so the choices differ), an InstancedMesh of 50, and a MeshBasicMaterial mesh. */
function field() {
  const meshes = [0, 1, 2, 3, 4].map((i) => {
    const m = new Mesh(sphere, new ShadingMaterial());
    m.position.set(i - 2, 0, -i * i * 8);
    return m;
  });
  const im = new InstancedMesh(sphere, new ShadingMaterial(), 50);
  const matrix = new Matrix4();
  for (let i = 0; i < 50; i++) im.setMatrixAt(i, matrix.makeTranslation((i % 10) - 5, 2, -i * 4));
  const basic = new Mesh(sphere, new MeshBasicMaterial());
  return { meshes, im, basic, sources: meshes.map((m) => m.material) };
}

const render = (node: ReactNode) => act(async () => root.render(node));
const frame = () =>
  act(async () => {
    advance(0);
  });

describe('<Adaptive>', () => {
  it('gives the meshes under it the choices of a vanilla AdaptiveShading (R3F camera, size × dpr), and puts them back', async () => {
    const { meshes, im, basic, sources } = field();
    const out: { current: AdaptiveShading | null } = { current: null };
    const children = [...meshes, im, basic].map((o) =>
      createElement('primitive', { key: o.uuid, object: o }),
    );
    await render(createElement(Adaptive, { maxError: 8, model: FAST, adaptiveRef: out }, children));
    await frame();
    const adaptive = out.current as AdaptiveShading;
    expect(adaptive).toBeInstanceOf(AdaptiveShading);
    expect(new Set(adaptive.objects)).toEqual(new Set([...meshes, im]));
    // The oracle: the same objects (copies: the managed ones wear the variants), camera and physical size.
    const vanilla = new AdaptiveShading({ maxError: 8, model: FAST });
    const copies = meshes.map((m) => {
      const c = new Mesh(sphere, new ShadingMaterial());
      c.position.copy(m.position);
      vanilla.add(c);
      return c;
    });
    const imCopy = new InstancedMesh(sphere, new ShadingMaterial(), 50);
    imCopy.instanceMatrix.array.set(im.instanceMatrix.array);
    vanilla.add(imCopy);
    vanilla.update(camera, { width: SIZE.width * 2, height: SIZE.height * 2 });
    const choices = (a: AdaptiveShading, ms: Mesh[], i: InstancedMesh) => [
      ...ms.map((m) => a.choiceOf(m)),
      ...Array.from({ length: 50 }, (_, k) => a.choiceOf(i, k)),
    ];
    expect(choices(adaptive, meshes, im)).toEqual(choices(vanilla, copies, imCopy));
    // Not all the same: the test means something.
    expect(new Set(choices(adaptive, meshes, im).map((c) => JSON.stringify(c))).size).toBeGreaterThan(1);
    meshes.forEach((m, k) => {
      expect((m.material as ShadingMaterial).shading).toBe(adaptive.choiceOf(m)?.shading);
      expect(m.material).not.toBe(sources[k]);
    });
    expect(basic.material).toBeInstanceOf(MeshBasicMaterial);
    expect(im.count).toBe(0);
    vanilla.dispose();
    // A still frame: the walk finds the same objects, the update computes nothing again.
    await frame();
    expect(adaptive.stats.recomputed).toBe(0);
    // Unmounted: every material, geometry and instance count back.
    await render(null);
    meshes.forEach((m, k) => {
      expect(m.material).toBe(sources[k]);
      expect(m.geometry).toBe(sphere);
    });
    expect(im.count).toBe(50);
    expect(im.children).toEqual([]);
    expect(adaptive.objects).toEqual([]);
  });

  it('adds children that appear and removes those that leave; a new budget makes a new AdaptiveShading', async () => {
    const { meshes, sources } = field();
    const out: { current: AdaptiveShading | null } = { current: null };
    const view = (n: number, maxError: number) =>
      createElement(
        Adaptive,
        { maxError, model: FAST, adaptiveRef: out },
        meshes.slice(0, n).map((o) => createElement('primitive', { key: o.uuid, object: o })),
      );
    await render(view(2, 8));
    await frame();
    expect(out.current?.objects.length).toBe(2);
    await render(view(5, 8));
    await frame();
    expect(new Set(out.current?.objects)).toEqual(new Set(meshes));
    await render(view(3, 8));
    await frame();
    expect(new Set(out.current?.objects)).toEqual(new Set(meshes.slice(0, 3)));
    expect(meshes[4].material).toBe(sources[4]);
    const first = out.current;
    await render(view(3, 255));
    await frame();
    expect(out.current).not.toBe(first);
    expect(first?.objects).toEqual([]);
    expect(out.current?.parameters.maxError).toBe(255);
    expect(new Set(out.current?.objects)).toEqual(new Set(meshes.slice(0, 3)));
  });

  it('a mesh it cannot compare with Phong shading is left as it is, with one error naming it', async () => {
    const error = vi.spyOn(console, 'error').mockImplementation(() => {});
    const noNormals = new BufferGeometry();
    noNormals.setAttribute('position', new Float32BufferAttribute([0, 0, 0, 1, 0, 0, 0, 1, 0], 3));
    const material = new ShadingMaterial();
    const odd = new Mesh(noNormals, material);
    odd.name = 'odd';
    await render(
      createElement(Adaptive, { maxError: 8, model: FAST }, createElement('primitive', { object: odd })),
    );
    for (let i = 0; i < 5; i++) await frame();
    expect(odd.material).toBe(material);
    const calls = error.mock.calls.filter((c) => String(c[0]).includes('<Adaptive>'));
    expect(calls.length).toBe(1);
    expect(String(calls[0][0])).toContain("'odd'");
    error.mockRestore();
  });

  it('a bad budget is refused at render with the RangeError of AdaptiveShading', async () => {
    const caught: unknown[] = [];
    const error = vi.spyOn(console, 'error').mockImplementation(() => {});
    await render(
      createElement(Boundary, { onError: (e) => caught.push(e) }, createElement(Adaptive, { maxError: 0 })),
    );
    error.mockRestore();
    expect(caught.length).toBe(1);
    expect(caught[0]).toBeInstanceOf(RangeError);
    expect(String(caught[0])).toMatch(/maxError must be a finite number > 0 .* got 0/);
  });
});
