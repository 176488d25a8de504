import type { ExpectMatcherState, Locator, MatcherReturnType } from '@playwright/test';
import { linearToSrgb8 } from '@shadelab/material';
import { compareToReference, type ImageError, renderReference } from '@shadelab/reference';
import { attachImage, currentTestInfo } from './attach.js';
import { diffImage } from './diffImage.js';
import { flipRows } from './png.js';
import { type ReferenceScene, referenceSceneOf, type SceneObjects } from './referenceSceneOf.js';
import { readCanvas } from './toHaveRendered.js';

/**
 * How far a render may be from the exact reference, in the units of the published trade-off (BENCHMARKS.md,
 * "Speed against accuracy"). A limit left out is not checked; at least one is needed.
 */
export interface ReferenceBudget {
  /** Largest RMSE over the interior, in 8-bit sRGB codes (all three channels). */
  rmse?: number;
  /** Largest channel error over the interior, in 8-bit sRGB codes. */
  max?: number;
  /**
   * Largest silhouette error in pixels: the farthest pixel centre from the exact silhouette among the pixels
   * whose coverage differs from the reference's.
   */
  silhouettePx?: number;
}

/** Options of `toMatchReference`: the budget, and how the comparison is made. */
export interface ReferenceOptions extends ReferenceBudget {
  /** Milliseconds to wait for the canvas to be visible and stable. @default the expect timeout (5000) */
  timeout?: number;
  /** Interior pixels are at least this far inside the exact silhouette, in pixels (≥ 0). @default 1 */
  interiorMarginPx?: number;
  /** Silhouette supersampling of the reference, per axis (1 … 16). @default 4 */
  samples?: number;
  /** Prefix of the attachments: `<name>-expected.png`, `-actual.png`, `-diff.png`. @default 'reference' */
  name?: string;
}

const LIMITS = ['rmse', 'max', 'silhouettePx'] as const;

function checkBudget(options: ReferenceOptions): void {
  if (options === null || typeof options !== 'object') {
    throw new TypeError(
      `toMatchReference: budget must be an object such as { rmse: 1, max: 4, silhouettePx: 1 }, got ${String(options)}`,
    );
  }
  if (LIMITS.every((k) => options[k] === undefined)) {
    throw new TypeError('toMatchReference: the budget needs at least one of rmse, max and silhouettePx');
  }
  for (const k of LIMITS) {
    const v = options[k];
    if (v !== undefined && !(typeof v === 'number' && v >= 0 && Number.isFinite(v))) {
      throw new RangeError(`toMatchReference: ${k} must be a finite number ≥ 0, got ${String(v)}`);
    }
  }
}

/** The canvas aspect against a symmetric projection's (P[5] / P[0]); a message when they disagree. */
function aspectProblem(scene: ReferenceScene, width: number, height: number): string | undefined {
  const p = scene.projectionMatrix;
  if (p[0] === 0 || p[5] === 0 || p[8] !== 0 || p[9] !== 0) return undefined;
  const aspect = p[5] / p[0];
  const canvas = width / height;
  if (Math.abs(aspect - canvas) <= 1e-6 * canvas) return undefined;
  return `the camera's projection has aspect ${aspect.toPrecision(6)} but the canvas is ${width}×${height} (aspect ${canvas.toPrecision(6)}): set the camera's aspect to the canvas's`;
}

const fmt = (x: number) => (Number.isInteger(x) ? String(x) : x.toFixed(2));

/** The report's lines: each limit, measured against the budget. */
function table(e: ImageError, budget: ReferenceBudget, worst: string): string[] {
  const row = (label: string, measured: number, limit: number | undefined, note: string) => {
    const verdict =
      limit === undefined ? '(not checked)' : measured <= limit ? `≤ ${limit}` : `> ${limit}  ✗`;
    return `  ${label.padEnd(14)} ${fmt(measured).padStart(8)} ${verdict.padEnd(16)} ${note}`;
  };
  return [
    row('RMSE', e.rmse, budget.rmse, `8-bit sRGB codes, over ${e.interiorPixels} interior pixels`),
    row('max', e.max, budget.max, `8-bit sRGB codes${worst}`),
    row(
      'silhouette px',
      e.silhouettePx,
      budget.silhouettePx,
      `${e.mismatchedPixels} pixels whose coverage differs (mean ${fmt(e.silhouetteMeanPx)} px per pixel of silhouette)`,
    ),
  ];
}

/**
 * The `toMatchReference` matcher: render the scene exactly with `renderReference` at the canvas's size, score
 * the canvas's screenshot with `compareToReference` and check the budget (RMSE, max, silhouette px, the
 * published trade-off's units). `scene` is a {@link ReferenceScene} or the app's three.js objects
 * ({@link SceneObjects}, read by {@link referenceSceneOf}). On failure the reference, the screenshot and a diff
 * (colour errors in red above `max` and orange within it; coverage errors in magenta farther than
 * `silhouettePx` from the exact silhouette and cyan within it) are attached to the report, with the numbers as
 * JSON.
 */
