// The measured choice behind toShadingMaterial's Standard/Physical (and Phong) rule: three's own BRDFs, written
// out on the CPU as three's shader chunks compute them (lights_physical_pars_fragment, bsdfs, common), against
// the lecture's specular term ks·Is·(n·h)^α with Is = colour/π (three's light as ShadingMaterial receives it).
import { toShadingMaterial } from '@shadelab/material';
import { MeshPhongMaterial, MeshPhysicalMaterial, MeshStandardMaterial } from 'three';
import { describe, expect, it } from 'vitest';
import type { Lighting } from './shade.js';
import { celBandsOf, ggxShininess, lobeShininess, MIN_ROUGHNESS, specularScale } from './shadingOptionsOf.js';

const PI = Math.PI;
type V3 = readonly [number, number, number];
const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (a: V3): V3 => {
  const d = Math.hypot(...a);
  return [a[0] / d, a[1] / d, a[2] / d];
};
const saturate = (x: number) => Math.min(Math.max(x, 0), 1);

/** three's F_Schlick (common.glsl: the SIGGRAPH '13 exp2 variant). */
function fSchlick(f0: number, f90: number, dotVH: number): number {
  const fresnel = 2 ** ((-5.55473 * dotVH - 6.98316) * dotVH);
  return f0 * (1 - fresnel) + f90 * fresnel;
}
/** three's V_GGX_SmithCorrelated. */
function vGgx(alpha: number, dotNL: number, dotNV: number): number {
  const a2 = alpha ** 2;
  const gv = dotNL * Math.sqrt(a2 + (1 - a2) * dotNV ** 2);
  const gl = dotNV * Math.sqrt(a2 + (1 - a2) * dotNL ** 2);
  return 0.5 / Math.max(gv + gl, 1e-6);
}
/** three's D_GGX. */
function dGgx(alpha: number, dotNH: number): number {
  const a2 = alpha ** 2;
  const denom = dotNH ** 2 * (a2 - 1) + 1;
  return a2 / (PI * denom ** 2);
}
/** three's BRDF_GGX for one channel (f0 = specularColorBlended, f90 = 1), normal +z. */
function brdfGgx(l: V3, v: V3, f0: number, roughness: number): number {
  const alpha = Math.max(roughness, MIN_ROUGHNESS) ** 2;
  const h = unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
  const dotNL = saturate(l[2]);
  const dotNV = saturate(v[2]);
  const dotNH = saturate(h[2]);
  const dotVH = saturate(dot(v, h));
  return fSchlick(f0, 1, dotVH) * vGgx(alpha, dotNL, dotNV) * dGgx(alpha, dotNH);
}
/** three's BRDF_BlinnPhong for one channel. */
function brdfBlinnPhong(l: V3, v: V3, specular: number, shininess: number): number {
  const h = unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
  const f = fSchlick(specular, 1, saturate(dot(v, h)));
  return f * 0.25 * (1 / PI) * (shininess * 0.5 + 1) * saturate(h[2]) ** shininess;
}

/**
 * Over a light colour of 1: three's direct specular radiance, irradiance × BRDF = (n·l) × BRDF, against the
 * lecture's ks × (1/π) × (n·h)^α, for a view `viewDeg` from the normal and lights over the hemisphere (0.05°
 * steps from the normal, azimuths every 10°; mirror-symmetric). Returns the largest |difference| over three's
 * largest value, and the ratio of the two highlights' energies (∫ over the light directions, dω = sinθ dθ dφ).
 */
