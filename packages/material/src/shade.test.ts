import {
  celDiffuse,
  celSpecular,
  linearToSrgb8,
  linearToSrgb8Channel,
  type ShadeLight,
  type ShadeMaterial,
  shade,
  specularPower,
  threeDistanceFalloff,
} from '@shadelab/material';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';

const S2 = Math.SQRT1_2;

const material: ShadeMaterial = {
  ka: [0.1, 0.2, 0.3],
  kd: [0.5, 0.4, 0.3],
  ks: [0.9, 0.8, 0.7],
  shininess: 2,
};
const white = (position: number[]): ShadeLight => ({
  position,
  ambient: [0.2, 0.2, 0.2],
  diffuse: [1, 1, 1],
  specular: [0.8, 0.8, 0.8],
});

function expectClose(actual: ArrayLike<number>, expected: ArrayLike<number>, digits = 12): void {
  expect(actual.length).toBe(expected.length);
  for (let i = 0; i < expected.length; i++) expect(actual[i]).toBeCloseTo(expected[i], digits);
}

/** I = ka·Ia + att·(kd·Id·diffuse + ks·Is·spec), channel by channel, for the `white` light. */
function expected(m: ShadeMaterial, diffuse: number, spec: number, att = 1): number[] {
  return [0, 1, 2].map((i) => m.ka[i] * 0.2 + att * (m.kd[i] * diffuse + m.ks[i] * 0.8 * spec));
}

describe('shade: the lecture’s lighting equation', () => {
  it('light, eye and normal aligned: full diffuse and specular (Phong and Blinn-Phong agree)', () => {
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 5, 1] };
    expectClose(shade(sample, material, [white([0, 0, 10])]), expected(material, 1, 1));
    expectClose(
      shade(sample, { ...material, lighting: 'blinn-phong' }, [white([0, 0, 10])]),
      expected(material, 1, 1),
    );
  });

  it('Phong uses r = 2(l·n)n − l, Blinn-Phong h = normalize(l + v): light at 45°, eye on the normal', () => {
    // l = (1, 0, 1)/√2, n = v = +z: l·n = cos 45°; v·r = cos 45°; n·h = cos 22.5°.
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 3, 1] };
    const lights = [white([4, 0, 4])];
    expectClose(shade(sample, material, lights), expected(material, S2, S2 ** 2));
    const cos225 = Math.cos(Math.PI / 8);
    expectClose(
      shade(sample, { ...material, lighting: 'blinn-phong' }, lights),
      expected(material, S2, cos225 ** 2),
    );
    // (1 + cos 45°)/2 = cos² 22.5°: the classic Blinn-Phong half-angle relation.
    expect(cos225 ** 2).toBeCloseTo((1 + S2) / 2, 14);
  });

  it('the normal is normalised and the position matters (point light, perspective eye)', () => {
    const sample = { position: [1, 2, 3], normal: [0, 10, 0], eye: [1, 7, 3, 1] };
    // l = (0, 1, 0) from (1, 5, 3): straight above; eye straight above too.
    expectClose(shade(sample, material, [white([1, 5, 3])]), expected(material, 1, 1));
  });

  it('an orthographic eye (w = 0) is a constant direction towards the viewer', () => {
    const normal = [0, 0, 1];
    const lights = [white([0, 0, 100])];
    const a = shade({ position: [0, 0, 0], normal, eye: [S2, 0, S2, 0] }, material, lights);
    const b = shade({ position: [50, -20, 3], normal, eye: [S2, 0, S2, 0] }, material, lights);
    // v = (1, 0, 1)/√2 everywhere; l ≈ +z: v·r = v·n = cos 45° at the origin.
    expectClose(a, expected(material, 1, 0.5));
    expect(b[0]).not.toBeCloseTo(a[0], 3); // l differs at the other point, not v
    const perspective = shade({ position: [0, 0, 0], normal, eye: [S2, 0, S2, 1] }, material, lights);
    expectClose(perspective, a); // same v at the origin when the eye point lies on that direction
  });

  it('no highlight on the unlit side (l·n ≤ 0), even where v·r > 0', () => {
    // Light below the surface; v = −l mirrored so that v·r = 1 for the naive formula.
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [-3, 0, -4, 1] };
    const out = shade(sample, material, [white([3, 0, -4])]);
    expectClose(out, expected(material, 0, 0));
  });

  it('attenuation 1/(a + b·t + c·t²) scales diffuse and specular, never ambient', () => {
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 5, 1] };
    const light = { ...white([0, 0, 2]), attenuation: { a: 1, b: 0.5, c: 0.25 } }; // 1 + 1 + 1 = 3
    expectClose(shade(sample, material, [light]), expected(material, 1, 1, 1 / 3));
  });

  it('several lights are summed', () => {
    const sample = { position: [0.3, -0.2, 0.1], normal: [0.2, 0.3, 1], eye: [0, 0, 4, 1] };
    const a = { ...white([-5, 10, 20]), attenuation: { a: 1, b: 0.1, c: 0.01 } };
    const b: ShadeLight = {
      position: [7, -3, 2],
      ambient: [0.1, 0, 0.05],
      diffuse: [0.3, 0.6, 0.9],
      specular: [1, 0.5, 0],
    };
    const both = shade(sample, material, [a, b]);
    const sum = shade(sample, material, [a]).map((x, i) => x + shade(sample, material, [b])[i]);
    expectClose(both, sum, 14);
    expectClose(shade(sample, material, []), [0, 0, 0]);
  });
});

