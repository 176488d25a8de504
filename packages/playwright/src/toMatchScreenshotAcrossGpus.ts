import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import type { ExpectMatcherState, Locator, MatcherReturnType } from '@playwright/test';
import { attachImage, currentTestInfo } from './attach.js';
import { compareNeighbourhood } from './compareNeighbourhood.js';
import { diffImage, errorColour } from './diffImage.js';
import { GPU_TOLERANCE, type GpuTolerance } from './gpuTolerance.js';
import { decodePng, encodePng, type RgbaImage } from './png.js';
import { readCanvas } from './toHaveRendered.js';

/** Options of `toMatchScreenshotAcrossGpus`: the tolerance, and how long to wait for the screenshot. */
export interface AcrossGpusOptions extends Partial<GpuTolerance> {
  /** Milliseconds to wait for the canvas to be visible and stable. @default the expect timeout (5000) */
  timeout?: number;
}

function checkTolerance({ maxChannelDiff, radiusPx, maxDiffPixels }: GpuTolerance): void {
  if (!(maxChannelDiff >= 0 && maxChannelDiff <= 255)) {
    throw new RangeError(
      `toMatchScreenshotAcrossGpus: maxChannelDiff must be a number of 8-bit codes 0 … 255, got ${String(maxChannelDiff)}`,
    );
  }
  if (!Number.isInteger(radiusPx) || radiusPx < 0 || radiusPx > 8) {
    throw new RangeError(
      `toMatchScreenshotAcrossGpus: radiusPx must be an integer 0 … 8, got ${String(radiusPx)}`,
    );
  }
  if (!Number.isInteger(maxDiffPixels) || maxDiffPixels < 0) {
    throw new RangeError(
      `toMatchScreenshotAcrossGpus: maxDiffPixels must be an integer ≥ 0, got ${String(maxDiffPixels)}`,
    );
  }
}

function write(path: string, image: RgbaImage): void {
  mkdirSync(dirname(path), { recursive: true });
  writeFileSync(path, encodePng(image));
}

/**
 * The `toMatchScreenshotAcrossGpus` matcher: compare the canvas's screenshot with the baseline `name` (a PNG
 * where `toHaveScreenshot` would keep it, so the preset names it without the platform) within the rasteriser
 * tolerance {@link GPU_TOLERANCE} (or the one given): each pixel within `maxChannelDiff` codes of the range its
 * `radiusPx` neighbourhood spans in the other picture. Made for baselines recorded under SwiftShader and
 * checked on a real GPU. Baselines are kept as `toHaveScreenshot` keeps them: a missing one is written and the
 * test fails, unless `--update-snapshots` is given (then it passes); `--update-snapshots` (changed) rewrites a
 * failing one, `--update-snapshots=all` every one. On failure the expected, actual and diff pictures are attached to the report.
 */
export async function toMatchScreenshotAcrossGpus(
  this: ExpectMatcherState,
  canvas: Locator,
  name: string,
  options: AcrossGpusOptions = {},
): Promise<MatcherReturnType> {
  const tolerance: GpuTolerance = {
    maxChannelDiff: options.maxChannelDiff ?? GPU_TOLERANCE.maxChannelDiff,
    radiusPx: options.radiusPx ?? GPU_TOLERANCE.radiusPx,
    maxDiffPixels: options.maxDiffPixels ?? GPU_TOLERANCE.maxDiffPixels,
  };
  checkTolerance(tolerance);
  if (typeof name !== 'string' || name === '') {
    throw new TypeError(
      `toMatchScreenshotAcrossGpus: name must be a file name such as 'scene.png', got ${String(name)}`,
    );
  }
  const info = currentTestInfo();
  if (info === undefined) throw new Error('toMatchScreenshotAcrossGpus: call it inside a Playwright test');
  const file = name.endsWith('.png') ? name : `${name}.png`;
  const base = file.slice(0, -4);
  const path = info.snapshotPath(file, { kind: 'screenshot' });
  const hint = `expect(canvas).toMatchScreenshotAcrossGpus(${JSON.stringify(file)})`;
  const actual = await readCanvas(canvas, { timeout: options.timeout ?? this.timeout });
  const update = info.config.updateSnapshots;
  if (!existsSync(path)) {
    if (update === 'none') {
      return {
        pass: false,
        name: 'toMatchScreenshotAcrossGpus',
        message: () => `${hint}\n\nNo baseline at ${path}.`,
      };
    }
    // As toHaveScreenshot does: written; the test fails unless --update-snapshots asked for it.
    write(path, actual);
    await attachImage(`${base}-actual.png`, actual);
    return {
      pass: update !== 'default',
      name: 'toMatchScreenshotAcrossGpus',
      message: () =>
        `${hint}\n\nThere was no baseline at ${path}: written from this run. Check it and run again.`,
    };
  }
  const expected = decodePng(readFileSync(path));
  if (expected.width !== actual.width || expected.height !== actual.height) {
    if (update === 'all' || update === 'changed') write(path, actual);
    else {
      await attachImage(`${base}-expected.png`, expected);
      await attachImage(`${base}-actual.png`, actual);
    }
    return {
      pass: update === 'all' || update === 'changed',
      name: 'toMatchScreenshotAcrossGpus',
      message: () =>
        `${hint}\n\nThe canvas is ${actual.width}×${actual.height} pixels, the baseline ${path} ${expected.width}×${expected.height}.`,
    };
  }
  const result = compareNeighbourhood(actual, expected, tolerance);
  const pass = result.failingPixels <= tolerance.maxDiffPixels;
  const limits = `each pixel within ${tolerance.maxChannelDiff} codes of its ${2 * tolerance.radiusPx + 1}×${2 * tolerance.radiusPx + 1} neighbourhood's range, at most ${tolerance.maxDiffPixels} beyond`;
  if (!pass && !this.isNot) {
    if (update === 'all' || update === 'changed') {
      write(path, actual);
      return {
        pass: true,
        name: 'toMatchScreenshotAcrossGpus',
        message: () => `${hint}\n\nThe baseline ${path} was rewritten from this run.`,
      };
    }
    await attachImage(`${base}-expected.png`, expected);
    await attachImage(`${base}-actual.png`, actual);
    await attachImage(
      `${base}-diff.png`,
      diffImage(actual, (k) =>
        result.excess[k] > 0 ? errorColour(result.excess[k], tolerance.maxChannelDiff) : null,
      ),
    );
  } else if (update === 'all') {
    write(path, actual);
  }
  const where =
    result.worst === null ? '' : ` (largest at x ${result.worst.x}, y ${result.worst.y} from the top left)`;
  const message = () =>
    pass
      ? `${hint}\n\nThe canvas matches ${path} within the tolerance (${limits}): largest excess ${result.maxExcess} codes.`
      : `${hint}\n\nThe canvas differs from ${path} beyond the tolerance (${limits}): ${result.failingPixels} pixels beyond, largest excess ${result.maxExcess} codes${where}. Diff attached: ${base}-diff.png (red: beyond, orange: within).`;
  return { pass, message, name: 'toMatchScreenshotAcrossGpus' };
}
