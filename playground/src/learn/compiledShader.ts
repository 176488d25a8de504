/**
 * The shader as compiled: a GLSL preprocessor's conditionals (#if, #ifdef, #ifndef, #elif, #else, #endif with
 * the object-like #defines in force) run over a source, so that the shader view can show only the code the GPU
 * compiles for this scene, and the tests can compare two programs by their active code ({@link activeGlsl}).
 *
 * Pure text functions (no DOM, no three.js): the playground and the Playwright specs share them.
 */

/** GLSL tokens: identifiers, numbers, two-character operators, any other single character. */
const TOKEN =
  /[A-Za-z_]\w*|\d*\.\d+(?:[eE][+-]?\d+)?[fF]?|\d+\.?(?:[eE][+-]?\d+)?[uUfF]?|&&|\|\||[=!<>]=|<<|>>|\S/g;

/** The directives that open, switch or close a conditional block. */
const CONDITIONALS = new Set(['if', 'ifdef', 'ifndef', 'elif', 'else', 'endif']);

/** `#name rest` of a preprocessor line (already trimmed), or null. */
function directiveOf(line: string): { name: string; rest: string } | null {
  const match = /^#\s*(\w+)\s*(.*)$/.exec(line);
  return match ? { name: match[1]!, rest: match[2]! } : null;
}

/** Whether a (trimmed) line is a conditional directive (#if … #endif): the lines the active view drops. */
export function isConditional(line: string): boolean {
  const directive = directiveOf(line.trim());
  return directive !== null && CONDITIONALS.has(directive.name);
}

/** Evaluates an integer expression of numbers and C operators (! ~ * / % + - < > <= >= == != && || and ()). */
function evaluateTokens(tokens: string[], expression: string): number {
  let at = 0;
  const fail = (): never => {
    throw new Error(`cannot evaluate #if ${expression}`);
  };
  const BINARY: Array<Record<string, (a: number, b: number) => number>> = [
    { '||': (a, b) => Number(a !== 0 || b !== 0) },
    { '&&': (a, b) => Number(a !== 0 && b !== 0) },
    { '==': (a, b) => Number(a === b), '!=': (a, b) => Number(a !== b) },
    {
      '<': (a, b) => Number(a < b),
      '>': (a, b) => Number(a > b),
      '<=': (a, b) => Number(a <= b),
      '>=': (a, b) => Number(a >= b),
    },
    { '+': (a, b) => a + b, '-': (a, b) => a - b },
    { '*': (a, b) => a * b, '/': (a, b) => a / b, '%': (a, b) => a % b },
  ];
  const unary = (): number => {
    const token = tokens[at++] ?? fail();
    if (token === '!') return Number(unary() === 0);
    if (token === '-') return -unary();
    if (token === '+') return unary();
    if (token === '(') {
      const value = binary(0);
      if (tokens[at++] !== ')') fail();
      return value;
    }
    const number = /^(\d*\.?\d+(?:[eE][+-]?\d+)?)[uU]?$/.exec(token);
    return number ? Number(number[1]) : fail();
  };
  const binary = (level: number): number => {
    if (level === BINARY.length) return unary();
    let value = binary(level + 1);
    for (let op = BINARY[level]![tokens[at]!]; op; op = BINARY[level]![tokens[at]!]) {
      at++;
      value = op(value, binary(level + 1));
    }
    return value;
  };
  const value = binary(0);
  if (at !== tokens.length) fail();
  return value;
}

