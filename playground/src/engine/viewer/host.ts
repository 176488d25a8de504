/**
 * What the viewer's parts share: the viewer's objects they read (the host) and the events the app listens to.
 */
import type { Camera, CameraMovement } from '@shadelab/camera';
import type { Trackball } from '@shadelab/trackball';
import type * as THREE from 'three';
import type { PlaygroundState, Vec3 } from '../../state/schema';
import type { WebGPUEvents } from '../webgpu/switch';
import type { ParityResult } from './parity';
import type { FrameStats } from './stats';

/** The viewer's objects, as its parts see them (read when an event comes, never copied). */
export interface ViewerHost {
  readonly canvas: HTMLCanvasElement;
  readonly scene: THREE.Scene;
  readonly camera: Camera;
  /** The trackball turns this group; the sphere mesh and a picked scene sit in it. */
  readonly pivot: THREE.Group;
  readonly trackball: Trackball;
  /** The camera's movement keys (and gaze turns by drag). */
  readonly mover: CameraMovement;
  /** The state applied last; null before the first. */
  readonly state: PlaygroundState | null;
  /** Renders at the next animation frame. */
  requestRender(): void;
}

export interface ViewerEvents extends WebGPUEvents {
  /** The camera moved (movement keys) or the trackball turned; the new values for the state. */
  onView?: (view: {
    eye: Vec3;
    at: Vec3;
    up?: Vec3;
    zoom: number;
    rotation: [number, number, number, number];
  }) => void;
  /** The gizmo moved light `index` to `position`. */
  onLightMoved?: (index: number, position: Vec3) => void;
  /** Drawing failed (the message), or succeeded again (null). */
  onRenderError?: (message: string | null) => void;
  /** The compiled variant changed (its key and generated GLSL). */
  onVariant?: () => void;
  onStats?: (stats: FrameStats) => void;
  onContext?: (status: 'lost' | 'restored') => void;
  onFirstFrame?: (ms: number) => void;
  /** The parity view compared WebGL's and WebGPU's pictures of a frame. */
  onParity?: (result: ParityResult) => void;
}
