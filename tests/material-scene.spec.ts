import { createHash } from 'node:crypto';
import { expect, type Page, test } from '@playwright/test';
import type { ProgramSource } from '../playground/harness/material';
import { activeGlsl, withoutUseFog } from './glsl-active';

// ShadingMaterial in an ordinary three.js scene (issue 14, phase 1): three's program parameters (instancing,
// batching, skinning, morph targets, fog, clipping, tone mapping, output colour space) through three's shader
// chunks, judged against three's own MeshPhongMaterial for where and whether something is drawn, and against
// shade() for colours. Runs in headless Chromium (SwiftShader) on the material harness page.

async function open(page: Page): Promise<void> {
  await page.goto('/harness/material.html');
  await expect(page.locator('body')).toHaveAttribute('data-ready', '1');
}

const sha = (text: string) => createHash('sha256').update(text).digest('hex').slice(0, 16);

test('a scene without the new features compiles the same programs as before (active GLSL and cache keys)', async ({
  page,
}) => {
  await open(page);
  const programs: ProgramSource[] = await page.evaluate(() => window.materialHarness.programSources());
  expect(programs.length).toBe(74);
  // One line per scene: the cache key (three's parameters and the material's defines; the only difference
  // allowed is `useFog`, true by default like MeshPhongMaterial's, which compiles to nothing without
  // scene.fog) and the hashes of the code the GPU compiles (the preprocessor's active lines, see glsl-active.ts).
  const table = programs
    .map(
      (p) =>
        `${p.name} | ${withoutUseFog(p.cacheKey)} | ${sha(activeGlsl(p.vertex))} | ${sha(activeGlsl(p.fragment))}`,
    )
    .join('\n');
  expect(`${table}\n`).toMatchSnapshot('lecture-programs.txt');
  // The README's lecture program in full, for a readable diff.
  const lecture = programs.find((p) => p.name === 'standard phong blinn-phong cel 0 normals');
  expect(lecture).toBeDefined();
  expect(
    `${activeGlsl(lecture?.vertex ?? '')}\n----\n${activeGlsl(lecture?.fragment ?? '')}\n`,
  ).toMatchSnapshot('lecture-program.glsl');
});
