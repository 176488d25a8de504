import type { ExpectMatcherState, Locator } from '@playwright/test';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { type CanvasState, inspectCanvas } from './canvasContexts.js';
import { encodePng } from './png.js';
import { toHaveRendered, waitForFirstFrame } from './toHaveRendered.js';

/** Playwright's error for an evaluation that ran out of its time (its `name` is what tells it apart). */
const timeoutError = () =>
  Object.assign(
    new Error("locator.evaluate: Timeout 1000ms exceeded.\nCall log:\n  - waiting for locator('canvas')"),
    {
      name: 'TimeoutError',
    },
  );

const canvasState = (state: Partial<CanvasState>): CanvasState => ({
  tag: 'canvas',
  width: 2,
  height: 1,
  context: 'webgl2',
  lost: false,
  configured: true,
  recorded: true,
  ...state,
});

/** A 2 × 1 picture, one red and one blue pixel: rendered. */
const DRAWN = encodePng({ width: 2, height: 1, data: new Uint8Array([255, 0, 0, 255, 0, 0, 255, 255]) });

/**
 * A locator whose n-th look at the canvas (`inspectCanvas`; `probe` when it asks for each context type) gets
 * `answer(n, probe)`: a state, or an error thrown. The screenshot is `DRAWN`; `count` says how many elements
 * match.
 */
function fakeCanvas(
  answer: (n: number, probe: boolean) => CanvasState | Error,
  count = 1,
): { canvas: Locator; calls: () => number } {
  let n = 0;
  const canvas = {
    evaluate: async (fn: unknown, probe: unknown) => {
      if (fn !== inspectCanvas) return undefined; // readCanvas marking the element
      lookTick();
      const result = answer(n++, probe === true);
      if (result instanceof Error) throw result;
      return result;
    },
    screenshot: async () => Buffer.from(DRAWN),
    count: async () => count,
  } as unknown as Locator;
  return { canvas, calls: () => n };
}

/** The first look answers `first`, every later one times out. */
const thenTimeouts = (first: CanvasState) => (n: number) => (n === 0 ? first : timeoutError());

const matcher = (isNot: boolean) => ({ isNot, timeout: 300 }) as ExpectMatcherState;

/** Each look at the fake canvas takes this long on the clock {@link onTheLooksClock} sets. */
const LOOK_MS = 40;
/** Called by the fake canvas at each look (a no-op off {@link onTheLooksClock}). */
let lookTick = () => {};

/**
 * The matcher's clock (Date.now) advanced by the looks alone, {@link LOOK_MS} each: how many looks fit in a
 * timeout is then the same on an idle and on a busy machine.
 */
function onTheLooksClock(): void {
  let now = 0;
  vi.spyOn(Date, 'now').mockImplementation(() => now);
  lookTick = () => {
    now += LOOK_MS;
  };
}

describe('toHaveRendered on a page too slow to answer (a look cut short by its own timeout)', () => {
  beforeEach(onTheLooksClock);
  afterEach(() => {
    vi.restoreAllMocks();
    lookTick = () => {};
  });

  it('reports what an earlier look saw, not that the canvas could not be found', async () => {
    // The flake: the canvas had no context, and the last look ran out of time under load.
    const { canvas, calls } = fakeCanvas(thenTimeouts(canvasState({ context: null })));
    const result = await toHaveRendered.call(matcher(false), canvas, { timeout: 300 });
    expect(calls()).toBeGreaterThan(1);
    expect(result.pass).toBe(false);
    expect(result.message()).toContain('the canvas has no context: the page never called getContext on it');
    expect(result.message()).toContain('Canvas: 2×1, no context.');
    await expect(
      waitForFirstFrame(fakeCanvas(thenTimeouts(canvasState({ context: null }))).canvas, {
        timeout: 300,
      }),
    ).rejects.toThrow(
      /^waitForFirstFrame: the canvas did not render within \d+ ms: the canvas has no context/,
    );
  });

  it('does not let .not pass on a rendered canvas because a later look ran out of time', async () => {
    const { canvas, calls } = fakeCanvas(thenTimeouts(canvasState({})));
    const result = await toHaveRendered.call(matcher(true), canvas, { timeout: 300 });
    expect(calls()).toBeGreaterThan(1);
    expect(result.pass).toBe(true); // rendered: .not fails
    expect(result.message()).toContain('The canvas rendered (2×1, WebGL2 context, 1 pixels drawn over');
  });

  it('reports its own message, not a thrown TimeoutError, when the probe for an unrecorded context times out', async () => {
    const { canvas } = fakeCanvas((_, probe) =>
      probe ? timeoutError() : canvasState({ context: null, recorded: false }),
    );
    const result = await toHaveRendered.call(matcher(false), canvas, { timeout: 300 });
    expect(result.pass).toBe(false);
    expect(result.message()).toMatch(/The canvas did not render within \d+ ms/);
    expect(result.message()).toContain(
      "the canvas's context could not be read: locator.evaluate: Timeout 1000ms exceeded.",
    );
  });

  it('says the canvas could not be found when no element matches, and .not passes', async () => {
    const { canvas } = fakeCanvas(() => timeoutError(), 0);
    const result = await toHaveRendered.call(matcher(false), canvas, { timeout: 300 });
    expect(result.pass).toBe(false);
    expect(result.message()).toContain(
      'the canvas could not be found: locator.evaluate: Timeout 1000ms exceeded.',
    );
    expect(result.message()).toContain('\nCanvas: not found.');
    const negated = await toHaveRendered.call(matcher(true), fakeCanvas(() => timeoutError(), 0).canvas, {
      timeout: 300,
    });
    expect(negated.pass).toBe(false);
  });

  it('passes as soon as a look sees the picture, after looks cut short', async () => {
    const { canvas, calls } = fakeCanvas((n) => (n < 2 ? timeoutError() : canvasState({})));
    const frame = await waitForFirstFrame(canvas, { timeout: 5_000 });
    expect(calls()).toBe(3);
    expect(frame.picture.drawnPixels).toBe(1);
  });
});
