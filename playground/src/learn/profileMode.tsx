/**
 * Profile mode (loaded when the mode is first turned on): a left drag on the canvas draws a line instead of
 * turning the trackball; on release the line's pixels are read back from the view drawn
 * in flat, Gouraud and Phong shading (`profileSample.ts`) and plotted (`profilePlot.tsx`). A zero-length line
 * (both ends in one pixel) does nothing. The profile is read again after every change of the view (trackball
 * keys, panel edits) while the mode is on.
 */
import { type RefObject, useEffect, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { useDock } from '../ui/dock';
import { LEARN_PANEL } from './learnTool';
import { type CanvasPoint, linePixels } from './profileLine';
import ProfilePlot from './profilePlot';
import { type ProfileSamples, sampleProfile } from './profileSample';

/** A segment on the canvas, drawing-buffer pixels. */
type Segment = { from: CanvasPoint; to: CanvasPoint };
type Profile = { pixels: [number, number][]; samples: ProfileSamples };

/** Quiet time after a change of the view before the profile is read again, ms. */
const FOLLOW_MS = 200;

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

/** The overlay, the line and the plot's panel (see the module comment). */
export default function ProfileMode({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const dock = useDock();
  const [segment, setSegment] = useState<Segment | null>(null);
  const [dragging, setDragging] = useState<Segment | null>(null);
  const [profile, setProfile] = useState<Profile | null>(null);
  const [error, setError] = useState<string | null>(null);
  const blocked = unavailable(state, viewerRef.current);

  // Read the profile of the committed line, again after every change of the view (once the app applied it: its
  // effect runs after this child's, hence the delay).
  // biome-ignore lint/correctness/useExhaustiveDependencies: a new state is a new view to read, though unread here.
  useEffect(() => {
    if (!segment || blocked) return;
    const timer = window.setTimeout(() => {
      const viewer = viewerRef.current;
      if (!viewer) return;
      const pixels = linePixels(segment.from, segment.to, viewer.canvas.width, viewer.canvas.height);
      if (!pixels) return;
      try {
        setProfile({ pixels, samples: sampleProfile(viewer, pixels) });
        setError(null);
      } catch (e) {
        setError(e instanceof Error ? e.message : String(e));
      }
    }, FOLLOW_MS);
    return () => window.clearTimeout(timer);
  }, [segment, state, blocked, viewerRef]);

  const canvas = viewerRef.current?.canvas;
  const [bw, bh] = canvas ? [canvas.width, canvas.height] : [1, 1];

  // The drag is taken from the canvas before anything on it sees the press: a capturing listener on its parent
  // stops a left press on the canvas there, so the trackball, the light gizmo and the probe never get it, while the
  // controls over and under the view keep their clicks. Moves and the release are followed on the window.
  useEffect(() => {
    if (blocked || !canvas?.parentElement) return;
    const stage = canvas.parentElement;
    const at = (e: PointerEvent): CanvasPoint => {
      const box = canvas.getBoundingClientRect();
      return [
        ((e.clientX - box.left) * canvas.width) / box.width,
        ((e.clientY - box.top) * canvas.height) / box.height,
      ];
    };
    let from: CanvasPoint | null = null;
    const move = (e: PointerEvent) => from && setDragging({ from, to: at(e) });
    const up = (e: PointerEvent) => {
      if (!from) return;
      const line = { from, to: at(e) };
      from = null;
      setDragging(null);
      window.removeEventListener('pointermove', move);
      window.removeEventListener('pointerup', up);
      // A zero-length line (both ends in one pixel) does nothing: the last profile stays.
      if (linePixels(line.from, line.to, canvas.width, canvas.height)) setSegment(line);
    };
    const down = (e: PointerEvent) => {
      if (e.target !== canvas || e.button !== 0) return;
      e.stopPropagation();
      e.preventDefault();
      canvas.focus();
      from = at(e);
      setDragging({ from, to: from });
      window.addEventListener('pointermove', move);
      window.addEventListener('pointerup', up);
    };
    const cursor = canvas.style.cursor;
    canvas.style.cursor = 'crosshair';
    stage.addEventListener('pointerdown', down, { capture: true });
    return () => {
      canvas.style.cursor = cursor;
      stage.removeEventListener('pointerdown', down, { capture: true });
      window.removeEventListener('pointermove', move);
      window.removeEventListener('pointerup', up);
    };
  }, [blocked, canvas]);
  const shown = dragging ?? segment;

  return (
    <>
      {!blocked && (
        <svg
          data-testid="profile-overlay"
          viewBox={`0 0 ${bw} ${bh}`}
          preserveAspectRatio="none"
          aria-hidden="true"
          style={{ position: 'absolute', inset: 0, width: '100%', height: '100%', pointerEvents: 'none' }}
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
      {dock &&
        createPortal(
          <section style={LEARN_PANEL} aria-label="Mach bands: intensity profile" data-testid="profile-panel">
            {blocked ??
              error ??
              (!profile && 'Drag a line across the view: its intensity profile appears here.')}
            {!blocked && profile && <ProfilePlot pixels={profile.pixels} samples={profile.samples} />}
          </section>,
          dock,
        )}
    </>
  );
}
