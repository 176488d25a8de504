// What the playground's index.html loads at start, from a Vite build's output: its entry chunk and every chunk
// it imports statically, raw bytes and gzip -9, split in three groups (three.js; the @shadelab packages; React,
// react-dom, leva and the app) by the share of each chunk's rendered modules. Used by scripts/bundle-size.mjs and bench/playground-refactor.bench.mjs.
import { sep } from 'node:path';
import { gzipSync } from 'node:zlib';

/** @typedef {import('vite').Rolldown.OutputChunk} Chunk */
/** @typedef {{ raw: number, gzip: number, chunks: { file: string, raw: number, gzip: number }[] }} Group */

/** The group names and what the tables call them. */
export const BUNDLE_GROUPS = /** @type {const} */ ({
  three: 'three.js',
  app: 'React, react-dom, leva and the app',
  shadelab: 'the @shadelab packages',
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
  /** @param {string} id */
  const groupOf = (id) => (inThree(id) ? 'three' : inPackages(id) ? 'shadelab' : 'app');
  const empty = () => /** @type {Group} */ ({ raw: 0, gzip: 0, chunks: [] });
  /** @type {Record<keyof typeof BUNDLE_GROUPS, Group>} */
  const groups = { three: empty(), app: empty(), shadelab: empty() };
  // A chunk's bytes (raw and gzip -9) go to the groups in proportion to its modules' rendered lengths: the
  // bundler puts three, the packages and the app in one chunk or several as the entries share them. The
  // bundler's own virtual helpers (ids starting with NUL: the module-preload polyfill, the runtime) count as
  // the app's.
  for (const chunk of loaded) {
    const code = Buffer.from(chunk.code);
    const gzip = gzipSync(code, { level: 9 }).length;
    const lengths = { three: 0, app: 0, shadelab: 0 };
    for (const [id, m] of Object.entries(chunk.modules)) {
      lengths[id.startsWith('\0') ? 'app' : groupOf(id)] += m.renderedLength;
    }
    const sum = lengths.three + lengths.app + lengths.shadelab;
    for (const k of /** @type {(keyof typeof BUNDLE_GROUPS)[]} */ (['three', 'app', 'shadelab'])) {
      const share = sum > 0 ? lengths[k] / sum : k === 'app' ? 1 : 0;
      if (share === 0) continue;
      const g = groups[k];
      g.raw += code.length * share;
      g.gzip += gzip * share;
      g.chunks.push({
        file: chunk.fileName,
        raw: Math.round(code.length * share),
        gzip: Math.round(gzip * share),
      });
    }
  }
  for (const g of Object.values(groups)) {
    g.raw = Math.round(g.raw);
    g.gzip = Math.round(g.gzip);
  }
  // The total is the chunks' own bytes (the groups' rounded shares may differ from it by a byte or two).
  const total = loaded.reduce(
    (a, c) => {
      const code = Buffer.from(c.code);
      return { raw: a.raw + code.length, gzip: a.gzip + gzipSync(code, { level: 9 }).length };
    },
    { raw: 0, gzip: 0 },
  );
  return { groups, total };
}
