/**
 * The viewer's renderer switch: WebGL mode (the viewer's own WebGLRenderer) or WebGPU mode (WebGPUView.ts, loaded
 * by dynamic import the first time it is wanted, so that WebGL mode's bundle and first frame never pay for
 * three/webgpu). Leaving WebGPU mode drops its renderer and canvas: the WebGL canvas draws the same state again.
 */
import type { GpuHost, WebGPUEvents, WebGPUView } from './WebGPUView';

export type { GpuHost, WebGPUEvents } from './WebGPUView';

export class WebGPUSwitch {
  private view: WebGPUView | null = null;
  private wanted = false;

  constructor(
    private readonly host: GpuHost,
    private readonly events: WebGPUEvents,
  ) {}

  /** Whether WebGPU mode is on (its renderer may still be loading: {@link render} then draws nothing). */
  get active(): boolean {
    return this.wanted;
  }

  /** Turns WebGPU mode on or off. */
  set(enabled: boolean): void {
    if (enabled === this.wanted) return;
    this.wanted = enabled;
    if (!enabled) {
      this.view?.dispose();
      this.view = null;
      this.events.onStatus?.(null);
      this.host.requestRender();
      return;
    }
    this.events.onStatus?.({ state: 'loading' });
    import('./WebGPUView').then(
      ({ WebGPUView }) => {
        if (this.wanted && !this.view) this.view = new WebGPUView(this.host, this.events);
      },
      (error: unknown) =>
        this.events.onStatus?.({
          state: 'failed',
          message: `three/webgpu did not load: ${error instanceof Error ? error.message : String(error)}`,
        }),
    );
  }

  /** Draws a frame in WebGPU mode; false when nothing was drawn (still loading, or off). */
  render(): boolean {
    return this.view?.render() ?? false;
  }

  dispose(): void {
    this.wanted = false;
    this.view?.dispose();
    this.view = null;
  }
}