describe('shade: extremes (docs/design.md material rows)', () => {
  const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 5, 1] };

  it('shininess 0: 0⁰ = 1, a uniform highlight over the lit side', () => {
    expect(specularPower(0, 0)).toBe(1);
    expect(specularPower(0.3, 0)).toBe(1);
    expect(specularPower(0, 2)).toBe(0);
    // v ⟂ r: v·r = 0, yet spec = 1 with shininess 0.
    const grazing = { position: [0, 0, 0], normal: [0, 0, 1], eye: [5, 0, 0, 1] };
    expectClose(shade(grazing, { ...material, shininess: 0 }, [white([0, 0, 10])]), expected(material, 1, 1));
  });

  it('shininess 10⁴: finite, 1 in the mirror direction, ≈ 0 a few degrees off', () => {
    const m = { ...material, shininess: 1e4 };
    expectClose(shade(sample, m, [white([0, 0, 10])]), expected(material, 1, 1));
    // l at 0.1 rad from n, so r at 0.1 rad from v: cos(0.1)^10⁴ ≈ e⁻⁵⁰.
    const off = shade(sample, m, [white([Math.tan(0.1) * 10, 0, 10])]);
    expect(off.every(Number.isFinite)).toBe(true);
    expectClose(off, expected(material, Math.cos(0.1), Math.cos(0.1) ** 1e4), 14);
    expect(Math.cos(0.1) ** 1e4).toBeLessThan(1e-21);
  });

  it('ks = 0 removes the highlight, kd = 0 the diffuse term', () => {
    const lights = [white([0, 0, 10])];
    expectClose(
      shade(sample, { ...material, ks: [0, 0, 0] }, lights),
      expected({ ...material, ks: [0, 0, 0] }, 1, 1),
    );
    expectClose(
      shade(sample, { ...material, kd: [0, 0, 0] }, lights),
      expected({ ...material, kd: [0, 0, 0] }, 1, 1),
    );
  });

  it('a light at the surface (t = 0) lights it head-on, finite even with a = 0', () => {
    const atSurface = white([0, 0, 0]);
    expectClose(shade(sample, material, [atSurface]), expected(material, 1, 1));
    const out = shade(sample, material, [{ ...atSurface, attenuation: { a: 0, b: 1, c: 1 } }]);
    expect(out.every(Number.isFinite)).toBe(true);
    expectClose(out, expected(material, 1, 1, 1e6), 4); // denominator clamped at 1e-6
  });

  it('zero normal falls back to the view direction, eye at the point to the normal', () => {
    const zero = shade({ position: [0, 0, 0], normal: [0, 0, 0], eye: [0, 0, 5, 1] }, material, [
      white([0, 0, 10]),
    ]);
    expectClose(zero, expected(material, 1, 1));
    const eyeAtPoint = shade({ position: [1, 1, 1], normal: [0, 0, 1], eye: [1, 1, 1, 1] }, material, [
      white([1, 1, 9]),
    ]);
    expectClose(eyeAtPoint, expected(material, 1, 1));
    const both = shade({ position: [1, 1, 1], normal: [0, 0, 0], eye: [1, 1, 1, 1] }, material, [
      white([1, 1, 1]),
    ]);
    expect(both.every(Number.isFinite)).toBe(true);
  });
});

