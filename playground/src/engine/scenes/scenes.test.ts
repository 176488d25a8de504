import { ShadingMaterial } from '@shadelab/material';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { SCENES } from '../../state/schema';
import { createScene, SCENE_LABELS, SPHERE_ONLY_INPUTS, sceneNote } from './index';
import { FIELD } from './instanced';
import { bumpNormalTexture, checkerTexture, TEXTURE } from './textured';

const NAMES = ['instanced', 'skinned', 'textured', 'lights'] as const;

describe('the picker scenes', () => {
  it('label every scene and say what applies', () => {
    expect(Object.keys(SCENE_LABELS)).toEqual([...SCENES]);
    expect(new Set(Object.values(SCENE_LABELS)).size).toBe(SCENES.length);
    expect(sceneNote('sphere')).toMatch(/every option applies/);
    for (const name of NAMES) expect(sceneNote(name)).toMatch(/for the lecture’s sphere only/);
    for (const path of SPHERE_ONLY_INPUTS) expect(path.startsWith('Sphere.')).toBe(true);
  });

  for (const name of NAMES) {
    it(`${name}: every part is a ShadingMaterial mesh in the root, with an outline, and is freed`, () => {
      const scene = createScene(name);
      expect(scene.parts.length).toBeGreaterThan(0);
      for (const part of scene.parts) {
        expect(part.material).toBeInstanceOf(ShadingMaterial);
        expect(part.mesh.material).toBe(part.material);
        let inRoot = false;
        scene.root.traverse((o) => {
          inRoot ||= o === part.mesh;
        });
        expect(inRoot).toBe(true);
        expect(part.outline.parent).toBe(part.mesh);
        // Flat shading gets its own geometry, built once; the others share the mesh's.
        const shared = part.geometry('phong');
        expect(part.geometry('gouraud')).toBe(shared);
        const flat = part.geometry('flat');
        expect(flat).not.toBe(shared);
        expect(part.geometry('flat')).toBe(flat);
      }
      scene.dispose();
      for (const part of scene.parts) expect(part.outline.parent).toBeNull();
    });
  }

  it('instanced: the same field on every build, each instance tinted', () => {
    const a = createScene('instanced');
    const b = createScene('instanced');
    const mesh = a.parts[0]!.mesh as THREE.InstancedMesh;
    expect(mesh.count).toBe(FIELD.columns * FIELD.rows * FIELD.layers);
    expect(mesh.instanceColor).not.toBeNull();
    expect(Array.from(mesh.instanceMatrix.array).every(Number.isFinite)).toBe(true);
    const other = b.parts[0]!.mesh as THREE.InstancedMesh;
    expect(Array.from(other.instanceMatrix.array)).toEqual(Array.from(mesh.instanceMatrix.array));
    expect(Array.from(other.instanceColor!.array)).toEqual(Array.from(mesh.instanceColor!.array));
    a.dispose();
    b.dispose();
  });

  it('skinned: weights sum to 1 on existing bones; the morph has unit normals; flat keeps skin and morph', () => {
    const scene = createScene('skinned');
    const mesh = scene.parts[0]!.mesh as THREE.SkinnedMesh;
    expect(mesh.isSkinnedMesh).toBe(true);
    const bones = mesh.skeleton.bones.length;
    const index = mesh.geometry.getAttribute('skinIndex');
    const weight = mesh.geometry.getAttribute('skinWeight');
    for (let i = 0; i < index.count; i++) {
      expect(weight.getX(i) + weight.getY(i) + weight.getZ(i) + weight.getW(i)).toBeCloseTo(1, 6);
      for (const c of [index.getX(i), index.getY(i)]) expect(c).toBeLessThan(bones);
    }
    const normals = mesh.geometry.morphAttributes['normal']![0]!;
    for (let i = 0; i < normals.count; i++) {
      expect(Math.hypot(normals.getX(i), normals.getY(i), normals.getZ(i))).toBeCloseTo(1, 5);
    }
    expect(mesh.morphTargetInfluences).toEqual([1]);
    const flat = scene.parts[0]!.geometry('flat');
    expect(flat.getAttribute('skinIndex')).toBeDefined();
    expect(flat.getAttribute('skinWeight')).toBeDefined();
    expect(flat.morphAttributes['position']).toHaveLength(1);
    scene.dispose();
  });

  it('textured: the textures are the same texels on every build; the normal map holds unit normals facing out', () => {
    const { size } = TEXTURE;
    expect(checkerTexture().image.data).toEqual(checkerTexture().image.data);
    const normal = bumpNormalTexture();
    expect(normal.image.data).toEqual(bumpNormalTexture().image.data);
    const data = normal.image.data as Uint8Array;
    for (let i = 0; i < size * size; i++) {
      const [x, y, z] = [0, 1, 2].map((c) => (data[4 * i + c]! / 255) * 2 - 1) as [number, number, number];
      expect(Math.abs(Math.hypot(x, y, z) - 1)).toBeLessThan(0.02);
      expect(z).toBeGreaterThan(0.3);
    }
    const scene = createScene('textured');
    const material = scene.parts[0]!.material as unknown as { map: THREE.Texture; normalMap: THREE.Texture };
    expect(material.map).toBeInstanceOf(THREE.DataTexture);
    expect(material.map.colorSpace).toBe(THREE.SRGBColorSpace);
    expect(material.normalMap.colorSpace).toBe(THREE.NoColorSpace);
    // Flat shading draws a soup that keeps the uv.
    const flat = scene.parts[0]!.geometry('flat');
    expect(flat.index).toBeNull();
    expect(flat.getAttribute('uv').count).toBe(flat.getAttribute('position').count);
    scene.dispose();
  });

  it("lights: three's five lights in the root; fog, background and clipping while shown, put back after", () => {
    const scene = createScene('lights');
    const kinds = new Set<string>();
    scene.root.traverse((o) => {
      if ((o as THREE.Light).isLight) kinds.add(o.type);
    });
    expect([...kinds].sort()).toEqual([
      'AmbientLight',
      'DirectionalLight',
      'HemisphereLight',
      'PointLight',
      'SpotLight',
    ]);
    expect(scene.parts.some((p) => (p.material.clippingPlanes ?? []).length > 0)).toBe(true);
    const three = new THREE.Scene();
    const background = new THREE.Color(0);
    three.background = background;
    const renderer = { localClippingEnabled: false } as THREE.WebGLRenderer;
    scene.enter!(three, renderer);
    expect(three.fog).toBeInstanceOf(THREE.Fog);
    expect(three.background).not.toBe(background);
    expect(renderer.localClippingEnabled).toBe(true);
    scene.leave!(three, renderer);
    expect(three.fog).toBeNull();
    expect(three.background).toBe(background);
    expect(renderer.localClippingEnabled).toBe(false);
    scene.dispose();
  });
});
