/**
 * The Mach-band tool's toggle (in the hint line under the view): it puts the view in profile mode
 * (`profileMode.tsx`, drawn over the canvas), where a drag across the canvas draws a line instead of turning the
 * trackball and a plot shows the intensity along it in flat, Gouraud and Phong shading. Only this toggle is in the
 * first frame's bundle: the mode, the read-back and the plot load when the mode is first turned on. Esc leaves the
 * mode. The learning tools' panel style lives here too.
 */
import { lazy, type RefObject, Suspense, useEffect, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';

const ProfileMode = lazy(() => import('./profileMode'));

/** A learning tool's panel (the plot and its text). */
export const LEARN_PANEL = {
  position: 'absolute',
  right: 8,
  width: 'min(320px, calc(100% - 16px))',
  zIndex: 1,
  padding: 6,
  background: '#181c20ee',
  border: '1px solid #444',
  borderRadius: 4,
  boxSizing: 'border-box',
  overflow: 'auto',
} as const;

/** The toggle and, while it is on, profile mode (see the module comment). */
export function ProfileTool({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const [on, setOn] = useState(false);
  useEffect(() => {
    if (!on) return;
    const onKey = (e: KeyboardEvent) => e.key === 'Escape' && setOn(false);
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [on]);
  if (isEmbedded()) return null;
  // Over the canvas: in its parent, the stage (this button sits in the hint line).
  const stage = on ? viewerRef.current?.canvas.parentElement : null;
  return (
    <>
      <button
        type="button"
        aria-pressed={on}
        title="Drag a line across the view to plot the intensity along it in flat, Gouraud and Phong shading (Esc leaves)"
        onClick={() => setOn(!on)}
      >
        intensity profile
      </button>
      {stage &&
        createPortal(
          <Suspense fallback={null}>
            <ProfileMode viewerRef={viewerRef} state={state} />
          </Suspense>,
          stage,
        )}
    </>
  );
}
