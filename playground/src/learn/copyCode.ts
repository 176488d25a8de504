/**
 * Copy as code: the playground's scene as a program to take home, in two variants: plain three.js with the
 * `@shadelab/*` packages (`copyCodeThree.ts`) and React Three Fiber with `@shadelab/react` (`copyCodeR3f.ts`).
 * Loaded on first use (the buttons import this module when clicked).
 */
import type { PlaygroundState } from '../state/schema';
import { r3fProgram } from './copyCodeR3f';
import { threeProgram } from './copyCodeThree';

export { NOT_EXPORTED } from './copyCodeModel';
export { r3fProgram, threeProgram };

/** The two variants: a three.js program (`src/main.ts`) or an R3F app (`src/main.tsx`). */
export type CodeVariant = 'three' | 'r3f';

/** The program for `state` in `variant`. */
export function programOf(variant: CodeVariant, state: PlaygroundState): string {
  return variant === 'three' ? threeProgram(state) : r3fProgram(state);
}
