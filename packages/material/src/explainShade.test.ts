import {
  linearToSrgb8,
  type ShadeLight,
  type ShadeMaterial,
  type ShadeThreeLight,
  shade,
} from '@shadelab/material';
import { explainShade } from '@shadelab/material/explain';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';

const material: ShadeMaterial = {
  ka: [0.1, 0.2, 0.3],
  kd: [0.5, 0.4, 0.3],
  ks: [0.9, 0.8, 0.7],
  shininess: 8,
};
const light: ShadeLight = {
  position: [0, 0, 5],
  ambient: [0.2, 0.2, 0.2],
  diffuse: [1, 1, 1],
  specular: [0.8, 0.8, 0.8],
};

describe('explainShade: the lecture’s terms at a point', () => {
  it('head-on: l = v = n, r = n (Phong), each term as the lecture writes it', () => {
    const e = explainShade({ position: [0, 0, 1], normal: [0, 0, 2], eye: [0, 0, 3] }, material, [light]);
    const [x] = e.lights;
    expect(e.n).toEqual([0, 0, 1]);
    expect(x!.l).toEqual([0, 0, 1]);
    expect(x!.v).toEqual([0, 0, 1]);
    expect(x!.r).toEqual([0, 0, 1]);
    expect(x!.h).toBeNull();
    expect(x!.t).toBe(4);
    expect(x!.attenuation).toBe(1);
    expect(x!.ambient).toEqual([0.1 * 0.2, 0.2 * 0.2, 0.3 * 0.2]);
    expect(x!.diffuse).toEqual([0.5, 0.4, 0.3]);
    expect(x!.specular[0]).toBeCloseTo(0.9 * 0.8, 15);
    expect(e.sum).toEqual(
      shade({ position: [0, 0, 1], normal: [0, 0, 2], eye: [0, 0, 3] }, material, [light]),
    );
    expect(e.srgb8).toEqual(linearToSrgb8(e.sum));
    expect(e.clamped).toEqual(e.sum.map((c) => Math.min(c, 1)));
  });

  it('Blinn-Phong: h = (l + v)/|l + v| and the cosine is n·h; attenuation 1/(a + b·t + c·t²)', () => {
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [3, 0, 3] };
    const attenuated = { ...light, position: [-3, 0, 3], attenuation: { a: 1, b: 0.5, c: 0.25 } };
    const e = explainShade(sample, { ...material, lighting: 'blinn-phong' }, [attenuated]);
    const [x] = e.lights;
    const t = Math.hypot(3, 3);
    expect(x!.t).toBeCloseTo(t, 14);
    expect(x!.attenuation).toBeCloseTo(1 / (1 + 0.5 * t + 0.25 * t * t), 14);
    expect(x!.r).toBeNull();
    expect(x!.h![0]).toBeCloseTo(0, 14);
    expect(x!.h![2]).toBeCloseTo(1, 14);
    expect(x!.cosine).toBeCloseTo(1, 14);
  });

  it('cel: the band of max(l·n, 0) and the hard highlight', () => {
    // l·n = cos 60° = 0.5 with 4 bands: band 2, diffuse 2/3.
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 1] };
    const side = { ...light, position: [Math.sqrt(3), 0, 1] };
    const e = explainShade(sample, { ...material, celBands: 4 }, [side]);
    expect(e.lights[0]!.band).toBe(2);
    expect(e.lights[0]!.diffuseFactor).toBeCloseTo(2 / 3, 15);
    expect([0, 1]).toContain(e.lights[0]!.specularFactor);
    expect(explainShade(sample, material, [side]).lights[0]!.band).toBeNull();
  });

  it("three's lights: ambient and hemisphere give only ka·Ia (Ia = irradiance/π); Id = colour/π", () => {
    const sample = { position: [0, 0, 0], normal: [0, 1, 0], eye: [0, 0, 2] };
    const lights: ShadeThreeLight[] = [
      { type: 'ambient', color: [Math.PI, Math.PI, Math.PI] },
      { type: 'hemisphere', color: [Math.PI, 0, 0], groundColor: [0, 0, Math.PI], direction: [0, 1, 0] },
      { type: 'directional', color: [Math.PI, Math.PI, Math.PI], direction: [0, 1, 0] },
      {
        type: 'spot',
        color: [1, 1, 1],
        position: [0, 2, 0],
        direction: [0, 1, 0],
        coneCos: 0.9,
        penumbraCos: 0.95,
      },
    ];
    const e = explainShade(sample, material, lights);
    expect(e.lights.map((l) => l.kind)).toEqual(['ambient', 'hemisphere', 'directional', 'spot']);
    expect(e.lights[0]!.ia[0]).toBeCloseTo(1, 15);
    expect(e.lights[0]!.l).toBeNull();
    expect(e.lights[1]!.ia[0]).toBeCloseTo(1, 15);
    expect(e.lights[1]!.ia[2]).toBe(0);
    expect(e.lights[2]!.id[0]).toBeCloseTo(1, 15);
    expect(e.lights[2]!.t).toBeNull();
    expect(e.lights[2]!.diffuse[0]).toBeCloseTo(0.5, 14);
    expect(e.lights[3]!.t).toBe(2);
    expect(e.lights[3]!.attenuation).toBeCloseTo(1 / 4, 14); // 1/t², the point inside the cone
    expect(e.sum).toEqual(shade(sample, material, lights));
  });

  it('degenerate inputs follow shade(): a light at the point lights it head-on, a zero normal is v', () => {
    const e = explainShade({ position: [0, 0, 5], normal: [0, 0, 0], eye: [0, 3, 5] }, material, [light]);
    expect(e.n).toEqual([0, 1, 0]);
    expect(e.lights[0]!.l).toEqual([0, 1, 0]);
    expect(e.lights[0]!.t).toBe(0);
  });

  it('refuses a bad sample or lights, naming the parameter', () => {
    expect(() => explainShade({ position: [0, 0], normal: [0, 0, 1], eye: [0, 0, 1] }, material, [])).toThrow(
      /sample\.position/,
    );
    expect(() =>
      explainShade({ position: [0, 0, 0], normal: [0, Number.NaN, 1], eye: [0, 0, 1] }, material, []),
    ).toThrow(RangeError);
    expect(() =>
      explainShade({ position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 1] }, material, null as never),
    ).toThrow(/lights/);
  });

  it('sum equals shade() exactly and the terms add up to it (property, fixed seed)', () => {
    const num = (lo: number, hi: number) => fc.double({ min: lo, max: hi, noNaN: true });
    const vec = (lo: number, hi: number) => fc.tuple(num(lo, hi), num(lo, hi), num(lo, hi));
    const phong = fc.record({
      position: vec(-10, 10),
      ambient: vec(0, 2),
      diffuse: vec(0, 2),
      specular: vec(0, 2),
      attenuation: fc.option(fc.record({ a: num(0, 4), b: num(0, 4), c: num(0, 4) }), { nil: undefined }),
    });
    const three = fc.oneof(
      fc.record({ type: fc.constant('ambient' as const), color: vec(0, 3) }),
      fc.record({
        type: fc.constant('hemisphere' as const),
        color: vec(0, 3),
        groundColor: vec(0, 3),
        direction: vec(-1, 1),
      }),
      fc.record({ type: fc.constant('directional' as const), color: vec(0, 3), direction: vec(-1, 1) }),
      fc.record({
        type: fc.constant('point' as const),
        color: vec(0, 3),
        position: vec(-10, 10),
        distance: num(0, 20),
        decay: num(0, 3),
      }),
      fc.record({
        type: fc.constant('spot' as const),
        color: vec(0, 3),
        position: vec(-10, 10),
        direction: vec(-1, 1),
        coneCos: num(0, 1),
        penumbraCos: num(0, 1),
      }),
    );
    const mat = fc.record({
      ka: vec(0, 1),
      kd: vec(0, 1),
      ks: vec(0, 1),
      shininess: num(0, 200),
      lighting: fc.constantFrom('phong' as const, 'blinn-phong' as const),
      celBands: fc.constantFrom(0, 2, 3, 5),
      emissive: fc.option(vec(0, 0.5), { nil: undefined }),
    });
    const sample = fc.record({
      position: vec(-5, 5),
      normal: vec(-1, 1),
      eye: fc.oneof(vec(-10, 10), fc.tuple(num(-1, 1), num(-1, 1), num(-1, 1), fc.constantFrom(0, 1))),
      tint: fc.option(vec(0, 1), { nil: undefined }),
    });
    fc.assert(
      fc.property(sample, mat, fc.array(fc.oneof(phong, three), { maxLength: 4 }), (s, m, lights) => {
        const e = explainShade(s, m, lights);
        expect(e.sum).toEqual(shade(s, m, lights));
        expect(e.srgb8).toEqual(linearToSrgb8(shade(s, m, lights)));
        const total = [0, 1, 2].map(
          (k) =>
            e.emissive[k]! +
            e.lights.reduce((acc, l) => acc + l.ambient[k]! + l.diffuse[k]! + l.specular[k]!, 0),
        );
        for (let k = 0; k < 3; k++) expect(total[k]).toBeCloseTo(e.sum[k]!, 9);
        for (const l of e.lights) {
          if (l.r && l.kind !== 'directional') expect(Math.hypot(...l.r)).toBeCloseTo(1, 9);
          if (l.band !== null) expect(l.band).toBeLessThan(m.celBands);
        }
      }),
      { numRuns: 300 },
    );
  });
});
