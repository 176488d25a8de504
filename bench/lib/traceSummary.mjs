// Where a page's time to its first frame goes, from one Chromium trace of its load (bench/first-frame.bench.mjs
// traces one load of each page after its timed rounds): the page's main thread, between two console.timeStamp marks the page leaves in the trace (its
// document's start and its first frame), split three ways:
// - the V8 sampling profile (the trace's ProfileChunk events): each sample's time to the next, by the leaf's
//   script, named by the chunk groups the profile build splits the code into (three, react, the packages, the
//   app), or by the native function it is in (`webglCall`: inside a WebGL call the bench's init script wraps, a
//   draw, a compile or a wait for the GPU process; the page's DOM calls) or V8's own states
//   ((program): the browser's own work on the thread, (garbage collector), (idle));
// - the main thread's trace events of a few kinds (script evaluation, compiles, style, layout, paint), inclusive;
// - how long the GPU process's main thread was busy (SwiftShader compiles shaders and draws there).
// Pure: a trace in, numbers out.

/** @typedef {{ name: string, ph: string, ts: number, dur?: number, pid: number, tid: number, id?: string, args?: any }} TraceEvent */

/** The main thread's event kinds the summary totals (inclusive: an event's nested events count in it too). */
export const EVENT_KINDS = [
  'ParseHTML',
  'EvaluateScript',
  'v8.compileModule',
  'v8.evaluateModule',
  'v8.compile',
  'FunctionCall',
  'RunMicrotasks',
  'FireAnimationFrame',
  'UpdateLayoutTree',
  'Layout',
  'Paint',
  'MajorGC',
  'MinorGC',
];

/**
 * The total length of the union of intervals [start, end), clipped to [from, to].
 * @param {[number, number][]} intervals @param {number} from @param {number} to
 */
export function unionLength(intervals, from, to) {
  const clipped = intervals
    .map(([a, b]) => /** @type {[number, number]} */ ([Math.max(a, from), Math.min(b, to)]))
    .filter(([a, b]) => b > a)
    .sort((x, y) => x[0] - y[0]);
  let total = 0;
  let end = Number.NEGATIVE_INFINITY;
  for (const [a, b] of clipped) {
    if (b <= end) continue;
    total += b - Math.max(a, end);
    end = b;
  }
  return total;
}

/**
 * A script URL's bucket: its file name without the build's hash (`three-AbC12.js` → `three`), or `other` for
 * a script that is not a file (an inline script, an extension).
 * @param {string} url
 */
export function scriptBucket(url) {
  const file = /\/([^/?#]+)\.m?js(?:[?#].*)?$/.exec(url)?.[1];
  return file ? file.replace(/-[\w-]{8}$/, '') : 'other';
}

/**
 * One page load's summary (ms, rounded to 0.1) from its trace's events, between the `console.timeStamp(start)`
 * and `console.timeStamp(end)` marks of the page (the main thread is the one they are on).
 * @param {TraceEvent[]} events @param {{ start: string, end: string, top?: number }} marks
 */
export function summarizeTrace(events, { start, end, top = 12 }) {
  const stamp = (/** @type {string} */ message) =>
    events.find((e) => e.name === 'TimeStamp' && (e.args?.data?.message ?? e.args?.data?.name) === message);
  const from = stamp(start);
  const to = stamp(end);
  if (!from || !to) throw new Error(`trace: no console.timeStamp ${from ? end : start}`);
  const { pid, tid } = from;
  const ms = (/** @type {number} */ us) => Math.round(us / 100) / 10;
  const inWindow = (/** @type {TraceEvent} */ e) => e.ts < to.ts && e.ts + (e.dur ?? 0) > from.ts;
  const clip = (/** @type {TraceEvent} */ e) =>
    Math.min(e.ts + (e.dur ?? 0), to.ts) - Math.max(e.ts, from.ts);

  const main = events.filter((e) => e.pid === pid && e.tid === tid && e.ph === 'X' && inWindow(e));
  /** @type {Record<string, number>} */
  const kinds = {};
  for (const kind of EVENT_KINDS) {
    const total = main.filter((e) => e.name === kind).reduce((sum, e) => sum + clip(e), 0);
    if (total > 0) kinds[kind] = ms(total);
  }
  const busy = unionLength(
    main.map((e) => [e.ts, e.ts + (e.dur ?? 0)]),
    from.ts,
    to.ts,
  );

  // The GPU process's main thread: the thread named CrGpuMain.
  const gpuThread = events.find(
    (e) => e.ph === 'M' && e.name === 'thread_name' && e.args?.name === 'CrGpuMain',
  );
  const gpuBusy = gpuThread
    ? unionLength(
        events
          .filter((e) => e.pid === gpuThread.pid && e.tid === gpuThread.tid && e.ph === 'X')
          .map((e) => [e.ts, e.ts + (e.dur ?? 0)]),
        from.ts,
        to.ts,
      )
    : null;

  // The sampling profile of the page's renderer: its chunks, by profile id; the one with the most samples.
  /** @type {Map<string, { startTime: number, nodes: Map<number, any>, samples: number[], deltas: number[] }>} */
  const profiles = new Map();
  for (const e of events) {
    if (e.pid !== pid || e.id === undefined) continue;
    if (e.name === 'Profile')
      profiles.set(e.id, { startTime: e.args.data.startTime, nodes: new Map(), samples: [], deltas: [] });
    else if (e.name === 'ProfileChunk') {
      const p = profiles.get(e.id);
      const data = e.args?.data ?? {};
      if (!p) continue;
      for (const node of data.cpuProfile?.nodes ?? []) p.nodes.set(node.id, node);
      p.samples.push(...(data.cpuProfile?.samples ?? []));
      p.deltas.push(...(data.timeDeltas ?? []));
    }
  }
  const profile = [...profiles.values()].sort((a, b) => b.samples.length - a.samples.length)[0];
  /** @type {Record<string, number>} */
  const self = {};
  if (profile) {
    let t = profile.startTime;
    const times = profile.deltas.map((d) => {
      t += d;
      return t;
    });
    for (let i = 0; i + 1 < profile.samples.length; i++) {
      const a = Math.max(times[i], from.ts);
      const b = Math.min(times[i + 1], to.ts);
      if (b <= a) continue;
      const frame = profile.nodes.get(profile.samples[i])?.callFrame ?? {
        functionName: '(unknown)',
        url: '',
      };
      const name = frame.functionName || '(anonymous)';
      const bucket = name.startsWith('(')
        ? name
        : frame.url
          ? `script ${scriptBucket(frame.url)}`
          : `native ${name}`;
      self[bucket] = (self[bucket] ?? 0) + (b - a);
    }
  }
  const ranked = Object.entries(self).sort((x, y) => y[1] - x[1]);
  return {
    windowMs: ms(to.ts - from.ts),
    mainBusyMs: ms(busy),
    gpuBusyMs: gpuBusy === null ? null : ms(gpuBusy),
    events: kinds,
    samples: Object.fromEntries(ranked.slice(0, top).map(([k, v]) => [k, ms(v)])),
    otherSamplesMs: ms(ranked.slice(top).reduce((sum, [, v]) => sum + v, 0)),
  };
}
