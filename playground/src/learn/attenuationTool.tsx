/**
 * The attenuation tool: a toggle (in the hint line under the view) that opens, over the canvas, the plot of each light's 1/(a + b·t + c·t²) over the distances the
 * scene spans, with the object's range of t marked (`attenuationPlot.tsx`, loaded when first opened).
 */
import { lazy, type RefObject, Suspense, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';
import { LEARN_PANEL } from './profileTool';

const AttenuationPlot = lazy(() => import('./attenuationPlot'));

/** The toggle and, when open, the plot (see the module comment). */
export function AttenuationTool({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const [open, setOpen] = useState(false);
  if (isEmbedded()) return null;
  // Over the canvas: in its parent, the stage (this button sits in the hint line).
  const stage = open ? viewerRef.current?.canvas.parentElement : null;
  return (
    <>
      <button
        type="button"
        aria-pressed={open}
        title="Plot each light's attenuation 1/(a + b·t + c·t²) against the distance, with the object's range marked"
        onClick={() => setOpen(!open)}
      >
        attenuation curve
      </button>
      {stage &&
        createPortal(
          <section
            style={{ ...LEARN_PANEL, bottom: 52, maxHeight: 'calc(50% - 56px)' }}
            aria-label="Attenuation curve"
            data-testid="attenuation-panel"
          >
            <Suspense fallback="Loading the plot…">
              <AttenuationPlot viewerRef={viewerRef} state={state} />
            </Suspense>
          </section>,
          stage,
        )}
    </>
  );
}
