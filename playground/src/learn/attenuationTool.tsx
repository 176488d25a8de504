/**
 * The attenuation tool: a toggle (in the side column's tools) that opens, in the dock, the plot of each
 * light's 1/(a + b·t + c·t²) over the distances the scene spans, with the object's range of t marked
 * (`attenuationPlot.tsx`, loaded when first opened).
 */
import { lazy, type RefObject } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { LearnTool } from './learnTool';

const AttenuationPlot = lazy(() => import('./attenuationPlot'));

/** The toggle and, when open, the plot (see the module comment). */
export function AttenuationTool({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  return (
    <LearnTool
      viewerRef={viewerRef}
      label="attenuation curve"
      title="Plot each light's attenuation 1/(a + b·t + c·t²) against the distance, with the object's range marked"
      panel={{
        name: 'Attenuation curve',
        testId: 'attenuation-panel',
        loading: 'Loading the plot…',
      }}
    >
      <AttenuationPlot viewerRef={viewerRef} state={state} />
    </LearnTool>
  );
}
