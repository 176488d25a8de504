/**
 * The tools at the top of the side column: how to move the view, the trade-off page of this view, opening a model,
 * copy as code, and the learning tools' toggles (their panels open in the dock below, `dock.ts`).
 */
import type { RefObject } from 'react';
import { MOVE_KEYS, TURN_KEYS_TEXT } from '../engine/viewer/input';
import type { Viewer } from '../engine/viewer/Viewer';
import { AdaptiveTool } from '../learn/adaptiveTool';
import { AttenuationTool } from '../learn/attenuationTool';
import { CopyCodeButtons } from '../learn/CopyCodeButtons';
import { NormalMatrixTool } from '../learn/normalMatrixTool';
import { ProfileTool } from '../learn/profileTool';
import { type PlaygroundState, serializeState } from '../state/schema';
import { ModelPicker } from './ModelPicker';
import type { StatsFeed } from './Stats';
import type { Update } from './useFolder';
import type { ModelControls } from './useModel';

export function Tools({
  viewerRef,
  state,
  feed,
  update,
  model,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
  feed: StatsFeed;
  update: Update;
  model: ModelControls;
}) {
  return (
    <nav className="tools hint" aria-label="tools">
      <p>
        Drag or {TURN_KEYS_TEXT}: trackball · wheel: zoom ·{' '}
        <span title={`Click the view, then ${MOVE_KEYS}`}>camera keys on the clicked view</span> · Alt+click:
        probe a pixel
      </p>
      <p>
        <ModelPicker model={model} /> · <CopyCodeButtons state={state} /> ·{' '}
        <a href={`./tradeoff.html#${new URLSearchParams({ s: serializeState(state) })}`}>
          speed/accuracy trade-off of this view
        </a>
        <br />
        learn: <ProfileTool viewerRef={viewerRef} state={state} />{' '}
        <AttenuationTool viewerRef={viewerRef} state={state} />{' '}
        <NormalMatrixTool viewerRef={viewerRef} state={state} />{' '}
        <AdaptiveTool viewerRef={viewerRef} state={state} feed={feed} update={update} />
      </p>
    </nav>
  );
}
