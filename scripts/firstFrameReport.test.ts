import { describe, expect, it } from 'vitest';
import { renderBenchmarks, table } from './benchmarks.mjs';
import { FIRST_FRAME_TITLE, firstFrameSection } from './firstFrameReport.mjs';

// BENCHMARKS.md's first-frame section on a small hand-made first-frame.json: the ratio and whether the target
// is met, each page's figures and phases, the probe, and the profile when the run made one.

const phases = (firstFrameMs: number) => ({
  scriptsMs: 40.2,
  domContentLoadedMs: 900,
  firstCompileMs: 950,
  firstDrawMs: firstFrameMs - 30,
  firstFrameMs,
  waitMs: 400,
  programs: 3,
  scriptBytes: 1_234_567,
});
const summary = (median: number, min: number, max: number) => ({ median, min, max, runs: 3 });
const RESULT = {
  viewport: { width: 800, height: 600 },
  rounds: 3,
  target: 1.5,
  quickStart: 'README.md:58',
  note: 'How it was measured.',
  firstFrame: {
    playground: { ...summary(3000, 2900, 3500), samplesMs: [3000, 2900, 3500] },
    quickStart: { ...summary(1000, 990, 1200), samplesMs: [1000, 990, 1200] },
    ratios: [3, 2.929, 2.917],
    ratio: 2.929,
    met: false,
  },
  phases: { playground: phases(3000), quickStart: phases(1000) },
  playgroundOwnFirstFrameMs: [2990, 2890, 3490],
  probe: {
    at: { fx: 0.5, fy: 0.5 },
    quietMs: 400,
    ...summary(1500, 1400, 1600),
    samplesMs: [1500, 1400, 1600],
    shownMs: [1480, 1380, 1580],
  },
};
const helpers = { table, fromLine: (name: string) => `From ${name}.` };

describe('firstFrameSection', () => {
  it('shows the ratio against the target, each page’s first frame and the probe', () => {
    const lines = firstFrameSection(RESULT, helpers);
    expect(lines[0]).toBe(`## ${FIRST_FRAME_TITLE}`);
    expect(lines).toContain('From first-frame.');
    expect(lines).toContain('| median | 3,000 ms | 1,000 ms | **2.93** (≤ 1.5: **not met**) |');
    expect(lines).toContain('| fastest | 2,900 ms | 990 ms |  |');
    expect(lines).toContain(
      'Every round (ms): playground 3,000, 2,900, 3,500; Quick start 1,000, 990, 1,200; ratios 3.00, 2.93, 2.92.',
    );
    expect(lines).toContain('| **first frame** | 3,000 ms | 1,000 ms |');
    expect(lines).toContain('| programs linked before the first draw | 3 | 3 |');
    expect(lines).toContain('| scripts loaded (decoded) | 1,234.6 kB | 1,234.6 kB |');
    expect(lines.find((l) => l.startsWith('Alt+click'))).toContain('median **1,500 ms**, fastest 1,400 ms');
    expect(lines.at(-1)).toBe('How it was measured.');
    expect(lines).not.toContain('### Where the time goes');
  });

  it('says met when the ratio is within the target', () => {
    const met = { ...RESULT, firstFrame: { ...RESULT.firstFrame, ratio: 1.2, met: true } };
    expect(firstFrameSection(met, helpers).join('\n')).toContain('**1.20** (≤ 1.5: met)');
  });

  it('adds the profile’s table, its buckets in the playground’s order', () => {
    const trace = (samples: Record<string, number>) => ({
      windowMs: 3000,
      mainBusyMs: 2500,
      gpuBusyMs: 800,
      events: { EvaluateScript: 700 },
      samples,
      otherSamplesMs: 5,
    });
    const profiled = {
      ...RESULT,
      profile: {
        playground: {
          firstFrame: trace({ 'script react': 900, '(program)': 1200 }),
          probe: trace({ 'script index': 300 }),
        },
        quickStart: { firstFrame: trace({ '(program)': 400, 'script three': 100 }) },
      },
    };
    const lines = firstFrameSection(profiled, helpers);
    const at = lines.indexOf('### Where the time goes');
    expect(at).toBeGreaterThan(0);
    const rows = lines.slice(at).filter((l) => l.startsWith('| samples'));
    expect(rows).toEqual([
      '| samples: `(program)` | 1,200 ms | 400 ms |',
      '| samples: `script react` | 900 ms | — |',
      '| samples: `script three` | — | 100 ms |',
      '| samples: the rest | 5 ms | 5 ms |',
    ]);
    expect(lines.join('\n')).toContain('The traced probe: 3,000 ms from the click');
  });

  it('is a section of BENCHMARKS.md, listed in its contents and in Runs', () => {
    const page = renderBenchmarks({ 'first-frame': { meta: {}, ...RESULT } });
    expect(page).toContain('[First frame against the Quick start](#first-frame-against-the-quick-start)');
    expect(page).toContain(`\n## ${FIRST_FRAME_TITLE}\n`);
    expect(page).toContain('[`bench/first-frame.bench.mjs`](bench/first-frame.bench.mjs)');
  });
});
