// What bench/first-frame.bench.mjs measures in a page, and how it sums the loads up. The measurement is one
// init script, the same for every page: it wraps the WebGL contexts' draw calls and records, from navigation
// start (performance.now()), the first draw into a canvas of the document's own framebuffer and the animation
// frame after it (that frame's callback runs once the frame holding the draw has been handed on to be shown);
// beside them the phases before it (the scripts fetched, DOMContentLoaded, the first shader compile) and the
// time the page's main thread spent inside WebGL calls that wait for the GPU process (a program's link status,
// where SwiftShader's shader compiles are waited for), so that two pages are compared by the same clock and
// their difference can be placed. No three, no browser here: the functions below are pure, and tested.
import { summarize } from './bench.mjs';

/**
 * @typedef {object} FirstFrameMarks what the init script records in a page (ms from navigation start)
 * @property {number | null} firstDrawMs the first draw call into a document canvas's default framebuffer
 * @property {number | null} firstFrameMs the animation frame after it
 * @property {number | null} firstCompileMs the first compileShader call
 * @property {number} programs linkProgram calls before the first draw
 * @property {number} waitMs time inside the WebGL calls that wait for the GPU process, before the first draw
 * @property {number} waits how many such calls
 */

/** The console.timeStamp marks firstFrameInit leaves in a trace (as it spells them). */
export const FIRST_FRAME_MARKS = { start: 'first-frame:start', end: 'first-frame:end' };
/** The console.timeStamp marks probeTimer leaves: the Alt+click, the panel on screen. */
export const PROBE_MARKS = { start: 'probe:start', end: 'probe:end' };

/**
 * The init script (page.addInitScript): installs the hooks and keeps its marks in `window.__firstFrame`. It
 * runs in the page, before the page's own scripts, so it only uses what the page has.
 */
export function firstFrameInit() {
  // Its own copy of the marks' names: the function is sent to the page as its source.
  const stamps = { start: 'first-frame:start', end: 'first-frame:end' };
  /** @type {FirstFrameMarks} */
  const marks = {
    firstDrawMs: null,
    firstFrameMs: null,
    firstCompileMs: null,
    programs: 0,
    waitMs: 0,
    waits: 0,
  };
  /** @type {any} */ (window).__firstFrame = marks;
  // Each wrapper is named webglCall: a profile's samples in it are the page inside a WebGL call.
  // The marks a trace of the load holds (bench/lib/traceSummary.mjs): the document's start, the first frame.
  console.timeStamp(stamps.start);
  const DRAWS = [
    'drawArrays',
    'drawElements',
    'drawArraysInstanced',
    'drawElementsInstanced',
    'drawRangeElements',
  ];
  // The calls that return only once the GPU process has answered (a compile or link waits here).
  const WAITS = [
    'getProgramParameter',
    'getShaderParameter',
    'getProgramInfoLog',
    'getShaderInfoLog',
    'readPixels',
  ];
  for (const name of ['WebGLRenderingContext', 'WebGL2RenderingContext']) {
    const proto = /** @type {any} */ (window)[name]?.prototype;
    if (!proto) continue;
    for (const draw of DRAWS) {
      const original = proto[draw];
      if (typeof original !== 'function') continue;
      proto[draw] = function webglCall(/** @type {unknown[]} */ ...args) {
        const result = original.apply(this, args);
        if (
          marks.firstDrawMs === null &&
          this.canvas instanceof HTMLCanvasElement &&
          this.canvas.isConnected &&
          this.getParameter(this.FRAMEBUFFER_BINDING) === null
        ) {
          marks.firstDrawMs = performance.now();
          requestAnimationFrame(() => {
            marks.firstFrameMs = performance.now();
            console.timeStamp(stamps.end);
          });
        }
        return result;
      };
    }
    for (const wait of WAITS) {
      const original = proto[wait];
      if (typeof original !== 'function') continue;
      proto[wait] = function webglCall(/** @type {unknown[]} */ ...args) {
        if (marks.firstDrawMs !== null) return original.apply(this, args);
        const t0 = performance.now();
        const result = original.apply(this, args);
        marks.waitMs += performance.now() - t0;
        marks.waits += 1;
        return result;
      };
    }
    const { compileShader, linkProgram } = proto;
    proto.compileShader = function webglCall(/** @type {unknown[]} */ ...args) {
      marks.firstCompileMs ??= performance.now();
      return compileShader.apply(this, args);
    };
    proto.linkProgram = function webglCall(/** @type {unknown[]} */ ...args) {
      if (marks.firstDrawMs === null) marks.programs += 1;
      return linkProgram.apply(this, args);
    };
  }
}

/**
 * One load's record, read from the page once `__firstFrame.firstFrameMs` is set: the init script's marks, when
 * the scripts had arrived (the last script or module-preload response, ms) and their decoded bytes, and
 * DOMContentLoaded (which waits for the module scripts to run). Runs in the page (page.evaluate).
 */
