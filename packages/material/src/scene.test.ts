// ShadingMaterial in any three.js scene (issue 14, phase 1), the parts that need no GPU: three's fog uniforms
// and flags, flat shading's data for skinned and morphed meshes, shade()'s tint and fogFactor() against three's
// own formulas. The pictures are tested in tests/material-scene.spec.ts.
import {
  FLAT_CORNER_INDEX,
  FLAT_CORNERS,
  flatShadingGeometry,
  fogFactor,
  PhongLight,
  type ShadeLight,
  type ShadeMaterial,
  ShadingMaterial,
  shade,
} from '@shadelab/material';
import { SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import fc from 'fast-check';
import {
  Bone,
  type BufferGeometry,
  CylinderGeometry,
  type DataTexture,
  Float32BufferAttribute,
  Group,
  InstancedMesh,
  MathUtils,
  Mesh,
  PerspectiveCamera,
  Plane,
  Scene,
  ShaderChunk,
  Skeleton,
  SkinnedMesh,
  Uint16BufferAttribute,
  UniformsLib,
  Vector3,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it } from 'vitest';
import { vertexShader } from './ShadingMaterial.glsl.js';

const renderer = {} as WebGLRenderer;

function draw(material: ShadingMaterial, mesh: Mesh): void {
  mesh.updateMatrixWorld();
  material.onBeforeRender(renderer, new Scene(), new PerspectiveCamera(), mesh.geometry, mesh, new Group());
}

/** A cylinder skinned to two bones (weights blend over |y| < 0.5), with one position morph target. */
function skinnedCylinder(): BufferGeometry {
  const g = new CylinderGeometry(0.5, 0.5, 3, 8, 4);
  const n = g.getAttribute('position').count;
  const index = new Uint16Array(4 * n);
  const weight = new Float32Array(4 * n);
  const morph = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) {
    const y = g.getAttribute('position').getY(i);
    const w = MathUtils.clamp(y + 0.5, 0, 1);
    index.set([0, 1, 0, 0], 4 * i);
    weight.set([1 - w, w, 0, 0], 4 * i);
    morph.set([0.1 * i, -0.2 * i, 0.3], 3 * i);
  }
  g.setAttribute('skinIndex', new Uint16BufferAttribute(index, 4));
  g.setAttribute('skinWeight', new Float32BufferAttribute(weight, 4));
  g.morphAttributes.position = [new Float32BufferAttribute(morph, 3)];
  g.morphTargetsRelative = true;
  return g;
}

describe('three.js scene features: defaults and uniforms', () => {
  it("fog, clipping and tone mapping default on like three's mesh materials, with three's fog uniforms", () => {
    const materials = [new ShadingMaterial(), new SphereImpostorMaterial(), new OutlineMaterial()];
    for (const m of materials) {
      expect([m.fog, m.clipping, m.toneMapped]).toEqual([true, true, true]);
      // three's refreshFogUniforms writes these (a ShaderMaterial without them threw a TypeError).
      for (const name of Object.keys(UniformsLib.fog)) expect(m.uniforms[name]?.value).toBeDefined();
      expect(m.uniforms.fogColor.value).not.toBe(UniformsLib.fog.fogColor.value); // a copy per material
      const clone = m.clone();
      expect([clone.fog, clone.clipping, clone.toneMapped]).toEqual([true, true, true]);
    }
    // The lecture's variant: nothing new in the defines.
    expect(new ShadingMaterial().defines).toEqual({ SHADING_PHONG: '', CEL_BANDS: 0, NUM_LIGHTS: 0 });
  });

  it("builds the vertex stage from three's chunks, meshphong's order: batching, morph, skinning, project, clip, fog", () => {
    const order = [
      'batching_vertex',
      'morphinstance_vertex',
      'skinbase_vertex',
      'morphtarget_vertex',
      'skinning_vertex',
      'project_vertex',
      'clipping_planes_vertex',
      'fog_vertex',
    ].map((chunk) => {
      expect(ShaderChunk[chunk as keyof typeof ShaderChunk], chunk).toBeDefined();
      return vertexShader.indexOf(`#include <${chunk}>`);
    });
    expect(order.every((at) => at > 0)).toBe(true);
    expect([...order].sort((a, b) => a - b)).toEqual(order);
  });

  it('createOutline shares the mesh material’s clipping planes', () => {
    const planes = [new Plane(new Vector3(1, 0, 0), 0)];
    const material = new ShadingMaterial();
    material.clippingPlanes = planes;
    material.clipIntersection = true;
    const outline = createOutline(new Mesh(new SubdivisionSphereGeometry({ level: 1 }), material));
    expect(outline.material.clippingPlanes).toBe(planes);
    expect(outline.material.clipIntersection).toBe(true);
    expect(createOutline(new Mesh(undefined, new ShadingMaterial())).material.clippingPlanes).toBeNull();
  });
});

