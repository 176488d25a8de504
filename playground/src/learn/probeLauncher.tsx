/**
 * Alt+click on the view opens the pixel probe (a plain drag still turns the trackball), in the dock. This part is
 * loaded with the app and is tiny; the panel and the probe's code (probePanel.tsx) load on the first Alt+click. Not
 * in embed mode, which shows the view alone.
 */
import { lazy, type RefObject, Suspense, useEffect, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';
import { useDock } from '../ui/dock';
import type { ProbeRequest } from './probePanel';

const ProbePanel = lazy(() => import('./probePanel'));

/** Listens for Alt+click on the view and shows the probe panel for the clicked pixel until it is closed. */
export function ProbeLauncher({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const dock = useDock();
  const [request, setRequest] = useState<ProbeRequest | null>(null);
  useEffect(() => {
    if (isEmbedded()) return;
    let serial = 0;
    const onClick = (event: MouseEvent) => {
      const target = event.target as HTMLElement | null;
      if (!event.altKey || target?.dataset['testid'] !== 'viewport') return;
      event.preventDefault();
      serial++;
      setRequest({ clientX: event.clientX, clientY: event.clientY, serial });
    };
    document.addEventListener('click', onClick);
    return () => document.removeEventListener('click', onClick);
  }, []);
  if (!request || !dock) return null;
  return createPortal(
    <Suspense fallback={null}>
      <ProbePanel viewerRef={viewerRef} state={state} request={request} onClose={() => setRequest(null)} />
    </Suspense>,
    dock,
  );
}
