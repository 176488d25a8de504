import type { ExpectMatcherState, JSHandle, MatcherReturnType, Page } from '@playwright/test';
import { attachImage, currentTestInfo } from './attach.js';
import { compareNeighbourhood } from './compareNeighbourhood.js';
import { diffImage, errorColour } from './diffImage.js';
import { GPU_TOLERANCE, type GpuTolerance, RENDERER_TOLERANCE } from './gpuTolerance.js';
import type { PageRenderers, RenderedPicture, RenderRequest, SceneFactory } from './page.js';
import { rgbText, summarisePicture } from './picture.js';
import type { RgbaImage } from './png.js';
import { type BackendProof, RENDERER_NAMES, type RendererName, rasteriserOf } from './rendererNames.js';

/** Options of `toMatchAcrossRenderers`: the renderers, the picture, the tolerance. */
export interface AcrossRenderersOptions extends Partial<GpuTolerance> {
  /**
   * The renderers to draw with; the first is the one the others are compared with (at least two, no repeats).
   * @default ['webgl', 'webgpu', 'webgpu-webgl2']
   */
  renderers?: readonly RendererName[];
  /** Picture width in pixels (1 … 4096). @default 256 */
  width?: number;
  /** Picture height in pixels (1 … 4096). @default 256 */
  height?: number;
  /** Handed to the scene factory as `context.arg` (JSON-serialisable). @default undefined */
  arg?: unknown;
  /** Prefix of the attachments: `<name>-<renderer>.png`, `<name>-<renderer>-diff.png`, `<name>-backends.json`. @default 'renderers' */
  name?: string;
  /** Milliseconds to wait for the page's renderers (`exposeRenderers`) to be there. @default the expect timeout (5000) */
  timeout?: number;
}

const KEY = 'shadelab.renderers';

function checkOptions(o: AcrossRenderersOptions, renderers: readonly RendererName[]): void {
  if (!Array.isArray(renderers) || renderers.length < 2) {
    throw new RangeError(
      `toMatchAcrossRenderers: renderers must list at least two of ${RENDERER_NAMES.join(', ')}, got ${JSON.stringify(renderers)}`,
    );
  }
  for (const r of renderers) {
    if (!RENDERER_NAMES.includes(r)) {
      throw new TypeError(
        `toMatchAcrossRenderers: renderers may hold ${RENDERER_NAMES.map((n) => `'${n}'`).join(', ')}, got ${JSON.stringify(r)}`,
      );
    }
  }
  if (new Set(renderers).size !== renderers.length) {
    throw new RangeError(`toMatchAcrossRenderers: renderers has a repeat: ${JSON.stringify(renderers)}`);
  }
  for (const k of ['width', 'height'] as const) {
    const v = o[k];
    if (v !== undefined && !(Number.isInteger(v) && v >= 1 && v <= 4096)) {
      throw new RangeError(
        `toMatchAcrossRenderers: ${k} must be an integer 1 … 4096 pixels, got ${String(v)}`,
      );
    }
  }
  const { maxChannelDiff, radiusPx, maxDiffPixels } = o;
  if (maxChannelDiff !== undefined && !(maxChannelDiff >= 0 && maxChannelDiff <= 255)) {
    throw new RangeError(
      `toMatchAcrossRenderers: maxChannelDiff must be a number of 8-bit codes 0 … 255, got ${String(maxChannelDiff)}`,
    );
  }
  if (radiusPx !== undefined && !(Number.isInteger(radiusPx) && radiusPx >= 0 && radiusPx <= 8)) {
    throw new RangeError(
      `toMatchAcrossRenderers: radiusPx must be an integer 0 … 8, got ${String(radiusPx)}`,
    );
  }
  if (maxDiffPixels !== undefined && !(Number.isInteger(maxDiffPixels) && maxDiffPixels >= 0)) {
    throw new RangeError(
      `toMatchAcrossRenderers: maxDiffPixels must be an integer ≥ 0, got ${String(maxDiffPixels)}`,
    );
  }
}

/** How a renderer's backend reads in a report line. */
export function describeProof(p: BackendProof | null, name: RendererName): string {
  if (p === null) return name === 'webgl' ? 'WebGLRenderer' : 'WebGPURenderer (not initialised)';
  if (name === 'webgl') return `WebGLRenderer, WebGL2: ${p.glRenderer}`;
  if (p.api === 'webgpu') {
    const a = p.adapter;
    const adapter =
      a === null ? 'adapter unknown' : [a.vendor, a.architecture, a.description].filter((s) => s).join(' ');
    return `WebGPURenderer, WebGPU backend (GPUDevice; ${adapter})`;
  }
  if (p.isWebGLBackend) return `WebGPURenderer, WebGL2 backend: ${p.glRenderer}`;
  return 'WebGPURenderer, no backend';
}