describe('cel shading', () => {
  it('N bands: min(⌊cos·N⌋, N−1)/(N−1), and a hard highlight at 0.5', () => {
    expect([0, 0.2, 0.34, 0.5, 0.66, 0.67, 1].map((c) => celDiffuse(c, 3))).toEqual([
      0, 0, 0.5, 0.5, 0.5, 1, 1,
    ]);
    expect([0, 0.49, 0.5, 1].map(celSpecular)).toEqual([0, 0, 1, 1]);
  });

  it('shade() with celBands takes only N diffuse values and a 0/1 highlight', () => {
    const bands = 4;
    const m = { ...material, celBands: bands, shininess: 8 };
    const seen = new Set<string>();
    for (let k = 0; k <= 200; k++) {
      const angle = (k / 200) * Math.PI;
      const normal = [Math.sin(angle), 0, Math.cos(angle)];
      const c = shade({ position: [0, 0, 0], normal, eye: [0, 0, 1, 0] }, { ...m, ks: [0, 0, 0] }, [
        white([0, 0, 1e6]),
      ]);
      seen.add(((c[0] - 0.1 * 0.2) / 0.5).toFixed(9));
    }
    expect([...seen].map(Number).sort()).toEqual([0, 1 / 3, 2 / 3, 1].map((x) => Number(x.toFixed(9))));
  });
});

describe('linearToSrgb8', () => {
  it('matches the sRGB transfer function at known codes', () => {
    expect(linearToSrgb8([0, 1, 0.5])).toEqual([0, 255, 188]);
    expect(linearToSrgb8Channel(0.0031308)).toBe(Math.round(0.0031308 * 12.92 * 255));
    expect(linearToSrgb8([2, -1, Number.NaN])).toEqual([255, 0, 0]);
    // Every code round-trips through the inverse transfer function (the sRGB EOTF).
    for (let k = 0; k <= 255; k++) {
      const v = k / 255;
      const linear = v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
      expect(linearToSrgb8Channel(linear)).toBe(k);
    }
  });
});

