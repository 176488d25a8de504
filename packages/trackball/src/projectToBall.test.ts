import { projectToBall } from '@shadelab/trackball';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';

const norm = (p: number[]) => Math.hypot(p[0], p[1], p[2]);
const coord = fc.double({ min: -1e6, max: 1e6, noNaN: true });

describe('projectToBall: arcball (Shoemake)', () => {
  it('puts the centre at the pole facing the viewer', () => {
    expect(projectToBall(0, 0, 'arcball')).toEqual([0, 0, 1]);
  });

  it('lies on the unit hemisphere inside the rim: (x, y, √(1 − x² − y²))', () => {
    const p = projectToBall(0.6, -0.3, 'arcball');
    expect(p[0]).toBe(0.6);
    expect(p[1]).toBe(-0.3);
    expect(p[2]).toBeCloseTo(Math.sqrt(1 - 0.36 - 0.09), 15);
  });

  it('puts a pointer on the rim on the equator', () => {
    const p = projectToBall(Math.SQRT1_2, -Math.SQRT1_2, 'arcball');
    expect(p[2]).toBeCloseTo(0, 7);
    expect(norm(p)).toBeCloseTo(1, 15);
  });

  it('pulls a pointer outside the rim radially onto the equator', () => {
    expect(projectToBall(3, 4, 'arcball')).toEqual([0.6, 0.8, 0]);
    const far = projectToBall(-1e300, 1e300, 'arcball');
    expect(far[0]).toBeCloseTo(-Math.SQRT1_2, 15);
    expect(far[1]).toBeCloseTo(Math.SQRT1_2, 15);
    expect(far[2]).toBe(0);
  });

  it('always returns a finite unit vector with z ≥ 0 (property)', () => {
    fc.assert(
      fc.property(coord, coord, (x, y) => {
        const p = projectToBall(x, y, 'arcball');
        return p.every(Number.isFinite) && p[2] >= 0 && Math.abs(norm(p) - 1) < 1e-12;
      }),
    );
  });
});

describe('projectToBall: Bell (sphere + hyperbolic sheet)', () => {
  it('is the unit sphere inside r = 1/√2 and the sheet z = 1/(2r) outside', () => {
    const inside = projectToBall(0.3, 0.4, 'bell');
    expect(inside[2]).toBeCloseTo(Math.sqrt(0.75), 15);
    const outside = projectToBall(3, 4, 'bell');
    expect(outside).toEqual([3, 4, 0.1]);
    expect(projectToBall(1, 0, 'bell')).toEqual([1, 0, 0.5]);
  });

  it('is continuous with a continuous slope at r = 1/√2 (no kink at the rim)', () => {
    const r0 = Math.SQRT1_2;
    const h = 1e-7;
    const z = (r: number) => projectToBall(r, 0, 'bell')[2];
    expect(z(r0 - 1e-12)).toBeCloseTo(z(r0 + 1e-12), 10);
    const slopeIn = (z(r0 - h) - z(r0 - 2 * h)) / h;
    const slopeOut = (z(r0 + 2 * h) - z(r0 + h)) / h;
    expect(slopeIn).toBeCloseTo(-1, 5);
    expect(slopeOut).toBeCloseTo(-1, 5);
  });

  it('has z > 0 and finite everywhere, and is the default mapping (property)', () => {
    fc.assert(
      fc.property(coord, coord, (x, y) => {
        const p = projectToBall(x, y);
        const q = projectToBall(x, y, 'bell');
        return p.every(Number.isFinite) && p[2] > 0 && p.every((v, i) => v === q[i]);
      }),
    );
  });

  it('reaches the same points as the arcball inside r = 1/√2 (property)', () => {
    const inner = fc.double({ min: -0.5, max: 0.5, noNaN: true });
    fc.assert(
      fc.property(inner, inner, (x, y) => {
        const a = projectToBall(x, y, 'arcball');
        const b = projectToBall(x, y, 'bell');
        return a.every((v, i) => v === b[i]);
      }),
    );
  });
});

describe('projectToBall: input checks', () => {
  it('writes into out and returns it', () => {
    const out: [number, number, number] = [9, 9, 9];
    expect(projectToBall(0, 0, 'arcball', out)).toBe(out);
    expect(out).toEqual([0, 0, 1]);
  });

  it.each([
    [Number.NaN, 0, /x must be a finite number, got NaN/],
    [0, Number.POSITIVE_INFINITY, /y must be a finite number, got Infinity/],
  ])('refuses x = %s, y = %s with a RangeError naming it', (x, y, message) => {
    expect(() => projectToBall(x, y)).toThrow(RangeError);
    expect(() => projectToBall(x, y)).toThrow(message);
  });

  it('refuses an unknown mapping with a TypeError naming it', () => {
    expect(() => projectToBall(0, 0, 'sphere' as 'bell')).toThrow(TypeError);
    expect(() => projectToBall(0, 0, 'sphere' as 'bell')).toThrow(
      /mapping must be 'arcball' or 'bell', got sphere/,
    );
  });
});
