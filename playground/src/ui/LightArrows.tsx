/**
 * An arrow at the view's border for each of the panel's lights the view does not show (lightArrows.ts), with the
 * light's number: the lecture's light 1 sits behind the eye, and its gizmo cannot be dragged in the view. Redrawn
 * after each frame (the camera may have moved); in the single view of the scenes the panel's lights light.
 */
import { type RefObject, useEffect, useState } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';
import { type LightArrow, lightArrows } from './lightArrows';
import type { StatsFeed } from './Stats';

/** Room for the arrow and its label inside the border, px. */
const MARGIN = 34;

export function LightArrows({
  viewerRef,
  state,
  feed,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
  feed: StatsFeed;
}) {
  const [arrows, setArrows] = useState<LightArrow[]>([]);
  const shown = state.view === 'single' && state.scene !== 'model' && !isEmbedded();
  const positions = JSON.stringify(state.lights.map((l) => l.position));
  useEffect(() => {
    if (!shown) {
      setArrows([]);
      return;
    }
    const lights = JSON.parse(positions) as [number, number, number][];
    const place = () => {
      const viewer = viewerRef.current;
      if (!viewer) return;
      const { clientWidth: w, clientHeight: h } = viewer.canvas;
      const next = lightArrows(viewer.camera, lights, w, h, MARGIN);
      setArrows((previous) => (JSON.stringify(previous) === JSON.stringify(next) ? previous : next));
    };
    place();
    return feed.subscribe(place);
  }, [feed, viewerRef, shown, positions]);
  return arrows.map(({ index, x, y, angle, behind }) => (
    <div
      key={index}
      className="light-arrow"
      data-testid="light-arrow"
      data-light={index + 1}
      role="note"
      aria-label={`Light ${index + 1} is ${behind ? 'behind the eye' : 'outside the view'}: this way`}
      style={{ left: x, top: y }}
    >
      <span style={{ transform: `rotate(${angle}rad)` }}>➤</span> light {index + 1}
    </div>
  ));
}
