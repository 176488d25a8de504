/**
 * What WebGPU mode tells the user: which backend of three's WebGPURenderer runs and why, and which of the
 * panel's settings it does not draw. Pure functions of the state and the status (no three/webgpu here: this
 * file is in the WebGL bundle).
 */
import type * as THREE from 'three';
import type { PlaygroundState } from '../../state/schema';
import type { CellRenderer } from '../viewer/layout';

/** What WebGPU mode needs of the viewer: its canvas (the overlay's size and place), scene, camera and mesh. */
export interface GpuHost {
  readonly canvas: HTMLCanvasElement;
  readonly scene: THREE.Scene;
  readonly camera: THREE.Camera;
  /** The lecture's sphere (the shader panel shows its node material's code). */
  readonly mesh: THREE.Mesh;
  requestRender(): void;
}

/** What WebGPU mode reports to the app. */
export interface WebGPUEvents {
  /** The backend that runs (and why), or null when WebGPU mode is left. */
  onStatus?: (status: WebGPUStatus | null) => void;
  /** The mesh material's generated shader, after a variant change or a backend change. */
  onShader?: (shader: GeneratedShader | null) => void;
  /** A frame's GPU time arrived (three's timestamp queries), ms. */
  onGpuTime?: (ms: number) => void;
}

/** Where WebGPU mode draws: its own canvas over the WebGL one, or a render target read back (the parity view). */
export type GpuOutput = 'canvas' | 'offscreen';

/** Draws a frame's views with `renderer` on a `w` × `h` target (the viewer's draw code). */
export type GpuDraw = (renderer: CellRenderer, w: number, h: number) => void;

/** GPU time of a recent frame, ms, or null with why (`note`). */
export interface GpuTime {
  readonly ms: number | null;
  readonly note: string | null;
}

/** What a WebGPU frame drew and cost. */
export interface GpuFrame {
  /** CPU time of the frame's submission, ms. */
  readonly cpuMs: number;
  readonly gpuMs: GpuTime;
  /** Triangles drawn in the frame (three's count, every cell). */
  readonly triangles: number;
  /** Programs (pipelines' shader modules) alive (three's `info.memory.programs`). */
  readonly programs: number;
}

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
 * What WebGPU mode draws differently from WebGL mode for the state, one sentence each (the shader panel's note
 * always). The settings are kept: switching back to WebGL draws them as before.
 */
export function webgpuNotes(state: PlaygroundState): string[] {
  const notes: string[] = [];
  if (state.scene === 'lights')
    notes.push(
      "The fog is three's node fog, blended in linear before the output conversion (WebGL blends after it): fogged colours differ.",
    );
  if (state.scene === 'model')
    notes.push(
      "Your model's materials are swapped with swapNodeMaterials; a material the swap skipped (a ShaderMaterial) is not drawn by WebGPURenderer.",
    );
  if (state.camera.depth !== 'standard')
    notes.push(`The "${state.camera.depth}" depth buffer is WebGL-only: WebGPU mode uses the standard one.`);
  notes.push(
    'The shader panel shows the node material’s generated code, read-only (GLSL editing is WebGL-only).',
  );
  return notes;
}
