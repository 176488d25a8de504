// What a canvas draws with, seen from the page. Both functions run in the browser (Playwright serialises them):
// they use nothing from this module's scope.

/** The context of a canvas, as `toHaveRendered` sees it in the page. */
export interface CanvasState {
  /** The element's tag name, lower case (`'canvas'` for a canvas). */
  readonly tag: string;
  /** Drawing buffer width in pixels (0 for an element that is not a canvas). */
  readonly width: number;
  /** Drawing buffer height in pixels. */
  readonly height: number;
  /**
   * The context type passed to `getContext` (`'webgl2'`, `'webgl'`, `'webgpu'`, `'2d'`, …), or null when the
   * canvas has none (or none could be seen, see `recorded`).
   */
  readonly context: string | null;
  /**
   * Whether the context is lost: `isContextLost()` of a WebGL or 2D context, or a WebGPU device whose `lost`
   * promise has resolved (seen only when `recorded`); false when unknown.
   */
  readonly lost: boolean;
  /** For WebGPU: whether the context was configured with a device (`context.configure(…)`). */
  readonly configured: boolean;
  /**
   * Whether the page records its canvases' contexts ({@link recordCanvasContexts}, installed by the `test`
   * of `@shadelab/playwright/test`). Otherwise the context is found by asking the canvas for each type, which
   * is only done when `probe` is set (asking a canvas without a context would create one).
   */
  readonly recorded: boolean;
}

/**
 * Init script (runs in the page before its own scripts): remember the context each canvas creates, and for
 * WebGPU the device a context is configured with and whether it was lost, under
 * `Symbol.for('shadelab.canvasContexts')`. The `test` of `@shadelab/playwright/test` adds it to every page.
 */
export function recordCanvasContexts(): void {
  type Entry = { type: string; context: object; device?: { lost: Promise<unknown> }; lost: boolean };
  const scope = globalThis as unknown as Record<symbol, unknown> & {
    GPUCanvasContext?: { prototype: { configure(config: { device: { lost: Promise<unknown> } }): void } };
  };
  const key = Symbol.for('shadelab.canvasContexts');
  if (scope[key] !== undefined || typeof HTMLCanvasElement === 'undefined') return;
  const canvases = new WeakMap<object, Entry>();
  const contexts = new WeakMap<object, Entry>();
  scope[key] = canvases;
  const getContext = HTMLCanvasElement.prototype.getContext as (
    this: HTMLCanvasElement,
    type: string,
    ...rest: unknown[]
  ) => object | null;
  HTMLCanvasElement.prototype.getContext = function (
    this: HTMLCanvasElement,
    type: string,
    ...rest: unknown[]
  ) {
    const context = getContext.call(this, type, ...rest);
    if (context !== null && !canvases.has(this)) {
      const entry: Entry = { type, context, lost: false };
      canvases.set(this, entry);
      contexts.set(context, entry);
    }
    return context;
  } as typeof HTMLCanvasElement.prototype.getContext;
  const gpu = scope.GPUCanvasContext;
  if (gpu !== undefined) {
    const configure = gpu.prototype.configure;
    gpu.prototype.configure = function (this: object, config) {
      configure.call(this, config);
      const entry = contexts.get(this);
      if (entry !== undefined) {
        entry.device = config.device;
        entry.lost = false;
        config.device.lost.then(() => {
          if (entry.device === config.device) entry.lost = true;
        });
      }
    };
  }
}

/**
 * Runs in the page on the canvas element: its size and context, and whether the context is lost. With
 * `probe`, a canvas the page did not record is asked for each context type in turn, which finds the one it
 * has (the others return null); asking a canvas that has no context yet creates one, so only probe a canvas
 * known to have drawn.
 */
export function inspectCanvas(element: Element, probe: boolean): CanvasState {
  const tag = element.tagName.toLowerCase();
  if (!(element instanceof HTMLCanvasElement)) {
    return { tag, width: 0, height: 0, context: null, lost: false, configured: false, recorded: false };
  }
  const key = Symbol.for('shadelab.canvasContexts');
  const canvases = (globalThis as unknown as Record<symbol, WeakMap<object, unknown> | undefined>)[key];
  const recorded = canvases !== undefined;
  let entry = canvases?.get(element) as
    | { type: string; context: object; device?: object; lost: boolean }
    | undefined;
  if (entry === undefined && !recorded && probe) {
    for (const type of ['webgl2', 'webgl', 'webgpu', '2d', 'bitmaprenderer']) {
      try {
        const context = element.getContext(type) as object | null;
        if (context !== null) {
          entry = { type, context, lost: false };
          break;
        }
      } catch {
        // A canvas transferred to an OffscreenCanvas, or a type this browser lacks.
      }
    }
  }
  const { width, height } = element;
  if (entry === undefined) {
    return { tag, width, height, context: null, lost: false, configured: false, recorded };
  }
  const context = entry.context as { isContextLost?: () => boolean };
  const lost = typeof context.isContextLost === 'function' ? context.isContextLost() : entry.lost;
  const configured = entry.type !== 'webgpu' || entry.device !== undefined || !recorded;
  return { tag, width, height, context: entry.type, lost, configured, recorded };
}
