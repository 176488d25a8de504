/**
 * WebGPU mode draws the viewer's own scene graph (the sphere, the compare meshes, the impostor, a picked scene,
 * the user's model, the outlines): for each draw, every WebGL-only material is swapped for its node version,
 * made once and kept in step with it, and put back after.
 *
 * - ShadingMaterial → ShadingNodeMaterial (every option and the surface: `scene.ts`); on the user's model, the
 *   model's own materials swapped by `swapNodeMaterials`, as WebGL mode swaps them with `swapMaterials`.
 * - OutlineMaterial → the node inverted hull (`outlineNode.ts`); SphereImpostorMaterial → SphereImpostorNodeMaterial.
 * - A material's `clippingPlanes` (WebGL's clipping) → the mesh drawn inside a `ClippingGroup` of those planes
 *   (WebGPURenderer clips by groups).
 * - A flatShadingGeometry → one made for the backend's provoking vertex.
 * three's own materials (the light markers, the gizmo) are drawn by WebGPURenderer as they are.
 */
import { type ProvokingVertex, ShadingMaterial } from '@shadelab/material';
import { SphereImpostorMaterial } from '@shadelab/material/impostor';
import { OutlineMaterial } from '@shadelab/material/outline';
import {
  ShadingNodeMaterial,
  SphereImpostorNodeMaterial,
  type SwappedMaterials,
  swapNodeMaterials,
} from '@shadelab/material/webgpu';
import * as THREE from 'three/webgpu';
import { originalsOf } from './originals';
import { createOutlineNode, type OutlineNode, withNormals } from './outlineNode';
import { flatFor, mirrorLighting, mirrorMaterial } from './scene';

type Materials = THREE.Material | THREE.Material[];

/** The user's model swapped with swapNodeMaterials: each mesh's node material(s), and the swap. */
interface ModelSwap {
  readonly byMesh: Map<THREE.Mesh, Materials>;
  readonly swap: SwappedMaterials<ShadingNodeMaterial>;
  key: string;
}

export class NodeMirror {
  private readonly shading = new Map<ShadingMaterial, ShadingNodeMaterial>();
  private readonly impostors = new Map<SphereImpostorMaterial, SphereImpostorNodeMaterial>();
  private readonly outlines = new Map<OutlineMaterial, OutlineNode>();
  private readonly models = new Map<THREE.Object3D, ModelSwap>();
  private readonly groups = new WeakMap<readonly THREE.Plane[], THREE.ClippingGroup>();

  /** @param provokingVertex - The running backend's (`provokingVertexOf(renderer)`). */
  constructor(private readonly provokingVertex: ProvokingVertex) {}

  /** Runs `draw` with `root`'s visible meshes as WebGPURenderer must see them; everything put back after. */
  draw(root: THREE.Object3D, draw: () => void): void {
    const undo: (() => void)[] = [];
    const clipped: { mesh: THREE.Mesh; source: THREE.Material }[] = [];
    root.traverseVisible((object) => {
      const mesh = object as THREE.Mesh;
      if (!mesh.isMesh) return;
      const { material, geometry } = mesh;
      const node = Array.isArray(material)
        ? material.map((m) => this.nodeFor(m))
        : (this.modelNode(mesh) ?? this.nodeFor(material));
      const first = Array.isArray(material) ? material[0] : material;
      const drawn =
        first instanceof OutlineMaterial
          ? withNormals(geometry)
          : first instanceof ShadingMaterial
            ? flatFor(geometry, this.provokingVertex)
            : geometry;
      if (node === material && drawn === geometry) return;
      mesh.material = node;
      mesh.geometry = drawn;
      undo.push(() => {
        mesh.material = material;
        mesh.geometry = geometry;
      });
      if (first instanceof ShadingMaterial && (first.clippingPlanes?.length ?? 0) > 0) {
        clipped.push({ mesh, source: first });
      }
    });
    for (const { mesh, source } of clipped) undo.push(this.clip(mesh, source));
    try {
      draw();
    } finally {
      for (let i = undo.length - 1; i >= 0; i--) undo[i]!();
    }
  }

  /** The node version of `material` (kept in step with it), or `material` itself. */
  private nodeFor(material: THREE.Material): THREE.Material {
    if (material instanceof SphereImpostorMaterial) {
      const node = made(this.impostors, material, () => new SphereImpostorNodeMaterial());
      mirrorLighting(material, node);
      return node;
    }
    if (material instanceof ShadingMaterial) {
      const node = made(this.shading, material, () => new ShadingNodeMaterial());
      mirrorMaterial(material, node);
      return node;
    }
    if (material instanceof OutlineMaterial) {
      const node = made(this.outlines, material, createOutlineNode, (o) => o.material.dispose());
      node.sync(material);
      return node.material;
    }
    return material;
  }

