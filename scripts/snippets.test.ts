// scripts/snippets.mjs on a tiny Markdown fixture: which blocks it extracts and with what marks, that a good
// block (complete or partial with its context) type-checks, and that a broken one is reported at its Markdown
// line and column, in the block or in its context.
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import {
  checkBlocks,
  collectBlocks,
  extractBlocks,
  pictureFile,
  quickStartBlock,
  root,
  runPageFiles,
  runPageName,
  writeRunPages,
} from './snippets.mjs';

const FIXTURE = `# Fixture

\`\`\`sh
npm install three
\`\`\`

A complete block, with three's types and the DOM:

\`\`\`ts
import { Vector3 } from 'three';

const length: number = new Vector3(3, 4, 0).length();
document.title = String(length);
\`\`\`

<!-- context
import type { Vector3 } from 'three';
declare const v: Vector3;
-->

\`\`\`ts partial
const x: number = v.x;
\`\`\`

- In a list, indented, with a type error on its second line:

  \`\`\`typescript
  const n: number = 1;
  const s: string = n;
  \`\`\`

<!-- context=broken
const missing: number = notDeclared;
-->

\`\`\`ts partial=broken
export const y = missing + 1;
\`\`\`

\`\`\`ts run=lecture
import { Camera } from '@shadelab/camera';
new Camera().lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
\`\`\`
`;

describe('extractBlocks', () => {
  test('finds every ts block with its fence line, marks, heading and context; skips other languages', () => {
    const blocks = extractBlocks(FIXTURE, 'docs/fixture.md');
    expect(
      blocks.map((b) => ({ line: b.line, ext: b.ext, partial: b.partial, run: b.run, indent: b.indent })),
    ).toEqual([
      { line: 9, ext: 'ts', partial: undefined, run: undefined, indent: 0 },
      { line: 21, ext: 'ts', partial: true, run: undefined, indent: 0 },
      { line: 27, ext: 'ts', partial: undefined, run: undefined, indent: 2 },
      { line: 36, ext: 'ts', partial: 'broken', run: undefined, indent: 0 },
      { line: 40, ext: 'ts', partial: undefined, run: 'lecture', indent: 0 },
    ]);
    expect(blocks[0].heading).toBe('Fixture');
    expect(blocks[1].context).toEqual({
      name: undefined,
      line: 17,
      lines: ["import type { Vector3 } from 'three';", 'declare const v: Vector3;'],
    });
    expect(blocks[2].code).toBe('const n: number = 1;\nconst s: string = n;\n');
  });

  test('refuses a misspelt mark, a partial block without its context, an orphan context and run with partial', () => {
    expect(() => extractBlocks('```ts partal\nlet a = 1;\n```\n', 'a.md')).toThrow(
      "a.md:1: unknown mark 'partal'",
    );
    expect(() => extractBlocks('text\n\n```ts partial\na;\n```\n', 'b.md')).toThrow(
      'b.md:3: a partial block needs its context',
    );
    expect(() => extractBlocks('<!-- context\ndeclare const a: 1;\n-->\n\n```ts\na;\n```\n', 'c.md')).toThrow(
      'c.md:1: this context comment is not followed by a `partial` block',
    );
    expect(() => extractBlocks('```ts partial=nowhere\na;\n```\n', 'd.md')).toThrow(
      'd.md:1: partial=nowhere names no <!-- context=nowhere --> comment',
    );
    expect(() =>
      extractBlocks('<!-- context\ndeclare const a: 1;\n-->\n```ts partial run=lecture\na;\n```\n', 'e.md'),
    ).toThrow('e.md:4: a run=lecture block is run as it stands');
  });

  test('picture=NAME: a complete block whose canvas is images/NAME.png beside its Markdown; refused partial, twice or misnamed', () => {
    const [block] = extractBlocks('# Shading\n\n```ts picture=flat-shading\na;\n```\n', 'docs/concepts.md');
    expect([block.picture, block.run, block.partial, block.heading]).toEqual([
      'flat-shading',
      undefined,
      undefined,
      'Shading',
    ]);
    expect(pictureFile({ ...block, picture: 'flat-shading' })).toBe('docs/images/flat-shading.png');
    expect(pictureFile({ ...block, file: 'README.md', picture: 'x' })).toBe('images/x.png');
    expect(() =>
      extractBlocks('<!-- context\ndeclare const a: 1;\n-->\n```ts partial picture=p\na;\n```\n', 'g.md'),
    ).toThrow('g.md:4: a picture=p block is run as it stands: it cannot be partial');
    expect(() => extractBlocks('```ts picture=p\na;\n```\n\n```ts picture=p\nb;\n```\n', 'h.md')).toThrow(
      'h.md:5: a second picture=p in this file',
    );
    expect(() => extractBlocks('```ts picture=Bad_Name\na;\n```\n', 'i.md')).toThrow(
      "i.md:1: unknown mark 'picture=Bad_Name'",
    );
  });
});

