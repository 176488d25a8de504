import { linearToSrgb8, PhongLight, ShadingMaterial, shade } from '@shadelab/material';
import { explainShade } from '@shadelab/material/explain';
import fc from 'fast-check';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { outputOf } from './probeInputs';
import {
  barycentric,
  blend,
  devicePixelOf,
  displayed8,
  maxChannelDifference,
  ndcOfPixel,
  nearCelEdge,
  pixelOfNdc,
  raw8,
  type V3,
} from './probeMath';
import { pixelOfFollowed, probePixel } from './probePick';

const finite = (lo: number, hi: number) => fc.double({ min: lo, max: hi, noNaN: true });
const point = fc.tuple(finite(-10, 10), finite(-10, 10), finite(-10, 10));

describe('probe arithmetic', () => {
  it('barycentric weights sum to 1 and rebuild the point (property, fixed seed)', () => {
    fc.assert(
      fc.property(point, point, point, finite(0, 1), finite(0, 1), (a, b, c, s, t) => {
        const area = new THREE.Vector3(...b).sub(new THREE.Vector3(...a));
        area.cross(new THREE.Vector3(...c).sub(new THREE.Vector3(...a)));
        fc.pre(area.length() > 1e-3);
        const [u, v] = s + t > 1 ? [1 - s, 1 - t] : [s, t];
        const p = [0, 1, 2].map((k) => a[k]! + u * (b[k]! - a[k]!) + v * (c[k]! - a[k]!));
        const w = barycentric(p, a, b, c);
        expect(w[0] + w[1] + w[2]).toBeCloseTo(1, 9);
        expect(w[1]).toBeCloseTo(u, 6);
        expect(w[2]).toBeCloseTo(v, 6);
        const rebuilt = blend([a, b, c], w);
        for (let k = 0; k < 3; k++) expect(rebuilt[k]).toBeCloseTo(p[k]!, 6);
      }),
    );
  });

  it('a degenerate triangle weighs its corners equally; the corners weigh 1', () => {
    expect(barycentric([0, 0, 0], [1, 1, 1], [1, 1, 1], [1, 1, 1])).toEqual([1 / 3, 1 / 3, 1 / 3]);
    expect(barycentric([0, 1, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1])).toEqual([0, 1, 0]);
  });

  it('client → device pixel → NDC of its centre → the same pixel; outside the canvas is null', () => {
    const rect = { left: 10, top: 20, width: 400, height: 300 };
    expect(devicePixelOf(10, 20, rect, 800, 600)).toEqual([0, 0]);
    expect(devicePixelOf(409.9, 319.9, rect, 800, 600)).toEqual([799, 599]);
    expect(devicePixelOf(9, 20, rect, 800, 600)).toBeNull();
    expect(devicePixelOf(410, 20, rect, 800, 600)).toBeNull();
    expect(ndcOfPixel(0, 0, 2, 2)).toEqual([-0.5, 0.5]);
    for (const [x, y] of [
      [0, 0],
      [799, 599],
      [400, 17],
    ] as const) {
      const [nx, ny] = ndcOfPixel(x, y, 800, 600);
      expect(pixelOfNdc(nx, ny, 800, 600)).toEqual([x, y]);
    }
    expect(pixelOfNdc(1.01, 0, 800, 600)).toBeNull();
  });

  it('the displayed colour is linearToSrgb8 without fog, the fog colour with fog factor 1', () => {
    const c: V3 = [0.2, 1.7, -0.1];
    expect(displayed8(c)).toEqual(linearToSrgb8(c));
    expect(displayed8(c, { color: [0, 0, 1], factor: 1 })).toEqual([0, 0, 255]);
    expect(maxChannelDifference([1, 2, 3], [3, 2, 1])).toBe(2);
    expect(raw8([0.5, -1, 2])).toEqual([128, 0, 255]); // a term view's data, written as is
  });

  it('the term views: ambient + diffuse + specular = the sum, the mean attenuation, the packed view normal', () => {
    const e = explainShade(
      { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 3] },
      { ka: [0.1, 0.2, 0.3], kd: [0.5, 0.4, 0.3], ks: [0.9, 0.8, 0.7], shininess: 8 },
      [
        { position: [1, 1, 2], ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [1, 1, 1] },
        {
          position: [0, 0, 4],
          ambient: [0, 0, 0],
          diffuse: [1, 1, 1],
          specular: [1, 1, 1],
          attenuation: { a: 1, b: 1, c: 0 },
        },
      ],
    );
    const view = new THREE.Matrix4();
    const terms = (['ambient', 'diffuse', 'specular'] as const).map((o) => outputOf(e, o, view));
    for (let k = 0; k < 3; k++)
      expect(terms[0]![k]! + terms[1]![k]! + terms[2]![k]!).toBeCloseTo(e.sum[k]!, 12);
    expect(outputOf(e, 'attenuation', view)).toEqual([0.6, 0.6, 0.6].map(() => (1 + 1 / 5) / 2));
    expect(outputOf(e, 'normal', view)).toEqual([0.5, 0.5, 1]);
    expect(outputOf(e, 'color', view)).toBe(e.sum);
  });
});