function decode(b64: string, width: number, height: number): RgbaImage {
  return { width, height, data: new Uint8Array(Buffer.from(b64, 'base64')) };
}

/**
 * The `toMatchAcrossRenderers` matcher: draw the scene of `scene` with `WebGLRenderer` and with
 * `WebGPURenderer` on its WebGPU and WebGL2 backends (or `options.renderers`), in the page, and compare each
 * picture with the first renderer's within the tolerance: each pixel within `maxChannelDiff` codes of the range
 * its `radiusPx` neighbourhood spans in the other picture. By default {@link RENDERER_TOLERANCE} when one
 * software rasteriser drew every picture (SwiftShader, or llvmpipe), else {@link GPU_TOLERANCE} (llvmpipe's
 * WebGL beside SwiftShader's WebGPU adapter, or a GPU, whose WebGL and WebGPU drivers differ). The page
 * must have called `exposeRenderers()` from `@shadelab/playwright/page`. `scene` is a factory function
 * (serialised into the page; see `SceneFactory`) or the name of a scene the page registered. Fails, whatever
 * `.not` says, when WebGPU was asked for and WebGPURenderer fell back to WebGL2 (the backend is proven:
 * `isWebGPUBackend` and a real `GPUDevice`), when a renderer throws, and when the first picture is blank. On
 * failure every picture, a diff per renderer beyond the tolerance and the backends (JSON) are attached.
 */