function sweep(
  viewDeg: number,
  three: (l: V3, v: V3) => number,
  ks: number,
  shininess: number,
  lighting: Lighting,
) {
  const tv = (viewDeg * PI) / 180;
  const v: V3 = [Math.sin(tv), 0, Math.cos(tv)];
  let maxThree = 0;
  let maxDiff = 0;
  let energyThree = 0;
  let energyOurs = 0;
  for (let i = 0; i < 1800; i++) {
    const theta = ((i + 0.5) * 0.05 * PI) / 180;
    for (let phiDeg = 0; phiDeg <= 180; phiDeg += 10) {
      const phi = (phiDeg * PI) / 180;
      const l: V3 = [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
      const t = l[2] * three(l, v);
      const h = unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
      // r = reflect(−l, n) = 2(n·l)n − l with n = +z.
      const cosine = lighting === 'phong' ? dot(v, [-l[0], -l[1], l[2]]) : h[2];
      const ours = (ks / PI) * Math.max(cosine, 0) ** shininess;
      maxThree = Math.max(maxThree, t);
      maxDiff = Math.max(maxDiff, Math.abs(t - ours));
      energyThree += t * Math.sin(theta);
      energyOurs += ours * Math.sin(theta);
    }
  }
  return { error: maxDiff / maxThree, energy: energyOurs / energyThree };
}

const N: V3 = [0, 0, 1];

describe('the GGX → Blinn-Phong rule (MeshStandard, MeshPhysical)', () => {
  it('shininess = 2/α² − 2 with α = max(roughness, 0.045)², ks scale (s + 2)/8', () => {
    expect(ggxShininess(0.5)).toBeCloseTo(30, 12);
    expect(ggxShininess(1)).toBe(0);
    expect(ggxShininess(0)).toBe(ggxShininess(MIN_ROUGHNESS));
    expect(ggxShininess(2)).toBe(0);
    expect(specularScale(30)).toBe(4);
    expect(lobeShininess(30, 'phong')).toBe(7.5);
    expect(lobeShininess(30, 'blinn-phong')).toBe(30);
  });

  it('(v·r)^(s/4) and (n·h)^s: one peak, one width in the plane of l and v (within 9 %, 2 %, 0.6 % of the peak for s = 8, 30, 100)', () => {
    const bounds: [number, number][] = [
      [8, 0.091],
      [30, 0.02],
      [100, 0.006],
      [1000, 0.001],
    ];
    for (const [s, bound] of bounds) {
      for (let theta = 0; theta < Math.PI / 4; theta += 0.0005) {
        // n·h = cos θ where v·r = cos 2θ.
        const phong = Math.cos(2 * theta) ** lobeShininess(s, 'phong');
        expect(Math.abs(phong - Math.cos(theta) ** s), `s ${s}, θ ${theta}`).toBeLessThan(bound);
      }
    }
  });

  it('equals three’s BRDF_GGX at l = v = n (within Schlick’s 2^−12.5 at v·h = 1)', () => {
    for (const roughness of [0.045, 0.1, 0.25, 0.5, 0.75, 1]) {
      for (const metalness of [0, 0.5, 1]) {
        const m = toShadingMaterial(new MeshStandardMaterial({ color: 0xffffff, roughness, metalness }));
        const f0 = 0.04 * (1 - metalness) + 1 * metalness;
        const three = brdfGgx(N, N, f0, roughness);
        const ours = m.ks.r / PI;
        expect(Math.abs(ours / three - 1)).toBeLessThan(0.005);
      }
    }
  });

  // The measured bound stated in the README ("Swap into an existing scene") and on toShadingMaterial.
  it('roughness ≤ 0.5, views ≤ 30° from the normal: every light direction within 17 % of three’s peak, energy within 0.85 … 1.10 (lighting phong: 0.94 … 1.04)', () => {
    for (const roughness of [0.1, 0.25, 0.35, 0.5]) {
      for (const metalness of [0, 1]) {
        const colour = 0.8;
        const source = new MeshStandardMaterial({ roughness, metalness });
        source.color.setScalar(colour);
        const m = toShadingMaterial(source);
        const f0 = 0.04 * (1 - metalness) + colour * metalness;
        for (const view of [0, 15, 30]) {
          const three = (l: V3, v: V3) => brdfGgx(l, v, f0, roughness);
          const { error, energy } = sweep(view, three, m.ks.r, m.shininess, m.lighting);
          expect(error, `roughness ${roughness}, metalness ${metalness}, view ${view}°`).toBeLessThan(0.17);
          expect(energy).toBeGreaterThan(0.85);
          expect(energy).toBeLessThan(1.1);
          const phong = toShadingMaterial(source, { lighting: 'phong' });
          const other = sweep(view, three, phong.ks.r, phong.shininess, 'phong');
          expect(other.error).toBeLessThan(0.17);
          expect(other.energy).toBeGreaterThan(0.94);
          expect(other.energy).toBeLessThan(1.04);
        }
      }
    }
  });

  it('rougher surfaces and grazing views: the bounds the README’s table states', () => {
    // roughness 0.75: three's n·l narrows a lobe the lecture's term (without n·l) does not; grazing views:
    // three's V ≈ 1/(4 n·v) brightens the highlight.
    const table: [number, number, number, number][] = [
      // roughness, view°, max error / peak ≤, energy ≥ … ≤ 1.5
      [0.5, 45, 0.36, 0.67],
      [0.5, 60, 0.75, 0.33],
      [0.75, 0, 0.23, 1],
      [0.75, 30, 0.5, 1],
      [1, 0, 1, 1],
    ];
    for (const [roughness, view, bound, minEnergy] of table) {
      for (const metalness of [0, 1]) {
        const source = new MeshStandardMaterial({ roughness, metalness });
        source.color.setScalar(0.8);
        const m = toShadingMaterial(source);
        const f0 = 0.04 * (1 - metalness) + 0.8 * metalness;
        const { error, energy } = sweep(
          view,
          (l, v) => brdfGgx(l, v, f0, roughness),
          m.ks.r,
          m.shininess,
          m.lighting,
        );
        expect(error, `roughness ${roughness}, view ${view}°`).toBeLessThanOrEqual(bound);
        expect(energy).toBeGreaterThanOrEqual(minEnergy);
        expect(energy).toBeLessThanOrEqual(1.65);
      }
    }
  });

  it('MeshPhysical: F0 from ior, specularColor and specularIntensity', () => {
    const source = new MeshPhysicalMaterial({ roughness: 0.5, metalness: 0, ior: 2, specularIntensity: 0.5 });
    source.specularColor.setRGB(1, 0.5, 0.25);
    const m = toShadingMaterial(source);
    const f = ((2 - 1) / (2 + 1)) ** 2;
    expect(m.ks.r).toBeCloseTo(f * 1 * 0.5 * 4, 12);
    expect(m.ks.g).toBeCloseTo(f * 0.5 * 0.5 * 4, 12);
    expect(m.ks.b).toBeCloseTo(f * 0.25 * 0.5 * 4, 12);
    const top = brdfGgx(N, N, f * 0.5, 0.5);
    expect(Math.abs(m.ks.r / PI / top - 1)).toBeLessThan(0.01);
  });

  it('the diffuse: three’s colour × (1 − metalness) × (1 − F(v·h)) within 3.6 % where v·h ≥ 0.5', () => {
    for (const metalness of [0, 0.3, 0.9]) {
      const source = new MeshStandardMaterial({ metalness, roughness: 0.5 });
      source.color.setScalar(0.6);
      const m = toShadingMaterial(source);
      for (let vh = 0.5; vh <= 1; vh += 0.01) {
        const three = 0.6 * (1 - metalness) * (1 - fSchlick(0.04, 1, vh));
        expect(Math.abs(m.kd.r / three - 1)).toBeLessThan(0.036);
      }
      expect(m.ka.equals(m.kd)).toBe(true);
    }
  });
});

describe('the Phong rule (MeshPhong)', () => {
  it('equals three’s BRDF_BlinnPhong at l = v = n; within 5 %, 12 %, 26 % of its peak at views 0°, 15°, 30° (shininess ≥ 30), either lighting', () => {
    // three's term has n·l (the highlight of a view 30° off the normal comes from a light 30° off: × 0.87) and
    // Schlick's Fresnel; the lecture's has neither.
    const bound = { 0: 0.05, 15: 0.12, 30: 0.26 };
    for (const shininess of [30, 100, 1000]) {
      for (const specular of [0.05, 0.5, 1]) {
        const source = new MeshPhongMaterial({ shininess });
        source.specular.setScalar(specular);
        for (const lighting of ['blinn-phong', 'phong'] as const) {
          const m = toShadingMaterial(source, { lighting });
          expect(m.shininess).toBe(lighting === 'phong' ? shininess / 4 : shininess);
          expect(m.ks.r).toBeCloseTo((specular * (shininess + 2)) / 8, 12);
          expect(Math.abs(m.ks.r / PI / brdfBlinnPhong(N, N, specular, shininess) - 1)).toBeLessThan(0.005);
          for (const view of [0, 15, 30] as const) {
            const three = (l: V3, v: V3) => brdfBlinnPhong(l, v, specular, shininess);
            const { error } = sweep(view, three, m.ks.r, m.shininess, lighting);
            expect(
              error,
              `${lighting}, shininess ${shininess}, specular ${specular}, view ${view}°`,
            ).toBeLessThan(bound[view]);
          }
        }
      }
    }
  });
});

describe('celBandsOf (MeshToon)', () => {
  it('the gradient map’s width in 2 … 255; 2 without one', () => {
    expect(celBandsOf(null)).toBe(2);
    expect(celBandsOf(undefined)).toBe(2);
    expect(celBandsOf({ isTexture: true, image: { width: 5, height: 1 } })).toBe(5);
    expect(celBandsOf({ isTexture: true, image: { width: 1, height: 1 } })).toBe(2);
    expect(celBandsOf({ isTexture: true, image: { width: 4096, height: 1 } })).toBe(255);
    expect(celBandsOf({ isTexture: true, image: null })).toBe(2);
    expect(celBandsOf({ isTexture: true, image: { width: Number.NaN } })).toBe(2);
  });
});