export async function toMatchReference(
  this: ExpectMatcherState,
  canvas: Locator,
  scene: ReferenceScene | SceneObjects,
  options: ReferenceOptions,
): Promise<MatcherReturnType> {
  checkBudget(options);
  const { interiorMarginPx = 1, samples = 4, name = 'reference' } = options;
  const described: ReferenceScene = 'camera' in scene ? referenceSceneOf(scene) : scene;
  const hint = `expect(canvas).${this.isNot ? 'not.' : ''}toMatchReference(scene, ${JSON.stringify(
    Object.fromEntries(LIMITS.filter((k) => options[k] !== undefined).map((k) => [k, options[k]])),
  ).replaceAll('"', '')})`;
  const fail = (why: string): MatcherReturnType => ({
    pass: false,
    name: 'toMatchReference',
    message: () => `${hint}\n\n${why}`,
  });
  const timeout = options.timeout ?? this.timeout;
  const buffer = await canvas.evaluate(
    (c) => (c instanceof HTMLCanvasElement ? [c.width, c.height] : null),
    undefined,
    { timeout },
  );
  if (buffer === null) return fail('The element is not a <canvas>.');
  const actual = await readCanvas(canvas, { timeout });
  const [width, height] = buffer;
  if (actual.width !== width || actual.height !== height) {
    return fail(
      `The canvas's drawing buffer is ${width}×${height} pixels but it shows ${actual.width}×${actual.height} on screen: make its CSS size its drawing buffer's (renderer.setPixelRatio(1) and setSize(${width}, ${height})) and keep deviceScaleFactor 1 (the preset's), so each canvas pixel is one screenshot pixel.`,
    );
  }
  const aspect = aspectProblem(described, width, height);
  if (aspect !== undefined) return fail(`The scene does not fit the canvas: ${aspect}.`);
  const reference = renderReference({ ...described, width, height, samples });
  const background = linearToSrgb8(Array.from(described.background ?? [0, 0, 0]));
  const bottomUp = flipRows(actual).data;
  const e = compareToReference(bottomUp, reference, { background, interiorMarginPx });
  let worstK = -1;
  for (let k = 0; k < e.colorError.length; k++)
    if (worstK < 0 || e.colorError[k] > e.colorError[worstK]) worstK = k;
  const worst =
    e.max > 0
      ? `, largest at x ${worstK % width}, y ${height - 1 - Math.floor(worstK / width)} from the top left`
      : '';
  const over = LIMITS.filter((k) => options[k] !== undefined && e[k] > (options[k] as number));
  let referenceInterior = 0;
  for (let k = 0; k < reference.edgeDistance.length; k++) {
    if (reference.edgeDistance[k] <= -interiorMarginPx) referenceInterior++;
  }
  const nothingDrawn = referenceInterior > 0 && e.interiorPixels === 0;
  const pass = over.length === 0 && !nothingDrawn;
  const lines = table(e, options, worst);
  const summary = nothingDrawn
    ? `Nothing is drawn where the reference has its ${referenceInterior} interior pixels: every one is the background ${JSON.stringify(background)} (is the background the canvas's clear colour?).`
    : pass
      ? 'The canvas matches the exact reference within the budget:'
      : `The canvas differs from the exact reference beyond the budget (${over.join(', ')}):`;
  if (!pass && !this.isNot) {
    const maxAllowed = options.max ?? Number.POSITIVE_INFINITY;
    const silhouetteAllowed = options.silhouettePx ?? Number.POSITIVE_INFINITY;
    // compareToReference's per-pixel errors are bottom-up, like the reference: draw them on the bottom-up
    // screenshot and flip the result for the report.
    const diff = diffImage({ width, height, data: bottomUp }, (k) => {
      const s = e.silhouetteError[k];
      if (s > 0) return s > silhouetteAllowed ? [255, 0, 255] : [0, 200, 255];
      const c = e.colorError[k];
      if (c > 0) return c > maxAllowed ? [255, 0, 0] : [255, 170, 0];
      return null;
    });
    await attachImage(
      `${name}-expected.png`,
      flipRows({ width, height, data: new Uint8Array(reference.rgba) }),
    );
    await attachImage(`${name}-actual.png`, actual);
    await attachImage(`${name}-diff.png`, flipRows(diff));
    const { colorError: _c, silhouetteError: _s, ...numbers } = e;
    await currentTestInfo()?.attach(`${name}-error.json`, {
      body: JSON.stringify(
        { measured: numbers, budget: Object.fromEntries(LIMITS.map((k) => [k, options[k] ?? null])) },
        null,
        2,
      ),
      contentType: 'application/json',
    });
  }
  const attached = pass
    ? ''
    : `\nAttached: ${name}-expected.png (the exact reference), ${name}-actual.png, ${name}-diff.png (red: colour error above max, orange: within; magenta: coverage wrong farther than silhouettePx from the exact silhouette, cyan: within) and ${name}-error.json.`;
  return {
    pass,
    name: 'toMatchReference',
    message: () => `${hint}\n\n${summary}\n${lines.join('\n')}${attached}`,
    expected: Object.fromEntries(LIMITS.map((k) => [k, options[k]])),
    actual: { rmse: e.rmse, max: e.max, silhouettePx: e.silhouettePx },
  };
}
