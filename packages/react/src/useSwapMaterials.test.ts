// useSwapMaterials and <ShadedModel> on a bare R3F root in node (as useTrackball.test.ts: the canvas and the
// renderer are stand-ins, no frame is drawn). The swap is @shadelab/material's real swapMaterials, wrapped to
// count its calls and its update()s: the model's meshes carry three's own materials before and after.
import { act, createRoot, type ReconcilerRoot } from '@react-three/fiber';
import type * as material from '@shadelab/material';
import { ShadingMaterial, type ShadingMaterialOptions, type SwappedMaterials } from '@shadelab/material';
import { createElement, type ReactNode, StrictMode } from 'react';
import {
  BoxGeometry,
  Group,
  type Material,
  Mesh,
  MeshLambertMaterial,
  MeshPhongMaterial,
  MeshStandardMaterial,
  type Object3D,
  PerspectiveCamera,
  Scene,
} from 'three';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { ShadedModel } from './ShadedModel.js';
import { useSwapMaterials } from './useSwapMaterials.js';

// Every swap the hook makes, and the options each of its update()s received.
const swaps: { root: Object3D; swapped: SwappedMaterials; updates: ShadingMaterialOptions[] }[] = [];
vi.mock('@shadelab/material', async (importOriginal) => {
  const actual = await importOriginal<typeof material>();
  return {
    ...actual,
    swapMaterials: (root: Object3D, options?: ShadingMaterialOptions) => {
      const swapped = actual.swapMaterials(root, options);
      const record = { root, swapped, updates: [] as ShadingMaterialOptions[] };
      const update = swapped.update.bind(swapped);
      const wrapped: SwappedMaterials = {
        get materials() {
          return swapped.materials;
        },
        get skipped() {
          return swapped.skipped;
        },
        update(o) {
          record.updates.push(o);
          update(o);
        },
        restore: () => swapped.restore(),
      };
      record.swapped = wrapped;
      swaps.push(record);
      return wrapped;
    },
  };
});

(globalThis as { IS_REACT_ACT_ENVIRONMENT?: boolean }).IS_REACT_ACT_ENVIRONMENT = true;

/** A model as a loader gives it: a Standard mesh, two meshes sharing a Phong material, a flat-shaded Lambert. */
function model() {
  const box = new BoxGeometry();
  const standard = new MeshStandardMaterial({ color: 0x336699, roughness: 0.5 });
  const phong = new MeshPhongMaterial({ color: 0xcc8844, specular: 0x222222, shininess: 40 });
  const flat = new MeshLambertMaterial({ color: 0x44aa44, flatShading: true });
  const root = new Group();
  const meshes: Mesh<BoxGeometry, Material>[] = [
    new Mesh(box, standard),
    new Mesh(box, phong),
    new Mesh(box, phong),
    new Mesh(box, flat),
  ];
  root.add(...meshes);
  const originals: Material[] = meshes.map((m) => m.material);
  return { root, meshes, originals };
}

let root: ReconcilerRoot<EventTarget>;
let scene: Scene;
beforeEach(async () => {
  swaps.length = 0;
  const canvas = Object.assign(new EventTarget(), { style: { touchAction: '' } });
  const gl = { render: () => {}, domElement: canvas, setSize: () => {}, setPixelRatio: () => {} };
  scene = new Scene();
  root = createRoot(canvas as never);
  await root.configure({
    gl: gl as never,
    camera: new PerspectiveCamera(),
    scene,
    frameloop: 'never',
    dpr: 1,
    size: { width: 100, height: 100, top: 0, left: 0 },
  });
});
afterEach(async () => {
  await act(async () => root.unmount());
});

const render = (node: ReactNode) => act(async () => root.render(node));

function Probe({
  object,
  options,
  out,
}: {
  object: Object3D | null | undefined;
  options?: ShadingMaterialOptions;
  out: { result?: SwappedMaterials | null };
}) {
  out.result = useSwapMaterials(object, options);
  return null;
}

