/**
 * The Mach-band tool's toggle: it puts the view in profile mode (`profileMode.tsx`), where a drag across the canvas
 * draws a line instead of turning the trackball and a plot shows the intensity along it in flat, Gouraud and Phong
 * shading. Only this toggle is in the first frame's bundle: the mode, the read-back and the plot load when the mode
 * is first turned on. Esc leaves the mode. The learning tools' shared styles live here too.
 */
import { lazy, type RefObject, Suspense, useEffect, useState } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';

const ProfileMode = lazy(() => import('./profileMode'));

/** The styles of the learning tools' buttons and panels (over the canvas, at its right). */
export const LEARN_BUTTON = {
  position: 'absolute',
  right: 8,
  width: 132,
  padding: '3px 6px',
  whiteSpace: 'nowrap',
  background: '#2a2f36',
  color: '#ddd',
  border: '1px solid #444',
  borderRadius: 3,
  font: '12px system-ui, sans-serif',
  cursor: 'pointer',
} as const;
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
  return (
    <>
      <button
        type="button"
        style={{ ...LEARN_BUTTON, top: 8, ...(on ? { background: '#3d5a80' } : {}) }}
        aria-pressed={on}
        title="Drag a line across the view to plot the intensity along it in flat, Gouraud and Phong shading (Esc leaves)"
        onClick={() => setOn(!on)}
      >
        intensity profile
      </button>
      {on && (
        <Suspense fallback={null}>
          <ProfileMode viewerRef={viewerRef} state={state} />
        </Suspense>
      )}
    </>
  );
}