describe('probePixel (three.js scene, no renderer)', () => {
  function scene(shading: 'flat' | 'gouraud' | 'phong') {
    const root = new THREE.Scene();
    const material = new ShadingMaterial({ shading, lighting: 'blinn-phong' });
    const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
    light.position.set(-5, 10, 20);
    root.add(light);
    material.phongLights = [light];
    const geometry = new THREE.IcosahedronGeometry(1, 2);
    geometry.deleteAttribute('normal'); // analytic sphere normals, as the playground's sphere
    const mesh = new THREE.Mesh(geometry, material);
    mesh.name = 'sphere';
    mesh.scale.set(2, 1, 2);
    root.add(mesh);
    const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
    camera.position.set(0, 0, 3);
    root.updateMatrixWorld(true);
    camera.updateMatrixWorld(true);
    return { root, camera, mesh, light };
  }

  it('Phong shading: lit at the ray’s hit point, its sum = shade() there', () => {
    const { root, camera, light } = scene('phong');
    const hit = probePixel(root, camera, 120, 90, 200, 200);
    if (!hit.hit) throw new Error(hit.reason);
    const eye = [0, 0, 3, 1];
    const lights = [
      {
        position: light.position.toArray(),
        ambient: light.ambient.toArray(),
        diffuse: light.diffuse.toArray(),
        specular: light.specular.toArray(),
      },
    ];
    const material = {
      ka: hit.material.ka.toArray(),
      kd: hit.material.kd.toArray(),
      ks: hit.material.ks.toArray(),
      shininess: hit.material.shininess,
      lighting: 'blinn-phong' as const,
    };
    expect(hit.linear).toEqual(
      shade({ position: hit.point, normal: hit.explanation.n, eye }, material, lights),
    );
    expect(hit.at).toEqual(hit.point);
    expect(hit.srgb8).toEqual(linearToSrgb8(hit.linear));
    // On the ellipsoid (x/2)² + y² + (z/2)² = 1, the analytic normal is close to the gradient (the mesh's facets).
    const [x, y, z] = hit.point;
    const gradient = new THREE.Vector3(x / 4, y, z / 4).normalize();
    expect(gradient.dot(new THREE.Vector3(...hit.explanation.n))).toBeGreaterThan(0.99);
  });

  it('Gouraud: the vertices’ colours blended by the barycentric weights; flat: the centroid with the face normal', () => {
    const gouraud = probePixel(...sceneArgs('gouraud'));
    if (!gouraud.hit || !gouraud.gouraud) throw new Error('no Gouraud hit');
    const { vertices, weights } = gouraud.gouraud;
    expect(weights.reduce((s, w) => s + w, 0)).toBeCloseTo(1, 12);
    for (let k = 0; k < 3; k++) {
      expect(gouraud.linear[k]).toBeCloseTo(
        vertices.reduce((s, v, i) => s + weights[i]! * v.color[k]!, 0),
        12,
      );
    }
    const flat = probePixel(...sceneArgs('flat'));
    if (!flat.hit || !flat.flat) throw new Error('no flat hit');
    expect(flat.at).toEqual(flat.flat.centroid);
    expect(flat.explanation.n).toEqual(flat.flat.normal);
  });

  it('off the object: a miss that says so; a followed point projects back onto its pixel', () => {
    const { root, camera, mesh } = scene('phong');
    const miss = probePixel(root, camera, 0, 0, 200, 200);
    expect(miss.hit).toBe(false);
    if (!miss.hit) expect(miss.reason).toMatch(/off the object/);
    const hit = probePixel(root, camera, 77, 131, 200, 200);
    if (!hit.hit) throw new Error('no hit');
    expect(pixelOfFollowed(camera, mesh, null, hit.local, 200, 200)).toEqual([77, 131]);
  });

  function sceneArgs(shading: 'flat' | 'gouraud') {
    const { root, camera } = scene(shading);
    return [root, camera, 100, 100, 200, 200] as const;
  }
});

describe('nearCelEdge', () => {
  const lit = (lDotN: number, cosine: number) =>
    ({ lights: [{ lDotN, cosine }] }) as unknown as Parameters<typeof nearCelEdge>[0];
  it('flags max(l·n, 0)·N at an inner band threshold and a highlight power at 0.5, nothing else', () => {
    expect(nearCelEdge(lit(0.5 + 1e-4, 0), 4, 32)).toBe(true); // 0.5 · 4 = 2: the edge of bands 1 and 2
    expect(nearCelEdge(lit(0.6, 0), 4, 32)).toBe(false);
    expect(nearCelEdge(lit(1, 0), 4, 32)).toBe(false); // the top is no threshold
    expect(nearCelEdge(lit(0.6, 0.5 ** (1 / 32)), 4, 32)).toBe(true); // power 0.5
    expect(nearCelEdge(lit(0.6, 0.9), 4, 32)).toBe(false);
    expect(nearCelEdge(lit(0.5, 0), 0, 32)).toBe(false); // cel off
  });
});
