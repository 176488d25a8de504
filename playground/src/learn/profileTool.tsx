/**
 * The Mach-band tool: a toggle that puts the view in profile mode, where a drag across the canvas draws a line
 * (instead of turning the trackball) and the plot shows the intensity along it in flat, Gouraud and Phong shading.
 * Only the toggle and the drag are in the first frame's bundle; the plot and the read-back load with the first
 * profile. The profile follows every change of the view (trackball keys, panel edits) while the mode is on.
 */
import { lazy, type PointerEvent, type RefObject, Suspense, useEffect, useRef, useState } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';
import { type CanvasPoint, linePixels } from './profileLine';
import type { ProfileSamples } from './profileSample';

const ProfilePlot = lazy(() => import('./profilePlot'));

/** A segment on the canvas, drawing-buffer pixels. */
type Segment = { from: CanvasPoint; to: CanvasPoint };
type Profile = { pixels: [number, number][]; samples: ProfileSamples };

/** Quiet time after a change of the view before the profile is read again, ms. */
const FOLLOW_MS = 200;

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

/** Why the profile cannot be read in this state, or null when it can. */
function unavailable(state: PlaygroundState, viewer: Viewer | null): string | null {
  if (state.view !== 'single' || state.renderer !== 'webgl') {
    return 'The profile reads the single view in WebGL mode: choose view "single sphere" and renderer "WebGL".';
  }
  if (viewer && viewer.material.fragmentShader !== viewer.getShaderSource().fragmentShader) {
    return 'A GLSL edit is running; each shading compiles its own program, which would drop it. Reset the edit to read a profile.';
  }
  return null;
}

/** The toggle, the line overlay in profile mode, and the plot (see the module comment). */
export function ProfileTool({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const [on, setOn] = useState(false);
  const [segment, setSegment] = useState<Segment | null>(null);
  const [dragging, setDragging] = useState<Segment | null>(null);
  const [profile, setProfile] = useState<Profile | null>(null);
  const [error, setError] = useState<string | null>(null);
  const overlay = useRef<SVGSVGElement>(null);
  const blocked = unavailable(state, viewerRef.current);

  // Read the profile of the committed line, again after every change of the view (once it is applied).
  // biome-ignore lint/correctness/useExhaustiveDependencies: a new state is a new view to read, though unread here.
  useEffect(() => {
    if (!on || !segment || blocked) return;
    const timer = window.setTimeout(async () => {
      const viewer = viewerRef.current;
      if (!viewer) return;
      const pixels = linePixels(segment.from, segment.to, viewer.canvas.width, viewer.canvas.height);
      if (!pixels) return;
      try {
        const { sampleProfile } = await import('./profileSample');
        setProfile({ pixels, samples: sampleProfile(viewer, pixels) });
        setError(null);
      } catch (e) {
        setError(e instanceof Error ? e.message : String(e));
      }
    }, FOLLOW_MS);
    return () => window.clearTimeout(timer);
  }, [on, segment, state, blocked, viewerRef]);

  useEffect(() => {
    if (!on) return;
    const onKey = (e: KeyboardEvent) => e.key === 'Escape' && setOn(false);
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [on]);

  if (isEmbedded()) return null;

  /** The pointer's position in the canvas's drawing-buffer pixels. */
  const at = (e: PointerEvent<SVGSVGElement>): CanvasPoint => {
    const canvas = viewerRef.current?.canvas;
    const box = e.currentTarget.getBoundingClientRect();
    const [sx, sy] = canvas ? [canvas.width / box.width, canvas.height / box.height] : [1, 1];
    return [(e.clientX - box.left) * sx, (e.clientY - box.top) * sy];
  };
  const onDown = (e: PointerEvent<SVGSVGElement>) => {
    if (e.button !== 0) return;
    e.currentTarget.setPointerCapture(e.pointerId);
    const p = at(e);
    setDragging({ from: p, to: p });
  };
  const onMove = (e: PointerEvent<SVGSVGElement>) => dragging && setDragging({ ...dragging, to: at(e) });
  const onUp = (e: PointerEvent<SVGSVGElement>) => {
    if (!dragging) return;
    const line = { ...dragging, to: at(e) };
    setDragging(null);
    const canvas = viewerRef.current?.canvas;
    // A zero-length line (both ends in one pixel) does nothing: the last profile stays.
    if (canvas && linePixels(line.from, line.to, canvas.width, canvas.height)) setSegment(line);
  };

  const shown = dragging ?? segment;
  const canvas = viewerRef.current?.canvas;
  const [bw, bh] = canvas ? [canvas.width, canvas.height] : [1, 1];
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
      {on && !blocked && (
        <svg
          ref={overlay}
          data-testid="profile-overlay"
          viewBox={`0 0 ${bw} ${bh}`}
          preserveAspectRatio="none"
          aria-label="Profile mode: drag a line across the view"
          style={{
            position: 'absolute',
            inset: 0,
            width: '100%',
            height: '100%',
            cursor: 'crosshair',
            touchAction: 'none',
          }}
          onPointerDown={onDown}
          onPointerMove={onMove}
          onPointerUp={onUp}
          onPointerCancel={() => setDragging(null)}
        >
          {shown && (
            <line
              data-testid="profile-line"
              x1={shown.from[0]}
              y1={shown.from[1]}
              x2={shown.to[0]}
              y2={shown.to[1]}
              stroke="#fff"
              strokeDasharray="4 3"
              vectorEffect="non-scaling-stroke"
            />
          )}
        </svg>
      )}
      {on && (
        <section
          style={{ ...LEARN_PANEL, top: 64 }}
          aria-label="Mach bands: intensity profile"
          data-testid="profile-panel"
        >
          {blocked ??
            error ??
            (!profile && 'Drag a line across the view: its intensity profile appears here.')}
          {!blocked && profile && (
            <Suspense fallback="Loading the plot…">
              <ProfilePlot pixels={profile.pixels} samples={profile.samples} />
            </Suspense>
          )}
        </section>
      )}
    </>
  );
}