/** Evaluates a #if expression: defined(X), integer macros, ! && || == != < > <= >= + - * / % ( ). */
function evaluate(expression: string, macros: ReadonlyMap<string, string>): boolean {
  const withDefined = expression.replace(
    /defined\s*\(\s*([A-Za-z_]\w*)\s*\)|defined\s+([A-Za-z_]\w*)/g,
    (_, a, b) => (macros.has(a ?? b) ? ' 1 ' : ' 0 '),
  );
  const resolve = (name: string, depth = 0): string => {
    const value = macros.get(name);
    if (value === undefined || depth > 16) return '0';
    const trimmed = value.trim();
    if (/^[A-Za-z_]\w*$/.test(trimmed)) return resolve(trimmed, depth + 1);
    return trimmed === '' ? '0' : trimmed;
  };
  const expanded = withDefined.replace(/(?<![\w.])[A-Za-z_]\w*/g, (name) => `(${resolve(name)})`);
  const tokens = expanded.match(/\d*\.?\d+(?:[eE][+-]?\d+)?[uU]?|&&|\|\||[=!<>]=|[-+*/%!<>()]|\S/g) ?? [];
  return evaluateTokens(tokens, expression) !== 0;
}

/** What the preprocessor made of one line: its directive (if any) and whether it is in an active region. */
export interface LineState {
  /** The directive's name (`if`, `define`, `include` …), or null for a code or blank line. */
  readonly directive: string | null;
  /**
   * Whether the line is compiled: a code line in an active region; a directive whose region (after it) is
   * active. A conditional directive is reported with the state after it (an `#endif` with its enclosing region's).
   */
  readonly active: boolean;
}

/**
 * Runs the conditionals over `lines` (comments already removed, one entry per source line) and reports each
 * line's state. Throws an Error on an unbalanced #if / #endif or an expression it cannot evaluate.
 *
 * @param macros - Macros in force before the first line (name → value); updated by the #define / #undef met.
 */
export function preprocess(lines: readonly string[], macros = new Map<string, string>()): LineState[] {
  // Each level: [this branch is taken, some branch of this #if was taken, the enclosing level is active].
  const stack: Array<{ taking: boolean; taken: boolean; outer: boolean }> = [];
  const active = () => stack.every((s) => s.taking);
  const out: LineState[] = [];
  for (const raw of lines) {
    const directive = directiveOf(raw.trim());
    if (!directive) {
      out.push({ directive: null, active: active() });
      continue;
    }
    const { name, rest } = directive;
    if (name === 'if' || name === 'ifdef' || name === 'ifndef') {
      const outer = active();
      let value = false;
      if (outer) {
        if (name === 'ifdef') value = macros.has(rest.trim());
        else if (name === 'ifndef') value = !macros.has(rest.trim());
        else value = evaluate(rest, macros);
      }
      stack.push({ taking: outer && value, taken: outer && value, outer });
    } else if (name === 'elif' || name === 'else' || name === 'endif') {
      const top = stack[stack.length - 1];
      if (!top) throw new Error(`#${name} without #if`);
      if (name === 'elif') {
        const value = top.outer && !top.taken && evaluate(rest, macros);
        top.taking = value;
        top.taken ||= value;
      } else if (name === 'else') {
        top.taking = top.outer && !top.taken;
        top.taken = true;
      } else stack.pop();
    } else if (active() && name === 'define') {
      const m = /^([A-Za-z_]\w*)(\([^)]*\))?\s*(.*)$/.exec(rest);
      if (m) macros.set(m[1]!, m[2] ? `${m[2]} ${m[3]}` : m[3]!);
    } else if (active() && name === 'undef') {
      macros.delete(rest.trim());
    }
    out.push({ directive: name, active: active() });
  }
  if (stack.length !== 0) throw new Error('unbalanced #if / #endif');
  return out;
}

/**
 * The code a GLSL compiler actually sees, normalised: runs the conditionals, drops comments and inactive lines,
 * and writes each remaining line as its tokens separated by one space. Two sources with the same active code
 * give the same text, however their inactive #ifdef blocks, comments and spacing differ: that is what "the
 * same program" means for a material whose feature chunks compile to nothing when the feature is off.
 */
