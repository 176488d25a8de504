// @shadelab/material as it was at an older commit, for benches that draw it beside this checkout's in one page
// (bench/lecture-refactor.bench.mjs; the page's loadModule: bench/harness/webgpu-bench.ts).
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';

const root = fileURLToPath(new URL('../..', import.meta.url));

/** The modules of three.js the bundle takes from the page, and the global the page puts each in. */
const THREE_MODULES = /** @type {const} */ ([
  ['three', '__shadelabThree'],
  ['three/webgpu', '__shadelabThreeWebGPU'],
  ['three/tsl', '__shadelabTSL'],
]);

/** @param {string[]} args */
const git = (args) => execFileSync('git', args, { cwd: root, encoding: 'utf8' }).trim();

/**
 * @shadelab/material's sources at `rev`, from git, bundled into one ES module that exports its main entry
 * (index.ts) and its webgpu entry (webgpu.ts, when the commit has one) together. Its `three`, `three/webgpu` and
 * `three/tsl` are the page's (globalThis.__shadelabThree, __shadelabThreeWebGPU, __shadelabTSL, which the page
 * sets before importing it), so that this build and the page's own draw through one three.js.
 * @param {string} rev a commit, e.g. `b0bbefe` or `3390eb4^`
 * @returns {Promise<{ code: string, commit: string }>}
 */
export async function bundleMaterialAt(rev) {
  const dir = mkdtempSync(join(tmpdir(), 'shadelab-material-'));
  try {
    const files = git(['ls-tree', '-r', '--name-only', rev, 'packages/material/src'])
      .split('\n')
      .filter((f) => f.endsWith('.ts') && !f.endsWith('.test.ts'));
    for (const file of files) {
      const out = join(dir, file);
      mkdirSync(dirname(out), { recursive: true });
      writeFileSync(out, execFileSync('git', ['show', `${rev}:${file}`], { cwd: root }));
    }
    const src = join(dir, 'packages/material/src');
    const entries = ['index.ts', 'webgpu.ts'].filter((f) => files.includes(`packages/material/src/${f}`));
    const entry = join(src, '__bench_entry.ts');
    writeFileSync(entry, entries.map((f) => `export * from './${f}';\n`).join(''));
    /** @type {Map<string, string>} */
    const shims = new Map();
    for (const [id, global] of THREE_MODULES) {
      const names = Object.keys(await import(id)).filter((n) => /^[A-Za-z_$][\w$]*$/.test(n));
      shims.set(
        `\0page:${id}`,
        `const T = globalThis.${global};\nexport const { ${names.join(', ')} } = T;\n`,
      );
    }
    const result = await build({
      configFile: false,
      root: dir,
      logLevel: 'warn',
      plugins: [
        {
          name: 'three-of-the-page',
          enforce: 'pre',
          resolveId: (id) => (shims.has(`\0page:${id}`) ? `\0page:${id}` : null),
          load: (id) => shims.get(id) ?? null,
        },
      ],
      build: {
        write: false,
        minify: false,
        lib: { entry, formats: ['es'], fileName: 'material' },
      },
    });
    const outputs = Array.isArray(result) ? result : [result];
    const chunks = outputs.flatMap((o) => ('output' in o ? o.output : [])).filter((o) => o.type === 'chunk');
    if (chunks.length !== 1 || chunks[0].type !== 'chunk') {
      throw new Error(`bundling @shadelab/material at ${rev} gave ${chunks.length} chunks, not one`);
    }
    return { code: chunks[0].code, commit: git(['rev-parse', rev]) };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}
