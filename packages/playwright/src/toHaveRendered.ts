import type { ExpectMatcherState, Locator, MatcherReturnType } from '@playwright/test';
import { attachImage } from './attach.js';
import { type CanvasState, inspectCanvas } from './canvasContexts.js';
import { type PictureSummary, rgbText, summarisePicture } from './picture.js';
import { decodePng, type RgbaImage } from './png.js';

/** Options of `toHaveRendered` and {@link waitForFirstFrame}. */
export interface RenderedOptions {
  /** How long to wait for a rendered picture, in milliseconds. @default the expect timeout (5000) */
  timeout?: number;
  /**
   * The background, 8-bit RGB (0 … 255 each): drawn pixels are those of another colour. @default the
   * picture's most frequent colour (any flat picture is blank)
   */
  background?: readonly [number, number, number];
  /** Drawn pixels needed, an integer ≥ 1. @default 1 */
  minDrawnPixels?: number;
}

/** A canvas that has rendered: what {@link waitForFirstFrame} resolves with. */
export interface RenderedFrame {
  /** Milliseconds from the call until the rendered picture was seen. */
  readonly waitedMs: number;
  /** The canvas's size and context. */
  readonly canvas: CanvasState;
  /** What the picture holds. */
  readonly picture: PictureSummary;
  /** The picture itself (the canvas's screenshot), rows top-down. */
  readonly image: RgbaImage;
}

/** One look at the canvas: rendered, or why not. */
interface Look {
  canvas?: CanvasState;
  picture?: PictureSummary;
  image?: RgbaImage;
  /** Why the canvas has not rendered; undefined when it has. */
  problem?: string;
  /**
   * The look ran out of its time on a canvas that is there (Playwright's TimeoutError while the page was slow to
   * answer, as on a loaded machine): it says nothing about the canvas, so it neither meets the wait nor replaces
   * what an earlier look saw.
   */
  cutShort?: boolean;
}

/** The attribute that marks the canvas being read, for the screenshot's style. */
const CAPTURE = 'data-shadelab-capture';

/**
 * The canvas's picture as it is on screen: a screenshot of the element, decoded (RGBA, rows top-down). Every
 * other element is hidden while it is taken (`visibility: hidden`, which keeps the layout), so text or controls
 * drawn over the canvas are not in it. With `deviceScaleFactor: 1` and a canvas whose CSS size is its drawing
 * buffer's, one pixel per canvas pixel.
 */
export async function readCanvas(
  canvas: Locator,
  { timeout }: { timeout?: number } = {},
): Promise<RgbaImage> {
  await canvas.evaluate((element, name) => element.setAttribute(name, ''), CAPTURE, { timeout });
  try {
    const png = await canvas.screenshot({
      timeout,
      animations: 'allow',
      caret: 'initial',
      style: `*{visibility:hidden!important}[${CAPTURE}]{visibility:visible!important}`,
    });
    return decodePng(png);
  } finally {
    await canvas.evaluate((element, name) => element.removeAttribute(name), CAPTURE).catch(() => undefined);
  }
}

const CONTEXT_NAMES: Record<string, string> = {
  webgl2: 'WebGL2',
  webgl: 'WebGL',
  'experimental-webgl': 'WebGL',
  webgpu: 'WebGPU',
  '2d': '2D',
  bitmaprenderer: 'bitmap renderer',
};

const contextName = (type: string) => CONTEXT_NAMES[type] ?? type;

function checkOptions({ background, minDrawnPixels = 1, timeout }: RenderedOptions): void {
  if (!Number.isInteger(minDrawnPixels) || minDrawnPixels < 1) {
    throw new RangeError(
      `toHaveRendered: minDrawnPixels must be an integer ≥ 1, got ${String(minDrawnPixels)}`,
    );
  }
  if (timeout !== undefined && !(timeout >= 0)) {
    throw new RangeError(
      `toHaveRendered: timeout must be a number of milliseconds ≥ 0, got ${String(timeout)}`,
    );
  }
  if (background !== undefined)
    summarisePicture({ width: 0, height: 0, data: new Uint8Array(0) }, background);
}

