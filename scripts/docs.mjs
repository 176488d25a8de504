// `node scripts/docs.mjs [--check]`: the documentation, from the TSDoc and the guides, in two forms.
//
// 1. The site: one static HTML site in docs/api/ (open docs/api/index.html; git-ignored, never committed): the
//    docs index (docs/README.md), the concepts guide and the design (docs/*.md), each package's guide
//    (packages/<name>/docs/guide.md) and the API reference of every package, built by TypeDoc with
//    tools/docs/typedoc.json. No source links: the packages' `repository` URLs do not resolve. The playground is
//    built into it (docs/api/playground/): the concept pages embed its `?embed` view.
// 2. The reference a package user has: each package's API reference as Markdown in
//    packages/<name>/docs/api/ (README.md, plus one page per subpath entry), built by TypeDoc with
//    typedoc-plugin-markdown (tools/docs/typedoc.markdown.json). It is committed, so that the package README's
//    relative links resolve in the repository, on a code host and in the tarball (npm pack ships docs/).
// TypeDoc converts the TSDoc once, in this process, for both (tools/docs/reference.mjs): each package's Markdown
// is rendered from that package's part of the conversion alone, as a TypeDoc run of that package would write it.
//
// --check: fail on any TypeDoc warning (an undocumented export, a broken {@link} or relative link) and when the
// committed Markdown reference differs from what the TSDoc generates (then run `npm run docs` and commit).
// TypeDoc needs the TypeScript 5 compiler API, which the root's TypeScript 7 does not have, so it lives in
// tools/docs, a separate npm project installed here when its node_modules is missing or stale.
import { cpSync, existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative } from 'node:path';
import { pathToFileURL } from 'node:url';
import { buildPackages, ensureDependencies, root, run } from './setup.mjs';

const tools = join(root, 'tools', 'docs');
const out = join(root, 'docs', 'api');
const check = process.argv.includes('--check');

/**
 * The documented packages: every non-private workspace under packages/ (the published ones, as
 * scripts/pack.mjs packs them), as folder names. Each has a guide, docs/guide.md.
 */
const DOC_PACKAGES = /** @type {{ workspaces: string[] }} */ (
  JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'))
).workspaces
  .filter((w) => w.startsWith('packages/'))
  .filter((w) => !JSON.parse(readFileSync(join(root, w, 'package.json'), 'utf8')).private)
  .map((w) => w.slice('packages/'.length));

/** First line of every generated Markdown page. */
const GENERATED_NOTE =
  '<!-- Generated from the TSDoc by `npm run docs` (scripts/docs.mjs); do not edit: npm test compares it. -->';

/**
 * Every file under `dir`, relative to it, with `/`, sorted.
 * @param {string} dir @returns {string[]}
 */
function listFiles(dir) {
  if (!existsSync(dir)) return [];
  return readdirSync(dir, { recursive: true, withFileTypes: true })
    .filter((e) => e.isFile())
    .map((e) =>
      relative(dir, join(e.parentPath ?? e.path, e.name))
        .split('\\')
        .join('/'),
    )
    .sort();
}

const noGuide = DOC_PACKAGES.filter((name) => !existsSync(join(root, 'packages', name, 'docs', 'guide.md')));
if (noGuide.length) {
  console.error(
    `docs: every package has a guide, packages/<name>/docs/guide.md (listed in docs/README.md); missing: ${noGuide.join(', ')}`,
  );
  process.exit(1);
}

/**
 * In the site, the guides' links to a package's Markdown reference (which TypeDoc copies into media/ as they
 * are) go to the same page of the site instead: the module's page, or the page of the member an anchor names
 * (`README.md#shadingmaterialoptions` → the ShadingMaterialOptions page).
 * @param {string} site the HTML output folder
 */
function linkReferenceToSite(site) {
  const media = join(site, 'media');
  if (!existsSync(media)) return;
  /** @type {Map<string, string>} module name (`@shadelab/material/outline`) → its page, relative to the site */
  const modulePages = new Map();
  for (const file of listFiles(join(site, 'modules'))) {
    const title = /<title>([^<|]+?) \|/.exec(readFileSync(join(site, 'modules', file), 'utf8'));
    if (title) modulePages.set(title[1], `modules/${file}`);
  }
  /** @type {Map<string, string>} media file → module name */
  const copies = new Map();
  for (const name of DOC_PACKAGES) {
    const dir = join(root, 'packages', name, 'docs', 'api');
    for (const page of listFiles(dir)) {
      const text = readFileSync(join(dir, page), 'utf8');
      const sub = page === 'README.md' ? '' : page.replace(/^@shadelab\.[^.]+\.(.+)\.md$/, '/$1');
      for (const file of listFiles(media)) {
        if (readFileSync(join(media, file), 'utf8') === text) copies.set(file, `@shadelab/${name}${sub}`);
      }
    }
  }
  const memberPages = listFiles(site).filter((f) =>
    /^(classes|interfaces|types|functions|variables|enums)\//.test(f),
  );
  /** @param {string} file @param {string} anchor @returns {string | undefined} */
  const target = (file, anchor) => {
    const modulePage = modulePages.get(copies.get(file) ?? '');
    if (!modulePage) return undefined;
    const prefix = modulePage.slice('modules/'.length, -'.html'.length);
    const member = memberPages.find(
      (f) => f.slice(f.indexOf('/') + 1).toLowerCase() === `${prefix}.${anchor}.html`,
    );
    return member ?? modulePage;
  };
  for (const page of listFiles(site).filter((f) => f.endsWith('.html'))) {
    const path = join(site, page);
    const html = readFileSync(path, 'utf8');
    const rewritten = html.replace(
      /href="((?:\.\.\/)*)media\/([^"#]+)(?:#([^"]*))?"/g,
      (all, up, file, anchor = '') => {
        const to = target(decodeURIComponent(file), anchor.toLowerCase());
        return to ? `href="${up}${to}"` : all;
      },
    );
    if (rewritten !== html) writeFileSync(path, rewritten);
  }
}

