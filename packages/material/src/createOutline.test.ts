import { ShadingMaterial } from '@shadelab/material';
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import {
  BackSide,
  Group,
  IcosahedronGeometry,
  type Matrix3,
  Mesh,
  PerspectiveCamera,
  Scene,
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