describe('flat shading of skinned and morphed meshes', () => {
  it('flatShadingGeometry keeps skinIndex, skinWeight and morph targets, and gives each vertex its corners’ indices', () => {
    const source = skinnedCylinder();
    const out = flatShadingGeometry(source);
    const index = out.index!;
    const position = out.getAttribute('position');
    const cornerIndex = out.getAttribute(FLAT_CORNER_INDEX);
    const [a, b] = FLAT_CORNERS.map((name) => out.getAttribute(name));
    expect(cornerIndex.count).toBe(position.count);
    expect(out.morphTargetsRelative).toBe(true);
    const morph = out.morphAttributes.position![0];
    const sourceMorph = source.morphAttributes.position![0];
    // Every vertex is a copy of a source vertex: the one with its position (first occurrence).
    const origin = (i: number) => {
      for (let j = 0; j < source.getAttribute('position').count; j++) {
        const p = source.getAttribute('position');
        if (
          p.getX(j) === position.getX(i) &&
          p.getY(j) === position.getY(i) &&
          p.getZ(j) === position.getZ(i)
        )
          return j;
      }
      return -1;
    };
    for (let i = 0; i < position.count; i++) {
      const j = i < source.getAttribute('position').count ? i : origin(i);
      expect(j).toBeGreaterThanOrEqual(0);
      for (const name of ['skinIndex', 'skinWeight']) {
        expect([0, 1, 2, 3].map((c) => out.getAttribute(name).getComponent(i, c))).toEqual(
          [0, 1, 2, 3].map((c) => source.getAttribute(name).getComponent(j, c)),
        );
      }
      expect([morph.getX(i), morph.getY(i), morph.getZ(i)]).toEqual([
        sourceMorph.getX(j),
        sourceMorph.getY(j),
        sourceMorph.getZ(j),
      ]);
    }
    // The provoking vertex of each face names its other two corners, whose positions it carries.
    for (let k = 0; k < index.count; k += 3) {
      const last = index.getX(k + 2);
      expect([cornerIndex.getX(last), cornerIndex.getY(last)]).toEqual([index.getX(k), index.getX(k + 1)]);
      expect(a.getX(last)).toBe(position.getX(index.getX(k)));
      expect(b.getZ(last)).toBe(position.getZ(index.getX(k + 1)));
    }
  });

  it('a geometry that is neither skinned nor morphed gets no extra attribute (the lecture’s memory)', () => {
    const out = flatShadingGeometry(
      new SubdivisionSphereGeometry({ level: 3, indexed: true, normals: 'none' }),
    );
    expect(Object.keys(out.attributes).sort()).toEqual(['flatCornerA', 'flatCornerB', 'position']);
    expect(out.morphAttributes).toEqual({});
  });

  it('binds the skin texture for a SkinnedMesh and refuses a prepared geometry without corner indices', () => {
    const light = new PhongLight();
    const material = new ShadingMaterial({ shading: 'flat', lights: [light] });
    const geometry = skinnedCylinder();
    const mesh = new SkinnedMesh(geometry.toNonIndexed(), material);
    const bone = new Bone();
    mesh.add(bone);
    mesh.bind(new Skeleton([bone, new Bone()]));
    draw(material, mesh);
    const texture: DataTexture = material.uniforms.faceSkin.value;
    expect(texture.image.width).toBe(2048);
    // Vertex i: skinIndex at texel 2i, skinWeight at 2i + 1.
    const data = texture.image.data as Float32Array;
    const skinWeight = mesh.geometry.getAttribute('skinWeight');
    expect(Array.from(data.subarray(4 * 14, 4 * 15))).toEqual([0, 1, 0, 0]); // every vertex's skinIndex
    expect(Array.from(data.subarray(4 * 15, 4 * 16))).toEqual(
      [0, 1, 2, 3].map((c) => skinWeight.getComponent(7, c)),
    );
    // Not a SkinnedMesh: no skin texture.
    draw(material, new Mesh(geometry.toNonIndexed(), material));
    expect(material.uniforms.faceSkin.value).toBeNull();
    // An old-style prepared geometry (corners but no indices) cannot move its corners: it is drawn like a plain
    // indexed one, with the derivative face normal per fragment (no skin texture).
    const prepared = flatShadingGeometry(geometry);
    prepared.deleteAttribute(FLAT_CORNER_INDEX);
    const skinned = new SkinnedMesh(prepared, material);
    skinned.bind(new Skeleton([new Bone(), new Bone()]));
    draw(material, skinned);
    expect(material.defines.FLAT_DERIVATIVES).toBe('');
    expect(material.defines.FLAT_CORNERS).toBeUndefined();
    expect(material.uniforms.faceSkin.value).toBeNull();
    // An instanced mesh of a plain prepared sphere needs none.
    const sphere = flatShadingGeometry(
      new SubdivisionSphereGeometry({ level: 2, indexed: true, normals: 'none' }),
    );
    expect(() => draw(material, new InstancedMesh(sphere, material, 3))).not.toThrow();
    expect(material.defines.FLAT_CORNERS).toBe('');
  });
});