export async function toMatchAcrossRenderers(
  this: ExpectMatcherState,
  page: Page,
  scene: SceneFactory | string,
  options: AcrossRenderersOptions = {},
): Promise<MatcherReturnType> {
  const renderers = options.renderers ?? RENDERER_NAMES;
  checkOptions(options, renderers);
  if (typeof scene !== 'function' && (typeof scene !== 'string' || scene === '')) {
    throw new TypeError(
      `toMatchAcrossRenderers: scene must be a scene factory function or a registered scene's name, got ${String(scene)}`,
    );
  }
  const { width = 256, height = 256, name = 'renderers' } = options;
  const timeout = options.timeout ?? this.timeout;
  const what = typeof scene === 'string' ? JSON.stringify(scene) : 'scene';
  const hint = `expect(page).${this.isNot ? 'not.' : ''}toMatchAcrossRenderers(${what})`;
  // A failure that `.not` must not turn into a pass (a missing backend is not a difference).
  const broken = (why: string): MatcherReturnType => ({
    pass: this.isNot,
    name: 'toMatchAcrossRenderers',
    message: () => `${hint}\n\n${why}`,
  });
  try {
    await page.waitForFunction(
      (key) => (globalThis as Record<symbol, unknown>)[Symbol.for(key)] !== undefined,
      KEY,
      {
        timeout,
      },
    );
  } catch {
    return broken(
      `The page (${page.url()}) has no renderers for the kit after ${timeout} ms: a script of the page must import { exposeRenderers } from '@shadelab/playwright/page' and call exposeRenderers().`,
    );
  }
  const request: RenderRequest = { renderers: [...renderers], width, height, arg: options.arg };
  let handle: JSHandle | undefined;
  let pictures: RenderedPicture[];
  try {
    if (typeof scene === 'function') handle = await page.evaluateHandle(`(${scene.toString()})`);
    pictures = await page.evaluate(
      ([key, factory, req]) =>
        ((globalThis as Record<symbol, unknown>)[Symbol.for(key)] as PageRenderers).render(
          factory as SceneFactory | string,
          req,
        ),
      [KEY, handle ?? scene, request] as const,
    );
  } catch (error) {
    return broken(
      `The scene could not be drawn: ${error instanceof Error ? error.message.split('\n')[0] : String(error)}`,
    );
  } finally {
    await handle?.dispose().catch(() => undefined);
  }
  const lines = pictures.map((p) => `  ${p.renderer.padEnd(14)} ${describeProof(p.proof, p.renderer)}`);
  const backends = `Renderers (${width}×${height}):\n${lines.join('\n')}`;
  const info = currentTestInfo();
  const attachBackends = () =>
    info?.attach(`${name}-backends.json`, {
      body: JSON.stringify(
        pictures.map(({ renderer, proof, ...rest }) => ({
          renderer,
          proof,
          error: 'error' in rest ? rest.error : null,
        })),
        null,
        2,
      ),
      contentType: 'application/json',
    });
  const failed = pictures.filter((p) => !p.ok);
  const images = new Map<RendererName, RgbaImage>();
  for (const p of pictures) if (p.ok) images.set(p.renderer, decode(p.pixels, width, height));
  if (failed.length > 0) {
    for (const [r, image] of images) await attachImage(`${name}-${r}.png`, image);
    await attachBackends();
    const why = failed.map((p) => `  ${p.renderer}: ${(p as { error: string }).error}`).join('\n');
    return broken(
      `${failed.length === 1 ? 'A renderer' : 'Renderers'} could not draw the scene:\n${why}\n${backends}`,
    );
  }
  // One software rasteriser drew every picture: the renderers' own variation. Otherwise (llvmpipe's WebGL beside
  // SwiftShader's WebGPU, or a GPU's two drivers) the rasterisers' as well.
  const rasterisers = [...new Set(pictures.map((p) => rasteriserOf(describeProof(p.proof, p.renderer))))];
  const oneRasteriser = rasterisers.length === 1 && rasterisers[0] !== 'gpu';
  const defaults = oneRasteriser ? RENDERER_TOLERANCE : GPU_TOLERANCE;
  const tolerance: GpuTolerance = {
    maxChannelDiff: options.maxChannelDiff ?? defaults.maxChannelDiff,
    radiusPx: options.radiusPx ?? defaults.radiusPx,
    maxDiffPixels: options.maxDiffPixels ?? defaults.maxDiffPixels,
  };
  const [first, ...others] = renderers;
  const reference = images.get(first) as RgbaImage;
  const summary = summarisePicture(reference);
  if (summary.drawnPixels === 0) {
    await attachImage(`${name}-${first}.png`, reference);
    await attachBackends();
    return broken(
      `Nothing to compare: ${first}'s picture is blank (all ${width}×${height} pixels are ${rgbText(summary.background)}). Is the camera looking at the scene?\n${backends}`,
    );
  }
  const limits = `each pixel within ${tolerance.maxChannelDiff} codes of its ${2 * tolerance.radiusPx + 1}×${2 * tolerance.radiusPx + 1} neighbourhood's range, at most ${tolerance.maxDiffPixels} beyond`;
  const rows: string[] = [];
  const beyond: { renderer: RendererName; result: ReturnType<typeof compareNeighbourhood> }[] = [];
  for (const r of others) {
    const image = images.get(r) as RgbaImage;
    const result = compareNeighbourhood(image, reference, tolerance);
    const exact = compareNeighbourhood(image, reference, { radiusPx: 0, maxChannelDiff: 0 });
    const ok = result.failingPixels <= tolerance.maxDiffPixels;
    if (!ok) beyond.push({ renderer: r, result });
    const where =
      result.worst === null || ok
        ? ''
        : `, largest at x ${result.worst.x}, y ${result.worst.y} from the top left`;
    rows.push(
      `  ${r.padEnd(14)} ${String(result.failingPixels).padStart(6)} pixels beyond, largest excess ${result.maxExcess} codes${where} (exact: largest difference ${exact.maxExcess}, ${exact.failingPixels} pixels differ)${ok ? '' : '  ✗'}`,
    );
  }
  const pass = beyond.length === 0;
  if (!pass && !this.isNot) {
    for (const [r, image] of images) await attachImage(`${name}-${r}.png`, image);
    for (const { renderer: r, result } of beyond) {
      await attachImage(
        `${name}-${r}-diff.png`,
        diffImage(images.get(r) as RgbaImage, (k) =>
          result.excess[k] > 0 ? errorColour(result.excess[k], tolerance.maxChannelDiff) : null,
        ),
      );
    }
    await attachBackends();
  }
  const attached = pass
    ? ''
    : `\nAttached: ${renderers.map((r) => `${name}-${r}.png`).join(', ')}, ${beyond.map((b) => `${name}-${b.renderer}-diff.png`).join(', ')} (red: beyond the tolerance, orange: within) and ${name}-backends.json.`;
  const verdict = pass
    ? `Every renderer's picture matches ${first}'s within the tolerance (${limits}):`
    : `${beyond.map((b) => b.renderer).join(' and ')} ${beyond.length === 1 ? 'differs' : 'differ'} from ${first} beyond the tolerance (${limits}):`;
  const which = oneRasteriser
    ? `one rasteriser, ${rasterisers[0]}: RENDERER_TOLERANCE`
    : `${rasterisers.join(' and ')}: GPU_TOLERANCE`;
  return {
    pass,
    name: 'toMatchAcrossRenderers',
    message: () =>
      `${hint}\n\n${verdict}\n${rows.join('\n')}\n${backends}\nRasterisers: ${which}${options.maxChannelDiff !== undefined || options.radiusPx !== undefined || options.maxDiffPixels !== undefined ? ' where the options do not say' : ''}.${attached}`,
  };
}
