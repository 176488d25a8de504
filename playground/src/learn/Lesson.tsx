/**
 * The Learn panel: the lecture's steps (lessonSteps.ts) one at a time at the top of the side column, beside the
 * view rather than over it. Entering a step sets the state it talks about; **back** and **next** walk the path,
 * **leave** closes it at any time and keeps the state reached (opening it again goes back to that step).
 */
import { Fragment, useState } from 'react';
import { isEmbedded } from '../state/embed';
import type { Update } from '../ui/useFolder';
import { applyStep, LESSON_STEPS } from './lessonSteps';

/** The step's text with its **bold** parts (the controls it names) in bold. */
function withBold(text: string) {
  return text.split('**').map((part, i) =>
    // biome-ignore lint/suspicious/noArrayIndexKey: the parts of one fixed text, in order.
    i % 2 === 1 ? <strong key={i}>{part}</strong> : <Fragment key={i}>{part}</Fragment>,
  );
}

export function Lesson({ update }: { update: Update }) {
  /** The step shown, or null while the panel is closed. */
  const [step, setStep] = useState<number | null>(null);
  /** The step reached, where the panel opens again. */
  const [reached, setReached] = useState(0);
  if (isEmbedded()) return null;
  const go = (index: number) => {
    setStep(index);
    setReached(index);
    update((d) => applyStep(d, LESSON_STEPS[index]!));
  };
  if (step === null) {
    return (
      <button type="button" className="lesson-open" data-testid="lesson-open" onClick={() => go(reached)}>
        Learn the lecture: {LESSON_STEPS.length} steps, in this page
      </button>
    );
  }
  const { id, title, text } = LESSON_STEPS[step]!;
  return (
    <section className="lesson" aria-label="Learn the lecture" data-testid="lesson" data-step={id}>
      <h2>
        Step {step + 1} of {LESSON_STEPS.length}: {title}
      </h2>
      <p data-testid="lesson-text">{withBold(text)}</p>
      <div className="lesson-buttons">
        <button type="button" disabled={step === 0} onClick={() => go(step - 1)}>
          back
        </button>
        <button type="button" disabled={step === LESSON_STEPS.length - 1} onClick={() => go(step + 1)}>
          next
        </button>
        <button type="button" onClick={() => setStep(null)}>
          leave the lesson
        </button>
      </div>
    </section>
  );
}
