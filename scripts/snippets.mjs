// `node scripts/snippets.mjs [--check] [--list] [--out DIR] [FILE.md ...]`: every ts/tsx/js/jsx code block of
// the Markdown a user reads (tracked *.md but CHANGELOG.md, .changeset/ and generated pages; or the FILEs given)
// is written as its own module into DIR (reports/snippets by default; git-ignored), named after its Markdown
// file and fence line, with a tsconfig, and type-checked with `npx tsc -p DIR` against the BUILT packages
// (`npx tsc -b` first): `@shadelab/*` resolves through the workspace's node_modules links and each package's
// `exports`, as in a user's app; strict, DOM, `three` with `@types/three`, skipLibCheck off. Errors are printed
// as `file.md:line:col`. `--list` prints the blocks without checking. The fence info string marks a block:
//   ```ts                 a complete module
//   ```ts partial         needs the context in the `<!-- context … -->` comment right above the fence
//   ```ts partial=NAME    needs the context in a `<!-- context=NAME … -->` comment anywhere in the same file
//   ```ts run=SCENE       complete, and run in Chromium by tests/snippets.spec.ts, its picture checked as SCENE
//   ```ts picture=NAME    complete, and run in Chromium by tests/snippets.spec.ts, its canvas compared pixel for
//                         pixel with images/NAME.png beside its Markdown (the image the Markdown shows)
//   ```ts file=PATH       a file of an app the Markdown builds (src/scene.ts): checked at PATH beside the other
//                         file= blocks of the same Markdown, so that relative imports between them resolve
// A context is code (imports, `declare const` lines) put before the block for the type check only.
// See DEVELOPERS.md, "Code in docs". tests/snippets.spec.ts and tests/pack.spec.ts import `collectBlocks`.
import { spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join, posix, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/** Fence languages that are checked, and the file extension each is checked as. */
const LANGUAGES = /** @type {const} */ ({
  ts: 'ts',
  typescript: 'ts',
  tsx: 'tsx',
  js: 'js',
  javascript: 'js',
  jsx: 'jsx',
});

/**
 * @typedef {object} Context
 * @property {string | undefined} name `undefined` for the comment right above a `partial` block
 * @property {number} line Markdown line (1-based) of the context's first code line
 * @property {string[]} lines its code
 */

/**
 * @typedef {object} Block
 * @property {string} file Markdown file, relative to the root, with `/`
 * @property {number} line Markdown line (1-based) of the opening fence
 * @property {string} lang the fence's language as written
 * @property {'ts' | 'tsx' | 'js' | 'jsx'} ext what it is checked as
 * @property {string} code the block's text, verbatim (the fence's indentation removed), ending with a newline
 * @property {number} indent columns of indentation removed from each line
 * @property {string | true | undefined} partial `true` for `partial`, NAME for `partial=NAME`
 * @property {string | undefined} run SCENE of `run=SCENE`
 * @property {string | undefined} picture NAME of `picture=NAME`: its canvas is images/NAME.png beside the Markdown
 * @property {string | undefined} path PATH of `file=PATH`: the block is that file of an app (relative, with `/`)
 * @property {string} heading the nearest Markdown heading above the block ('' if none)
 * @property {Context | undefined} context the context it is checked with
 */

/**
 * The Markdown files whose code is checked: tracked (or new, not ignored) *.md, without CHANGELOG.md,
 * .changeset/ (future changelog entries) and generated pages (BENCHMARKS.md, docs/api/, the packages' Markdown
 * API references in packages/<name>/docs/api/, whose examples are the TSDoc's fragments).
 * @param {string} [dir] repository root
 * @returns {string[]} paths relative to `dir`, sorted
 */
export function markdownFiles(dir = root) {
  const r = spawnSync('git', ['ls-files', '--cached', '--others', '--exclude-standard', '-z', '--', '*.md'], {
    cwd: dir,
    encoding: 'utf8',
  });
  if (r.status !== 0) throw new Error(`git ls-files failed in ${dir}: ${r.stderr}`);
  return [...new Set(r.stdout.split('\0').filter(Boolean))]
    .filter(
      (f) =>
        !/(^|\/)(node_modules|\.changeset)\//.test(f) &&
        !/(^|\/)CHANGELOG\.md$/.test(f) &&
        f !== 'BENCHMARKS.md' &&
        !f.startsWith('docs/api/') &&
        !/^packages\/[^/]+\/docs\/api\//.test(f),
    )
    .sort();
}

/**
 * Every ts/tsx/js/jsx fenced block of one Markdown text, with its marks and context. Throws on a malformed
 * mark (unknown word, `partial` without its context comment, `run` with `partial`).
 * @param {string} text Markdown
 * @param {string} file its path, for messages and names
 * @returns {Block[]}
 */
export function extractBlocks(text, file) {
  const lines = text.split(/\r?\n/);
  /** @type {Block[]} */
  const blocks = [];
  /** @type {Map<string, Context>} */
  const named = new Map();
  /** @type {Context | undefined} the unnamed context comment waiting for its block */
  let pending;
  let pendingEnd = -1;
  let heading = '';
  const problems = [];
  for (let i = 0; i < lines.length; i++) {
    const line = lines[i];
    const fence = /^( {0,3})(`{3,}|~{3,})\s*(.*)$/.exec(line);
    if (fence) {
      const [, pad, marker, info] = fence;
      // The closing fence: the same character, at least as long, nothing after it.
      let end = i + 1;
      while (
        end < lines.length &&
        !new RegExp(`^ {0,3}${marker[0] === '`' ? '`' : '~'}{${marker.length},}\\s*$`).test(lines[end])
      )
        end++;
      const [lang = '', ...words] = info.trim().split(/\s+/);
      const ext = Object.hasOwn(LANGUAGES, lang.toLowerCase())
        ? LANGUAGES[/** @type {keyof typeof LANGUAGES} */ (lang.toLowerCase())]
        : undefined;
      if (ext) {
        /** @type {Block} */
        const block = {
          file,
          line: i + 1,
          lang,
          ext,
          code: `${lines
            .slice(i + 1, end)
            .map((l) => l.slice(Math.min(pad.length, /^ */.exec(l)?.[0].length ?? 0)))
            .join('\n')}\n`,
          indent: pad.length,
          partial: undefined,
          run: undefined,
          picture: undefined,
          path: undefined,
          heading,
          context: undefined,
        };
        for (const word of words) {
          const [key, value] = word.split('=', 2);
          if (key === 'partial' && value === undefined) block.partial = true;
          else if (key === 'partial' && value) block.partial = value;
          else if (key === 'run' && value) block.run = value;
          else if (key === 'picture' && value && /^[a-z0-9]+(-[a-z0-9]+)*$/.test(value))
            block.picture = value;
          else if (
            key === 'file' &&
            value &&
            /^[\w.-]+(\/[\w.-]+)*$/.test(value) &&
            !/(^|\/)\.\.?(\/|$)/.test(value)
          )
            block.path = value;
          else
            problems.push(
              `${file}:${i + 1}: unknown mark '${word}' in \`\`\`${info.trim()} (allowed: partial, partial=NAME, run=SCENE, picture=NAME in lower-case-with-dashes, file=PATH)`,
            );
        }
        if (block.run && block.partial)
          problems.push(
            `${file}:${i + 1}: a run=${block.run} block is run as it stands: it cannot be partial`,
          );
        if (block.picture && (block.partial || block.path))
          problems.push(
            `${file}:${i + 1}: a picture=${block.picture} block is run as it stands: it cannot be partial or a file=`,
          );
        if (block.picture && blocks.some((b) => b.picture === block.picture))
          problems.push(`${file}:${i + 1}: a second picture=${block.picture} in this file`);
        if (block.partial === true) {
          if (pending && pendingEnd === i) block.context = pending;
          else
            problems.push(
              `${file}:${i + 1}: a partial block needs its context in a <!-- context … --> comment right above the fence`,
            );
        }
        blocks.push(block);
      }
      if (pending && pendingEnd === i && !(ext && blocks.at(-1)?.partial === true))
        problems.push(
          `${file}:${pending.line - 1}: this context comment is not followed by a \`partial\` block`,
        );
      pending = undefined;
      i = end;
      continue;
    }
    const h = /^#{1,6}\s+(.*?)\s*#*\s*$/.exec(line);
    if (h) heading = h[1];
    const comment = /^<!--\s*context(?:=([\w.-]+))?\s*$/.exec(line);
    if (comment) {
      let end = i + 1;
      while (end < lines.length && !/^\s*-->\s*$/.test(lines[end])) end++;
      if (end === lines.length) problems.push(`${file}:${i + 1}: context comment without its closing -->`);
      /** @type {Context} */
      const context = { name: comment[1], line: i + 2, lines: lines.slice(i + 1, end) };
      if (context.name) {
        if (named.has(context.name))
          problems.push(`${file}:${i + 1}: a second context named ${context.name}`);
        named.set(context.name, context);
      } else {
        if (pending && pendingEnd >= 0)
          problems.push(
            `${file}:${pending.line - 1}: this context comment is not followed by a \`partial\` block`,
          );
        pending = context;
        // Only blank lines may stand between the comment and its fence.
        pendingEnd = end + 1;
        while (pendingEnd < lines.length && lines[pendingEnd].trim() === '') pendingEnd++;
      }
      i = end;
    }
  }
  if (pending)
    problems.push(`${file}:${pending.line - 1}: this context comment is not followed by a \`partial\` block`);
  for (const block of blocks) {
    if (typeof block.partial !== 'string') continue;
    block.context = named.get(block.partial);
    if (!block.context)
      problems.push(
        `${block.file}:${block.line}: partial=${block.partial} names no <!-- context=${block.partial} --> comment in this file`,
      );
  }
  if (problems.length) throw new Error(problems.join('\n'));
  return blocks;
}