/** Whether `error` is Playwright's TimeoutError (an action or evaluation that ran out of its time). */
const isTimeout = (error: unknown) => error instanceof Error && error.name === 'TimeoutError';

async function look(canvas: Locator, options: RenderedOptions, timeout: number): Promise<Look> {
  let state: CanvasState;
  try {
    state = await canvas.evaluate(inspectCanvas, false, { timeout });
  } catch (error) {
    // Timed out with an element there: the page was too slow to answer, which says nothing about the canvas.
    if (isTimeout(error) && (await canvas.count().catch(() => 0)) > 0) {
      return { problem: `the canvas could not be read: ${firstLine(error)}`, cutShort: true };
    }
    return { problem: `the canvas could not be found: ${firstLine(error)}` };
  }
  if (state.tag !== 'canvas')
    return { canvas: state, problem: `the element is a <${state.tag}>, not a <canvas>` };
  if (state.width === 0 || state.height === 0) {
    return { canvas: state, problem: `the canvas has no pixels (${state.width}×${state.height})` };
  }
  if (state.recorded && state.context === null) {
    return { canvas: state, problem: 'the canvas has no context: the page never called getContext on it' };
  }
  if (state.context !== null) {
    const problem = contextProblem(state);
    if (problem !== undefined) return { canvas: state, problem };
  }
  let image: RgbaImage;
  try {
    image = await readCanvas(canvas, { timeout });
  } catch (error) {
    return {
      canvas: state,
      problem: `the canvas could not be captured: ${firstLine(error)}`,
      cutShort: isTimeout(error),
    };
  }
  const picture = summarisePicture(image, options.background);
  const min = options.minDrawnPixels ?? 1;
  if (picture.drawnPixels < min) {
    const problem =
      picture.drawnPixels === 0
        ? options.background === undefined
          ? `the picture is blank: all ${picture.width}×${picture.height} pixels are ${rgbText(picture.background)}`
          : `the picture is blank: no pixel differs from the background ${rgbText(picture.background)}`
        : `only ${picture.drawnPixels} pixels differ from the background ${rgbText(picture.background)}, ${min} needed`;
    return { canvas: state, picture, image, problem };
  }
  if (state.context === null) {
    // Not recorded: the canvas has drawn, so it has a context, and asking for each type finds it.
    try {
      state = await canvas.evaluate(inspectCanvas, true, { timeout });
    } catch (error) {
      return {
        canvas: state,
        picture,
        image,
        problem: `the canvas's context could not be read: ${firstLine(error)}`,
        cutShort: isTimeout(error),
      };
    }
    if (state.context === null) {
      return {
        canvas: state,
        picture,
        image,
        problem: 'no WebGL, WebGPU or 2D context was found on the canvas',
      };
    }
    const problem = contextProblem(state);
    if (problem !== undefined) return { canvas: state, picture, image, problem };
  }
  return { canvas: state, picture, image };
}

function contextProblem(state: CanvasState): string | undefined {
  if (state.context === null) return undefined;
  if (state.lost) {
    return state.context === 'webgpu'
      ? 'its WebGPU device is lost (device.lost has resolved)'
      : `its ${contextName(state.context)} context is lost (isContextLost() is true)`;
  }
  if (!state.configured) return 'its WebGPU context was never configured with a device (context.configure)';
  return undefined;
}

function firstLine(error: unknown): string {
  return String(error instanceof Error ? error.message : error).split('\n')[0];
}

const INTERVALS = [100, 250, 500, 1000];

/**
 * Look at the canvas until it has rendered (or, with `wanted` false, until it has not), or until `timeout`.
 * Resolves with the last look that saw the canvas (a look cut short by its time is one only when no other
 * was) and the time waited.
 */
