import { ShadingMaterial, swapMaterials } from '@shadelab/material';
import fc from 'fast-check';
import {
  BatchedMesh,
  Bone,
  BoxGeometry,
  BufferGeometry,
  Group,
  InstancedMesh,
  Line,
  LineBasicMaterial,
  LineSegments,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshDepthMaterial,
  MeshDistanceMaterial,
  MeshLambertMaterial,
  MeshMatcapMaterial,
  MeshNormalMaterial,
  MeshPhongMaterial,
  MeshPhysicalMaterial,
  MeshStandardMaterial,
  MeshToonMaterial,
  type Object3D,
  Points,
  PointsMaterial,
  RawShaderMaterial,
  ShaderMaterial,
  Skeleton,
  SkinnedMesh,
  Sprite,
  SpriteMaterial,
} from 'three';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

const geometry = new BoxGeometry();
let warn: ReturnType<typeof vi.spyOn>;
beforeEach(() => {
  warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
});
afterEach(() => {
  warn.mockRestore();
});

/** Each object and the material(s) it holds, in traversal order. */
const snapshot = (root: Object3D) => {
  const held: [Object3D, unknown][] = [];
  root.traverse((object) => {
    if ('material' in object) held.push([object, object.material]);
  });
  return held;
};

describe('swapMaterials: what it swaps', () => {
  it('Mesh, SkinnedMesh, InstancedMesh and BatchedMesh, visible or not', () => {
    const root = new Group();
    const mesh = new Mesh(geometry, new MeshLambertMaterial());
    const skinned = new SkinnedMesh(geometry, new MeshStandardMaterial());
    skinned.bind(new Skeleton([new Bone()]));
    const instanced = new InstancedMesh(geometry, new MeshPhongMaterial(), 3);
    const batched = new BatchedMesh(2, 100, 100, new MeshToonMaterial());
    const hidden = new Mesh(geometry, new MeshBasicMaterial());
    hidden.visible = false;
    root.add(mesh, skinned, instanced, batched);
    mesh.add(hidden);
    const swap = swapMaterials(root);
    for (const object of [mesh, skinned, instanced, batched, hidden]) {
      expect(object.material).toBeInstanceOf(ShadingMaterial);
    }
    // Depth first: the hidden mesh is the first mesh's child.
    expect(swap.materials).toEqual([mesh, hidden, skinned, instanced, batched].map((o) => o.material));
    expect(swap.skipped).toEqual([]);
    expect(warn).not.toHaveBeenCalled();
  });

  it('the root itself', () => {
    const mesh = new Mesh(geometry, new MeshLambertMaterial());
    swapMaterials(mesh);
    expect(mesh.material).toBeInstanceOf(ShadingMaterial);
  });

  it('a material shared by several meshes becomes one shared ShadingMaterial', () => {
    const shared = new MeshPhongMaterial();
    const other = new MeshPhongMaterial();
    const a = new Mesh(geometry, shared);
    const b = new Mesh(geometry, shared);
    const c = new Mesh(geometry, other);
    const root = new Group().add(a, b, c);
    const swap = swapMaterials(root);
    expect(a.material).toBe(b.material);
    expect(a.material).not.toBe(c.material);
    expect(swap.materials).toHaveLength(2);
  });

  it('material arrays (with groups) become new arrays, shared where the original was', () => {
    const phong = new MeshPhongMaterial();
    const shader = new ShaderMaterial();
    const array = [phong, shader, phong];
    const boxA = new Mesh(geometry, array);
    const boxB = new Mesh(geometry, array);
    const single = new Mesh(geometry, phong);
    const swap = swapMaterials(new Group().add(boxA, boxB, single));
    const given = boxA.material as Material[];
    expect(given).not.toBe(array);
    expect(boxB.material).toBe(given);
    expect(given[0]).toBeInstanceOf(ShadingMaterial);
    expect(given[1]).toBe(shader);
    expect(given[2]).toBe(given[0]);
    expect(single.material).toBe(given[0]);
    expect(array).toEqual([phong, shader, phong]); // the original array is not changed
    expect(swap.materials).toHaveLength(1);
    expect(swap.skipped.map((s) => [s.object, s.material])).toEqual([
      [boxA, shader],
      [boxB, shader],
    ]);
    swap.restore();
    expect(boxA.material).toBe(array);
    expect(boxB.material).toBe(array);
  });
});

