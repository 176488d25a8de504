import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

/** Issue 24: no playground source file over this many lines (one concept per file, small enough to read). */
const MAX_PLAYGROUND_FILE_LINES = 300;

const src = fileURLToPath(new URL('.', import.meta.url));

/** Every file under `dir`, recursively. */
function filesUnder(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) =>
    entry.isDirectory() ? filesUnder(join(dir, entry.name)) : [join(dir, entry.name)],
  );
}

/** Lines of a text: newline-separated, a final newline not starting one more. */
const linesOf = (text: string) => (text === '' ? 0 : text.replace(/\n$/, '').split('\n').length);

describe('playground/src', () => {
  const files = filesUnder(src).filter((f) => /\.(ts|tsx|css)$/.test(f));

  it('counts lines as an editor shows them', () => {
    expect([linesOf(''), linesOf('a'), linesOf('a\n'), linesOf('a\nb'), linesOf('a\n\nb\n')]).toEqual([
      0, 1, 1, 2, 3,
    ]);
  });

  it(`has no file over ${MAX_PLAYGROUND_FILE_LINES} lines`, () => {
    expect(files.length).toBeGreaterThan(50);
    const over = files
      .map((f) => ({ file: relative(src, f), lines: linesOf(readFileSync(f, 'utf8')) }))
      .filter((f) => f.lines > MAX_PLAYGROUND_FILE_LINES)
      .map((f) => `${f.file}: ${f.lines} lines`);
    expect(over).toEqual([]);
  });
});