async function poll(
  canvas: Locator,
  options: RenderedOptions,
  timeout: number,
  wanted: boolean,
): Promise<{ look: Look; waitedMs: number; met: boolean }> {
  const start = Date.now();
  /** The last look that was not cut short. */
  let seen: Look | undefined;
  for (let i = 0; ; i++) {
    // A look may run past the deadline rather than fail for want of time (a screenshot takes a while).
    const remaining = Math.max(timeout - (Date.now() - start), 1000);
    const current = await look(canvas, options, remaining);
    if (!current.cutShort) seen = current;
    const last = seen ?? current;
    const met = (last.problem === undefined) === wanted;
    const waitedMs = Date.now() - start;
    if ((met && !current.cutShort) || waitedMs >= timeout) return { look: last, waitedMs, met };
    const pause = INTERVALS[Math.min(i, INTERVALS.length - 1)];
    await new Promise((resolve) => setTimeout(resolve, Math.min(pause, timeout - waitedMs)));
  }
}

function describe(l: Look): string {
  const parts: string[] = [];
  if (l.canvas !== undefined && l.canvas.tag === 'canvas') {
    parts.push(`${l.canvas.width}×${l.canvas.height}`);
    parts.push(
      l.canvas.context === null
        ? l.canvas.recorded
          ? 'no context'
          : 'context not seen'
        : `${contextName(l.canvas.context)} context${l.canvas.lost ? ' (lost)' : ''}`,
    );
  }
  if (l.picture !== undefined) {
    parts.push(`${l.picture.drawnPixels} pixels drawn over ${rgbText(l.picture.background)}`);
  }
  return parts.join(', ');
}

/**
 * Wait until the canvas shows its first rendered frame: a live WebGL, WebGPU or 2D context (not lost) and a
 * picture that is not blank (some pixel differs from the background, see {@link RenderedOptions}). The
 * "first frame rendered" signal for a test, without any cooperation from the page.
 *
 * @throws Error, saying what the canvas showed last, when it has not rendered within the timeout (default
 * 5000 ms); RangeError for a bad option.
 */
export async function waitForFirstFrame(
  canvas: Locator,
  options: RenderedOptions = {},
): Promise<RenderedFrame> {
  checkOptions(options);
  const { look: last, waitedMs, met } = await poll(canvas, options, options.timeout ?? 5000, true);
  if (!met || last.canvas === undefined || last.picture === undefined || last.image === undefined) {
    throw new Error(`waitForFirstFrame: the canvas did not render within ${waitedMs} ms: ${last.problem}`);
  }
  return { waitedMs, canvas: last.canvas, picture: last.picture, image: last.image };
}

/**
 * The `toHaveRendered` matcher: the canvas has a live WebGL, WebGPU or 2D context (not lost) and a picture that
 * is not blank, within the timeout. Fails, saying why, on a lost context, a canvas without a context and a flat
 * picture; the last screenshot is attached to the report.
 */
export async function toHaveRendered(
  this: ExpectMatcherState,
  canvas: Locator,
  options: RenderedOptions = {},
): Promise<MatcherReturnType> {
  checkOptions(options);
  const timeout = options.timeout ?? this.timeout;
  const { look: last, waitedMs } = await poll(canvas, options, timeout, !this.isNot);
  const pass = last.problem === undefined;
  const hint = `expect(canvas).${this.isNot ? 'not.' : ''}toHaveRendered()`;
  if (pass === this.isNot && last.image !== undefined) {
    await attachImage('toHaveRendered-actual.png', last.image);
  }
  const message = () =>
    pass
      ? `${hint}\n\nThe canvas rendered (${describe(last)}), and was still rendered after ${waitedMs} ms.`
      : `${hint}\n\nThe canvas did not render within ${waitedMs} ms: ${last.problem}.\nCanvas: ${describe(last) || (last.cutShort ? 'there, not read in time' : 'not found')}.`;
  return { pass, message, name: 'toHaveRendered' };
}
