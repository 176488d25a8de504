/**
 * The messages over the view: the WebGL context's loss and recovery (dismissable once recovered), the notices (a refused URL or saved state, a
 * copied link; each dismissable), the user's model's message, and the errors of the state shown.
 */
import type { ModelMessage } from './useModel';

/** The messages over the view, top left; read by screen readers as they change. */
export function Messages({
  context,
  dismissContext,
  notices,
  dismissNotice,
  model,
  dismissModel,
  errors,
}: {
  /** The WebGL context's status. */
  context: 'ok' | 'lost' | 'restored';
  /** Hides the recovery message (the loss message stays until the context is back). */
  dismissContext: () => void;
  notices: string[];
  dismissNotice: (notice: string) => void;
  model: ModelMessage | null;
  dismissModel: () => void;
  /** Each refused section, schema or render error, as the line to show. */
  errors: string[];
}) {
  return (
    <div className="messages" aria-live="polite">
      {context === 'lost' && (
        <p className="message warn" data-testid="context-message">
          The WebGL context was lost; waiting for the browser to restore it. Nothing you set is lost.
        </p>
      )}
      {context === 'restored' && (
        <p className="message info" data-testid="context-message">
          The WebGL context was restored; the scene was rebuilt.{' '}
          <button type="button" onClick={dismissContext}>
            dismiss
          </button>
        </p>
      )}
      {notices.map((n) => (
        <p key={n} className="message warn" data-testid="notice">
          {n}{' '}
          <button type="button" onClick={() => dismissNotice(n)}>
            dismiss
          </button>
        </p>
      ))}
      {model && (
        <p className={`message ${model.kind}`} role="alert" data-testid="model-message">
          {model.text}{' '}
          <button type="button" onClick={dismissModel}>
            dismiss
          </button>
        </p>
      )}
      {errors.map((e) => (
        <p key={e} className="message error" role="alert" data-testid="input-error">
          {e}
        </p>
      ))}
    </div>
  );
}
