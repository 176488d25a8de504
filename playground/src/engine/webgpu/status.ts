/**
 * What WebGPU mode tells the user: which backend of three's WebGPURenderer runs and why, and which of the
 * panel's settings it does not draw. Pure functions of the state and the status (no three/webgpu here: this
 * file is in the WebGL bundle).
 */
import type { PlaygroundState } from '../../state/schema';

/** Why WebGPURenderer runs its WebGL2 backend instead of WebGPU. */
export type FallbackReason = 'no-webgpu' | 'no-adapter' | 'device-lost' | 'init-failed';

/** The state of WebGPU mode: loading three/webgpu, running on a backend, or failed altogether. */
export type WebGPUStatus =
  | { readonly state: 'loading' }
  | {
      readonly state: 'running';
      readonly backend: 'webgpu' | 'webgl2';
      /** Why the WebGL2 backend runs; null when WebGPU runs. */
      readonly reason: FallbackReason | null;
      /** The browser's message (a lost device's, a failed init's), when there is one. */
      readonly message?: string;
    }
  | { readonly state: 'failed'; readonly message: string };

/** The generated shader of the mesh's node material: WGSL on the WebGPU backend, GLSL on the WebGL2 backend. */
export interface GeneratedShader {
  readonly language: 'WGSL' | 'GLSL';
  readonly vertexShader: string;
  readonly fragmentShader: string;
}

const REASONS: Record<FallbackReason, string> = {
  'no-webgpu': 'this browser has no WebGPU',
  'no-adapter': 'no WebGPU adapter',
  'device-lost': 'the WebGPU device was lost',
  'init-failed': 'WebGPU failed to start',
};

/** The label of the running backend: "WebGPU", "WebGL2 (WebGPU's fallback: no WebGPU adapter)", … */
export function backendLabel(status: WebGPUStatus): string {
  switch (status.state) {
    case 'loading':
      return 'WebGPU mode: loading three/webgpu…';
    case 'failed':
      return `WebGPU mode failed (${status.message}); switch the renderer back to WebGL`;
    case 'running': {
      if (status.backend === 'webgpu') return 'WebGPU';
      const why = status.reason ? REASONS[status.reason] : 'forced';
      return `WebGL2 (WebGPU's fallback: ${why}${status.message ? `: ${status.message}` : ''})`;
    }
  }
}

/**
 * What WebGPU mode does not draw of the state, one sentence each (empty: everything set is drawn). The settings
 * are kept: switching back to WebGL draws them again.
 */
export function webgpuNotes(state: PlaygroundState): string[] {
  const notes: string[] = [];
  if (state.scene !== 'sphere')
    notes.push(
      `WebGPU mode draws the lecture's sphere only: the "${state.scene}" scene is drawn in WebGL mode.`,
    );
  if (state.view === 'compare')
    notes.push('The comparison view is WebGL-only: WebGPU mode shows the single view.');
  if (state.sphere.render === 'impostor')
    notes.push('The ray-cast impostor is WebGL-only: WebGPU mode draws the subdivided mesh.');
  if (state.material.outline && state.material.celBands > 0)
    notes.push('The cel outline is WebGL-only (an inverted-hull ShaderMaterial): not drawn in WebGPU mode.');
  if (state.camera.depth !== 'standard')
    notes.push(`The "${state.camera.depth}" depth buffer is WebGL-only: WebGPU mode uses the standard one.`);
  notes.push(
    'The shader panel shows the node material’s generated code, read-only (GLSL editing is WebGL-only); the stats are WebGL mode’s.',
  );
  return notes;
}