describe('useSwapMaterials', () => {
  it('swaps on mount: each distinct material one ShadingMaterial, shared stays shared; returns the swap', async () => {
    const { root: model1, meshes, originals } = model();
    const out: { result?: SwappedMaterials | null } = {};
    await render(createElement(Probe, { object: model1, out }));
    expect(swaps).toHaveLength(1);
    expect(out.result).toBe(swaps[0].swapped);
    for (const mesh of meshes) expect(mesh.material).toBeInstanceOf(ShadingMaterial);
    expect(meshes[1].material).toBe(meshes[2].material);
    expect(out.result?.materials).toHaveLength(3);
    expect(out.result?.skipped).toEqual([]);
    // Carried over: the flat-shaded Lambert is flat, the Phong material's colour is its ka and kd.
    expect((meshes[3].material as ShadingMaterial).shading).toBe('flat');
    expect((meshes[1].material as ShadingMaterial).kd.equals((originals[1] as MeshPhongMaterial).color)).toBe(
      true,
    );
  });

  it('applies options live through update(), never swapping again; the same values in a new literal apply nothing', async () => {
    const { root: model1, meshes } = model();
    const out: { result?: SwappedMaterials | null } = {};
    await render(
      createElement(Probe, { object: model1, options: { shading: 'gouraud', ka: [0.1, 0.2, 0.3] }, out }),
    );
    const swapped = meshes.map((m) => m.material);
    expect(swaps).toHaveLength(1);
    expect(swaps[0].updates).toEqual([{ shading: 'gouraud', ka: [0.1, 0.2, 0.3] }]);
    for (const mesh of meshes) expect((mesh.material as ShadingMaterial).shading).toBe('gouraud');

    // New literals with the same values (the array too): nothing applied.
    for (let i = 0; i < 3; i++) {
      await render(
        createElement(Probe, { object: model1, options: { shading: 'gouraud', ka: [0.1, 0.2, 0.3] }, out }),
      );
    }
    expect(swaps[0].updates).toHaveLength(1);

    // A changed value: only it goes to update(); the materials are the same objects.
    await render(
      createElement(Probe, {
        object: model1,
        options: { shading: 'gouraud', ka: [0.1, 0.2, 0.3], lighting: 'blinn-phong', celBands: 3 },
        out,
      }),
    );
    expect(swaps).toHaveLength(1);
    expect(swaps[0].updates.slice(1)).toEqual([{ lighting: 'blinn-phong', celBands: 3 }]);
    expect(meshes.map((m) => m.material)).toEqual(swapped);
    meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(swapped[i]);
      const m = mesh.material as ShadingMaterial;
      expect([m.shading, m.lighting, m.celBands]).toEqual(['gouraud', 'blinn-phong', 3]);
      expect(m.ka.toArray()).toEqual([0.1, 0.2, 0.3]);
    });
  });

  it('an option that goes away puts back each material’s own carried-over value', async () => {
    const { root: model1, meshes } = model();
    const out: { result?: SwappedMaterials | null } = {};
    await render(createElement(Probe, { object: model1, out }));
    const before = meshes.map((m) => {
      const s = m.material as ShadingMaterial;
      return { shading: s.shading, ka: s.ka.toArray(), shininess: s.shininess };
    });
    expect(before[3].shading).toBe('flat'); // the flat-shaded Lambert: not the default
    await render(
      createElement(Probe, { object: model1, options: { shading: 'gouraud', ka: 0.5, shininess: 7 }, out }),
    );
    for (const mesh of meshes) expect((mesh.material as ShadingMaterial).shininess).toBe(7);
    // `undefined` is as good as absent.
    await render(createElement(Probe, { object: model1, options: { shading: undefined }, out }));
    expect(
      meshes.map((m) => {
        const s = m.material as ShadingMaterial;
        return { shading: s.shading, ka: s.ka.toArray(), shininess: s.shininess };
      }),
    ).toEqual(before);
    expect(swaps).toHaveLength(1);
  });

  it('restores the original materials on unmount', async () => {
    const { root: model1, meshes, originals } = model();
    const out: { result?: SwappedMaterials | null } = {};
    await render(createElement(Probe, { object: model1, options: { shading: 'flat' }, out }));
    const made = [...(out.result?.materials ?? [])];
    const disposed: Material[] = [];
    for (const m of made) m.addEventListener('dispose', () => disposed.push(m));
    await render(null);
    expect(meshes.map((m) => m.material)).toEqual(originals);
    meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(originals[i]);
    });
    // The ShadingMaterials the swap made are disposed; the model's own are not.
    expect(disposed.sort((a, b) => a.id - b.id)).toEqual(made.sort((a, b) => a.id - b.id));
  });

  it('restores the old root and swaps the new one when root changes; null swaps nothing', async () => {
    const a = model();
    const b = model();
    const out: { result?: SwappedMaterials | null } = {};
    await render(createElement(Probe, { object: a.root, options: { shading: 'gouraud' }, out }));
    await render(createElement(Probe, { object: b.root, options: { shading: 'gouraud' }, out }));
    expect(a.meshes.map((m) => m.material)).toEqual(a.originals);
    a.meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(a.originals[i]);
    });
    expect(swaps.map((s) => s.root)).toEqual([a.root, b.root]);
    expect(out.result).toBe(swaps[1].swapped);
    // The new swap gets the options as a first swap does.
    for (const mesh of b.meshes) expect((mesh.material as ShadingMaterial).shading).toBe('gouraud');
    await render(createElement(Probe, { object: null, options: { shading: 'gouraud' }, out }));
    b.meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(b.originals[i]);
    });
    expect(out.result).toBeNull();
    expect(swaps).toHaveLength(2);
  });

  it('StrictMode’s double mount (swap, restore, swap) leaves the original materials in place after unmount', async () => {
    const { root: model1, meshes, originals } = model();
    const out: { result?: SwappedMaterials | null } = {};
    // React double-invokes the effects of a component placed inside an existing StrictMode tree (a model that
    // mounts when it has loaded, under <Canvas>'s bridged StrictMode); on the root's first render the placed
    // fiber is R3F's provider above the StrictMode element, and React does not double-invoke there.
    await render(createElement(StrictMode, null));
    await render(
      createElement(
        StrictMode,
        null,
        createElement(Probe, { object: model1, options: { celBands: 4 }, out }),
      ),
    );
    // The effects ran twice: the first swap was restored, the second is in place with the options.
    expect(swaps).toHaveLength(2);
    expect(out.result).toBe(swaps[1].swapped);
    meshes.forEach((mesh) => {
      expect(swaps[1].swapped.materials).toContain(mesh.material);
      expect((mesh.material as ShadingMaterial).celBands).toBe(4);
    });
    await render(null);
    meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(originals[i]);
    });
  });
});

