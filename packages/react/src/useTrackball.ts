import { useFrame, useThree } from '@react-three/fiber';
import { Trackball, type TrackballCamera, type TrackballOptions } from '@shadelab/trackball';
import { useEffect, useLayoutEffect, useMemo } from 'react';
import type { Object3D } from 'three';

/** Options of {@link useTrackball}: the trackball's own options, and where it listens. */
export interface UseTrackballOptions extends Omit<TrackballOptions, 'camera'> {
  /** The camera whose frame the axes are fixed in and which the wheel zooms. @default R3F's default camera */
  camera?: TrackballCamera;
  /** The element it listens on. @default R3F's event source (`events.connected`), else the canvas (`gl.domElement`) */
  domElement?: HTMLElement;
  /** Keep spinning after release, slowing down (the hook steps it every frame). @default false */
  enableDamping?: boolean;
  /** Whether pointer and wheel input turn and zoom. @default true */
  enabled?: boolean;
  /** Make it R3F's default controls (`useThree((s) => s.controls)`), restored on unmount. @default false */
  makeDefault?: boolean;
}

let defaults: Trackball | undefined;

/**
 * A {@link Trackball} for R3F: created once per `object` (in `useMemo`), connected to the canvas and to the
 * default camera (or the given ones) in an effect, invalidating the frame on every change (so
 * `frameloop="demand"` redraws), stepped every frame while damping, and disposed on unmount. Options are
 * applied through the trackball's setters (validated as they are: a bad value throws a `RangeError` naming it).
 *
 * @param object - what a drag turns. @default none: the rotation is read with `getMatrix()` / `getWorldMatrix()`
 * @param options - the trackball's options, the camera and element it uses, `enabled` and `makeDefault`.
 * @returns the trackball (the same instance for the lifetime of `object`).
 */
export function useTrackball(object?: Object3D | null, options: UseTrackballOptions = {}): Trackball {
  // An option left out takes the trackball's own default, read from a trackball built with none (not restated
  // here), so removing a prop restores the default.
  defaults ??= new Trackball();
  const {
    camera,
    domElement,
    enabled = defaults.enabled,
    makeDefault = false,
    mapping = defaults.mapping,
    rotateSpeed = defaults.rotateSpeed,
    zoomSpeed = defaults.zoomSpeed,
    minZoom = defaults.minZoom,
    maxZoom = defaults.maxZoom,
    enableDamping = defaults.enableDamping,
    dampingFactor = defaults.dampingFactor,
    radius = defaults.radius,
    target,
  } = options;
  const defaultCamera = useThree((state) => state.camera);
  const gl = useThree((state) => state.gl);
  // `false` until R3F's pointer events connect, and for good on a root made without them (`createRoot`).
  const connected = useThree((state) => state.events.connected) as HTMLElement | false | undefined;
  const invalidate = useThree((state) => state.invalidate);
  const set = useThree((state) => state.set);
  const get = useThree((state) => state.get);

  // The pivot is read once, at creation (as the constructor does): a new target makes a new trackball.
  const targetKey = target ? target.toArray().join() : '';
  // biome-ignore lint/correctness/useExhaustiveDependencies: the target is keyed by its coordinates, read once.
  const trackball = useMemo(() => new Trackball(object ?? null, null, { target }), [object, targetKey]);

  const cam = (camera ?? defaultCamera) as unknown as TrackballCamera;
  useLayoutEffect(() => {
    trackball.camera = cam;
    trackball.mapping = mapping;
    trackball.rotateSpeed = rotateSpeed;
    trackball.zoomSpeed = zoomSpeed;
    // In an order that never passes through min > max.
    if (minZoom > trackball.maxZoom) {
      trackball.maxZoom = maxZoom;
      trackball.minZoom = minZoom;
    } else {
      trackball.minZoom = minZoom;
      trackball.maxZoom = maxZoom;
    }
    trackball.enableDamping = enableDamping;
    trackball.dampingFactor = dampingFactor;
    trackball.radius = radius;
    trackball.enabled = enabled;
  }, [
    trackball,
    cam,
    mapping,
    rotateSpeed,
    zoomSpeed,
    minZoom,
    maxZoom,
    enableDamping,
    dampingFactor,
    radius,
    enabled,
  ]);

  const element = domElement ?? (connected || gl.domElement);
  useEffect(() => {
    trackball.connect(element);
    const onChange = () => invalidate();
    trackball.addEventListener('change', onChange);
    return () => {
      trackball.removeEventListener('change', onChange);
      // Removes every listener it added (the element's and the document's during a drag), stops a spin.
      trackball.dispose();
    };
  }, [trackball, element, invalidate]);

  useEffect(() => {
    if (!makeDefault) return;
    const previous = get().controls;
    set({ controls: trackball });
    return () => {
      if (get().controls === trackball) set({ controls: previous });
    };
  }, [makeDefault, trackball, get, set]);

  // Damping: keep spinning after release; update() sends `change` (which invalidates) while it moves.
  useFrame((_, delta) => {
    if (trackball.enableDamping) trackball.update(Math.max(delta, 0));
  }, -1);

  return trackball;
}
