// scripts/check-links.mjs on a small fixture tree: good links (files, folders, headings with GitHub's slugs and
// their repeats, explicit ids, HTML pages and their ids) pass; a missing file, a missing anchor, a link out of the
// tree and the non-existent repository URL are each reported at their line; links in code are not read.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import { checkMarkdown, checkSite, githubSlug, markdownAnchors, markdownLinks } from './check-links.mjs';

const dir = mkdtempSync(join(tmpdir(), 'shadelab-links-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

const write = (path: string, text: string) => {
  mkdirSync(join(dir, path, '..'), { recursive: true });
  writeFileSync(join(dir, path), text);
};

write(
  'docs/guide.md',
  [
    '# Guide', //                                                    1
    '', //                                                           2
    '## `shade(sample, material)` → linear RGB', //                  3
    '', //                                                           4
    '## Options', //                                                 5
    '', //                                                           6
    '## Options', //                                                 7
    '', //                                                           8
    '<a id="custom"></a>', //                                        9
    '', //                                                          10
    'Good: [self](#options-1), [code heading](#shadesample-material--linear-rgb), [id](#custom),', // 11
    '[up](../README.md#the-packages), [folder](../packages/), [image](pic.png), [external](https://threejs.org/docs/).', // 12
    '[ref]: ../README.md#install', //                               13
    '', //                                                          14
    'Bad: [missing file](nothere.md), [missing anchor](#nope), [other anchor](../README.md#nope).', // 15
    '[outside](../../outside.md) [repo](https://github.com/shadelab/shadelab/blob/main/README.md)', // 16
    '', //                                                          17
    '`[in code](nothere.md)`', //                                   18
    '', //                                                          19
    '```md', //                                                     20
    '[in a block](nothere.md)', //                                  21
    '```', //                                                       22
    '<!-- [in a comment](nothere.md) -->', //                       23
    '<img src="missing.png" alt="x">', //                           24
  ].join('\n'),
);
write('docs/pic.png', 'png');
write('README.md', '# shadelab\n\n## The packages\n\n## Install\n');
write('packages/sphere/README.md', '# sphere\n');
write(
  'site/index.html',
  '<a href="page.html#here">ok</a> <a href="page.html#gone">x</a>\n<a href="nope.html">x</a>\n' +
    // A fragment key=value is the page's state (the playground's #s=), not an anchor.
    '<iframe src="page.html?embed#s=%7B%22a%22%3A1%7D"></iframe>',
);
write(
  'site/page.html',
  '<h2 id="here">Here</h2><a href="index.html">back</a><a href="https://example.org/">ext</a>',
);

describe('check-links', () => {
  test("GitHub's heading slugs", () => {
    expect(githubSlug('Flat shading: how, and what it costs')).toBe('flat-shading-how-and-what-it-costs');
    expect(githubSlug('`subdivideSphere(options?) → { positions, normals?, indices? }`')).toBe(
      'subdividesphereoptions---positions-normals-indices-',
    );
    expect(githubSlug('DEFAULT\\_SPHERE\\_MAX\\_BYTES')).toBe('default_sphere_max_bytes');
    expect(githubSlug('**Bold** and _emphasis_ [link](x.md)')).toBe('bold-and-emphasis-link');
    expect([...markdownAnchors('# A\n\n## A\n\n```\n# not a heading\n```\n<a id="x"></a>')]).toEqual([
      'a',
      'a-1',
      'x',
    ]);
  });

  test('links are read outside code and comments only', () => {
    const text = '[a](x.md) `[b](y.md)`\n\n```\n[c](z.md)\n```\n<!-- [d](w.md) -->\n[e]: v.md\n';
    expect(markdownLinks(text).map((l) => [l.target, l.line])).toEqual([
      ['x.md', 1],
      ['v.md', 7],
    ]);
  });

  test('good Markdown links pass; each broken one is reported with its line and why', () => {
    const problems = checkMarkdown(['docs/guide.md', 'README.md', 'packages/sphere/README.md'], dir);
    expect(problems.map((p) => [p.file, p.line, p.target, p.reason])).toEqual([
      ['docs/guide.md', 15, 'nothere.md', 'no such file'],
      ['docs/guide.md', 15, '#nope', 'no anchor #nope in docs/guide.md'],
      ['docs/guide.md', 15, '../README.md#nope', 'no anchor #nope in README.md'],
      ['docs/guide.md', 16, '../../outside.md', 'outside the repository'],
      [
        'docs/guide.md',
        16,
        'https://github.com/shadelab/shadelab/blob/main/README.md',
        'the packages\u2019 repository URL, which does not exist',
      ],
      ['docs/guide.md', 24, 'missing.png', 'no such file'],
    ]);
  });

  test("the site's pages: missing pages and ids are reported", () => {
    const problems = checkSite(join(dir, 'site'));
    expect(problems.map((p) => [p.target, p.reason])).toEqual([
      ['page.html#gone', 'no anchor #gone in page.html'],
      ['nope.html', 'no such file'],
    ]);
  });
});
