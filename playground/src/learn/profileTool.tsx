/**
 * The Mach-band tool's toggle (in the side column's tools): it puts the view in profile mode
 * (`profileMode.tsx`, drawn over the canvas), where a drag across the canvas draws a line instead of turning the
 * trackball and a plot shows the intensity along it in flat, Gouraud and Phong shading. Only this toggle is in the
 * first frame's bundle: the mode, the read-back and the plot load when the mode is first turned on. Esc leaves the
 * mode.
 */
import { lazy, type RefObject, Suspense } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { LearnTool } from './learnTool';

const ProfileMode = lazy(() => import('./profileMode'));

/** The toggle and, while it is on, profile mode (see the module comment). */
export function ProfileTool({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  return (
    <LearnTool
      viewerRef={viewerRef}
      label="intensity profile"
      title="Drag a line across the view to plot the intensity along it in flat, Gouraud and Phong shading (Esc leaves)"
    >
      <Suspense fallback={null}>
        <ProfileMode viewerRef={viewerRef} state={state} />
      </Suspense>
    </LearnTool>
  );
}