/**
 * The blocks of every Markdown file (or of `files`), in file order.
 * @param {{ dir?: string, files?: string[] }} [options] `dir`: repository root; `files`: relative to it
 * @returns {Block[]}
 */
export function collectBlocks({ dir = root, files = markdownFiles(dir) } = {}) {
  const problems = [];
  const blocks = [];
  for (const file of files) {
    try {
      blocks.push(...extractBlocks(readFileSync(join(dir, file), 'utf8'), file.split('\\').join('/')));
    } catch (e) {
      problems.push(/** @type {Error} */ (e).message);
    }
  }
  if (problems.length) throw new Error(problems.join('\n'));
  return blocks;
}

/**
 * The module a block is checked as, relative to the output folder: its Markdown path and fence line.
 * @param {Block} block
 */
export function moduleName(block) {
  const md = block.file.replace(/^(\.\.\/)+/, '');
  // A file= block sits at its path in a folder of its Markdown's own, beside the others of that Markdown.
  if (block.path !== undefined) return `${md}.files/${block.path}`;
  return `${md}-${block.line}.${block.ext}`;
}

/** Compiler options: what a fresh Vite + TypeScript app has that matters here, with every check on. */
const COMPILER_OPTIONS = {
  target: 'ES2022',
  lib: ['ES2022', 'DOM', 'DOM.Iterable'],
  module: 'ESNext',
  moduleResolution: 'bundler',
  moduleDetection: 'force',
  strict: true,
  noEmit: true,
  isolatedModules: true,
  verbatimModuleSyntax: true,
  skipLibCheck: false,
  allowJs: true,
  checkJs: true,
  jsx: 'react-jsx',
  types: [],
};