  /**
   * A mesh of the user's model: its original material(s) swapped by swapNodeMaterials (once per model, all its
   * meshes at once, so that a shared material stays shared), with the panel's shading, lighting and cel bands
   * from the mesh's ShadingMaterial. null for any other mesh.
   */
  private modelNode(mesh: THREE.Mesh): Materials | null {
    const source = mesh.material;
    if (!(source instanceof ShadingMaterial)) return null;
    const found = originalsOf(mesh);
    if (!found) return null;
    let model = this.models.get(found.root);
    if (!model) {
      const current = new Map<THREE.Mesh, Materials>();
      const byMesh = new Map<THREE.Mesh, Materials>();
      let swap: SwappedMaterials<ShadingNodeMaterial>;
      // The viewer's outlines are the viewer's, not the model's: WebGPU mode draws them with its own node hull
      // (above), so the swap, which would leave them in place and say so, does not see them.
      const outlines: [THREE.Object3D, THREE.Object3D][] = [];
      found.root.traverse((o) => {
        if ((o as THREE.Mesh).material instanceof OutlineMaterial && o.parent) outlines.push([o, o.parent]);
      });
      try {
        for (const [o] of outlines) o.removeFromParent();
        for (const [m, original] of found.meshes) {
          current.set(m, m.material);
          m.material = original;
        }
        swap = swapNodeMaterials(found.root);
        for (const m of found.meshes.keys()) byMesh.set(m, m.material);
      } finally {
        for (const [m, material] of current) m.material = material;
        for (const [o, parent] of outlines) parent.add(o);
      }
      const made: ModelSwap = { byMesh, swap, key: '' };
      model = made;
      this.models.set(found.root, made);
      // The model's ShadingMaterials are disposed with the model (or to free programs): so are these.
      const forget = () => {
        if (this.models.get(found.root) !== made) return;
        this.models.delete(found.root);
        for (const m of made.swap.materials) m.dispose();
      };
      for (const m of current.values()) for (const one of [m].flat()) one.addEventListener('dispose', forget);
    }
    const key = `${source.shading}|${source.lighting}|${source.celBands}`;
    if (key !== model.key) {
      model.key = key;
      model.swap.update({ shading: source.shading, lighting: source.lighting, celBands: source.celBands });
    }
    return model.byMesh.get(mesh) ?? null;
  }

  /** Puts `mesh` inside a ClippingGroup of its material's planes, in its place; returns how to take it out. */
  private clip(mesh: THREE.Mesh, source: THREE.Material): () => void {
    const parent = mesh.parent;
    if (!parent) return () => {};
    const planes = source.clippingPlanes as THREE.Plane[];
    let group = this.groups.get(planes);
    if (!group) {
      group = new THREE.ClippingGroup();
      group.clippingPlanes = planes;
      this.groups.set(planes, group);
    }
    group.clipIntersection = source.clipIntersection;
    const index = parent.children.indexOf(mesh);
    // In place, without three's add/remove events: the R3F tree never sees it.
    parent.children[index] = group;
    group.parent = parent;
    group.children = [mesh];
    mesh.parent = group;
    const g = group;
    return () => {
      parent.children[index] = mesh;
      mesh.parent = parent;
      g.children = [];
      g.parent = null;
    };
  }

  dispose(): void {
    for (const m of this.shading.values()) m.dispose();
    for (const m of this.impostors.values()) m.dispose();
    for (const o of this.outlines.values()) o.material.dispose();
    for (const model of this.models.values()) for (const m of model.swap.materials) m.dispose();
    this.shading.clear();
    this.impostors.clear();
    this.outlines.clear();
    this.models.clear();
  }
}

/**
 * The node material made for `source` (made now if there is none): dropped and disposed when `source` is
 * disposed (a scene freed, or the viewer freeing programs: made again on next use).
 */
function made<S extends THREE.Material, N>(
  cache: Map<S, N>,
  source: S,
  make: () => N,
  dispose: (node: N) => void = (node) => (node as THREE.Material).dispose(),
): N {
  let node = cache.get(source);
  if (node === undefined) {
    const n = make();
    node = n;
    cache.set(source, n);
    const forget = () => {
      source.removeEventListener('dispose', forget);
      if (cache.get(source) === n) cache.delete(source);
      dispose(n);
    };
    source.addEventListener('dispose', forget);
  }
  return node;
}
