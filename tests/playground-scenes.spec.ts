import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import {
  choose,
  HIDE_OVERLAYS,
  open,
  picture,
  settle,
  stateUrl,
  toggle,
  typeInto,
  urlState,
} from './playground-helpers';

// The playground's scene picker (issue 14): the lecture's sphere (the default, unchanged) and four three.js
// scenes that show the material's features. Visual baselines are pixel-exact (SwiftShader; maxDiffPixels 0).
// Record the baselines of this spec after an intended change with:
//   SHADELAB_E2E_PORT=4343 CI=1 npx playwright test tests/playground-scenes.spec.ts --update-snapshots

const SCENES = ['instanced', 'skinned', 'textured', 'lights'] as const;
/** The picker's labels (playground/src/engine/scenes/index.ts). */
const LABELS = {
  sphere: "the lecture's sphere",
  instanced: 'instanced spheres',
  skinned: 'skinned + morphing mesh',
  textured: 'textured, normal map',
  lights: "three's lights, fog, clipping",
} as const;
const ALLOWED = 'sphere, instanced, skinned, textured, lights';

async function shot(page: Page, name: string) {
  await page.addStyleTag({ content: HIDE_OVERLAYS });
  await expect(page.getByTestId('viewport')).toHaveScreenshot(name);
}

test.describe('scene pictures', () => {
  for (const scene of SCENES) {
    test(`${scene} scene`, async ({ page }) => {
      await open(page, { scene });
      await shot(page, `scene-${scene}.png`);
    });
  }

  test('skinned scene, flat shading (the flat geometry keeps the skin and the morph)', async ({ page }) => {
    await open(page, { scene: 'skinned', material: { shading: 'flat' } });
    await shot(page, 'scene-skinned-flat.png');
  });

  test('textured scene, flat shading (a triangle soup keeps the uv)', async ({ page }) => {
    await open(page, { scene: 'textured', material: { shading: 'flat' } });
    await shot(page, 'scene-textured-flat.png');
  });

  test('skinned scene, cel shading with the outline (skinned and morphed as the mesh is)', async ({
    page,
  }) => {
    await open(page, { scene: 'skinned', material: { celBands: 3, outline: true } });
    await shot(page, 'scene-skinned-cel-outline.png');
  });

  test('instanced scene in the compare view: flat | Gouraud | Phong | cel', async ({ page }) => {
    await open(page, { scene: 'instanced', view: 'compare' });
    await shot(page, 'scene-instanced-compare.png');
  });
});

/** The picker's selected option (leva's select values are indices: its label names the scene). */
function picked(page: Page) {
  return page.locator('[id="View.scene"] option:checked');
}

/** The scene the URL's state names (the page writes it after every accepted change). */
async function urlScene(page: Page): Promise<unknown> {
  return (await urlState(page))['scene'];
}

test('the sphere stays the default and is drawn as before: opening on it, or coming back to it, is the same picture', async ({
  page,
}) => {
  await open(page);
  const lecture = await picture(page);
  expect(await urlScene(page)).toBe('sphere');
  await expect(picked(page)).toHaveText(LABELS.sphere);
  await open(page, { scene: 'sphere' });
  expect(await picture(page)).toBe(lecture);
  await choose(page, 'View.scene', LABELS.instanced);
  expect(await picture(page)).not.toBe(lecture);
  await choose(page, 'View.scene', LABELS.sphere);
  expect(await picture(page)).toBe(lecture);
  expect(await urlScene(page)).toBe('sphere');
});

// One test per scene (each reloads the page three times: together they came near the timeout on a busy machine).
for (const scene of SCENES) {
  test(`the ${scene} scene picked in the panel is the scene the URL opens, and survives a reload from storage`, async ({
    page,
  }) => {
    await open(page);
    const lecture = await picture(page);
    await choose(page, 'View.scene', LABELS[scene]);
    expect(await urlScene(page)).toBe(scene);
    await expect(page.getByTestId('scene-note')).not.toContainText('every option applies');
    await expect(page.getByRole('img', { name: `Lit scene: ${LABELS[scene]}.`, exact: false })).toBeVisible();
    const chosen = await picture(page);
    expect(chosen).not.toBe(lecture);
    // The URL the page wrote opens the same picture.
    const written = page.url();
    await page.goto('about:blank');
    await page.goto(written);
    await settle(page);
    await expect(picked(page)).toHaveText(LABELS[scene]);
    expect(await picture(page)).toBe(chosen);
    // Without a URL, the state comes back from localStorage.
    await page.goto('about:blank');
    await page.goto('/');
    await settle(page);
    await expect(picked(page)).toHaveText(LABELS[scene]);
    expect(await picture(page)).toBe(chosen);
    // A URL naming the scene (the rest defaulted) opens it too.
    await page.goto('about:blank');
    await page.goto(stateUrl({ scene }));
    await settle(page);
    expect(await picture(page)).toBe(chosen);
    expect(await urlScene(page)).toBe(scene);
  });
}

