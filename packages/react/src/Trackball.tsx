import type { Trackball as TrackballControls } from '@shadelab/trackball';
import { type ReactNode, type Ref, useEffect, useImperativeHandle, useMemo } from 'react';
import { Group, type Object3D } from 'three';
import { type UseTrackballOptions, useTrackball } from './useTrackball.js';

/** What the {@link Trackball} component's `onChange`, `onStart` and `onEnd` receive. */
export interface TrackballEvent<Type extends 'change' | 'start' | 'end'> {
  /** The event's type. */
  readonly type: Type;
  /** The trackball that sent it. */
  readonly target: TrackballControls;
}

/** Props of {@link Trackball}. */
export interface TrackballProps extends UseTrackballOptions {
  /** What a drag turns. @default a group holding `children` (nothing to turn without children) */
  object?: Object3D | null;
  /** Placed in a group that the trackball turns (when no `object` is given). */
  children?: ReactNode;
  /** Called on every change (rotation, zoom, damping step), after R3F's frame was invalidated. */
  onChange?: (event: TrackballEvent<'change'>) => void;
  /** Called when a drag or pinch starts. */
  onStart?: (event: TrackballEvent<'start'>) => void;
  /** Called when a drag or pinch ends. */
  onEnd?: (event: TrackballEvent<'end'>) => void;
  /** Receives the `Trackball` instance. */
  ref?: Ref<TrackballControls>;
}

/**
 * The lecture's virtual trackball as an R3F component, like drei's controls: it listens on R3F's canvas and
 * uses the default camera (or the given `domElement` and `camera`), turns its `children` (or `object`),
 * invalidates the frame on change (`frameloop="demand"` works), becomes R3F's `controls` with `makeDefault`,
 * and removes every listener on unmount. See {@link useTrackball} for the hook.
 *
 * @example
 * <Trackball makeDefault>
 *   <mesh>…</mesh>
 * </Trackball>
 */
export function Trackball({ object, children, onChange, onStart, onEnd, ref, ...options }: TrackballProps) {
  const group = useMemo(() => new Group(), []);
  const turned = object === undefined ? group : object;
  const trackball = useTrackball(turned, options);
  useImperativeHandle(ref, () => trackball, [trackball]);

  useEffect(() => {
    const listeners = [
      ['change', onChange],
      ['start', onStart],
      ['end', onEnd],
    ] as const;
    const added: ['change' | 'start' | 'end', (event: never) => void][] = [];
    for (const [type, listener] of listeners) {
      if (!listener) continue;
      trackball.addEventListener(type, listener as never);
      added.push([type, listener as never]);
    }
    return () => {
      for (const [type, listener] of added) trackball.removeEventListener(type, listener as never);
    };
  }, [trackball, onChange, onStart, onEnd]);

  return <primitive object={group}>{children}</primitive>;
}
