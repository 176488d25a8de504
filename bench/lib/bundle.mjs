// What the playground's index.html loads at start, from a Vite build's output: its entry chunk and every chunk
// it imports statically, in three groups (three.js; the @shadelab packages' own chunks; React, react-dom, leva and
// the app), raw bytes and gzip -9. Used by scripts/bundle-size.mjs and bench/playground-refactor.bench.mjs.
import { sep } from 'node:path';
import { gzipSync } from 'node:zlib';

/** @typedef {import('vite').Rolldown.OutputChunk} Chunk */
/** @typedef {{ raw: number, gzip: number, chunks: { file: string, raw: number, gzip: number }[] }} Group */

/** The group names and what the tables call them. */
export const BUNDLE_GROUPS = /** @type {const} */ ({
  three: 'three.js',
  app: 'React, react-dom, leva and the app',
  shadelab: 'the @shadelab packages (their own chunks)',
});

/**
 * @param {unknown} result what Vite's `build()` returned (one output or several)
 * @param {string} root the repository root, with a trailing separator (package modules live under `packages/`)
 * @returns {{ groups: Record<keyof typeof BUNDLE_GROUPS, Group>, total: { raw: number, gzip: number } }}
 */
export function indexBundle(result, root) {
  const outputs = /** @type {import('vite').Rolldown.RolldownOutput[]} */ (
    Array.isArray(result) ? result : [result]
  ).flatMap((r) => r.output);
  /** @type {Map<string, Chunk>} */
  const chunks = new Map();
  for (const o of outputs) if (o.type === 'chunk') chunks.set(o.fileName, o);
  const entry = [...chunks.values()].find(
    (c) => c.isEntry && c.facadeModuleId?.endsWith(`${sep}playground${sep}index.html`),
  );
  if (!entry) throw new Error('bundle: no chunk for playground/index.html in the build');
  /** @type {Chunk[]} */
  const loaded = [];
  const seen = new Set();
  const visit = (/** @type {string} */ fileName) => {
    if (seen.has(fileName)) return;
    seen.add(fileName);
    const chunk = chunks.get(fileName);
    if (!chunk) return;
    loaded.push(chunk);
    for (const imported of chunk.imports) visit(imported);
  };
  visit(entry.fileName);
  const inThree = (/** @type {string} */ id) => /[\\/]node_modules[\\/]three[\\/]/.test(id);
  const inPackages = (/** @type {string} */ id) =>
    id.startsWith(`${root}packages${sep}`) || id.startsWith(`${root}packages/`);
  // A chunk's group: all of its modules from three, all from packages/, or otherwise the app's. The bundler's own
  // virtual helpers (ids starting with NUL: the module-preload polyfill, the runtime) do not decide it.
  const group = (/** @type {Chunk} */ chunk) => {
    const ids = Object.keys(chunk.modules).filter(
      (id) => !id.startsWith('\0') && chunk.modules[id].renderedLength > 0,
    );
    if (ids.length > 0 && ids.every(inThree)) return 'three';
    if (ids.length > 0 && ids.every(inPackages)) return 'shadelab';
    return 'app';
  };
  const groups = /** @type {Record<keyof typeof BUNDLE_GROUPS, Group>} */ (
    Object.fromEntries(Object.keys(BUNDLE_GROUPS).map((k) => [k, { raw: 0, gzip: 0, chunks: [] }]))
  );
  for (const chunk of loaded) {
    const code = Buffer.from(chunk.code);
    const g = groups[group(chunk)];
    const gzip = gzipSync(code, { level: 9 }).length;
    g.raw += code.length;
    g.gzip += gzip;
    g.chunks.push({ file: chunk.fileName, raw: code.length, gzip });
  }
  const total = Object.values(groups).reduce((a, g) => ({ raw: a.raw + g.raw, gzip: a.gzip + g.gzip }), {
    raw: 0,
    gzip: 0,
  });
  return { groups, total };
}