describe('shade: properties', () => {
  const vec = (lo: number, hi: number) =>
    fc.tuple(
      fc.double({ min: lo, max: hi, noNaN: true }),
      fc.double({ min: lo, max: hi, noNaN: true }),
      fc.double({ min: lo, max: hi, noNaN: true }),
    );
  const light = fc.record({
    position: vec(-100, 100),
    ambient: vec(0, 1),
    diffuse: vec(0, 1),
    specular: vec(0, 1),
    attenuation: fc.record({
      a: fc.double({ min: 0, max: 10, noNaN: true }),
      b: fc.double({ min: 0, max: 10, noNaN: true }),
      c: fc.double({ min: 0, max: 10, noNaN: true }),
    }),
  });
  const mat = fc.record({
    ka: vec(0, 1),
    kd: vec(0, 1),
    ks: vec(0, 1),
    shininess: fc.double({ min: 0, max: 1e4, noNaN: true }),
    lighting: fc.constantFrom('phong' as const, 'blinn-phong' as const),
    celBands: fc.constantFrom(0, 2, 3, 5),
  });
  const sample = fc.record({
    position: vec(-10, 10),
    normal: vec(-1, 1),
    eye: fc.tuple(
      fc.double({ min: -20, max: 20, noNaN: true }),
      fc.double({ min: -20, max: 20, noNaN: true }),
      fc.double({ min: -20, max: 20, noNaN: true }),
      fc.constantFrom(0, 1),
    ),
  });

  it('finite, ≥ 0, and bounded by Σ ka·Ia + (kd·Id + ks·Is)/max(a + b·t + c·t², 1e-6)', () => {
    fc.assert(
      fc.property(sample, mat, fc.array(light, { maxLength: 4 }), (s, m, lights) => {
        const out = shade(s, m, lights);
        for (let i = 0; i < 3; i++) {
          let bound = 0;
          for (const l of lights) {
            const t = Math.hypot(
              l.position[0] - s.position[0],
              l.position[1] - s.position[1],
              l.position[2] - s.position[2],
            );
            const { a, b, c } = l.attenuation;
            const att = 1 / Math.max(a + b * t + c * t * t, 1e-6);
            bound += m.ka[i] * l.ambient[i] + att * (m.kd[i] * l.diffuse[i] + m.ks[i] * l.specular[i]);
          }
          expect(Number.isFinite(out[i])).toBe(true);
          expect(out[i]).toBeGreaterThanOrEqual(0);
          expect(out[i]).toBeLessThanOrEqual(bound * (1 + 1e-12) + 1e-300);
        }
      }),
    );
  });

  it('Blinn-Phong and Phong agree when l = v (then h = r = n-mirror of l… and n·h = v·r = 1 on the normal)', () => {
    fc.assert(
      fc.property(vec(-1, 1), fc.double({ min: 0, max: 200, noNaN: true }), (dir, shininess) => {
        const len = Math.hypot(...dir);
        fc.pre(len > 1e-3);
        const n = dir.map((x) => x / len);
        const s = { position: [0, 0, 0], normal: n, eye: [n[0] * 3, n[1] * 3, n[2] * 3, 1] };
        const lights = [white([n[0] * 7, n[1] * 7, n[2] * 7])];
        const a = shade(s, { ...material, shininess }, lights);
        const b = shade(s, { ...material, shininess, lighting: 'blinn-phong' }, lights);
        expectClose(a, b, 9);
      }),
    );
  });
});