describe('checkBlocks', () => {
  const dir = mkdtempSync(join(tmpdir(), 'shadelab-snippets-'));
  // Inside the repository, so that three and @shadelab/* resolve through its node_modules as in a user's app.
  mkdirSync(join(root, 'reports'), { recursive: true });
  const out = mkdtempSync(join(root, 'reports', 'snippets-test-'));
  afterAll(() => {
    rmSync(dir, { recursive: true, force: true });
    rmSync(out, { recursive: true, force: true });
  });

  test('good blocks pass; each error is reported at its Markdown line and column (block or context)', () => {
    writeFileSync(join(dir, 'fixture.md'), FIXTURE);
    const blocks = collectBlocks({ dir, files: ['fixture.md'] });
    const { errors } = checkBlocks(blocks, out);
    expect(errors).toEqual([
      // The list item's block: line 29 of the Markdown, column 9 counting the two spaces of indentation.
      expect.stringMatching(
        /^fixture\.md:29:9: error TS2322: Type 'number' is not assignable to type 'string'/,
      ),
      expect.stringMatching(
        /^fixture\.md:33:25 \(in the context of the block at line 36\): error TS2304: Cannot find name 'notDeclared'/,
      ),
    ]);
  });

  test('a block that type-checks alone passes', () => {
    const blocks = extractBlocks('```ts\nexport const a: number = Math.PI;\n```\n', 'ok.md');
    expect(checkBlocks(blocks, out).errors).toEqual([]);
  });

  test('file=PATH blocks are the files of one app: relative imports between them resolve; errors keep their lines', () => {
    const app = [
      '```ts file=src/scene.ts',
      'export const size: number = 400;',
      '```',
      '',
      '```ts file=tests/scene.spec.ts',
      "import { size } from '../src/scene';",
      'const label: string = size;',
      '```',
      '',
    ].join('\n');
    const blocks = extractBlocks(app, 'app.md');
    expect(blocks.map((b) => b.path)).toEqual(['src/scene.ts', 'tests/scene.spec.ts']);
    expect(checkBlocks(blocks, out).errors).toEqual([
      expect.stringMatching(/^app\.md:7:7: error TS2322: Type 'number' is not assignable to type 'string'/),
    ]);
    expect(() => extractBlocks('```ts file=../outside.ts\na;\n```\n', 'f.md')).toThrow(
      "f.md:1: unknown mark 'file=../outside.ts'",
    );
  });
});

describe('the pages of runnable blocks', () => {
  const markdown = `# Title

## Quick start

\`\`\`ts run=lecture
document.title = 'quick';
\`\`\`

## Later

\`\`\`ts run=lecture
document.title = 'later';
\`\`\`
`;
  const blocks = extractBlocks(markdown, 'README.md');

  test('a page is its block verbatim as main.ts, an entry that marks the page once it ran, and an index.html', () => {
    const files = runPageFiles(blocks[0]);
    expect(files['main.ts']).toBe(blocks[0].code);
    expect(files['entry.ts']).toBe("import './main.ts';\ndocument.documentElement.dataset.ran = 'true';\n");
    expect(files['index.html']).toContain('<script type="module" src="./entry.ts"></script>');
    expect(files['index.html']).toContain('<title>README.md:5</title>');
    expect(runPageName(blocks[0])).toBe('README.md-5');
    expect(runPageName({ ...blocks[0], file: 'packages/a b/README.md' })).toBe('packages_a_b_README.md-5');
  });

  test('writeRunPages writes each page in its folder and returns the build’s input', () => {
    const dir = mkdtempSync(join(tmpdir(), 'snippets-pages-'));
    try {
      const input = writeRunPages(blocks, dir);
      expect(input).toEqual({
        'README.md-5': join(dir, 'README.md-5', 'index.html'),
        'README.md-11': join(dir, 'README.md-11', 'index.html'),
      });
      expect(readFileSync(join(dir, 'README.md-11', 'main.ts'), 'utf8')).toBe("document.title = 'later';\n");
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });

  test('the Quick start block is the one block under that heading, marked to run', () => {
    expect(quickStartBlock(blocks).code).toBe("document.title = 'quick';\n");
    expect(() => quickStartBlock(blocks.slice(1))).toThrow(/found none/);
    expect(() => quickStartBlock([{ ...blocks[0], run: undefined }])).toThrow(/README.md:5/);
  });
});