ensureDependencies(tools);
buildPackages(); // @shadelab/reference's declarations import the built @shadelab/material.

// TypeDoc resolves and prints paths from the working directory: the repository root, as for the commands run
// here.
process.chdir(root);
/**
 * tools/docs/reference.mjs, loaded once its node_modules is installed.
 * @type {{ convertReference: (options: { packages: string[], check: boolean }) => Promise<{ ok: boolean,
 *   markdown: (dir: string, out: string) => Promise<boolean>, site: (out: string) => Promise<boolean> }> }}
 */
const { convertReference } = await import(pathToFileURL(join(tools, 'reference.mjs')).href);
let failed = false;
/** Whether TypeDoc reported an error, or a warning with --check, and so did not write what it concerns. */
let typedocFailed = false;

// 1. The TSDoc of every package, converted once for both forms.
console.log('docs: the TSDoc of every package (TypeDoc)…');
const reference = await convertReference({
  packages: DOC_PACKAGES.map((name) => join(root, 'packages', name)),
  check,
});
if (!reference.ok) typedocFailed = true;

// 2. The Markdown reference of each package, written into a temporary folder, then compared or copied.
const tmp = mkdtempSync(join(tmpdir(), 'shadelab-docs-'));
const stale = [];
/** Pages of the Markdown reference that were not there before this run. */
const added = [];
try {
  for (const name of DOC_PACKAGES) {
    console.log(`docs: @shadelab/${name} reference (TypeDoc, Markdown)…`);
    const generated = join(tmp, name);
    if (!(await reference.markdown(join(root, 'packages', name), generated))) {
      typedocFailed = true;
      continue;
    }
    for (const file of listFiles(generated)) {
      const path = join(generated, file);
      writeFileSync(path, `${GENERATED_NOTE}\n\n${readFileSync(path, 'utf8').trimEnd()}\n`);
    }
    const committed = join(root, 'packages', name, 'docs', 'api');
    if (check) {
      const want = listFiles(generated);
      const have = listFiles(committed);
      for (const f of new Set([...want, ...have])) {
        const a = want.includes(f) ? readFileSync(join(generated, f), 'utf8') : undefined;
        const b = have.includes(f) ? readFileSync(join(committed, f), 'utf8') : undefined;
        if (a !== b) {
          const what = b === undefined ? 'missing' : a === undefined ? 'not generated any more' : 'differs';
          stale.push(`${relative(root, join(committed, f))}: ${what}`);
        }
      }
    } else {
      const have = listFiles(committed);
      added.push(
        ...listFiles(generated)
          .filter((f) => !have.includes(f))
          .map((f) => relative(root, join(committed, f))),
      );
      rmSync(committed, { recursive: true, force: true });
      cpSync(generated, committed, { recursive: true });
    }
  }
} finally {
  rmSync(tmp, { recursive: true, force: true });
}

// 3. The HTML site, after the Markdown: TypeDoc copies the Markdown pages the guides link to into the site.
console.log('docs: the site (TypeDoc, HTML)…');
if (!(await reference.site(out))) typedocFailed = true;
else {
  // TypeDoc empties its output folder first, so the ignore file is written after it.
  writeFileSync(join(out, '.gitignore'), '# Generated by scripts/docs.mjs: never committed.\n*\n');
  linkReferenceToSite(out);
  // 4. The playground in the site (docs/api/playground/, relative paths), so that wherever the site is served, the
  // concept pages' `?embed` views of it (the iframes of docs/concepts.md) are served beside them.
  console.log('docs: the playground in the site (Vite)…');
  const playground = ['vite', 'build', 'playground', '--base', './', '--outDir', join(out, 'playground')];
  if (run('npx', [...playground, '--emptyOutDir', '--logLevel', 'warn']) !== 0) failed = true;
}

if (added.length) {
  // TypeDoc read the guides before these pages were written, so a guide's link to one resolves from the next run.
  console.log(
    `docs: new reference pages, which the site's guides link to from the next run: ${added.join(', ')}`,
  );
}
if (typedocFailed) {
  console.error(
    `docs: TypeDoc reported the ${check ? 'errors or warnings above (--check fails on any)' : 'errors above'}; ` +
      'what they concern was not written.',
  );
  failed = true;
}
if (stale.length) {
  console.error(
    `docs: the committed Markdown reference is not what the TSDoc generates:\n  ${stale.join('\n  ')}\n` +
      'Run `npm run docs` and commit packages/*/docs/api/.',
  );
  failed = true;
}
if (failed) process.exit(1);
console.log(`docs: ${join('docs', 'api', 'index.html')}; packages/<name>/docs/api/README.md`);
