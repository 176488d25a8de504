// `node scripts/check-links.mjs [--no-site] [FILE ...]`: every relative link of the Markdown and of the docs site
// resolves. Checked:
// - every Markdown file of the repository (tracked, or new and not ignored: READMEs, DEVELOPERS.md, docs/,
//   the packages' guides and generated references, CHANGELOGs, BENCHMARKS.md, tools/**/README.md…) or the
//   FILEs given: each relative link, image and reference definition (`[text](path#anchor)`, `![alt](path)`,
//   `[id]: path`, and `href`/`src` in inline HTML) names an existing file or folder inside the repository, and its
//   `#anchor`, in a Markdown file, is a heading there (GitHub's slugs, `-1`, `-2` for repeats) or an `id`/`name`;
// - the site `npm run docs` builds (docs/api/**/*.html, unless --no-site): each relative `href`/`src` names an
//   existing file, and its `#anchor`, in an HTML page, an `id` or `name` there.
// External links are not fetched (no network); a link to the packages' `repository` URL, which does not exist,
// is reported. Code (fenced blocks, inline code spans) and HTML comments are not read. Prints each broken link
// as `file:line: target (why)` and exits 1 when there is one. npm test runs it after the docs stage.
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, extname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/**
 * External URLs that do not resolve: the packages' `repository` (a GitHub repository that does not exist).
 * A link starting with one of these is reported.
 */
export const DEAD_URL_PREFIXES = [
  'https://github.com/shadelab/shadelab',
  'http://github.com/shadelab/shadelab',
];

/**
 * @typedef {object} Link
 * @property {string} target the link as written
 * @property {number} line 1-based line in the file
 */

/**
 * @typedef {object} Problem
 * @property {string} file relative to the root, with `/`
 * @property {number} line
 * @property {string} target
 * @property {string} reason
 */

/**
 * The Markdown files of the repository: tracked, or new and not ignored, outside node_modules.
 * @param {string} [dir] repository root @returns {string[]} paths relative to `dir`, sorted
 */
