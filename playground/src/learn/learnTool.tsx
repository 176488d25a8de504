/**
 * What the learning tools of the hint line under the view share: a toggle button that, while on, shows the tool
 * over the canvas (in its parent, the stage; the tool's code is `lazy`, loaded when first turned on, in a
 * `Suspense`: the `panel` given here, or the tool's own); Esc turns it off. Not shown in embed mode. The tools' panel
 * style lives here too.
 */
import { type CSSProperties, type ReactNode, type RefObject, Suspense, useEffect, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';

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

/**
 * A tool's panel: its accessible name, test id, where it sits ({@link LEARN_PANEL} + `style`) and the text shown
 * while its code loads.
 */
export interface LearnPanelProps {
  name: string;
  testId: string;
  style: CSSProperties;
  loading: string;
}

/**
 * The toggle (`label`, with `title` as its tooltip) and, while it is on, `children` over the canvas: in a
 * {@link LEARN_PANEL} section when `panel` is given.
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
  if (isEmbedded()) return null;
  const stage = on ? viewerRef.current?.canvas.parentElement : null;
  return (
    <>
      <button type="button" aria-pressed={on} title={title} onClick={() => setOn(!on)}>
        {label}
      </button>
      {stage &&
        createPortal(
          panel ? (
            <section
              style={{ ...LEARN_PANEL, ...panel.style }}
              aria-label={panel.name}
              data-testid={panel.testId}
            >
              <Suspense fallback={panel.loading}>{children}</Suspense>
            </section>
          ) : (
            children
          ),
          stage,
        )}
    </>
  );
}
