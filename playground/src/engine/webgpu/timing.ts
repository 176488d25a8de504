/**
 * GPU time of WebGPURenderer's frames: three's timestamp queries (`trackTimestamp: true`, resolved with
 * `renderer.resolveTimestampsAsync('render')`), where the backend has them: the WebGPU backend with the adapter's
 * 'timestamp-query' feature, the WebGL2 backend with EXT_disjoint_timer_query_webgl2. Elsewhere (SwiftShader has
 * neither here) the time is "n/a", with the reason.
 */
import type { WebGPURenderer } from 'three/webgpu';
import type { GpuTime } from './status';

const _last = new WeakMap<
  WebGPURenderer,
  { ms: number | null; pending: boolean; onResult: (ms: number) => void }
>();

/**
 * The GPU time of a recent frame of `renderer` (the render passes since the last resolve), and a resolve started
 * for the frame just drawn; `onResult` is called when a new time arrives.
 */
export function timestamps(renderer: WebGPURenderer, onResult: (ms: number) => void): GpuTime {
  const backend = renderer.backend as { isWebGPUBackend?: boolean; trackTimestamp?: boolean };
  if (backend.trackTimestamp !== true) {
    return {
      ms: null,
      note:
        backend.isWebGPUBackend === true
          ? "GPU time n/a: the WebGPU adapter has no 'timestamp-query' feature"
          : 'GPU time n/a: no EXT_disjoint_timer_query_webgl2 on the WebGL2 backend',
    };
  }
  let last = _last.get(renderer);
  if (!last) {
    last = { ms: null, pending: false, onResult };
    _last.set(renderer, last);
  }
  last.onResult = onResult;
  if (!last.pending) {
    const entry = last;
    entry.pending = true;
    renderer.resolveTimestampsAsync('render').then(
      (ms) => {
        entry.pending = false;
        if (typeof ms === 'number' && Number.isFinite(ms) && ms > 0) {
          entry.ms = ms;
          entry.onResult(ms);
        }
      },
      () => {
        entry.pending = false;
      },
    );
  }
  return { ms: last.ms, note: last.ms === null ? 'GPU time: waiting for the first timestamps' : null };
}
