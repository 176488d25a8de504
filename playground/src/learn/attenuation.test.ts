import { MIN_ATTENUATION_DENOMINATOR, PhongLight, shade } from '@shadelab/material';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { attenuationFactor, attenuationPlot, distanceRange } from './attenuation';

const att = (a: number, b: number, c: number) => ({ a, b, c });

describe('attenuationFactor', () => {
  it('is 1/(a + b·t + c·t²), the denominator clamped as the materials clamp it', () => {
    expect(attenuationFactor(att(1, 0, 0), 7)).toBe(1);
    expect(attenuationFactor(att(1, 0.5, 0.25), 2)).toBe(1 / 3);
    expect(attenuationFactor(att(0, 0, 1), 0)).toBe(1 / MIN_ATTENUATION_DENOMINATOR);
    expect(() => attenuationFactor(att(1, 0, 0), -1)).toThrow(
      new RangeError('attenuationFactor: t -1 is not a finite number ≥ 0'),
    );
  });

  it('scales shade()’s diffuse term exactly as shade() does (the CPU truth)', () => {
    const abc = fc.double({ min: 0, max: 10, noNaN: true });
    const sample = { position: [0, 0, 0], normal: [0, 0, 1], eye: [0, 0, 1] } as const;
    const material = { ka: [0, 0, 0], kd: [0.5, 0.5, 0.5], ks: [0, 0, 0], shininess: 1 } as const;
    fc.assert(
      fc.property(abc, abc, abc, fc.double({ min: 0.5, max: 50, noNaN: true }), (a, b, c, t) => {
        fc.pre(a + b + c > 0.01);
        const light = {
          position: [0, 0, t],
          ambient: [0, 0, 0],
          diffuse: [1, 1, 1],
          specular: [0, 0, 0],
        } as const;
        const lit = shade(sample, material, [{ ...light, attenuation: att(a, b, c) }]);
        const unlit = shade(sample, material, [light]);
        expect(lit[0]).toBeCloseTo(unlit[0] * attenuationFactor(att(a, b, c), t), 12);
      }),
    );
    expect(new PhongLight().attenuation).toEqual(att(1, 0, 0));
  });
});

describe('distanceRange and attenuationPlot', () => {
  it('the range is the distance to the centre ± the radius, 0 at the near end from inside', () => {
    expect(distanceRange([0, 3, 4], { center: [0, 0, 0], radius: 2 })).toEqual([3, 7]);
    expect(distanceRange([1, 0, 0], { center: [0, 0, 0], radius: 2 })).toEqual([0, 3]);
  });

  it('the lecture’s light and sphere: t from √525 − 2 to √525 + 2, factor 1 throughout', () => {
    const lecture = { position: [-5, 10, 20] as [number, number, number], attenuation: att(1, 0, 0) };
    const plot = attenuationPlot([lecture], { center: [0, 0, 0], radius: 2 });
    const d = Math.sqrt(525);
    expect(plot.curves[0]!.range).toEqual([d - 2, d + 2]);
    expect(plot.tMax).toBeCloseTo(1.15 * (d + 2), 12);
    expect(plot.yMax).toBeCloseTo(1.1, 12);
    expect(plot.curves[0]!.points).toHaveLength(97);
    for (const [, v] of plot.curves[0]!.points) expect(v).toBe(1);
  });

  it('every sample equals the formula; a = 0 does not blow the axis up', () => {
    const lights = [
      { position: [3, 0, 0] as [number, number, number], attenuation: att(1, 0.2, 0.05) },
      { position: [0, -9, 0] as [number, number, number], attenuation: att(0, 0, 1) },
    ];
    const plot = attenuationPlot(lights, { center: [0, 0, 0], radius: 1 }, 40);
    plot.curves.forEach((curve, i) => {
      expect(curve.points[0]![0]).toBe(0);
      expect(curve.points.at(-1)![0]).toBeCloseTo(plot.tMax, 12);
      for (const [t, v] of curve.points) expect(v).toBe(attenuationFactor(lights[i]!.attenuation, t));
    });
    // Light 2's factor is 10⁶ at t = 0 (a = 0) and 1/64 at the object: the axis tops at 1.1 × light 1's 1.
    expect(plot.curves[1]!.points[0]![1]).toBe(1 / MIN_ATTENUATION_DENOMINATOR);
    expect(plot.yMax).toBeCloseTo(1.1, 12);
    expect(() => attenuationPlot(lights, { center: [0, 0, 0], radius: 1 }, 0)).toThrow(RangeError);
  });
});
