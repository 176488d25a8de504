/**
 * The cel outline on WebGPURenderer. @shadelab/material has no node version of its `OutlineMaterial` (a GLSL
 * ShaderMaterial, which WebGPURenderer cannot draw), so WebGPU mode draws the same inverted hull with a node
 * material of three's own: `MeshBasicNodeMaterial` on the back faces, its vertices pushed out by `thickness`
 * world units along the unit world normal (three's normal matrix of the deformed, instanced normal: skinning,
 * morph targets and the instance matrix are applied by three's nodes first), in one colour, fogged like the
 * mesh. A geometry without a `normal` attribute (the playground's analytic spheres, as `OutlineMaterial` reads
 * them) gets one made from its positions (`withNormals`).
 */
import type { OutlineMaterial } from '@shadelab/material/outline';
import {
  Fn,
  modelNormalMatrix,
  modelWorldMatrixInverse,
  normalLocal,
  positionLocal,
  uniform,
  vec4,
} from 'three/tsl';
import * as THREE from 'three/webgpu';

/** The node outline: `sync` copies the WebGL outline's thickness, colour and fog onto it. */
export interface OutlineNode {
  readonly material: THREE.MeshBasicNodeMaterial;
  sync(source: OutlineMaterial): void;
}

export function createOutlineNode(): OutlineNode {
  const thickness = uniform(0.03);
  const color = uniform(new THREE.Color());
  const material = new THREE.MeshBasicNodeMaterial({ side: THREE.BackSide });
  material.name = 'outline (node)';
  material.positionNode = Fn(() => {
    const worldNormal = modelNormalMatrix.mul(normalLocal).normalize();
    const offset = modelWorldMatrixInverse.mul(vec4(worldNormal.mul(thickness), 0)).xyz;
    return positionLocal.add(offset);
  })();
  material.colorNode = vec4(color, 1);
  return {
    material,
    sync(source) {
      thickness.value = source.thickness;
      color.value.copy(source.color);
      material.fog = source.fog;
    },
  };
}

const _withNormals = new WeakMap<THREE.BufferGeometry, THREE.BufferGeometry>();

/**
 * `geometry`, or, when it has no `normal` attribute (a sphere lit with analytic normals), a geometry sharing its
 * attributes with the unit position as the normal (made once per geometry, freed with it): what the outline
 * pushes along, and what an instanced sphere is lit with (ShadingNodeMaterial takes a sphere's normal from
 * `positionLocal`, which on an InstancedMesh already holds the instance's matrix: its normals would be wrong).
 */
export function withNormals(geometry: THREE.BufferGeometry): THREE.BufferGeometry {
  if (geometry.hasAttribute('normal')) return geometry;
  let made = _withNormals.get(geometry);
  if (made === undefined) {
    const g = new THREE.BufferGeometry();
    for (const [name, attribute] of Object.entries(geometry.attributes)) g.setAttribute(name, attribute);
    g.setIndex(geometry.index);
    const position = geometry.getAttribute('position');
    const normal = new Float32Array(3 * position.count);
    const v = new THREE.Vector3();
    for (let i = 0; i < position.count; i++) {
      v.fromBufferAttribute(position, i)
        .normalize()
        .toArray(normal, 3 * i);
    }
    g.setAttribute('normal', new THREE.BufferAttribute(normal, 3));
    for (const group of geometry.groups) g.addGroup(group.start, group.count, group.materialIndex);
    geometry.addEventListener('dispose', () => g.dispose());
    _withNormals.set(geometry, g);
    made = g;
  }
  return made;
}
