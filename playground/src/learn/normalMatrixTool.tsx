/**
 * The normal-matrix tool: a toggle (in the side column's tools) that opens, in the dock, the lecture's
 * slide live (`normalMatrixView.tsx`, loaded when first opened): the sphere shaded with (M⁻¹)ᵀ and with M side by
 * side, with the tangent and both normals at the probed point.
 */
import { lazy, type RefObject } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { LearnTool } from './learnTool';

const NormalMatrixView = lazy(() => import('./normalMatrixView'));

/** The toggle and, when open, the figure (see the module comment). */
export function NormalMatrixTool({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  return (
    <LearnTool
      viewerRef={viewerRef}
      label="normal matrix"
      title="The sphere shaded with the normal matrix (M⁻¹)ᵀ and with M side by side, with the tangent and both normals at the probed point"
      panel={{
        name: 'The normal matrix',
        testId: 'normal-matrix-panel',
        loading: 'Loading the figure…',
      }}
    >
      <NormalMatrixView viewerRef={viewerRef} state={state} />
    </LearnTool>
  );
}