export function markdownFiles(dir = root) {
  const r = spawnSync('git', ['ls-files', '--cached', '--others', '--exclude-standard', '-z', '--', '*.md'], {
    cwd: dir,
    encoding: 'utf8',
  });
  if (r.status !== 0) throw new Error(`git ls-files failed in ${dir}: ${r.stderr}`);
  return [...new Set(r.stdout.split('\0').filter(Boolean))]
    .filter((f) => !/(^|\/)node_modules\//.test(f) && existsSync(join(dir, f)))
    .sort();
}

/**
 * The text with code and comments blanked out (same length and line breaks, so offsets and lines hold):
 * fenced code blocks (backtick or tilde fences of any length), HTML comments and, unless `inline` is false, inline code spans.
 * @param {string} text Markdown @param {boolean} [inline] blank inline code spans too
 * @returns {string}
 */
export function blankCode(text, inline = true) {
  const blank = (/** @type {string} */ s) => s.replace(/[^\n]/g, ' ');
  const lines = text.split('\n');
  /** @type {{ char: string, length: number } | null} */
  let fence = null;
  for (let i = 0; i < lines.length; i++) {
    const m = /^ {0,3}(`{3,}|~{3,})/.exec(lines[i]);
    if (fence) {
      if (
        m &&
        m[1][0] === fence.char &&
        m[1].length >= fence.length &&
        /^\s*$/.test(lines[i].slice(m[0].length))
      )
        fence = null;
      lines[i] = blank(lines[i]);
    } else if (m) {
      fence = { char: m[1][0], length: m[1].length };
      lines[i] = blank(lines[i]);
    }
  }
  const blocks = lines.join('\n').replace(/<!--[\s\S]*?-->/g, blank);
  return inline ? blocks.replace(/(`+)(?!`)[\s\S]*?[^`]\1(?!`)/g, blank) : blocks;
}

/** @param {string} text @param {number} index @returns {number} 1-based line of `index` */
function lineOf(text, index) {
  let line = 1;
  for (let i = 0; i < index; i++) if (text.charCodeAt(i) === 10) line++;
  return line;
}

/**
 * Every link target of a Markdown text, outside code: inline links and images, reference definitions,
 * autolinks and `href`/`src` attributes of inline HTML.
 * @param {string} markdown @returns {Link[]}
 */
export function markdownLinks(markdown) {
  const text = blankCode(markdown);
  /** @type {Link[]} */
  const links = [];
  const add = (/** @type {string} */ target, /** @type {number} */ index) =>
    links.push({ target, line: lineOf(text, index) });
  // [text](target "title") and ![alt](target); the target may be wrapped in <>.
  for (const m of text.matchAll(
    /\]\(\s*(<[^>\n]*>|[^()\s]*(?:\([^()\s]*\)[^()\s]*)*)(?:\s+(?:"[^"]*"|'[^']*'))?\s*\)/g,
  ))
    add(m[1].replace(/^<|>$/g, ''), m.index);
  // [id]: target
  for (const m of text.matchAll(/^ {0,3}\[[^\]\n]+\]:\s*<?([^\s>]+)>?/gm)) add(m[1], m.index);
  // <https://…>
  for (const m of text.matchAll(/<(https?:\/\/[^>\s]+)>/g)) add(m[1], m.index);
  // <a href="…">, <img src="…">
  for (const m of text.matchAll(/<[a-zA-Z][^>]*?\s(?:href|src)\s*=\s*(?:"([^"]*)"|'([^']*)')/g))
    add(m[1] ?? m[2], m.index);
  return links;
}

/**
 * GitHub's anchor for a heading: its text as rendered (Markdown marks removed), lower case, punctuation and
 * symbols removed (letters, digits, `-` and `_` kept), each space a `-`.
 * @param {string} heading the heading's Markdown, without the leading #s
 * @returns {string}
 */
export function githubSlug(heading) {
  const ESCAPED = '\uE000'; // an escaped underscore, kept
  const text = heading
    .trim()
    .replace(/\\([\\`*_{}[\]()#+\-.!|<>~])/g, (_, c) => (c === '_' ? ESCAPED : c)) // backslash escapes
    .replace(/!?\[([^\]]*)\]\([^)]*\)/g, '$1') // links and images: their text
    .replace(/<[^>]+>/g, '') // inline HTML
    .replace(/`/g, '')
    .replace(/(\*\*|__)(.+?)\1/g, '$2')
    .replace(/(^|[^\p{L}\p{N}])[*_]([^*_]+)[*_](?=[^\p{L}\p{N}]|$)/gu, '$1$2')
    .replace(/\*/g, '');
  return text
    .toLowerCase()
    .replace(/[^\p{L}\p{M}\p{N}\p{Pc}\uE000 -]/gu, '')
    .replace(/ /g, '-')
    .replace(/\uE000/g, '_');
}

/**
 * The anchors a Markdown text defines: its headings' GitHub slugs (a repeated slug gets `-1`, `-2`, …) and every
 * `id`/`name` attribute of its inline HTML.
 * @param {string} markdown @returns {Set<string>}
 */
export function markdownAnchors(markdown) {
  const text = blankCode(markdown, false);
  const anchors = new Set();
  /** @type {Map<string, number>} */
  const seen = new Map();
  for (const m of text.matchAll(/^ {0,3}#{1,6}[ \t]+(.*?)(?:[ \t]+#+)?[ \t]*$/gm)) {
    const base = githubSlug(m[1]);
    const n = seen.get(base) ?? 0;
    seen.set(base, n + 1);
    anchors.add(n === 0 ? base : `${base}-${n}`);
  }
  for (const m of text.matchAll(/\s(?:id|name)\s*=\s*(?:"([^"]*)"|'([^']*)')/g)) anchors.add(m[1] ?? m[2]);
  return anchors;
}

/** @param {string} html @returns {Set<string>} every `id` and `name` attribute of an HTML page */
export function htmlAnchors(html) {
  const anchors = new Set();
  for (const m of html.matchAll(/\s(?:id|name)\s*=\s*(?:"([^"]*)"|'([^']*)')/g)) anchors.add(m[1] ?? m[2]);
  return anchors;
}

/** @param {string} html @returns {Link[]} every `href` and `src` of an HTML page */
export function htmlLinks(html) {
  const text = html.replace(/<!--[\s\S]*?-->/g, (s) => s.replace(/[^\n]/g, ' '));
  return [...text.matchAll(/<[a-zA-Z][^>]*?\s(?:href|src)\s*=\s*(?:"([^"]*)"|'([^']*)')/g)].map((m) => ({
    target: (m[1] ?? m[2]).replace(/&amp;/g, '&'),
    line: lineOf(text, m.index),
  }));
}

/**
 * Checks links against the files under one root.
 * @param {string} base the root no relative link may leave
 */
export function createChecker(base) {
  /** @type {Map<string, Set<string>>} */
  const anchorCache = new Map();
  /** @param {string} path absolute @returns {Set<string>} */
  const anchorsOf = (path) => {
    let anchors = anchorCache.get(path);
    if (!anchors) {
      const text = readFileSync(path, 'utf8');
      anchors = extname(path).toLowerCase() === '.md' ? markdownAnchors(text) : htmlAnchors(text);
      anchorCache.set(path, anchors);
    }
    return anchors;
  };

  /**
   * Why a link of `file` does not resolve, or `undefined` when it does.
   * @param {string} file absolute path of the page the link is in
   * @param {string} target the link as written
   * @returns {string | undefined}
   */
  return function problemOf(file, target) {
    if (
      DEAD_URL_PREFIXES.some((p) => target === p || target.startsWith(`${p}/`) || target.startsWith(`${p}.`))
    )
      return 'the packages\u2019 repository URL, which does not exist';
    if (/^[a-zA-Z][a-zA-Z\d+.-]*:/.test(target) || target.startsWith('//')) return undefined; // external
    if (target === '' || target === '#') return undefined;
    const hash = target.indexOf('#');
    const pathPart = (hash === -1 ? target : target.slice(0, hash)).replace(/\?.*$/, '');
    const anchor = hash === -1 ? '' : decodeURIComponent(target.slice(hash + 1));
    let path;
    try {
      path =
        pathPart === ''
          ? file
          : resolve(pathPart.startsWith('/') ? base : dirname(file), `.${sep}${decodeURI(pathPart)}`);
    } catch {
      return 'not a valid path';
    }
    const rel = relative(base, path);
    if (rel.startsWith('..') || resolve(base, rel) !== path) return 'outside the repository';
    if (!existsSync(path)) return 'no such file';
    if (anchor === '' || statSync(path).isDirectory()) return undefined;
    // A fragment `key=value` is the page's own state, read by its script (the playground's `#s=`), not an anchor.
    if (/^[\w-]+=/.test(anchor)) return undefined;
    const ext = extname(path).toLowerCase();
    if (ext !== '.md' && ext !== '.html') return undefined;
    return anchorsOf(path).has(anchor)
      ? undefined
      : `no anchor #${anchor} in ${relative(base, path).split(sep).join('/')}`;
  };
}

/**
 * Every broken link of some Markdown files.
 * @param {string[]} files relative to `base` @param {string} [base] repository root
 * @returns {Problem[]}
 */
export function checkMarkdown(files, base = root) {
  const problemOf = createChecker(base);
  /** @type {Problem[]} */
  const problems = [];
  for (const file of files) {
    const path = resolve(base, file);
    for (const { target, line } of markdownLinks(readFileSync(path, 'utf8'))) {
      const reason = problemOf(path, target);
      if (reason) problems.push({ file: relative(base, path).split(sep).join('/'), line, target, reason });
    }
  }
  return problems;
}

/**
 * Every broken link of the HTML pages under `siteDir`.
 * @param {string} siteDir @param {string} [base] the root no link may leave (the site folder by default)
 * @returns {Problem[]}
 */
export function checkSite(siteDir, base = siteDir) {
  const problemOf = createChecker(base);
  /** @type {Problem[]} */
  const problems = [];
  const pages = readdirSync(siteDir, { recursive: true, encoding: 'utf8' }).filter((f) =>
    f.endsWith('.html'),
  );
  for (const page of pages.sort()) {
    const path = join(siteDir, page);
    for (const { target, line } of htmlLinks(readFileSync(path, 'utf8'))) {
      const reason = problemOf(path, target);
      if (reason) problems.push({ file: relative(root, path).split(sep).join('/'), line, target, reason });
    }
  }
  return problems;
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const files = args.filter((a) => !a.startsWith('--'));
  const markdown = files.length ? files : markdownFiles();
  const problems = checkMarkdown(markdown);
  let pages = 0;
  if (!args.includes('--no-site') && !files.length) {
    const site = join(root, 'docs', 'api');
    if (!existsSync(join(site, 'index.html'))) {
      problems.push({
        file: 'docs/api/index.html',
        line: 0,
        target: '',
        reason: 'the site is not built: run `npm run docs` first (or pass --no-site)',
      });
    } else {
      pages = readdirSync(site, { recursive: true, encoding: 'utf8' }).filter((f) =>
        f.endsWith('.html'),
      ).length;
      problems.push(...checkSite(site));
    }
  }
  for (const p of problems) console.error(`${p.file}:${p.line}: ${p.target} (${p.reason})`);
  console.log(
    `links: ${markdown.length} Markdown files${pages ? ` and ${pages} site pages` : ''}, ${problems.length} broken link${problems.length === 1 ? '' : 's'}`,
  );
  process.exit(problems.length ? 1 : 0);
}
