import { useCallback, useEffect, useState } from 'react';

/** How long the panels wait for a first frame that does not come (a slow WebGPU start). */
const PANELS_WITHOUT_FRAME_MS = 3000;

/**
 * Whether the panels (ui/Panels.tsx) are mounted, and `firstFrame`, to call when the viewer reports its first
 * frame: they mount in the frame after it, at once when `failed` (a state that cannot be drawn, shown with the
 * panels to mend it with), or without a frame after PANELS_WITHOUT_FRAME_MS.
 */
export function usePanelsShown(failed: boolean): [shown: boolean, firstFrame: () => void] {
  const [shown, setShown] = useState(false);
  if (failed && !shown) setShown(true);
  useEffect(() => {
    if (shown) return;
    const timer = window.setTimeout(() => setShown(true), PANELS_WITHOUT_FRAME_MS);
    return () => window.clearTimeout(timer);
  }, [shown]);
  const firstFrame = useCallback(() => {
    requestAnimationFrame(() => window.setTimeout(() => setShown(true)));
  }, []);
  return [shown, firstFrame];
}