/**
 * Write each block (after its context) as a module into `outDir`, with a tsconfig, and run `tsc -p` on it.
 * @param {Block[]} blocks
 * @param {string} outDir inside the repository, so that node_modules resolves as in a user's app
 * @returns {{ errors: string[], output: string }} errors as `file.md:line:col: error TS…: message`
 */
export function checkBlocks(blocks, outDir) {
  rmSync(outDir, { recursive: true, force: true });
  mkdirSync(outDir, { recursive: true });
  /** @type {Map<string, Block>} */
  const byModule = new Map();
  for (const block of blocks) {
    const name = moduleName(block);
    if (byModule.has(name)) throw new Error(`${block.file}:${block.line}: a second block for ${name}`);
    byModule.set(name, block);
    const path = join(outDir, name);
    mkdirSync(dirname(path), { recursive: true });
    const context = block.context ? `${block.context.lines.join('\n')}\n` : '';
    writeFileSync(path, context + block.code);
  }
  writeFileSync(
    join(outDir, 'tsconfig.json'),
    `${JSON.stringify({ compilerOptions: COMPILER_OPTIONS, files: [...byModule.keys()] }, null, 2)}\n`,
  );
  if (byModule.size === 0) return { errors: [], output: '' };
  const r = spawnSync(
    'npx',
    ['--no-install', 'tsc', '-p', join(outDir, 'tsconfig.json'), '--pretty', 'false'],
    {
      cwd: root,
      encoding: 'utf8',
      maxBuffer: 64 * 1024 * 1024,
    },
  );
  if (r.error) throw r.error;
  const output = `${r.stdout}${r.stderr}`;
  /** @type {string[]} */
  const errors = [];
  let current = -1;
  for (const text of output.split('\n')) {
    const m = /^(.*)\((\d+),(\d+)\): (error .*)$/.exec(text);
    if (!m) {
      // A message's continuation lines (indented) belong to the error above.
      if (current >= 0 && /^\s/.test(text) && text.trim()) errors[current] += `\n${text}`;
      else if (text.trim() && !/^npm warn/i.test(text)) {
        errors.push(text);
        current = errors.length - 1;
      }
      continue;
    }
    const [, path, row, col, message] = m;
    const block = byModule.get(relative(outDir, resolve(root, path)).split('\\').join('/'));
    if (!block) {
      errors.push(`${path}:${row}:${col}: ${message}`);
      current = errors.length - 1;
      continue;
    }
    const contextLines = block.context?.lines.length ?? 0;
    const n = Number(row);
    const where =
      block.context && n <= contextLines
        ? `${block.file}:${block.context.line + n - 1}:${col} (in the context of the block at line ${block.line})`
        : `${block.file}:${block.line + n - contextLines}:${Number(col) + block.indent}`;
    errors.push(`${where}: ${message}`);
    current = errors.length - 1;
  }
  if (r.status !== 0 && errors.length === 0) errors.push(`tsc failed with exit code ${r.status}:\n${output}`);
  return { errors, output };
}

