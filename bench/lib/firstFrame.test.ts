import { describe, expect, it } from 'vitest';
import { pairedSummary, phaseMedians } from './firstFrame.mjs';

// bench/first-frame.bench.mjs' sums: the per-round ratio and its median (not the ratio of the medians), and the
// phases' medians over the loads that recorded them.

describe('pairedSummary', () => {
  it('takes the median of the per-round ratios, beside each page’s own median', () => {
    // Round 2 is slow for both pages: its ratio is like the others, the medians are not from the same round.
    const s = pairedSummary([300, 900, 330, 310, 320], [100, 450, 110, 100, 100]);
    expect(s.ratios).toEqual([3, 2, 3, 3.1, 3.2]);
    expect(s.ratio).toBe(3);
    expect(s.a).toEqual({ median: 320, min: 300, max: 900, runs: 5 });
    expect(s.b).toEqual({ median: 100, min: 100, max: 450, runs: 5 });
  });

  it('averages the two middle ratios of an even count', () => {
    expect(pairedSummary([2, 4, 6, 8], [1, 1, 1, 1]).ratio).toBe(5);
  });

  it('refuses samples that are not paired', () => {
    expect(() => pairedSummary([1, 2], [1])).toThrow(/2 against 1/);
    expect(() => pairedSummary([], [])).toThrow();
  });
});

describe('phaseMedians', () => {
  const load = (over: Record<string, number | null>) => ({
    firstDrawMs: 100,
    firstFrameMs: 120,
    firstCompileMs: 80,
    programs: 1,
    waitMs: 10,
    waits: 2,
    scriptsMs: 50,
    scriptBytes: 1000,
    domContentLoadedMs: 90,
    ...over,
  });

  it('is each phase’s median, to 0.1 ms, and null where no load recorded the phase', () => {
    const m = phaseMedians([
      load({ firstFrameMs: 120.04, scriptsMs: null }),
      load({ firstFrameMs: 130.26, scriptsMs: null }),
      load({ firstFrameMs: 125.55, scriptsMs: null, programs: 3 }),
    ]);
    expect(m).toEqual({
      scriptsMs: null,
      domContentLoadedMs: 90,
      firstCompileMs: 80,
      firstDrawMs: 100,
      firstFrameMs: 125.6,
      waitMs: 10,
      programs: 1,
      scriptBytes: 1000,
    });
  });
});
