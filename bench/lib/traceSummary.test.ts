import { describe, expect, it } from 'vitest';
import { scriptBucket, summarizeTrace, unionLength } from './traceSummary.mjs';

// bench/lib/traceSummary.mjs on a small hand-made trace: the window between the page's two marks, the main
// thread's busy time and event kinds, the GPU process's busy time and the samples by where they were.

describe('unionLength', () => {
  it('counts overlapping intervals once, clipped to the window', () => {
    expect(
      unionLength(
        [
          [0, 10],
          [5, 15],
          [20, 30],
          [22, 25],
        ],
        2,
        28,
      ),
    ).toBe(13 + 8);
    expect(unionLength([], 0, 10)).toBe(0);
  });
});

describe('scriptBucket', () => {
  it('names a script by its file without the build’s hash', () => {
    expect(scriptBucket('http://127.0.0.1:4000/assets/three-B6aZ3x_k.js')).toBe('three');
    expect(scriptBucket('http://127.0.0.1:4000/assets/index-DxYz1234.js?v=1')).toBe('index');
    expect(scriptBucket('http://127.0.0.1:4000/assets/other-deps-AbCdEfGh.js')).toBe('other-deps');
    expect(scriptBucket('')).toBe('other');
  });
});

describe('summarizeTrace', () => {
  const MAIN = { pid: 1, tid: 10 };
  const GPU = { pid: 2, tid: 20 };
  const url = 'http://127.0.0.1:4000/assets/';
  const events = [
    { name: 'thread_name', ph: 'M', ts: 0, ...GPU, args: { name: 'CrGpuMain' } },
    { name: 'TimeStamp', ph: 'I', ts: 1000, ...MAIN, args: { data: { message: 'start' } } },
    { name: 'TimeStamp', ph: 'I', ts: 11000, ...MAIN, args: { data: { message: 'end' } } },
    // Before the window: not counted.
    { name: 'EvaluateScript', ph: 'X', ts: 0, dur: 500, ...MAIN },
    { name: 'EvaluateScript', ph: 'X', ts: 2000, dur: 3000, ...MAIN },
    { name: 'v8.compile', ph: 'X', ts: 2000, dur: 1000, ...MAIN },
    // Half inside the window.
    { name: 'Layout', ph: 'X', ts: 10000, dur: 2000, ...MAIN },
    // Another thread of the renderer: not the main thread's.
    { name: 'Layout', ph: 'X', ts: 3000, dur: 2000, pid: 1, tid: 11 },
    { name: 'GPUTask', ph: 'X', ts: 4000, dur: 4000, ...GPU },
    { name: 'GPUTask', ph: 'X', ts: 5000, dur: 1000, ...GPU },
    // The profile: samples every 1 ms from 0 to 12 ms.
    { name: 'Profile', ph: 'P', ts: 0, ...MAIN, id: '0x1', args: { data: { startTime: 0 } } },
    {
      name: 'ProfileChunk',
      ph: 'P',
      ts: 0,
      pid: 1,
      tid: 12,
      id: '0x1',
      args: {
        data: {
          cpuProfile: {
            nodes: [
              { id: 1, callFrame: { functionName: '(root)', url: '' } },
              { id: 2, parent: 1, callFrame: { functionName: 'a', url: `${url}three-B6aZ3x_k.js` } },
              { id: 3, parent: 2, callFrame: { functionName: 'getProgramParameter', url: '' } },
              { id: 4, parent: 1, callFrame: { functionName: '(idle)', url: '' } },
            ],
            samples: [4, 4, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4],
          },
          timeDeltas: [0, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000],
        },
      },
    },
  ];

  it('splits the window between the marks', () => {
    const s = summarizeTrace(events, { start: 'start', end: 'end' });
    expect(s.windowMs).toBe(10);
    expect(s.mainBusyMs).toBe(4);
    expect(s.gpuBusyMs).toBe(4);
    expect(s.events).toEqual({ EvaluateScript: 3, 'v8.compile': 1, Layout: 1 });
    // Samples at 1..10 ms, each to the next: idle 1 ms, three 3 ms, the WebGL wait 4 ms, idle again 2 ms.
    expect(s.samples).toEqual({ 'native getProgramParameter': 4, '(idle)': 3, 'script three': 3 });
    expect(s.otherSamplesMs).toBe(0);
  });

  it('keeps the top buckets and sums the rest', () => {
    const s = summarizeTrace(events, { start: 'start', end: 'end', top: 1 });
    expect(s.samples).toEqual({ 'native getProgramParameter': 4 });
    expect(s.otherSamplesMs).toBe(6);
  });

  it('says which mark is missing', () => {
    expect(() => summarizeTrace(events, { start: 'start', end: 'nowhere' })).toThrow(/nowhere/);
  });
});