describe('shade() tint and fogFactor()', () => {
  const material: ShadeMaterial = {
    ka: [0.1, 0.2, 0.3],
    kd: [0.5, 0.4, 0.3],
    ks: [0.9, 0.8, 0.7],
    shininess: 8,
  };
  const light: ShadeLight = {
    position: [1, 2, 3],
    ambient: [0.2, 0.3, 0.4],
    diffuse: [1, 0.9, 0.8],
    specular: [0.7, 0.6, 0.5],
  };
  const sample = { position: [0, 0, 1], normal: [0.2, 0.3, 1], eye: [0, 0, 3, 1] };

  it('a tint multiplies ka and kd, never ks (as instanceColor does on the GPU); white changes nothing', () => {
    fc.assert(
      fc.property(
        fc.tuple(
          fc.double({ min: 0, max: 4, noNaN: true }),
          fc.double({ min: 0, max: 4, noNaN: true }),
          fc.double({ min: 0, max: 4, noNaN: true }),
        ),
        (tint) => {
          const tinted = shade({ ...sample, tint }, material, [light]);
          const diffuseAmbient = shade(sample, { ...material, ks: [0, 0, 0] }, [light]);
          const specular = shade(sample, { ...material, ka: [0, 0, 0], kd: [0, 0, 0] }, [light]);
          for (let c = 0; c < 3; c++)
            expect(tinted[c]).toBeCloseTo(tint[c] * diffuseAmbient[c] + specular[c], 12);
        },
      ),
    );
    expect(shade({ ...sample, tint: [1, 1, 1] }, material, [light])).toEqual(
      shade(sample, material, [light]),
    );
  });

  it("Fog is three's smoothstep(near, far, depth); near = far a step; FogExp2 is 1 − exp(−(density·depth)²)", () => {
    const smoothstep = (e0: number, e1: number, x: number) => {
      const t = MathUtils.clamp((x - e0) / (e1 - e0), 0, 1);
      return t * t * (3 - 2 * t);
    };
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 50, noNaN: true }),
        fc.double({ min: 0.01, max: 50, noNaN: true }),
        fc.double({ min: 0, max: 200, noNaN: true }),
        (near, span, depth) => {
          expect(fogFactor({ near, far: near + span }, depth)).toBeCloseTo(
            smoothstep(near, near + span, depth),
            12,
          );
          expect(fogFactor({ density: span }, depth)).toBeCloseTo(1 - Math.exp(-((span * depth) ** 2)), 12);
        },
      ),
    );
    // Extremes: finite, in 0 … 1.
    expect([1.9, 2, 2.1].map((d) => fogFactor({ near: 2, far: 2 }, d))).toEqual([0, 1, 1]);
    expect(fogFactor({ near: 3, far: 1 }, 2)).toBe(0);
    expect(fogFactor({ density: 0 }, 1e30)).toBe(0);
    expect(fogFactor({ density: 1e6 }, 0.5)).toBe(1);
    expect(fogFactor({ density: 1e6 }, 0)).toBe(0);
  });
});