describe('<ShadedModel>', () => {
  it('renders the object with its props, swaps it with the option props, restores and removes it on unmount', async () => {
    const { root: model1, meshes, originals } = model();
    const refs: (Object3D | null)[] = [];
    const ref = (o: Object3D | null) => {
      refs.push(o);
    };
    await render(
      createElement(ShadedModel, {
        object: model1,
        shading: 'gouraud',
        position: [1, 2, 3],
        visible: true,
        ref,
      }),
    );
    expect(model1.parent).toBe(scene);
    expect(model1.position.toArray()).toEqual([1, 2, 3]);
    expect(refs).toEqual([model1]);
    expect(swaps).toHaveLength(1);
    for (const mesh of meshes) expect((mesh.material as ShadingMaterial).shading).toBe('gouraud');
    // An option prop changed: applied to the same materials. An object prop changed: not an option.
    const swapped = meshes.map((m) => m.material);
    await render(
      createElement(ShadedModel, {
        object: model1,
        shading: 'phong',
        lighting: 'blinn-phong',
        position: [0, 0, 1],
      }),
    );
    expect(swaps).toHaveLength(1);
    expect(swaps[0].updates.slice(1)).toEqual([{ shading: 'phong', lighting: 'blinn-phong' }]);
    expect(model1.position.toArray()).toEqual([0, 0, 1]);
    meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(swapped[i]);
      expect((mesh.material as ShadingMaterial).lighting).toBe('blinn-phong');
    });
    await render(null);
    expect(model1.parent).toBeNull();
    meshes.forEach((mesh, i) => {
      expect(mesh.material).toBe(originals[i]);
    });
  });
});
