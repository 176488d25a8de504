/**
 * The "copy as code" buttons (in the side column's tools): each puts the current scene's program on the
 * clipboard and shows it in a dialog (from which it can be selected and copied when the clipboard is refused).
 * The generators are loaded on the first click.
 */
import { useEffect, useRef, useState } from 'react';
import { createPortal } from 'react-dom';
import { type PlaygroundState, validateState } from '../state/schema';
import type { CodeVariant } from './copyCode';

const LABELS: Record<CodeVariant, { button: string; title: string; file: string }> = {
  three: { button: 'three.js', title: 'three.js program', file: 'src/main.ts' },
  r3f: { button: 'R3F', title: 'React Three Fiber (R3F) app', file: 'src/main.tsx' },
};

const DIALOG_STYLE = {
  position: 'fixed',
  inset: '5vh 5vw',
  zIndex: 1000,
  display: 'flex',
  flexDirection: 'column',
  gap: 6,
  padding: 10,
  background: '#1b1e23',
  color: '#ddd',
  border: '1px solid #444',
  borderRadius: 6,
  font: '12px system-ui, sans-serif',
} as const;

/** What the dialog shows: the variant, its code, and whether it reached the clipboard. */
interface Shown {
  variant: CodeVariant;
  code: string;
  copied: boolean | null;
}

/** The two buttons and, after a click, the dialog with the code. */
export function CopyCodeButtons({ state }: { state: PlaygroundState }) {
  const [shown, setShown] = useState<Shown | null>(null);
  const [error, setError] = useState<string | null>(null);
  const copy = async (variant: CodeVariant) => {
    const checked = validateState(state);
    if (!checked.ok) {
      setError(`Not copied: ${checked.error}`);
      return;
    }
    setError(null);
    const { programOf } = await import('./copyCode');
    const code = programOf(variant, checked.state);
    setShown({ variant, code, copied: null });
    const copied = await navigator.clipboard?.writeText(code).then(
      () => true,
      () => false,
    );
    setShown((s) => (s?.code === code ? { ...s, copied: copied ?? false } : s));
  };
  const label = shown && LABELS[shown.variant];
  const opener = useRef<HTMLButtonElement | null>(null);
  const close = useRef<HTMLButtonElement | null>(null);
  const isShown = shown !== null;
  // While the dialog is open, Escape closes it; the close button takes the focus, and the button that opened the
  // dialog gets it back.
  useEffect(() => {
    if (!isShown) return;
    const returnTo = opener.current;
    close.current?.focus();
    const onKey = (event: KeyboardEvent) => {
      if (event.key === 'Escape') setShown(null);
    };
    document.addEventListener('keydown', onKey);
    return () => {
      document.removeEventListener('keydown', onKey);
      returnTo?.focus();
    };
  }, [isShown]);
  return (
    <span>
      copy as code:{' '}
      {(Object.keys(LABELS) as CodeVariant[]).map((variant) => (
        <button
          key={variant}
          type="button"
          data-testid={`copy-code-${variant}`}
          aria-label={`copy as code: ${LABELS[variant].title}`}
          onClick={(event) => {
            opener.current = event.currentTarget;
            void copy(variant);
          }}
        >
          {LABELS[variant].button}
        </button>
      ))}
      {error && <span role="alert"> {error}</span>}
      {shown &&
        label &&
        createPortal(
          <div
            role="dialog"
            aria-modal="true"
            aria-label={`Copy as code: ${label.title}`}
            style={DIALOG_STYLE}
          >
            <div>
              <strong>{label.title}</strong> ({label.file} of a Vite app;{' '}
              {shown.copied === null
                ? 'copying…'
                : shown.copied
                  ? 'copied to the clipboard'
                  : 'the clipboard was refused: select the code and copy it'}
              ){' '}
              <button type="button" ref={close} onClick={() => setShown(null)}>
                close
              </button>
            </div>
            <textarea
              readOnly
              aria-label={`${label.title}: ${label.file}`}
              data-testid="copy-code"
              data-variant={shown.variant}
              value={shown.code}
              spellCheck={false}
              style={{ flex: 1, background: '#111', color: '#ddd', font: '12px ui-monospace, monospace' }}
            />
          </div>,
          document.body,
        )}
    </span>
  );
}