export function activeGlsl(source: string): string {
  const withoutComments = source.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, '');
  const lines = withoutComments
    .split('\n')
    .map((l) => l.trim())
    .filter((l) => l !== '');
  const states = preprocess(lines);
  const out: string[] = [];
  lines.forEach((line, i) => {
    const { directive, active } = states[i]!;
    if (directive !== null && CONDITIONALS.has(directive)) return;
    if (!active) return;
    if (directive !== null) {
      const rest = directiveOf(line)!.rest;
      out.push(`#${directive} ${(rest.match(TOKEN) ?? []).join(' ')}`.trim());
    } else out.push((line.match(TOKEN) ?? []).join(' '));
  });
  return out.join('\n');
}

/** The tag {@link tagForActive} appends to a line: `// @A<line>` (1-based). */
const ACTIVE_TAG = /\/\/ @A(\d+)\s*$/;

/**
 * Tags each line of a material's GLSL with its number (`… // @A12`), so that the lines of the program three
 * compiles from it (after its prefix, `#include` expansion, its number replacements and loop unrolling) can be
 * traced back. Left untagged, as three's regexes read them: `#pragma` and `#version` lines, the line closing an
 * unrolled loop, lines continued with a backslash, blank lines. An `#include` line's tag ends up after the chunk.
 */
export function tagForActive(source: string): string {
  const lines = source.split('\n');
  return lines
    .map((line, i) => {
      const trimmed = line.trim();
      if (!trimmed || line.endsWith('\\') || /^#\s*(pragma|version)\b/.test(trimmed)) return line;
      const next = lines.slice(i + 1).find((l) => l.trim() !== '');
      if (next?.trim().startsWith('#pragma unroll_loop_end')) return line;
      return `${line} // @A${i + 1}`;
    })
    .join('\n');
}

/**
 * Comments blanked out, keeping every line where it is (a block comment's lines become empty lines), so that
 * line `i` of the result is line `i` of `source`.
 */
function blankComments(source: string): string {
  return source
    .replace(/\/\*[\s\S]*?\*\//g, (comment) => comment.replace(/[^\n]/g, ' '))
    .replace(/\/\/.*$/gm, '');
}

/**
 * The numbers of the lines of a material's source (1-based) that are compiled, read from the program three
 * compiled from the {@link tagForActive tagged} source (`compiled`: the whole stage as the GPU got it, three's
 * prefix included, e.g. `gl.getShaderSource`).
 */
export function activeTags(compiled: string): Set<number> {
  const rawLines = compiled.split('\n');
  const states = preprocess(blankComments(compiled).split('\n'));
  const active = new Set<number>();
  rawLines.forEach((raw, i) => {
    const tag = ACTIVE_TAG.exec(raw);
    if (tag && states[i]!.active) active.add(Number(tag[1]));
  });
  return active;
}

/**
 * A material's source with only its compiled lines: the lines whose tag is in `active` (see {@link activeTags}),
 * without the conditional directives (#if … #endif), an untagged line going with the tagged line above it
 * (below it at the start), and runs of blank lines kept as one. Three's prefix is not part of it: the result
 * is a drop-in for the material's own source, and compiles to the same program.
 */
export function activeSource(source: string, active: ReadonlySet<number>): string {
  const lines = source.split('\n');
  const tagged = tagForActive(source).split('\n');
  const keep: boolean[] = lines.map((_, i) => ACTIVE_TAG.test(tagged[i]!) && active.has(i + 1));
  const isTagged = (i: number) => ACTIVE_TAG.test(tagged[i]!);
  let last: boolean | null = null;
  for (let i = 0; i < lines.length; i++) {
    if (isTagged(i)) last = keep[i]!;
    else if (last !== null) keep[i] = last;
    else keep[i] = keep[lines.findIndex((_, j) => j > i && isTagged(j))] ?? true;
  }
  const out: string[] = [];
  lines.forEach((line, i) => {
    if (!keep[i] || isConditional(line)) return;
    const blank = line.trim() === '';
    if (blank && (out.length === 0 || out[out.length - 1]!.trim() === '')) return;
    out.push(line);
  });
  return out.join('\n');
}
