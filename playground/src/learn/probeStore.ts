/**
 * The probed point, published for the playground's other learning features (a tiny subscribe/get store): the
 * probe panel sets it whenever it probes (a click, or the view moved while it is open) and clears it when it
 * closes. Readers never change it.
 */
import type * as THREE from 'three';

/** The probe at a pixel: where it hit (world space), or null for a probe off the object. */
export interface Probe {
  /** The device pixel probed: x from the left, y from the top, in the canvas's drawing buffer. */
  readonly pixel: readonly [number, number];
  /** The surface point under the pixel's centre, world space; null off the object. */
  readonly point: readonly [number, number, number] | null;
  /** The unit normal the point is lit with (interpolated, or the face's for flat shading), world space. */
  readonly normal: readonly [number, number, number] | null;
  /** The mesh hit (a ShadingMaterial mesh: the sphere, or a part of the picked scene); null off the object. */
  readonly object: THREE.Mesh | null;
  /** The instance hit in an InstancedMesh; null otherwise. */
  readonly instanceId: number | null;
}

type Listener = (probe: Probe | null) => void;

let current: Probe | null = null;
const listeners = new Set<Listener>();

/** The current probe (null while the probe panel is closed), and its changes. */
export const probeStore = {
  /** The current probe; null while none is open. */
  get(): Probe | null {
    return current;
  },
  /** Calls `listener` with each new probe (null when the panel closes); returns the unsubscribe function. */
  subscribe(listener: Listener): () => void {
    listeners.add(listener);
    return () => {
      listeners.delete(listener);
    };
  },
  /** Publishes a probe (the probe panel only). */
  set(probe: Probe | null): void {
    current = probe;
    for (const listener of listeners) listener(probe);
  },
};
