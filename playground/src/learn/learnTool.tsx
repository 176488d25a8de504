/**
 * What the learning tools share: a toggle button (in the side column's tools) that, while on, shows the tool: its
 * `panel` in the dock (`ui/dock.ts`), or, without one, the tool's own parts in the stage (what it draws over the
 * view; its panel it docks itself). The tool's code is `lazy`, loaded when first turned on, in a `Suspense`. Esc
 * turns it off. Not shown in embed mode. The panels' style lives here too.
 */
import { type ReactNode, type RefObject, Suspense, useEffect, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import { useDock } from '../ui/dock';

/** A learning tool's panel (the plot and its text), in the dock. */
export const LEARN_PANEL = {
  flex: '0 0 auto',
  padding: 6,
  background: '#1f262d',
  border: '1px solid #444',
  borderRadius: 4,
  boxSizing: 'border-box',
  overflow: 'auto',
} as const;

/** A tool's panel: its accessible name, test id and the text shown while its code loads. */
export interface LearnPanelProps {
  name: string;
  testId: string;
  loading: string;
}

/**
 * The toggle (`label`, with `title` as its tooltip) and, while it is on, `children`: in a {@link LEARN_PANEL}
 * section in the dock when `panel` is given, else in the stage.
 */
export function LearnTool({
  viewerRef,
  label,
  title,
  panel,
  children,
}: {
  viewerRef: RefObject<Viewer | null>;
  label: string;
  title: string;
  panel?: LearnPanelProps;
  children: ReactNode;
}) {
  const [on, setOn] = useState(false);
  useEffect(() => {
    if (!on) return;
    const onKey = (e: KeyboardEvent) => e.key === 'Escape' && setOn(false);
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [on]);
  const dock = useDock();
  if (isEmbedded()) return null;
  const target = on ? (panel ? dock : viewerRef.current?.canvas.parentElement) : null;
  return (
    <>
      <button type="button" aria-pressed={on} title={title} onClick={() => setOn(!on)}>
        {label}
      </button>
      {target &&
        createPortal(
          panel ? (
            <section style={LEARN_PANEL} aria-label={panel.name} data-testid={panel.testId}>
              <Suspense fallback={panel.loading}>{children}</Suspense>
            </section>
          ) : (
            children
          ),
          target,
        )}
    </>
  );
}
