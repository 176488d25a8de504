/**
 * The viewer's WebGPU switch: off (WebGL mode: the viewer's own WebGLRenderer), WebGPU mode on a canvas of its own
 * (`'canvas'`), or offscreen for the parity view (`'offscreen'`). WebGPUView.ts is loaded by dynamic import the
 * first time it is wanted, so that WebGL mode's bundle and first frame never pay for three/webgpu. Leaving drops
 * its renderer and canvas: the WebGL canvas draws the same state again.
 */
import type { GpuDraw, GpuFrame, GpuHost, GpuOutput, WebGPUEvents } from './status';
import type { WebGPUView } from './WebGPUView';

export type { GpuHost, WebGPUEvents } from './status';

export class WebGPUSwitch {
  private view: WebGPUView | null = null;
  private wanted: GpuOutput | null = null;

  constructor(
    private readonly host: GpuHost,
    private readonly events: WebGPUEvents,
  ) {}

  /** Where WebGPU draws now (its renderer may still be loading: {@link render} then draws nothing); null: off. */
  get output(): GpuOutput | null {
    return this.wanted;
  }

  /** Turns WebGPU on (drawing to `output`) or off (null). */
  set(output: GpuOutput | null): void {
    if (output === this.wanted) return;
    this.wanted = output;
    this.view?.dispose();
    this.view = null;
    if (output === null) {
      this.events.onStatus?.(null);
      this.host.requestRender();
      return;
    }
    this.events.onStatus?.({ state: 'loading' });
    import('./WebGPUView').then(
      ({ WebGPUView }) => {
        if (this.wanted === output && !this.view) this.view = new WebGPUView(this.host, this.events, output);
      },
      (error: unknown) =>
        this.events.onStatus?.({
          state: 'failed',
          message: `three/webgpu did not load: ${error instanceof Error ? error.message : String(error)}`,
        }),
    );
  }

  /** Draws a frame with `draw`; null when nothing was drawn (still loading, or off). */
  render(draw: GpuDraw, size?: { w: number; h: number }): GpuFrame | null {
    return this.view?.render(draw, size) ?? null;
  }

  /** The last offscreen frame's pixels (rows bottom-up); null when there is none. */
  read(): Promise<{ pixels: Uint8Array; w: number; h: number } | null> {
    return this.view?.read() ?? Promise.resolve(null);
  }

  dispose(): void {
    this.wanted = null;
    this.view?.dispose();
    this.view = null;
  }
}