describe('swapMaterials: what it skips, and why', () => {
  it('every kind left in place is listed with its reason and reported in one console.warn', () => {
    const kinds: [Object3D, RegExp][] = [
      [new Mesh(geometry, new ShaderMaterial()), /ShaderMaterial has its own shaders/],
      [new Mesh(geometry, new RawShaderMaterial()), /RawShaderMaterial has its own shaders/],
      [new Mesh(geometry, new MeshNormalMaterial()), /MeshNormalMaterial is not one of three's lit/],
      [new Mesh(geometry, new MeshDepthMaterial()), /MeshDepthMaterial is not one of/],
      [new Mesh(geometry, new MeshDistanceMaterial()), /MeshDistanceMaterial is not one of/],
      [new Mesh(geometry, new MeshMatcapMaterial()), /MeshMatcapMaterial is not one of/],
      [new Mesh(geometry, new ShadingMaterial()), /ShadingMaterial is already a shading material/],
      [new Points(geometry, new PointsMaterial()), /Points draws points, lines or sprites/],
      [new Line(geometry, new LineBasicMaterial()), /Line draws points, lines or sprites/],
      [new LineSegments(geometry, new LineBasicMaterial()), /LineSegments draws points/],
      [new Sprite(new SpriteMaterial()), /Sprite draws points/],
      [new Mesh(geometry, null as never), /its material is not a THREE\.Material \(null\)/],
    ];
    const bad = new MeshLambertMaterial();
    bad.opacity = 7; // its conversion throws: the message is the reason
    kinds.push([new Mesh(geometry, bad), /ShadingMaterial\.opacity must be in 0 … 1, got 7/]);
    const root = new Group();
    for (const [object] of kinds) root.add(object);
    const before = snapshot(root);
    const swap = swapMaterials(root);
    expect(swap.materials).toEqual([]);
    expect(swap.skipped).toHaveLength(kinds.length);
    kinds.forEach(([object, reason], i) => {
      const entry = swap.skipped[i];
      expect(entry.object).toBe(object);
      expect(entry.material).toBe((object as Mesh).material ?? null);
      expect(entry.reason).toMatch(reason);
    });
    expect(snapshot(root)).toEqual(before);
    expect(warn).toHaveBeenCalledTimes(1);
    expect(String(warn.mock.calls[0][0])).toMatch(/^swapMaterials: left 13 material\(s\) in place:\n1 × /);
  });

  it('a material that fails is listed for each object holding it, converted once', () => {
    const bad = new MeshLambertMaterial();
    bad.alphaTest = -1;
    const swap = swapMaterials(new Group().add(new Mesh(geometry, bad), new Mesh(geometry, bad)));
    expect(swap.skipped).toHaveLength(2);
    expect(warn).toHaveBeenCalledTimes(1);
    expect(String(warn.mock.calls[0][0])).toMatch(/2 × ShadingMaterial\.alphaTest/);
  });
});

describe('swapMaterials: restore', () => {
  it('puts back exactly the original objects and disposes only the materials the swap made', () => {
    const originals = [
      new MeshBasicMaterial(),
      new MeshLambertMaterial(),
      new MeshPhongMaterial(),
      new MeshStandardMaterial(),
      new MeshPhysicalMaterial(),
      new MeshToonMaterial(),
      new ShaderMaterial(),
    ];
    const root = new Group();
    for (const material of originals) root.add(new Mesh(geometry, material));
    root.add(new Mesh(geometry, [originals[0], originals[6]]));
    const before = snapshot(root);
    const userDisposed = vi.fn();
    for (const material of originals) material.addEventListener('dispose', userDisposed);
    const swap = swapMaterials(root);
    const madeDisposed = vi.fn();
    for (const material of swap.materials) material.addEventListener('dispose', madeDisposed);
    swap.restore();
    const after = snapshot(root);
    after.forEach(([object, material], i) => {
      expect(object).toBe(before[i][0]);
      expect(material).toBe(before[i][1]);
    });
    expect(userDisposed).not.toHaveBeenCalled();
    expect(madeDisposed).toHaveBeenCalledTimes(6);
    swap.restore(); // idempotent
    expect(madeDisposed).toHaveBeenCalledTimes(6);
    expect(snapshot(root)).toEqual(before);
  });

  it('leaves an object alone whose material the user replaced after the swap', () => {
    const original = new MeshPhongMaterial();
    const mine = new MeshLambertMaterial();
    const mesh = new Mesh<BufferGeometry, Material>(geometry, original);
    const swap = swapMaterials(mesh);
    mesh.material = mine;
    swap.restore();
    expect(mesh.material).toBe(mine);
  });

  it('1,000 swap/restore cycles leave no listener and no material behind', () => {
    const shared = new MeshStandardMaterial();
    const array = [new MeshPhongMaterial(), shared];
    const root = new Group().add(new Mesh(geometry, shared), new Mesh(geometry, array));
    const before = snapshot(root);
    let made = 0;
    let disposed = 0;
    for (let i = 0; i < 1000; i++) {
      const swap = swapMaterials(root, { shading: i % 2 === 0 ? 'gouraud' : 'flat' });
      made += swap.materials.length;
      for (const material of swap.materials) material.addEventListener('dispose', () => disposed++);
      swap.restore();
    }
    expect(made).toBe(2000);
    expect(disposed).toBe(2000);
    expect(snapshot(root)).toEqual(before);
    for (const material of [shared, ...array]) {
      const listeners = (material as unknown as { _listeners?: Record<string, unknown[]> })._listeners;
      expect(Object.values(listeners ?? {}).flat()).toEqual([]);
    }
    expect(Object.values((root as unknown as { _listeners?: object })._listeners ?? {}).flat()).toEqual([]);
  });
});

describe('swapMaterials: update', () => {
  it('sets the options on every material the swap made', () => {
    const root = new Group().add(
      new Mesh(geometry, new MeshPhongMaterial()),
      new Mesh(geometry, new MeshToonMaterial()),
    );
    const swap = swapMaterials(root);
    swap.update({ shading: 'gouraud', celBands: 5, ks: 0.5, lights: [] });
    for (const material of swap.materials) {
      expect([material.shading, material.celBands]).toEqual(['gouraud', 5]);
      expect(material.ks.toArray()).toEqual([0.5, 0.5, 0.5]);
    }
  });

  it('a new lighting carries each original’s highlight over for it (phong: exponent / 4), unless a shininess is given', () => {
    const root = new Group().add(
      new Mesh(geometry, new MeshPhongMaterial({ shininess: 40 })),
      new Mesh(geometry, new MeshStandardMaterial({ roughness: 0.5 })),
    );
    const swap = swapMaterials(root);
    expect(swap.materials.map((m) => [m.lighting, m.shininess])).toEqual([
      ['blinn-phong', 40],
      ['blinn-phong', 30],
    ]);
    swap.update({ lighting: 'phong' });
    expect(swap.materials.map((m) => [m.lighting, m.shininess])).toEqual([
      ['phong', 10],
      ['phong', 7.5],
    ]);
    swap.update({ shading: 'gouraud' });
    expect(swap.materials.map((m) => m.shininess)).toEqual([10, 7.5]);
    swap.update({ lighting: 'blinn-phong', shininess: 12 });
    expect(swap.materials.map((m) => [m.lighting, m.shininess])).toEqual([
      ['blinn-phong', 12],
      ['blinn-phong', 12],
    ]);
  });

  it('a bad value throws before any material is changed, naming the parameter', () => {
    const root = new Group().add(
      new Mesh(geometry, new MeshPhongMaterial()),
      new Mesh(geometry, new MeshLambertMaterial()),
    );
    const swap = swapMaterials(root);
    expect(() => swap.update({ shading: 'flat', celBands: 300 })).toThrow(RangeError);
    expect(() => swap.update({ shading: 'flat', celBands: 300 })).toThrow(
      /celBands must be 0 \(off\) or an integer/,
    );
    expect(() => swap.update(null as never)).not.toThrow();
    expect(() => swap.update(7 as never)).toThrow(/swapMaterials: update options must be an options object/);
    for (const material of swap.materials) expect(material.shading).toBe('phong');
  });

  it('after restore it checks and changes nothing', () => {
    const swap = swapMaterials(new Mesh(geometry, new MeshPhongMaterial()));
    swap.restore();
    swap.update({ shading: 'flat' });
    expect(swap.materials[0].shading).toBe('phong');
    expect(() => swap.update({ shading: 'x' as never })).toThrow(TypeError);
  });
});

describe('swapMaterials: bad input', () => {
  it('a root that is not an Object3D: a TypeError naming the parameter', () => {
    for (const bad of [null, undefined, {}, 3, new MeshPhongMaterial()]) {
      expect(() => swapMaterials(bad as never)).toThrow(/swapMaterials: root must be a THREE\.Object3D/);
    }
  });

  it('bad options throw before anything is swapped', () => {
    const mesh = new Mesh(geometry, new MeshPhongMaterial());
    const before = mesh.material;
    expect(() => swapMaterials(mesh, { lighting: 'cel' as never })).toThrow(/lighting must be one of/);
    expect(() => swapMaterials(mesh, 'flat' as never)).toThrow(
      /swapMaterials: options must be an options object/,
    );
    expect(mesh.material).toBe(before);
  });
});

describe('swapMaterials: property over random trees', () => {
  const kinds = [
    () => new MeshBasicMaterial(),
    () => new MeshLambertMaterial(),
    () => new MeshPhongMaterial(),
    () => new MeshStandardMaterial(),
    () => new MeshPhysicalMaterial(),
    () => new MeshToonMaterial(),
    () => new ShaderMaterial(),
    () => new MeshNormalMaterial(),
  ];
  const swappable = (m: Material) => !(m instanceof ShaderMaterial) && !(m instanceof MeshNormalMaterial);

  it('after the swap every swappable material is a ShadingMaterial, sharing is kept, restore is the identity', () => {
    const tree = fc.record({
      pool: fc.array(fc.integer({ min: 0, max: kinds.length - 1 }), { minLength: 1, maxLength: 6 }),
      nodes: fc.array(
        fc.record({
          parent: fc.nat(),
          kind: fc.constantFrom('mesh', 'array', 'group', 'points'),
          picks: fc.array(fc.nat(), { minLength: 1, maxLength: 3 }),
        }),
        { maxLength: 12 },
      ),
    });
    fc.assert(
      fc.property(tree, ({ pool, nodes }) => {
        const materials = pool.map((k) => kinds[k]());
        const root = new Group();
        const all: Object3D[] = [root];
        for (const { parent, kind, picks } of nodes) {
          const pick = picks.map((p) => materials[p % materials.length]);
          const object =
            kind === 'mesh'
              ? new Mesh(geometry, pick[0])
              : kind === 'array'
                ? new Mesh(geometry, pick)
                : kind === 'points'
                  ? new Points(new BufferGeometry(), new PointsMaterial())
                  : new Group();
          all[parent % all.length].add(object);
          all.push(object);
        }
        const before = snapshot(root);
        const swap = swapMaterials(root);
        const during = snapshot(root);
        const mapping = new Map<unknown, unknown>();
        during.forEach(([object, held], i) => {
          const original = before[i][1];
          if (object instanceof Points) {
            expect(held).toBe(original);
            return;
          }
          const pairs: [unknown, unknown][] = Array.isArray(original)
            ? (original as Material[]).map((m, j) => [m, (held as Material[])[j]])
            : [[original, held]];
          for (const [from, to] of pairs) {
            if (swappable(from as Material)) expect(to).toBeInstanceOf(ShadingMaterial);
            else expect(to).toBe(from);
            // One made material per original: the same original always maps to the same material.
            if (mapping.has(from)) expect(mapping.get(from)).toBe(to);
            mapping.set(from, to);
          }
        });
        const distinct = new Set([...mapping.keys()].filter((m) => swappable(m as Material)));
        expect(swap.materials).toHaveLength(distinct.size);
        swap.restore();
        expect(snapshot(root)).toEqual(before);
        before.forEach(([, held], i) => {
          expect(snapshot(root)[i][1]).toBe(held);
        });
      }),
      { numRuns: 100 },
    );
  });
});
