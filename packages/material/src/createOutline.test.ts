import { ShadingMaterial } from '@shadelab/material';
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import {
  BackSide,
  BatchedMesh,
  Bone,
  Float32BufferAttribute,
  Group,
  IcosahedronGeometry,
  InstancedMesh,
  type Matrix3,
  Matrix4,
  Mesh,
  PerspectiveCamera,
  Scene,
  Skeleton,
  SkinnedMesh,
  Uint16BufferAttribute,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it } from 'vitest';

describe('createOutline / OutlineMaterial', () => {
  it('adds a back-face child sharing the geometry, with validated options', () => {
    const mesh = new Mesh(new IcosahedronGeometry(1, 2), new ShadingMaterial({ celBands: 3 }));
    const outline = createOutline(mesh, { thickness: 0.05, color: [1, 0, 0] });
    expect(outline.parent).toBe(mesh);
    expect(outline.geometry).toBe(mesh.geometry);
    expect(outline.material).toBeInstanceOf(OutlineMaterial);
    expect(outline.material.side).toBe(BackSide);
    expect(outline.material.thickness).toBe(0.05);
    expect(outline.material.uniforms.outlineColor.value.toArray()).toEqual([1, 0, 0]);
    expect(() => new OutlineMaterial({ thickness: -1 })).toThrow(
      new RangeError('OutlineMaterial.thickness must be a finite number ≥ 0, got -1'),
    );
    expect(() => new OutlineMaterial({ color: [Number.NaN, 0, 0] })).toThrow(/OutlineMaterial\.color/);
  });

  it('uses analytic normals on a flagged sphere without normals, and the robust normal matrix', () => {
    const geometry = new IcosahedronGeometry(1, 2);
    geometry.deleteAttribute('normal');
    geometry.userData.isSphere = true;
    const m = new OutlineMaterial();
    const mesh = new Mesh(geometry, m);
    mesh.scale.set(2, 1, 0);
    mesh.updateMatrixWorld();
    const version = m.version;
    m.onBeforeRender({} as WebGLRenderer, new Scene(), new PerspectiveCamera(), geometry, mesh, new Group());
    expect(m.defines).toEqual({ SPHERE_NORMALS: '' });
    expect(m.version).toBe(version + 1);
    const n: Matrix3 = m.uniforms.shadingNormalMatrix.value;
    expect(n.elements).toEqual([0, 0, 0, 0, 0, 0, 0, 0, 1]);
  });
});

describe('createOutline on deformed and instanced meshes', () => {
  it('makes a SkinnedMesh that reads the skeleton, bind mode and bind matrices of the mesh', () => {
    const geometry = new IcosahedronGeometry(1, 1);
    const count = geometry.getAttribute('position').count;
    geometry.setAttribute('skinIndex', new Uint16BufferAttribute(new Uint16Array(4 * count), 4));
    geometry.setAttribute(
      'skinWeight',
      new Float32BufferAttribute(new Float32Array(4 * count).fill(0.25), 4),
    );
    const mesh = new SkinnedMesh(geometry, new ShadingMaterial());
    const bone = new Bone();
    mesh.add(bone);
    mesh.bind(new Skeleton([bone]));
    const outline = createOutline(mesh) as unknown as SkinnedMesh;
    expect(outline).toBeInstanceOf(SkinnedMesh);
    expect(outline.skeleton).toBe(mesh.skeleton);
    expect(outline.bindMatrix).toBe(mesh.bindMatrix);
    expect(outline.bindMatrixInverse).toBe(mesh.bindMatrixInverse);
    const skeleton = new Skeleton([bone]);
    mesh.bind(skeleton); // rebinding the mesh rebinds its outline
    expect(outline.skeleton).toBe(skeleton);
    expect(outline.boundingSphere).toBe(mesh.boundingSphere);
    expect(outline.boundingSphere).not.toBeNull();
  });

  it('makes an InstancedMesh that reads the instance matrices, count, morph weights and culling sphere', () => {
    const mesh = new InstancedMesh(new IcosahedronGeometry(1, 1), new ShadingMaterial(), 3);
    mesh.setMatrixAt(2, new Matrix4().makeTranslation(5, 0, 0));
    const outline = createOutline(mesh) as unknown as InstancedMesh;
    expect(outline).toBeInstanceOf(InstancedMesh);
    expect(outline.instanceMatrix).toBe(mesh.instanceMatrix);
    expect(outline.instanceColor).toBeNull();
    // three culls an instanced object with its own sphere: the outline's is the mesh's, computed on demand.
    expect(mesh.boundingSphere).toBeNull();
    expect(outline.boundingSphere?.center.x).toBeCloseTo(2.5, 6);
    expect(outline.boundingSphere).toBe(mesh.boundingSphere);
    outline.computeBoundingSphere(); // three's own call on the object stays valid
    expect(outline.boundingSphere?.radius).toBeCloseTo(3.5, 6);
    mesh.count = 2;
    expect(outline.count).toBe(2);
  });

  it('reads the morph weights of the mesh, and is culled only when the mesh is', () => {
    const geometry = new IcosahedronGeometry(1, 1);
    geometry.morphAttributes.position = [geometry.getAttribute('position').clone()];
    const mesh = new Mesh(geometry, new ShadingMaterial());
    const outline = createOutline(mesh);
    expect(outline.morphTargetInfluences).toBe(mesh.morphTargetInfluences);
    mesh.morphTargetInfluences = [0.5];
    expect(outline.morphTargetInfluences).toEqual([0.5]);
    expect(outline.frustumCulled).toBe(true);
    mesh.frustumCulled = false;
    expect(outline.frustumCulled).toBe(false);
    mesh.frustumCulled = true;
    outline.frustumCulled = false;
    expect(outline.frustumCulled).toBe(false);
  });

  it('refuses a BatchedMesh with a TypeError naming it', () => {
    const batched = new BatchedMesh(1, 12, 0, new ShadingMaterial());
    expect(() => createOutline(batched as unknown as Mesh)).toThrow(
      new TypeError(
        'createOutline(mesh): mesh must be a Mesh, SkinnedMesh or InstancedMesh, got a BatchedMesh (not supported: outline each geometry with its own mesh)',
      ),
    );
  });
});