describe("shade() with three's lights (Id = Is = colour × intensity / π, three's falloff, ambient as Ia)", () => {
  const PI = Math.PI;
  const m: ShadeMaterial = { ka: [0.5, 0.5, 0.5], kd: [0.4, 0.4, 0.4], ks: [0.2, 0.2, 0.2], shininess: 1 };
  const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 10] };

  it('ambient: ka·Ia with Ia = colour / π; hemisphere: three’s sky/ground blend by the normal, / π', () => {
    expectClose(shade(sample, m, [{ type: 'ambient', color: [0.2, 0.4, 0.6] }]), [
      0.1 / PI,
      0.2 / PI,
      0.3 / PI,
    ]);
    const hemi = { type: 'hemisphere', color: [1, 1, 1], groundColor: [0, 0, 0] } as const;
    // The normal along the sky direction: all sky; against it: all ground; across: half of each.
    expectClose(shade(sample, m, [{ ...hemi, direction: [0, 0, 1] }]), [0.5 / PI, 0.5 / PI, 0.5 / PI]);
    expectClose(shade(sample, m, [{ ...hemi, direction: [0, 0, -1] }]), [0, 0, 0]);
    expectClose(shade(sample, m, [{ ...hemi, direction: [0, 1, 0] }]), [0.25 / PI, 0.25 / PI, 0.25 / PI]);
  });

  it('directional: (kd·(l·n) + ks·(v·r)^α)·I/π, no falloff', () => {
    // l = (0, 0.6, 0.8): l·n = 0.8; r = (0, −0.6, 0.8), v = z: v·r = 0.8.
    const out = shade(sample, m, [{ type: 'directional', color: [2, 2, 2], direction: [0, 0.6, 0.8] }]);
    expectClose(
      out,
      [0, 1, 2].map(() => (2 * (0.4 * 0.8 + 0.2 * 0.8)) / PI),
    );
  });

  it('point: 1/t^decay, the cut-off window (1 − (t/distance)⁴)², 1/0.01 at most', () => {
    expect(threeDistanceFalloff(2, 0, 2)).toBe(0.25);
    expect(threeDistanceFalloff(2, 0, 0)).toBe(1);
    expect(threeDistanceFalloff(2, 4, 1)).toBeCloseTo(0.5 * (1 - 1 / 16) ** 2, 12);
    expect(threeDistanceFalloff(5, 4, 2)).toBe(0);
    expect(threeDistanceFalloff(0, 0, 2)).toBe(100);
    const out = shade(sample, m, [{ type: 'point', color: [1, 1, 1], position: [0, 0, 2], decay: 2 }]);
    // Head-on from 2 units: l·n = 1, v·r = 1: (0.4 + 0.2) / 4 / π.
    expectClose(out, [0.15 / PI, 0.15 / PI, 0.15 / PI]);
  });

  it('spot: the point falloff times smoothstep(coneCos, penumbraCos, l·direction)', () => {
    const spot = {
      type: 'spot',
      color: [1, 1, 1],
      position: [0, 0, 2],
      direction: [0, 0, 1],
      decay: 0,
      coneCos: Math.cos(0.5),
      penumbraCos: Math.cos(0.25),
    } as const;
    expectClose(shade(sample, m, [spot]), [0.6 / PI, 0.6 / PI, 0.6 / PI]); // on the axis: full
    const outside = { ...sample, position: [3, 0, 0] }; // 56° off the axis: dark
    expectClose(shade(outside, m, [spot]), [0, 0, 0]);
    // Between the cone and the penumbra: smoothstep of the cosine.
    const x = 2 * Math.tan(0.4);
    const l = [-x, 0, 2].map((c) => c / Math.hypot(x, 2));
    const cone = smoothstepRef(Math.cos(0.5), Math.cos(0.25), l[2]);
    const inPenumbra = shade({ ...sample, position: [x, 0, 0] }, { ...m, ks: [0, 0, 0] }, [spot]);
    expectClose(
      inPenumbra,
      [0, 1, 2].map(() => (cone * 0.4 * l[2]) / PI),
    );
    expect(cone).toBeGreaterThan(0.05);
    expect(cone).toBeLessThan(0.95);
  });

  it('three’s lights and PhongLights add up, tinted like instance colours, finite for a light at the point', () => {
    const lights = [white([0, 0, 5]), { type: 'point', color: [1, 1, 1], position: [0, 0, 0] } as const];
    const out = shade({ ...sample, tint: [1, 0.5, 0] }, m, lights);
    expect(out.every(Number.isFinite)).toBe(true);
    const phong = shade({ ...sample, tint: [1, 0.5, 0] }, m, [lights[0]]);
    // The point light at the point: head-on, falloff 1/0.01.
    expectClose(
      out.map((c, k) => c - phong[k]),
      [0, 1, 2].map((k) => (100 * (0.4 * [1, 0.5, 0][k] + 0.2)) / PI),
      9,
    );
  });
});

