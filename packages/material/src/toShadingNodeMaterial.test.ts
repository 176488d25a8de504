import { toShadingMaterial } from '@shadelab/material';
import { ShadingNodeMaterial, swapNodeMaterials, toShadingNodeMaterial } from '@shadelab/material/webgpu';
import {
  BoxGeometry,
  Color,
  DataTexture,
  DoubleSide,
  Group,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshPhongMaterial,
  MeshPhysicalMaterial,
  MeshStandardMaterial,
  MeshToonMaterial,
  Plane,
  ShaderMaterial,
} from 'three';
import { MeshStandardNodeMaterial } from 'three/webgpu';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

/** Whether this ShadingNodeMaterial takes three's surface options (emissive, map, ...). */
const takesEmissive = 'emissive' in new ShadingNodeMaterial();

let warn: ReturnType<typeof vi.spyOn>;
beforeEach(() => {
  warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
});
afterEach(() => {
  warn.mockRestore();
});

const lit = (): Material[] => {
  const colour = new Color(0.5, 0.25, 0.125);
  const gradientMap = new DataTexture(new Uint8Array(12), 3, 1);
  return [
    new MeshLambertMaterial({ color: colour, flatShading: true }),
    new MeshPhongMaterial({ color: colour, specular: 0x333333, shininess: 80 }),
    new MeshStandardMaterial({ color: colour, roughness: 0.3, metalness: 0.6 }),
    new MeshPhysicalMaterial({ color: colour, roughness: 0.7, ior: 1.8, specularIntensity: 0.5 }),
    new MeshToonMaterial({ color: colour, gradientMap }),
  ];
};

describe('toShadingNodeMaterial', () => {
  it('carries over what toShadingMaterial does, for every option ShadingNodeMaterial takes (one mapping)', () => {
    for (const source of lit()) {
      Object.assign(source, { side: DoubleSide, name: 'n', opacity: 0.5, transparent: true, alphaTest: 0.1 });
      source.clippingPlanes = [new Plane()];
      const node = toShadingNodeMaterial(source);
      const webgl = toShadingMaterial(source);
      expect(node).toBeInstanceOf(ShadingNodeMaterial);
      expect([node.shading, node.lighting, node.celBands, node.shininess]).toEqual([
        webgl.shading,
        webgl.lighting,
        webgl.celBands,
        webgl.shininess,
      ]);
      for (const k of ['ka', 'kd', 'ks'] as const) expect(node[k].equals(webgl[k])).toBe(true);
      expect([node.side, node.name, node.opacity, node.transparent, node.alphaTest]).toEqual([
        DoubleSide,
        'n',
        0.5,
        true,
        0.1,
      ]);
      expect(node.clippingPlanes).toBe(source.clippingPlanes);
    }
  });

  it('options override; bad ones throw naming the option', () => {
    const node = toShadingNodeMaterial(new MeshPhongMaterial(), { shading: 'gouraud', celBands: 3 });
    expect([node.shading, node.celBands]).toEqual(['gouraud', 3]);
    expect(() => toShadingNodeMaterial(new MeshPhongMaterial(), { celBands: 1 })).toThrow(
      /ShadingNodeMaterial\.celBands/,
    );
  });

  it('three’s node materials convert by the same flags', () => {
    const source = new MeshStandardNodeMaterial({ roughness: 0.5, metalness: 1 });
    source.color.setRGB(0.5, 0.5, 0.5);
    const node = toShadingNodeMaterial(source);
    const webgl = toShadingMaterial(
      new MeshStandardMaterial({ color: source.color, roughness: 0.5, metalness: 1 }),
    );
    expect(node.ks.equals(webgl.ks)).toBe(true);
    expect(node.shininess).toBe(webgl.shininess);
  });

  it('MeshBasic: drawn through emissive when the node material takes it, else refused (never black)', () => {
    const source = new MeshBasicMaterial({ color: 0x808080 });
    if (takesEmissive) {
      const node = toShadingNodeMaterial(source) as ShadingNodeMaterial & { emissive: Color };
      expect(node.emissive.equals(source.color)).toBe(true);
      for (const k of [node.ka, node.kd, node.ks]) expect(k.toArray()).toEqual([0, 0, 0]);
    } else {
      expect(() => toShadingNodeMaterial(source)).toThrow(
        /toShadingNodeMaterial: cannot convert material MeshBasicMaterial: an unlit material is drawn through emissive/,
      );
    }
  });

  it('refuses other kinds and what is not a Material', () => {
    expect(() => toShadingNodeMaterial(new ShaderMaterial())).toThrow(
      /material ShaderMaterial has its own shaders/,
    );
    expect(() => toShadingNodeMaterial({} as never)).toThrow(
      /toShadingNodeMaterial: material must be a THREE\.Material/,
    );
  });

  it('surface options: carried over exactly when the node material has them', () => {
    const map = new DataTexture(new Uint8Array(4), 1, 1);
    const node = toShadingNodeMaterial(new MeshLambertMaterial({ map })) as ShadingNodeMaterial & {
      map?: unknown;
    };
    expect(node.map).toBe(takesEmissive ? map : undefined);
  });
});

describe('swapNodeMaterials', () => {
  it('the same traversal: shared stays shared, MeshBasic skipped with the reason, restore puts back the originals', () => {
    const geometry = new BoxGeometry();
    const shared = new MeshPhongMaterial();
    const basic = new MeshBasicMaterial();
    const a = new Mesh(geometry, shared);
    const array = [shared, basic];
    const b = new Mesh(geometry, array);
    const shader = new ShaderMaterial();
    const c = new Mesh(geometry, shader);
    const swap = swapNodeMaterials(new Group().add(a, b, c), { shading: 'flat' });
    expect(a.material).toBeInstanceOf(ShadingNodeMaterial);
    expect((b.material as Material[])[0]).toBe(a.material);
    expect(swap.materials[0].shading).toBe('flat');
    if (takesEmissive) {
      expect((b.material as Material[])[1]).toBeInstanceOf(ShadingNodeMaterial);
      expect(swap.materials).toHaveLength(2);
      expect(swap.skipped.map((s) => s.material)).toEqual([shader]);
    } else {
      expect((b.material as Material[])[1]).toBe(basic);
      expect(swap.materials).toHaveLength(1);
      expect(swap.skipped.map((s) => s.material)).toEqual([basic, shader]);
      expect(swap.skipped[0].reason).toMatch(/drawn through emissive/);
    }
    expect(warn).toHaveBeenCalledTimes(1);
    swap.update({ lighting: 'phong' });
    expect(swap.materials[0].lighting).toBe('phong');
    expect(() => swap.update({ celBands: -1 })).toThrow(/ShadingNodeMaterial\.celBands/);
    const disposed = vi.fn();
    swap.materials[0].addEventListener('dispose', disposed);
    swap.restore();
    expect(a.material).toBe(shared);
    expect(b.material).toBe(array);
    expect(c.material).toBe(shader);
    expect(disposed).toHaveBeenCalledTimes(1);
    expect(() => swapNodeMaterials(null as never)).toThrow(
      /swapNodeMaterials: root must be a THREE\.Object3D/,
    );
  });
});
