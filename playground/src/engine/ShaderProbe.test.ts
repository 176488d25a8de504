import { describe, expect, it } from 'vitest';
import { parseInfoLog, tagLines } from './ShaderProbe';

const user = [
  'uniform float shininess;',
  '#define TWO 2.0',
  'void main() {',
  '  #pragma unroll_loop_start',
  '  for ( int i = 0; i < 2; i ++ ) {',
  '    x += lights[ i ];',
  '  }',
  '  #pragma unroll_loop_end',
  '  broken here;',
  '}',
].join('\n');

describe('tagLines', () => {
  it('tags code lines with their number and leaves preprocessor lines and loop ends alone', () => {
    const tagged = tagLines(user).split('\n');
    expect(tagged).toHaveLength(10);
    expect(tagged[0]).toBe('uniform float shininess; // @L1');
    expect(tagged[1]).toBe('#define TWO 2.0');
    expect(tagged[3]).toBe('  #pragma unroll_loop_start');
    expect(tagged[5]).toBe('    x += lights[ i ]; // @L6');
    expect(tagged[6]).toBe('  }');
    expect(tagged[8]).toBe('  broken here; // @L9');
  });

  it('never tags a macro continued with a backslash', () => {
    expect(tagLines('#define A \\\n  1.0 \\\n  + 2.0')).toBe('#define A \\\n  1.0 \\\n  + 2.0 // @L3');
  });
});

describe('parseInfoLog', () => {
  it("maps an error in three's expanded program back to the user's line", () => {
    // What three compiles: a prefix, then the user's text with its loop unrolled (lines duplicated).
    const prefix = Array.from({ length: 57 }, (_, i) => `#define P${i}`);
    const tagged = tagLines(user).split('\n');
    const unrolled = [...tagged.slice(0, 4), tagged[5]!, tagged[5]!, ...tagged.slice(8)];
    const compiled = [...prefix, ...unrolled].join('\n');
    const line = compiled.split('\n').findIndex((l) => l.includes('broken here')) + 1;
    const log = `ERROR: 0:${line}: 'broken' : undeclared identifier\nERROR: 0:${line}: '' : compilation terminated\n\0`;
    expect(parseInfoLog(log, 'fragment', compiled)).toEqual([
      { stage: 'fragment', line: 9, message: "'broken' : undeclared identifier" },
      { stage: 'fragment', line: 9, message: "'' : compilation terminated" },
    ]);
  });

  it('reports a line inside the prefix as no user line, and keeps untagged messages', () => {
    const compiled = '#version 300 es\nprecision highp float;\nvoid main() {} // @L1';
    expect(parseInfoLog("ERROR: 0:2: 'x' : bad\nlink failed", 'vertex', compiled)).toEqual([
      { stage: 'vertex', line: null, message: "'x' : bad" },
      { stage: 'vertex', line: null, message: 'link failed' },
    ]);
  });
});