/**
 * The image a `picture=NAME` block's canvas must equal, relative to the root: images/NAME.png in its Markdown's
 * folder, which the Markdown shows as `![…](images/NAME.png)`.
 * @param {Block & { picture: string }} block
 */
export const pictureFile = (block) => posix.join(posix.dirname(block.file), 'images', `${block.picture}.png`);

/**
 * The folder (and URL path) of a runnable block's page: its Markdown file and fence line.
 * @param {Block} block
 */
export const runPageName = (block) => `${block.file.replace(/[^\w.-]+/g, '_')}-${block.line}`;

/**
 * A runnable block's page, as a user would run the block: the block verbatim as main.ts, an entry that imports it
 * and then marks the page (`<html data-ran="true">`: a module that throws stops before the mark), and an
 * index.html that loads the entry. File name → text.
 * @param {Block} block @returns {Record<'main.ts' | 'entry.ts' | 'index.html', string>}
 */
export function runPageFiles(block) {
  return {
    'main.ts': block.code,
    'entry.ts': "import './main.ts';\ndocument.documentElement.dataset.ran = 'true';\n",
    'index.html': `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8" />
    <link rel="icon" href="data:," />
    <title>${block.file}:${block.line}</title>
    <style>html, body { margin: 0; } canvas { display: block; }</style>
  </head>
  <body>
    <script type="module" src="./entry.ts"></script>
  </body>
</html>
`,
  };
}

/**
 * Write each block's page (runPageFiles) into `srcDir`/<runPageName>/, for one Vite build of them all
 * (tests/snippets.spec.ts, bench/first-frame.bench.mjs). Returns the build's input: page name → its index.html.
 * @param {Block[]} blocks @param {string} srcDir @returns {Record<string, string>}
 */
export function writeRunPages(blocks, srcDir) {
  /** @type {Record<string, string>} */
  const input = {};
  for (const block of blocks) {
    const dir = join(srcDir, runPageName(block));
    mkdirSync(dir, { recursive: true });
    for (const [name, text] of Object.entries(runPageFiles(block))) writeFileSync(join(dir, name), text);
    input[runPageName(block)] = join(dir, 'index.html');
  }
  return input;
}

/**
 * The README's Quick start block: the one block under its "Quick start" heading, which must be marked to run.
 * @param {Block[]} blocks @returns {Block}
 */
export function quickStartBlock(blocks) {
  const found = blocks.filter((b) => b.file === 'README.md' && /quick start/i.test(b.heading));
  if (found.length !== 1 || !found[0].run)
    throw new Error(
      `README.md: expected one run= block under "Quick start", found ${found.map(describeBlock).join(', ') || 'none'}`,
    );
  return found[0];
}

/** @param {Block} b */
export const describeBlock = (b) =>
  `${b.file}:${b.line} \`\`\`${b.lang}${b.partial === true ? ' partial' : b.partial ? ` partial=${b.partial}` : ''}${b.run ? ` run=${b.run}` : ''}${b.picture ? ` picture=${b.picture}` : ''}${b.path ? ` file=${b.path}` : ''}`;

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const outAt = args.indexOf('--out');
  const outDir = resolve(root, outAt >= 0 ? args[outAt + 1] : 'reports/snippets');
  const files = args.filter((a, i) => !a.startsWith('--') && (outAt < 0 || i !== outAt + 1));
  let blocks;
  try {
    blocks = collectBlocks(files.length ? { files: files.map((f) => relative(root, resolve(f))) } : {});
  } catch (e) {
    console.error(/** @type {Error} */ (e).message);
    process.exit(1);
  }
  if (args.includes('--list')) {
    for (const b of blocks) console.log(describeBlock(b));
    process.exit(0);
  }
  const { errors } = checkBlocks(blocks, outDir);
  const markdown = new Set(blocks.map((b) => b.file));
  if (errors.length) {
    for (const e of errors) console.error(e);
    console.error(
      `\n${errors.length} error(s) in the code blocks of the Markdown (${blocks.length} blocks checked)`,
    );
    process.exit(1);
  }
  const runs = blocks.filter((b) => b.run || b.picture).length;
  const pictures = blocks.filter((b) => b.picture).length;
  const partial = blocks.filter((b) => b.partial).length;
  console.log(
    `${blocks.length} code blocks in ${markdown.size} Markdown files type-check against the built packages ` +
      `(${partial} partial with their context, ${runs} also run by tests/snippets.spec.ts, ${pictures} of them drawing a picture of the docs)`,
  );
}
