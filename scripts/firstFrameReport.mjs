// BENCHMARKS.md's section on bench/results/first-frame.json (bench/first-frame.bench.mjs): the playground's first
// frame against the README's Quick start page, the phases of both loads, the first probe and, when the run
// profiled, where each page's time went. scripts/benchmarks.mjs calls it with its own table and from-line
// helpers, so that this section reads as the others do. Pure: the same results give the same lines.

export const FIRST_FRAME_TITLE = 'First frame against the Quick start';

/** @param {number | null | undefined} x */
const ms = (x) => (typeof x === 'number' ? `${Math.round(x).toLocaleString('en-US')} ms` : '—');

/** The phases the bench records, in the order a load reaches them, with how each reads. */
const PHASES = /** @type {const} */ ([
  ['scriptsMs', 'the scripts arrived (last script response)', ms],
  ['domContentLoadedMs', 'DOMContentLoaded (the module scripts ran)', ms],
  ['firstCompileMs', 'first shader compile', ms],
  ['firstDrawMs', 'first draw', ms],
  ['firstFrameMs', '**first frame**', ms],
  ['waitMs', 'main thread waiting for the GPU process before the first draw', ms],
  [
    'programs',
    'programs linked before the first draw',
    (/** @type {number | null} */ x) => (x === null ? '—' : String(x)),
  ],
  [
    'scriptBytes',
    'scripts loaded (decoded)',
    (/** @type {number | null} */ x) =>
      x === null
        ? '—'
        : `${(x / 1000).toLocaleString('en-US', { minimumFractionDigits: 1, maximumFractionDigits: 1 })} kB`,
  ],
]);

/**
 * One traced load's summary as a table: the main thread's samples by where they were, then its busy time, the
 * GPU process's and the event kinds.
 * @param {any} playground @param {any} quickStart @param {typeof import('./benchmarks.mjs').table} table
 */
function profileTable(playground, quickStart, table) {
  const keys = [...new Set([...Object.keys(playground.samples), ...Object.keys(quickStart.samples)])].sort(
    (a, b) => (playground.samples[b] ?? 0) - (playground.samples[a] ?? 0),
  );
  const events = [...new Set([...Object.keys(playground.events), ...Object.keys(quickStart.events)])];
  return table(['', 'playground', 'Quick start'], 'lrr', [
    ['traced window (document start → first frame)', ms(playground.windowMs), ms(quickStart.windowMs)],
    ['main thread busy (trace events)', ms(playground.mainBusyMs), ms(quickStart.mainBusyMs)],
    ['GPU process main thread busy', ms(playground.gpuBusyMs), ms(quickStart.gpuBusyMs)],
    ...keys.map((k) => [`samples: \`${k}\``, ms(playground.samples[k]), ms(quickStart.samples[k])]),
    ['samples: the rest', ms(playground.otherSamplesMs), ms(quickStart.otherSamplesMs)],
    ...events.map((k) => [
      `events: \`${k}\` (inclusive)`,
      ms(playground.events[k]),
      ms(quickStart.events[k]),
    ]),
  ]);
}

/**
 * The section's lines.
 * @param {any} r bench/results/first-frame.json
 * @param {{ table: typeof import('./benchmarks.mjs').table, fromLine: (name: string, data: any) => string }} helpers
 * @returns {string[]}
 */
export function firstFrameSection(r, { table, fromLine }) {
  const { firstFrame: f, phases, probe } = r;
  const met = f.met ? 'met' : '**not met**';
  const samples = (/** @type {number[]} */ xs) =>
    xs.map((x) => Math.round(x).toLocaleString('en-US')).join(', ');
  const out = [
    `## ${FIRST_FRAME_TITLE}`,
    '',
    fromLine('first-frame', r),
    '',
    `The playground's production build on its default state against the README's Quick start block (\`${r.quickStart}\`, built as \`tests/snippets.spec.ts\` builds it), both at ${r.viewport.width}×${r.viewport.height} in fresh pages of one browser, ${r.rounds} rounds after a warm-up. Target (issue 35): the first frame ≤ ${r.target} × the Quick start's, the median of the per-round ratios: **${f.ratio.toFixed(2)}**, ${met}.`,
    '',
    ...table(['first frame', 'playground', 'Quick start', 'playground / Quick start'], 'lrrr', [
      [
        'median',
        ms(f.playground.median),
        ms(f.quickStart.median),
        `**${f.ratio.toFixed(2)}** (≤ ${r.target}: ${met})`,
      ],
      ['fastest', ms(f.playground.min), ms(f.quickStart.min), ''],
      ['slowest', ms(f.playground.max), ms(f.quickStart.max), ''],
    ]),
    '',
    `Every round (ms): playground ${samples(f.playground.samplesMs)}; Quick start ${samples(f.quickStart.samplesMs)}; ratios ${f.ratios.map((/** @type {number} */ x) => x.toFixed(2)).join(', ')}.`,
    '',
    'Where the loads part (medians over the same loads, ms from navigation start):',
    '',
    ...table(
      ['phase', 'playground', 'Quick start'],
      'lrr',
      PHASES.map(([key, label, show]) => [label, show(phases.playground[key]), show(phases.quickStart[key])]),
    ),
    '',
    '### The first probe',
    '',
    `Alt+click at the canvas's centre (${probe.at.fx}, ${probe.at.fy}) in each round's playground page, once it had rested ${probe.quietMs} ms after its first frame, to the frame after the probe panel showed its values: median **${ms(probe.median)}**, fastest ${ms(probe.min)}, slowest ${ms(probe.max)} (every probe: ${samples(probe.samplesMs)} ms; to the panel's values, before that frame: ${samples(probe.shownMs)} ms).`,
  ];
  if (r.profile) {
    out.push(
      '',
      '### Where the time goes',
      '',
      "One more load of each page under Chromium's tracing, from builds split into chunks by origin (`three`, `react`, `r3f`: React Three Fiber with its reconciler, `leva` with its own dependencies, `other-deps`, `shadelab`: the packages; the rest the page's own code): the main thread's samples of V8's profiler by the script or native function they were in, between the document's start and the first frame (`(program)`: the browser's own work on the thread; `native webglCall`: inside a WebGL call, a draw, a compile or a wait for the GPU process):",
      '',
      ...profileTable(r.profile.playground.firstFrame, r.profile.quickStart.firstFrame, table),
    );
    const p = r.profile.playground.probe;
    if (p)
      out.push(
        '',
        `The traced probe: ${ms(p.windowMs)} from the click to the panel on screen, the main thread busy ${ms(p.mainBusyMs)}, the GPU process ${ms(p.gpuBusyMs)}; samples: ${Object.entries(
          p.samples,
        )
          .map(([k, v]) => `\`${k}\` ${ms(/** @type {number} */ (v))}`)
          .join(', ')}.`,
      );
  }
  if (r.note) out.push('', r.note);
  return out;
}