test('a hostile scene value in the URL is refused like any bad state: the saved state (or the default) opens', async ({
  page,
}) => {
  const hostile: [string, string][] = [
    ['{"scene":"<img src=x onerror=window.__pwned=1>"}', '"<img src=x onerror=window.__pwned=1>"'],
    ['{"scene":"__proto__"}', '"__proto__"'],
    ['{"scene":"Sphere"}', '"Sphere"'],
    ['{"scene":{"toString":"sphere"}}', 'object'],
    ['{"scene":["lights"]}', 'an array'],
    ['{"scene":1}', '1'],
    ['{"scene":null}', 'null'],
  ];
  const go = async (text: string) => {
    const params = new URLSearchParams();
    params.set('s', text);
    await page.goto('about:blank');
    await page.goto(`/#${params}`);
    await settle(page);
  };
  // Fresh storage: the lecture's sphere.
  await open(page);
  const lecture = await picture(page);
  for (const [text, shown] of hostile.slice(0, 2)) {
    await page.evaluate(() => localStorage.clear());
    await go(text);
    await expect(page.getByTestId('notice').first()).toContainText(
      `The state in the URL was refused: state.scene: ${shown} is not one of ${ALLOWED}`,
    );
    await expect(picked(page)).toHaveText(LABELS.sphere);
    expect(await picture(page)).toBe(lecture);
  }
  // A saved scene: it opens instead of the refused URL.
  await open(page, { scene: 'skinned' });
  const skinned = await picture(page);
  for (const [text, shown] of hostile) {
    await go(text);
    await expect(page.getByTestId('notice').first()).toContainText(
      `The state in the URL was refused: state.scene: ${shown} is not one of ${ALLOWED}`,
    );
    await expect(picked(page)).toHaveText(LABELS.skinned);
    expect(await picture(page)).toBe(skinned);
    const pwned = await page.evaluate(() => ({
      pwned: (window as unknown as { __pwned?: number }).__pwned,
      polluted: ({} as Record<string, unknown>)['polluted'],
    }));
    expect(pwned).toEqual({ pwned: undefined, polluted: undefined });
  }
});

const SPHERE_ONLY = ['Sphere.level', 'Sphere.base', 'Sphere.radius', 'Sphere.maxErrorPx'];

test('on the lecture’s sphere every option applies: the sphere-only inputs are live', async ({ page }) => {
  await open(page);
  for (const id of SPHERE_ONLY) await expect(page.locator(`[id="${id}"]`)).toBeEnabled();
  await expect(page.getByTestId('scene-note')).toContainText('every option applies');
});

test('the sphere folder greys out the detail the picture does not take, and the stats name what is drawn', async ({
  page,
}) => {
  const detail = ['Sphere.base', 'Sphere.level'];
  await open(page);
  for (const id of [...detail, 'Sphere.auto', 'Sphere.maxErrorPx'])
    await expect(page.locator(`[id="${id}"]`)).toBeEnabled();
  // The mesh's level: its silhouette error (tetrahedron 6 at the demo's size: a fraction of a pixel).
  await expect(page.getByTestId('stats-error')).toHaveText(/^\d+\.\d{3} px$/);
  expect(Number.parseFloat((await page.getByTestId('stats-error').textContent())!)).toBeGreaterThan(0);
  // The impostor is the exact sphere: no level to choose, no silhouette error; the radius still applies.
  await choose(page, 'Sphere.render', 'ray-cast impostor');
  await expect(page.getByTestId('stats-error')).toHaveText('0.000 px');
  for (const id of [...detail, 'Sphere.auto', 'Sphere.maxErrorPx'])
    await expect(page.locator(`[id="${id}"]`)).toBeDisabled();
  await expect(page.locator('[id="Sphere.radius"]')).toBeEnabled();
  // Automatic detail chooses the base and level (the stats say which); its error bound applies.
  await choose(page, 'Sphere.render', 'subdivided mesh');
  await toggle(page, 'Sphere.auto');
  for (const id of detail) await expect(page.locator(`[id="${id}"]`)).toBeDisabled();
  await expect(page.locator('[id="Sphere.maxErrorPx"]')).toBeEnabled();
  await expect(page.getByTestId('stats-detail')).toHaveText(
    /^(tetrahedron|octahedron|icosahedron) \d+ \(\d+\.\d{3} px\)$/,
  );
  await expect(page.getByTestId('stats-error')).not.toHaveText('0.000 px');
});

test('the stats count the cells drawn, not the parts of a scene', async ({ page }) => {
  await open(page, { scene: 'lights' });
  await expect(page.getByTestId('stats')).toContainText(/triangles\s*\d/);
  await choose(page, 'View.view', 'flat | Gouraud | Phong | cel');
  await expect(page.getByTestId('stats')).toContainText('triangles (4 cells)');
});

// One test per scene (nine edits each: together they came near the timeout on a busy machine).
for (const scene of SCENES) {
  test(`in the ${scene} scene the options that apply stay live; the sphere-only inputs are greyed out and say why`, async ({
    page,
  }) => {
    const sphereOnly = SPHERE_ONLY;
    await open(page, { scene });
    await expect(page.getByTestId('scene-note')).toContainText('for the lecture’s sphere only');
    for (const id of sphereOnly) await expect(page.locator(`[id="${id}"]`)).toBeDisabled();
    // The GLSL editor edits the sphere's program: hidden here.
    await expect(page.locator('.shader-editor')).toHaveCount(0);
    const seen = new Set([await picture(page)]);
    const edits: [string, () => Promise<void>][] = [
      ['shading flat', () => choose(page, 'Material.shading', 'flat')],
      ['shading gouraud', () => choose(page, 'Material.shading', 'gouraud')],
      ['lighting phong', () => choose(page, 'Material.lighting', 'phong')],
      ['cel bands', () => typeInto(page, 'Material.celBands', '3')],
      ['outline', () => toggle(page, 'Material.outline')],
      ['outline width', () => typeInto(page, 'Material.outlineWidth', '0.1')],
      ['kd', () => typeInto(page, 'Material.kd.y', '0.9')],
      ['shininess', () => typeInto(page, 'Material.shininess', '5')],
      ['light position', () => typeInto(page, 'Light 1.light1Position', '5')],
    ];
    for (const [name, edit] of edits) {
      await edit();
      const now = await picture(page);
      expect(seen.has(now), `${scene}: ${name} changed the picture`).toBe(false);
      seen.add(now);
    }
  });
}