describe('shade() under three’s lights is three’s Lambert (the drop-in mapping)', () => {
  it('a PhongLight with Id = Is = 1 lights like a PointLight of intensity π with decay 0 (the documented equivalence)', () => {
    const m: ShadeMaterial = { ka: [0.3, 0.3, 0.3], kd: [0.6, 0.4, 0.2], ks: [0.5, 0.5, 0.5], shininess: 12 };
    const position = [1, 2, 3] as const;
    for (const normal of [
      [0, 0, 1],
      [0.6, 0, 0.8],
      [0, -1, 0],
    ]) {
      const sample = { position: [0, 0, 0], normal, eye: [0, 1, 5] };
      const phong = shade(sample, m, [
        { position, ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [1, 1, 1] },
      ]);
      const point = shade(sample, m, [
        { type: 'point', color: [Math.PI, Math.PI, Math.PI], position, decay: 0 },
      ]);
      expectClose(point, phong, 12);
    }
  });

  // three's MeshLambertMaterial / MeshPhongMaterial({ specular: 0 }) at a point, written from three's chunks:
  // outgoing = BRDF_Lambert(c) · (ambient + hemisphere irradiance + Σ colour·falloff·max(n·l, 0)), BRDF_Lambert =
  // c / π (lights_lambert_pars_fragment, bsdfs, lights_pars_begin).
  it('{ ka: c, kd: c, ks: 0 } equals three’s Lambert for any mix of the five kinds (property)', () => {
    const unit = fc
      .tuple(
        fc.double({ min: -1, max: 1, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
        fc.double({ min: -1, max: 1, noNaN: true }),
      )
      .filter((v) => Math.hypot(...v) > 0.1);
    const rgb = fc.tuple(
      fc.double({ min: 0, max: 2, noNaN: true }),
      fc.double({ min: 0, max: 2, noNaN: true }),
      fc.double({ min: 0, max: 2, noNaN: true }),
    );
    fc.assert(
      fc.property(unit, unit, unit, rgb, rgb, rgb, (n0, sky, toPoint, c, ambient, direct) => {
        const norm = (v: number[]) => v.map((x) => x / Math.hypot(...v));
        const n = norm(n0);
        const dir = norm(sky);
        const position = toPoint.map((x) => 3 * x);
        const lights = [
          { type: 'ambient', color: ambient },
          { type: 'hemisphere', color: direct, groundColor: ambient, direction: dir },
          { type: 'directional', color: direct, direction: dir },
          { type: 'point', color: direct, position, decay: 2 },
        ] as const;
        const out = shade(
          { position: [0, 0, 0], normal: n, eye: [0, 0, 10] },
          { ka: c, kd: c, ks: [0, 0, 0], shininess: 8 },
          lights,
        );
        const t = Math.hypot(...position);
        const l = position.map((x) => x / t);
        const dot = (a: readonly number[], b: readonly number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const w = 0.5 * dot(n, dir) + 0.5;
        const three = [0, 1, 2].map((k) => {
          const irradiance =
            ambient[k] +
            (ambient[k] + (direct[k] - ambient[k]) * w) +
            direct[k] * Math.max(dot(n, dir), 0) +
            (direct[k] / Math.max(t * t, 0.01)) * Math.max(dot(n, l), 0);
          return (c[k] / Math.PI) * irradiance;
        });
        expectClose(out, three, 9);
      }),
    );
  });
});

function smoothstepRef(e0: number, e1: number, x: number): number {
  const t = Math.min(Math.max((x - e0) / (e1 - e0), 0), 1);
  return t * t * (3 - 2 * t);
}

describe('shade() with a surface: texel × vertex colour as tint (ka, kd, not ks), emissive added outside', () => {
  const light: ShadeLight = {
    position: [1, 2, 5],
    ambient: [0.2, 0.3, 0.4],
    diffuse: [1, 0.9, 0.8],
    specular: [0.7, 0.8, 0.9],
  };
  const material: ShadeMaterial = {
    ka: [0.5, 0.4, 0.3],
    kd: [0.6, 0.5, 0.4],
    ks: [0.3, 0.3, 0.3],
    shininess: 8,
  };
  const sample = { position: [0, 0, 0], normal: [0.2, 0.3, 1], eye: [0, 0, 3] } as const;

  it('tint = texel × vertex colour scales the ka and kd terms exactly and leaves the ks term', () => {
    const texel = [0.25, 0.5, 0.75];
    const vertex = [0.8, 0.6, 0.4];
    const tint = texel.map((t, k) => t * vertex[k]);
    const plain = shade(sample, material, [light]);
    const tinted = shade({ ...sample, tint }, material, [light]);
    const specularOnly = shade(sample, { ...material, ka: [0, 0, 0], kd: [0, 0, 0] }, [light]);
    for (let k = 0; k < 3; k++)
      expect(tinted[k]).toBeCloseTo(tint[k] * (plain[k] - specularOnly[k]) + specularOnly[k], 12);
  });

  it('emissive is added once, outside the sum (not tinted, not attenuated, with no lights too)', () => {
    const emissive = [0.1, 0.2, 0.3];
    const plain = shade({ ...sample, tint: [0.5, 0.5, 0.5] }, material, [light, light]);
    const lit = shade({ ...sample, tint: [0.5, 0.5, 0.5] }, { ...material, emissive }, [light, light]);
    for (let k = 0; k < 3; k++) expect(lit[k]).toBeCloseTo(plain[k] + emissive[k], 12);
    expect(shade(sample, { ...material, emissive }, [])).toEqual(emissive);
  });
});
