// scripts/gateReport.mjs on a small Playwright report: a worker's time between two tests is the later one's set-up,
// the page-load, gpu-process and renderer annotations add up per test and per spec file (– where no test recorded
// the CPU times), and the tests nearest their timeout come first.
import { describe, expect, test } from 'vitest';
import { gateLines, gateSummary, singleCoreMs, testRuns } from './gateReport.mjs';

const result = (
  startTime: string,
  duration: number,
  annotations: { type: string; description: string }[],
) => ({
  startTime,
  duration,
  parallelIndex: 0,
  status: 'passed',
  annotations,
});
const report = {
  stats: { startTime: '2026-12-02T10:00:00.000Z', duration: 9000 },
  suites: [
    {
      specs: [
        {
          file: 'a.spec.ts',
          line: 3,
          title: 'first',
          tests: [
            {
              projectName: 'swiftshader',
              timeout: 10_000,
              results: [
                result('2026-12-02T10:00:01.000Z', 2000, [
                  { type: 'page-load', description: '500 7.1' },
                  { type: 'page-load', description: '250 7.2' },
                  { type: 'gpu-process', description: '1200' },
                  { type: 'renderer', description: '300' },
                ]),
              ],
            },
          ],
        },
        {
          file: 'a.spec.ts',
          line: 9,
          title: 'second',
          tests: [
            {
              projectName: 'swiftshader',
              timeout: 4000,
              results: [
                // The load of a beforeAll hook, on each test of its group: counted once per spec file.
                result('2026-12-02T10:00:05.000Z', 3000, [
                  { type: 'page-load', description: '500 7.1' },
                  { type: 'gpu-process', description: '800' },
                ]),
              ],
            },
          ],
        },
        {
          file: 'b.spec.ts',
          line: 1,
          title: 'on Playwright’s own test',
          tests: [
            {
              projectName: 'swiftshader',
              timeout: 10_000,
              results: [{ ...result('2026-12-02T10:00:01.000Z', 1000, []), parallelIndex: 1 }],
            },
          ],
        },
      ],
    },
  ],
};

describe('gateReport', () => {
  test('each test: its duration, the gap before it on its worker as set-up, its annotations summed', () => {
    expect(testRuns(report)).toEqual([
      expect.objectContaining({
        title: 'first',
        seconds: 2,
        setupSeconds: 1,
        pageLoadSeconds: 0.75,
        gpuSeconds: 1.2,
        rendererSeconds: 0.3,
      }),
      expect.objectContaining({
        title: 'second',
        seconds: 3,
        setupSeconds: 2,
        pageLoadSeconds: 0.5,
        gpuSeconds: 0.8,
        rendererSeconds: null,
      }),
      expect.objectContaining({
        file: 'b.spec.ts',
        setupSeconds: 1,
        gpuSeconds: null,
        rendererSeconds: null,
      }),
    ]);
  });

  test('per spec file and in all; the tests by their share of their timeout', () => {
    const g = gateSummary({
      stages: [{ name: 'x', seconds: 12 }],
      totalSeconds: 12,
      singleCoreMs: 230.5,
      report,
      passed: 2,
      failed: 0,
    });
    expect(g.playwright).toEqual({
      tests: 3,
      wallSeconds: 9,
      workerSeconds: 10,
      setupSeconds: 4,
      pageLoadSeconds: 0.8,
      gpuSeconds: 2,
      rendererSeconds: 0.3,
    });
    expect(g.slowestSpecs).toEqual([
      {
        file: 'a.spec.ts',
        tests: 2,
        seconds: 8,
        setupSeconds: 3,
        pageLoadSeconds: 0.8,
        gpuSeconds: 2,
        rendererSeconds: 0.3,
      },
      {
        file: 'b.spec.ts',
        tests: 1,
        seconds: 2,
        setupSeconds: 1,
        pageLoadSeconds: 0,
        gpuSeconds: null,
        rendererSeconds: null,
      },
    ]);
    expect(g.slowestTests.map((t) => [t.test, t.shareOfTimeout])).toEqual([
      ['a.spec.ts:9 second', 0.75],
      ['a.spec.ts:3 first', 0.2],
      ['b.spec.ts:1 on Playwright’s own test', 0.1],
    ]);
    expect(gateLines(g)[0]).toMatch(
      /, \d+ cores; one core's fixed workload \(singleCoreMs in scripts\/gateReport\.mjs\): 230\.5 ms$/,
    );
    expect(gateLines(g)).toContain('    8 s  (  3 /   1 s;   2 /   0 s)    2 tests  a.spec.ts');
    expect(gateLines(g)).toContain('    2 s  (  1 /   0 s;   – /   – s)    1 tests  b.spec.ts');
  });

  test('singleCoreMs: a positive, finite time of the fixed workload', () => {
    const ms = singleCoreMs();
    expect(ms).toBeGreaterThan(0);
    expect(Number.isFinite(ms)).toBe(true);
  });
});
