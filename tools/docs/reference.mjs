// The TypeDoc work of scripts/docs.mjs, in its process: the TSDoc of every package is converted once and
// rendered twice, by two TypeDoc applications: the HTML site of all the packages (typedoc.json) and each
// package's Markdown reference (typedoc.markdown.json, with typedoc-plugin-markdown). Converting is most of
// TypeDoc's time.
//
// The site's application converts, in the `packages` strategy: each package on its own with its own options,
// serialized to JSON, then the JSONs revived into one project. Each package's JSON is kept as it is serialized,
// and the Markdown application revives it alone, with the steps of the packages strategy for a single package,
// as `typedoc --options typedoc.markdown.json --entryPoints packages/<name>` would: so each package's reference
// is the reference of that package alone, its pages README.md and `@shadelab.<name>.<subpath>.md`, the other
// packages external to it (linked through typedoc.markdown.json's externalSymbolLinkMappings). One application
// cannot render both: the options applied when a project is revived (externalSymbolLinkMappings, readme,
// validation) differ between the two, and the Markdown pages are named for a project of one package.
//
// Where the site's conversion of a package differs from what the package's own Markdown run would convert, the
// package's JSON is made the latter's:
// - the site's documents of the package (its guide: packageOptions.projectDocuments of typedoc.json) are taken
//   out;
// - a package with one entry point: its guide makes TypeDoc convert that entry point as a module, which the
//   module's `@mergeModuleWith <project>` merges into the package, dropping the module's comment; the package's
//   own run converts the entry point as the package itself, with that comment. The comment is kept from before
//   the merge and put on the package.
// `--check` compares the Markdown written here with the committed reference, so a TypeDoc that converts in
// another way fails the check instead of changing the reference unseen.
//
// With `check`, warnings follow the `typedoc` command's --treatWarningsAsErrors: a warning when converting or
// validating stops the outputs made from that (the site, or a package's Markdown) before they are written.
import { readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { isDeepStrictEqual } from 'node:util';
import {
  Application,
  Converter,
  normalizePath,
  ReflectionKind,
  Serializer,
  ValidatingFileRegistry,
} from 'typedoc';

/** @typedef {import('typedoc').JSONOutput.ProjectReflection} ProjectJson */
/** @typedef {import('typedoc').ProjectReflection} Project */
/** @typedef {{ errors: number, warnings: number }} Counts */

const here = dirname(fileURLToPath(import.meta.url));

/**
 * @typedef {object} Reference the packages' TSDoc, converted
 * @property {boolean} ok false when converting reported an error, or a warning with `check`
 * @property {(dir: string, out: string) => Promise<boolean>} markdown write the Markdown reference of the
 *   package in `dir` into `out`; false when it was not written (not converted, or an error, or a warning with
 *   `check`)
 * @property {(out: string) => Promise<boolean>} site write the HTML site into `out`; false as for `markdown`
 */

/**
 * Convert the TSDoc of the packages once, for the site and for each package's Markdown reference.
 * @param {{ packages: string[], check: boolean }} options `packages`: the package folders (absolute);
 *   `check`: any warning fails, as with `typedoc --treatWarningsAsErrors`.
 * @returns {Promise<Reference>}
 */
export async function convertReference({ packages, check }) {
  const html = await Application.bootstrapWithPlugins({
    options: join(here, 'typedoc.json'),
    entryPoints: packages,
  });
  // Quiet, as `typedoc --logLevel Warn`: the site's application says what it converts.
  const md = await Application.bootstrapWithPlugins({
    options: join(here, 'typedoc.markdown.json'),
    entryPoints: packages,
    logLevel: 'Warn',
  });
  /** @param {Application} app @returns {Counts} */
  const counts = (app) => ({ errors: app.logger.errorCount, warnings: app.logger.warningCount });
  /** Whether `app` reported an error, or a warning with `check`, since `before`. */
  const failedSince = (/** @type {Application} */ app, /** @type {Counts} */ before) =>
    app.logger.errorCount > before.errors || (check && app.logger.warningCount > before.warnings);
  /**
   * Validate `project` with `app` and, when that reports no failure since `before`, write it into `out`; false
   * when TypeDoc reported a failure.
   * @param {Application} app @param {any} project @param {string} out @param {Counts} before
   */
  const validateAndWrite = async (app, project, out, before) => {
    app.validate(project);
    if (failedSince(app, before)) return false;
    app.options.setValue('out', out);
    await app.generateOutputs(project);
    return !failedSince(app, before);
  };
  const start = { errors: 0, warnings: 0 };
  // The Markdown is made from the site's conversion, so both configurations must convert a package alike.
  /** @param {Application} app */
  const converting = (app) =>
    Object.fromEntries(
      Object.entries(app.options.getValue('packageOptions')).filter(([name]) => name !== 'projectDocuments'),
    );
  if (!isDeepStrictEqual(converting(html), converting(md))) {
    md.logger.error(
      'typedoc.json and typedoc.markdown.json have different packageOptions (only projectDocuments may differ): ' +
        "each package's Markdown is made from the site's conversion of it",
    );
  }
  if (failedSince(html, start) || failedSince(md, start)) {
    const nothing = async () => false;
    return { ok: false, markdown: nothing, site: nothing };
  }

  /** @type {WeakMap<Project, import('typedoc').DeclarationReflection>} a package's one entry point's module */
  const entryModules = new WeakMap();
  html.converter.on(
    Converter.EVENT_RESOLVE_BEGIN,
    (context) => {
      const [entry, ...others] = context.project.children ?? [];
      if (entry?.kindOf(ReflectionKind.Module) && !others.length) entryModules.set(context.project, entry);
    },
    // Before TypeDoc's own listeners: one of them merges the module into the package.
    Number.MAX_SAFE_INTEGER,
  );
  /** @type {Map<string, { json: ProjectJson, siteDocuments: string[] }>} by package folder */
  const converted = new Map();
  html.serializer.on(Serializer.EVENT_END, (event) => {
    const dir = html.options.packageDir;
    const output = event.output;
    if (dir === undefined || output?.variant !== 'project') return;
    const project = /** @type {Project} */ (event.project);
    const json = structuredClone(output);
    const entry = entryModules.get(project);
    if (entry && project.children?.includes(entry)) {
      html.logger.error(
        `${json.name}: its one entry point is a module of its own in the site, which the package's Markdown ` +
          'reference cannot be made from: its module comment (src/index.ts) needs `@mergeModuleWith <project>`',
      );
      return;
    }
    if (entry?.comment) {
      html.converter.resolveLinks(entry.comment, project);
      json.comment = html.serializer.toObject(entry.comment);
    }
    converted.set(key(dir), { json, siteDocuments: html.options.getValue('projectDocuments') });
  });
  const project = await html.convert();
  const ok = project !== undefined && !failedSince(html, start);

  return {
    ok,
    async markdown(dir, out) {
      const entry = converted.get(key(dir));
      if (!entry) return false;
      const before = counts(md);
      // The package's options as the Markdown configuration gives them (its packageOptions and the package's
      // own typedoc.json), read as the packages strategy reads them: the Markdown plugin names pages with them.
      const options = md.options.copyForPackage(dir);
      await options.read(md.logger, dir);
      const markdownDocuments = new Set(/** @type {string[]} */ (options.getValue('projectDocuments')));
      const json = withoutDocuments(
        entry.json,
        entry.siteDocuments.filter((path) => !markdownDocuments.has(path)),
      );
      // The packages strategy's steps after converting, for one package: its JSON revived into a project of
      // its own, with a file registry of its own (the files its pages link to are copied from it).
      md.files = new ValidatingFileRegistry(md.options.getValue('basePath'));
      const name = md.options.getValue('name') || 'Documentation';
      const reference = md.deserializer.reviveProjects(name, [json], {
        projectRoot: normalizePath(process.cwd()),
        registry: md.files,
        alwaysCreateEntryPointModule: md.options.getValue('alwaysCreateEntryPointModule'),
      });
      md.converter.addProjectDocuments(reference);
      // What typedoc-plugin-markdown records of each package it converts, here the only one.
      const { description } = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
      /** @type {any} */ (md.renderer).packagesMeta = { [json.name]: { description, options } };
      md.trigger(Application.EVENT_PROJECT_REVIVE, reference);
      return validateAndWrite(md, reference, out, before);
    },
    async site(out) {
      if (!project || !ok) return false;
      return validateAndWrite(html, project, out, counts(html));
    },
  };
}

/** @param {string} dir a package folder @returns {string} its key, as TypeDoc names it */
function key(dir) {
  return normalizePath(resolve(dir));
}

/**
 * A package's serialized project without the project documents read from `paths` (absolute).
 * @param {ProjectJson} json @param {string[]} paths @returns {ProjectJson}
 */
function withoutDocuments(json, paths) {
  const files = json.files;
  /** @type {Map<string, string>} file id → path, relative to the working directory */
  const entries = new Map(Object.entries(files.entries));
  const wanted = new Set(paths.map((path) => normalizePath(path)));
  /** @type {Set<number>} the reflections of those files */
  const fromFiles = new Set();
  for (const [file, id] of Object.entries(files.reflections)) {
    const path = entries.get(file);
    if (path !== undefined && wanted.has(normalizePath(resolve(path)))) fromFiles.add(id);
  }
  /** @type {Set<number>} */
  const gone = new Set(json.documents?.filter((d) => fromFiles.has(d.id)).map((d) => d.id));
  if (!gone.size) return json;
  const keep = (/** @type {number} */ id) => !gone.has(id);
  /** @template T @param {T[] | undefined} list @returns {T[] | undefined} */
  const orNone = (list) => (list?.length ? list : undefined);
  const documents = orNone(json.documents?.filter((d) => keep(d.id)));
  return {
    ...json,
    documents,
    // Serialized only when there are both children and documents, as TypeDoc does.
    childrenIncludingDocuments:
      documents && json.children?.length ? json.childrenIncludingDocuments?.filter(keep) : undefined,
    groups: orNone(
      json.groups
        ?.map((group) => ({ ...group, children: group.children?.filter(keep) }))
        .filter((group) => group.children?.length),
    ),
    files: {
      ...files,
      reflections: Object.fromEntries(Object.entries(files.reflections).filter(([, id]) => keep(id))),
    },
  };
}
