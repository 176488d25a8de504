import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { polyline, scale, tickLabel, ticks } from './profileAxes';

describe('the plots’ axes', () => {
  it('scale maps the domain onto the range linearly (y flipped too)', () => {
    const s = scale([0, 255], [150, 8]);
    expect([s(0), s(255), s(127.5)]).toEqual([150, 8, 79]);
    expect(() => scale([1, 1], [0, 1])).toThrow(
      new RangeError('scale: domain [1, 1] is not a finite interval with d1 > d0'),
    );
  });

  it('ticks are 1, 2 or 5 × 10ⁿ steps inside the range', () => {
    expect(ticks(0, 255, 4)).toEqual([0, 100, 200]);
    expect(ticks(0, 1.1, 4)).toEqual([0, 0.5, 1]);
    expect(ticks(0, 28.7)).toEqual([0, 10, 20]);
    fc.assert(
      fc.property(
        fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        fc.double({ min: 1e-3, max: 1e6, noNaN: true }),
        (lo, span) => {
          const t = ticks(lo, lo + span);
          expect(t.length).toBeGreaterThanOrEqual(1);
          expect(t.length).toBeLessThanOrEqual(11);
          for (const v of t) {
            expect(v).toBeGreaterThanOrEqual(lo);
            expect(v).toBeLessThanOrEqual(lo + span);
          }
        },
      ),
    );
  });

  it('labels and polylines', () => {
    expect([tickLabel(0.30000000000000004), tickLabel(1200), tickLabel(0.125)]).toEqual([
      '0.3',
      '1200',
      '0.125',
    ]);
    expect(
      polyline([
        [1, 2],
        [3.456, 4],
      ]),
    ).toBe('1.00,2.00 3.46,4.00');
  });
});
