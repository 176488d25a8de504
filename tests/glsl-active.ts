// The code a GLSL compiler actually sees: runs the preprocessor's conditionals (#if, #ifdef, #ifndef, #elif,
// #else, #endif with the object-like #defines in force), drops comments and inactive lines, and writes each
// remaining line as its tokens separated by one space. Two sources with the same active code give the same
// text, however their inactive #ifdef blocks, comments and spacing differ: that is what "the same program"
// means for a material that gained feature chunks which compile to nothing when the feature is off.

const TOKEN =
  /[A-Za-z_]\w*|\d*\.\d+(?:[eE][+-]?\d+)?[fF]?|\d+\.?(?:[eE][+-]?\d+)?[uUfF]?|&&|\|\||[=!<>]=|<<|>>|\S/g;

function stripComments(source: string): string {
  return source.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, '');
}

/** Evaluates a #if expression: defined(X), integer macros, ! && || == != < > <= >= + - * / ( ). */
function evaluate(expression: string, macros: Map<string, string>): boolean {
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
  const js = withDefined
    .replace(/[A-Za-z_]\w*/g, (name) => `(${resolve(name)})`)
    .replace(/(\d)[uU]\b/g, '$1');
  if (!/^[\d\s()!&|=<>+\-*/.]*$/.test(js)) throw new Error(`cannot evaluate #if ${expression}`);
  return Boolean(new Function(`return (${js});`)());
}

/** The active code of `source`, one normalised line per active source line. */
export function activeGlsl(source: string): string {
  const macros = new Map<string, string>();
  // Each level: [this branch is taken, some branch of this #if was taken, the enclosing level is active].
  const stack: Array<{ taking: boolean; taken: boolean; outer: boolean }> = [];
  const active = () => stack.every((s) => s.taking);
  const out: string[] = [];
  for (const raw of stripComments(source).split('\n')) {
    const line = raw.trim();
    if (line === '') continue;
    const directive = /^#\s*(\w+)\s*(.*)$/.exec(line);
    if (directive) {
      const [, name, rest] = directive;
      if (name === 'if' || name === 'ifdef' || name === 'ifndef') {
        const outer = active();
        let value = false;
        if (outer) {
          if (name === 'ifdef') value = macros.has(rest.trim());
          else if (name === 'ifndef') value = !macros.has(rest.trim());
          else value = evaluate(rest, macros);
        }
        stack.push({ taking: outer && value, taken: outer && value, outer });
        continue;
      }
      if (name === 'elif') {
        const top = stack[stack.length - 1];
        const value = top.outer && !top.taken && evaluate(rest, macros);
        top.taking = value;
        top.taken ||= value;
        continue;
      }
      if (name === 'else') {
        const top = stack[stack.length - 1];
        top.taking = top.outer && !top.taken;
        top.taken = true;
        continue;
      }
      if (name === 'endif') {
        stack.pop();
        continue;
      }
      if (!active()) continue;
      if (name === 'define') {
        const m = /^([A-Za-z_]\w*)(\([^)]*\))?\s*(.*)$/.exec(rest);
        if (m) macros.set(m[1], m[2] ? `${m[2]} ${m[3]}` : m[3]);
      } else if (name === 'undef') {
        macros.delete(rest.trim());
      }
      out.push(`#${name} ${(rest.match(TOKEN) ?? []).join(' ')}`.trim());
      continue;
    }
    if (!active()) continue;
    out.push((line.match(TOKEN) ?? []).join(' '));
  }
  if (stack.length !== 0) throw new Error('unbalanced #if / #endif');
  return out.join('\n');
}

/**
 * Three's program cache key (without its `customProgramCacheKey` suffix: `…, flag mask 1, flag mask 2,
 * renderer.outputColorSpace`) with the `useFog` bit (bit 1 of the second flag mask) cleared.
 */
export function withoutUseFog(cacheKey: string): string {
  const parts = cacheKey.split(',');
  const i = parts.length - 2;
  parts[i] = String(Number(parts[i]) & ~2);
  return parts.join(',');
}