export function readLoad() {
  const marks = /** @type {any} */ (window).__firstFrame;
  const scripts = performance
    .getEntriesByType('resource')
    .map((e) => /** @type {PerformanceResourceTiming} */ (e))
    .filter((e) => e.initiatorType === 'script' || e.initiatorType === 'link' || /\.m?js$/.test(e.name));
  const navigation = /** @type {PerformanceNavigationTiming | undefined} */ (
    performance.getEntriesByType('navigation')[0]
  );
  return {
    ...marks,
    scriptsMs: scripts.length ? Math.max(...scripts.map((e) => e.responseEnd)) : null,
    scriptBytes: scripts.reduce((sum, e) => sum + e.decodedBodySize, 0),
    domContentLoadedMs: navigation ? navigation.domContentLoadedEventStart : null,
  };
}

/** @typedef {ReturnType<typeof readLoad>} Load */

/** @param {number} x */
const round1 = (x) => Math.round(x * 10) / 10;

/**
 * Two pages' first frames loaded in the same rounds (sample i of each from round i): each page's median, min,
 * max, and the per-round ratios a / b with their median, the figure the target is on (loads seconds apart share
 * the machine's load; the two medians need not come from the same rounds).
 * @param {number[]} a @param {number[]} b
 */
export function pairedSummary(a, b) {
  if (a.length !== b.length || a.length === 0)
    throw new Error(`paired samples: ${a.length} against ${b.length}`);
  const ratios = a.map((x, i) => x / b[i]);
  return { a: summarize(a), b: summarize(b), ratios, ratio: summarize(ratios).median };
}

/**
 * The medians of each phase of a page's loads (ms, rounded to 0.1; null when no load recorded it), so that the
 * table can show where two pages part.
 * @param {Load[]} loads
 */
export function phaseMedians(loads) {
  /** @param {(l: Load) => number | null} pick */
  const median = (pick) => {
    const xs = loads.map(pick).filter((x) => typeof x === 'number');
    return xs.length ? round1(summarize(/** @type {number[]} */ (xs)).median) : null;
  };
  return {
    scriptsMs: median((l) => l.scriptsMs),
    domContentLoadedMs: median((l) => l.domContentLoadedMs),
    firstCompileMs: median((l) => l.firstCompileMs),
    firstDrawMs: median((l) => l.firstDrawMs),
    firstFrameMs: median((l) => l.firstFrameMs),
    waitMs: median((l) => l.waitMs),
    programs: median((l) => l.programs),
    scriptBytes: median((l) => l.scriptBytes),
  };
}

/**
 * The probe's timer (page.evaluate, before the Alt+click): from the click (the event's own time stamp, so that
 * time the click waited for the main thread counts) to the panel showing its values (the probe panel has probed
 * and shows the probe's colour), and to the animation frame after that (the panel on screen). Keeps its marks
 * in `window.__probe`, ms from navigation start.
 */
export function probeTimer() {
  const stamps = { start: 'probe:start', end: 'probe:end' };
  const marks = { clickMs: /** @type {number | null} */ (null), shownMs: null, paintedMs: null };
  /** @type {any} */ (window).__probe = marks;
  document.addEventListener(
    'click',
    (event) => {
      if (!event.altKey || marks.clickMs !== null) return;
      marks.clickMs = event.timeStamp;
      console.timeStamp(stamps.start);
    },
    { capture: true },
  );
  const observer = new MutationObserver(() => {
    if (marks.clickMs === null || marks.shownMs !== null) return;
    const panel = document.querySelector('[data-testid="probe-panel"]');
    if (!panel || (panel.getAttribute('data-probed') ?? '0') === '0') return;
    if (!panel.querySelector('[data-testid="probe-cpu"][data-rgb]')) return;
    /** @type {any} */ (marks).shownMs = performance.now();
    observer.disconnect();
    requestAnimationFrame(() => {
      /** @type {any} */ (marks).paintedMs = performance.now();
      console.timeStamp(stamps.end);
    });
  });
  observer.observe(document.body, { subtree: true, childList: true, attributes: true });
}

/**
 * Waits in the page until the playground rests (as tests/playground-helpers.ts' settle: no new frame and no
 * frame asked for during `quietMs`, or 50 × that at most), so that the probe is timed on a page that has
 * finished what loads after its first frame. Runs in the page (page.evaluate).
 * @param {number} quietMs
 */
export function settleInPage(quietMs) {
  const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('[data-testid="viewport"]'));
  return new Promise((resolve) => {
    const start = performance.now();
    let last = canvas.dataset.frames;
    let since = start;
    const check = () => {
      const now = performance.now();
      const busy = canvas.hasAttribute('data-render-pending') || document.querySelector('[aria-busy="true"]');
      if (canvas.dataset.frames !== last || busy) {
        last = canvas.dataset.frames;
        since = now;
      }
      if (now - since >= quietMs || now - start >= 50 * quietMs) resolve(undefined);
      else requestAnimationFrame(check);
    };
    requestAnimationFrame(check);
  });
}
