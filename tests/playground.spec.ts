import { expect, type Page } from '@playwright/test';
import { test } from './harness-helpers';
import {
  cellPictures,
  choose,
  drag,
  fling,
  frames,
  litArea,
  litBox,
  open,
  picture,
  pixel,
  press,
  settle,
  stateUrl,
  toggle,
  typeInto,
  urlRotation,
  urlState,
} from './playground-helpers';

/** Runs each step and checks that the canvas pixels differ from the previous step's. */
async function eachChangesThePicture(page: Page, steps: [string, () => Promise<void>][]) {
  let before = await picture(page);
  for (const [name, step] of steps) {
    await step();
    const after = await picture(page);
    expect(after === before, `${name} changes the picture`).toBe(false);
    before = after;
  }
}

test.describe('the playground', () => {
  test('opens on the lecture scene and reports the first frame', async ({ page }) => {
    const logs: string[] = [];
    page.on('console', (m) => logs.push(m.text()));
    await open(page);
    await expect(page.getByTestId('stats-triangles')).toHaveText('16,384');
    // Tetrahedron level 6, indexed: V = 2 + T/2 vertices; positions 3 float32 each, Uint16 indices 3 per triangle.
    await expect(page.getByTestId('stats-vertices')).toHaveText('8,194');
    const bytes = 8194 * 3 * 4 + 16384 * 3 * 2;
    await expect(page.getByTestId('stats-bytes')).toHaveText(
      `${(bytes / 1024).toFixed(1)} KiB (${bytes.toLocaleString('en-US')} B)`,
    );
    await expect(page.getByTestId('stats-gpu')).toHaveText(/^(n\/a \(no timer query\)|\d+\.\d\d ms)$/);
    // The lecture's shader: Phong shading with the half vector (Blinn-Phong lighting).
    await expect(page.locator('[id="Material.shading"]')).toHaveValue('2'); // flat, gouraud, phong
    await expect(page.locator('[id="Material.lighting"]')).toHaveValue('1'); // phong, blinn-phong
    // The trackball's package default mapping.
    await expect(page.locator('[id="Trackball.mapping"]')).toHaveValue('0'); // bell, arcball
    await expect(page.locator('[id="Sphere.base"]')).toHaveValue('0');
    await expect(page.locator('[id="Camera.eye.z"]')).toHaveValue('3.0');
    await expect(page.locator('[id="Camera.fovy"]')).toHaveValue('90');
    await expect(page.locator('[id="Light 1.light1Position"]')).toHaveValue('-5.0');
    const ms = Number(await page.getByTestId('viewport').getAttribute('data-first-frame-ms'));
    expect(ms).toBeGreaterThan(0);
    expect(logs.some((l) => l.startsWith('[shadelab] first frame rendered'))).toBe(true);
    test.info().annotations.push({ type: 'first frame (ms after navigation)', description: ms.toFixed(1) });
    console.log(`first frame: ${ms.toFixed(1)} ms after navigation start`);
  });

  test('every material control changes the picture', async ({ page }) => {
    test.setTimeout(120_000);
    await open(page);
    await eachChangesThePicture(page, [
      ['shading flat', () => choose(page, 'Material.shading', 'flat')],
      ['shading gouraud', () => choose(page, 'Material.shading', 'gouraud')],
      ['shading phong', () => choose(page, 'Material.shading', 'phong')],
      ['lighting phong', () => choose(page, 'Material.lighting', 'phong')],
      ['lighting blinn-phong', () => choose(page, 'Material.lighting', 'blinn-phong')],
      ['cel bands', () => typeInto(page, 'Material.celBands', '3')],
      ['outline', () => toggle(page, 'Material.outline')],
      ['outline width', () => typeInto(page, 'Material.outlineWidth', '0.1')],
      ['outline colour', () => typeInto(page, 'Material.outlineColor', '#ff0000')],
      ['ka', () => typeInto(page, 'Material.ka', '0.1')],
      ['kd', () => typeInto(page, 'Material.kd.y', '0.9')],
      ['ks', () => typeInto(page, 'Material.ks.z', '0.2')],
      ['shininess', () => typeInto(page, 'Material.shininess', '5')],
    ]);
  });

  test('every light control changes the picture; lights are added and removed', async ({ page }) => {
    test.setTimeout(120_000);
    await open(page);
    const l = 'Light 1.light1';
    await eachChangesThePicture(page, [
      ['position', () => typeInto(page, `${l}Position`, '5')],
      ['Ia', () => typeInto(page, `${l}Ia`, '0.6')],
      ['Id', () => typeInto(page, `${l}Id.y`, '0.4')],
      ['Is', () => typeInto(page, `${l}Is.z`, '0.1')],
      ['attenuation b', () => typeInto(page, `${l}B`, '0.05')],
      ['attenuation c', () => typeInto(page, `${l}C`, '0.01')],
      ['attenuation a', () => typeInto(page, `${l}A`, '0.5')],
      ['add light', () => press(page, 'add light')],
      ['remove light', () => press(page, 'remove light 2')],
      ['remove the last light', () => press(page, 'remove light 1')],
    ]);
    expect((await urlState(page))['lights']).toHaveLength(0);
  });

  test('every sphere, model and view control changes the picture', async ({ page }) => {
    test.setTimeout(120_000);
    await open(page);
    await eachChangesThePicture(page, [
      ['ray-cast impostor', () => choose(page, 'Sphere.render', 'ray-cast impostor')],
      ['subdivided mesh', () => choose(page, 'Sphere.render', 'subdivided mesh')],
      ['base', () => choose(page, 'Sphere.base', 'icosahedron')],
      ['level', () => typeInto(page, 'Sphere.level', '1')],
      ['auto detail', () => toggle(page, 'Sphere.auto')],
      ['max error', () => typeInto(page, 'Sphere.maxErrorPx', '40')],
      ['radius', () => typeInto(page, 'Sphere.radius', '0.6')],
      ['model scale', () => typeInto(page, 'Sphere.scale.y', '1.8')],
      ['compare view', () => choose(page, 'View.view', 'flat | Gouraud | Phong | cel')],
    ]);
  });

  test('every camera control changes the picture', async ({ page }) => {
    test.setTimeout(120_000);
    await open(page);
    await eachChangesThePicture(page, [
      ['eye', () => typeInto(page, 'Camera.eye.z', '4')],
      ['at', () => typeInto(page, 'Camera.at', '0.5')],
      ['up', () => typeInto(page, 'Camera.up', '0.5')],
      ['fovy', () => typeInto(page, 'Camera.fovy', '60')],
      ['near', () => typeInto(page, 'Camera.near', '2.5')],
      ['far', () => typeInto(page, 'Camera.far', '2.8')],
      ['orthographic', () => choose(page, 'Camera.projection', 'orthographic')],
      ['ortho top', () => typeInto(page, 'Camera.top', '3')],
      ['ortho fit aspect off', () => toggle(page, 'Camera.fitAspect')],
      ['ortho right', () => typeInto(page, 'Camera.right', '4')],
      ['ortho left', () => typeInto(page, 'Camera.left', '-1')],
      ['ortho bottom', () => typeInto(page, 'Camera.bottom', '-2')],
    ]);
  });

  test('a trackball drag rotates the sphere, and its speed and mapping matter', async ({ page }) => {
    await open(page);
    const start = await picture(page);
    await drag(page, [0.5, 0.5], [0.7, 0.5]);
    const turned = await picture(page);
    expect(turned).not.toBe(start);
    const rotation = ((await urlState(page))['trackball'] as { rotation: number[] }).rotation;
    expect(rotation[1]).toBeGreaterThan(0.05); // a turn about the camera's v axis = world y here
    expect(Math.hypot(...rotation)).toBeCloseTo(1, 9);

    // Same drag at twice the speed turns further.
    await press(page, 'reset rotation');
    expect(await picture(page)).toBe(start);
    await typeInto(page, 'Trackball.rotateSpeed', '2');
    await drag(page, [0.5, 0.5], [0.7, 0.5]);
    expect(await picture(page)).not.toBe(turned);

    // A drag past the rim maps differently on Bell's sheet (the default) than on the arcball.
    await typeInto(page, 'Trackball.rotateSpeed', '1');
    const rim = async () => {
      await press(page, 'reset rotation');
      await drag(page, [0.5, 0.5], [0.98, 0.9]);
      return picture(page);
    };
    const bell = await rim();
    await choose(page, 'Trackball.mapping', 'arcball');
    expect(await rim()).not.toBe(bell);
  });

  test('the trackball ball radius changes how far a drag turns', async ({ page }) => {
    await open(page);
    const angle = async () => 2 * Math.acos(Math.min(1, Math.abs((await urlRotation(page))[3]!)));
    await drag(page, [0.5, 0.5], [0.6, 0.5]);
    const big = await angle();
    const turned = await picture(page);
    await press(page, 'reset rotation');
    await typeInto(page, 'Trackball.radius', '0.5');
    await drag(page, [0.5, 0.5], [0.6, 0.5]);
    // A smaller ball: the same pixels are a larger arc of it.
    expect(await angle()).toBeGreaterThan(big * 1.5);
    expect(await picture(page)).not.toBe(turned);
  });

  test('with damping on, a fling keeps the sphere turning after release until it rests; off, it stops at once', async ({
    page,
  }) => {
    await open(page);
    const rotationY = async () =>
      ((await urlState(page))['trackball'] as { rotation: number[] }).rotation[1]!;
    // Damping off: the picture after the release is the last one.
    await fling(page, [0.45, 0.5], [0.55, 0.5]);
    await settle(page);
    const released = await frames(page);
    await page.waitForTimeout(500);
    expect(await frames(page)).toBe(released);
    const without = await rotationY();

    await press(page, 'reset rotation');
    await toggle(page, 'Trackball.damping');
    await settle(page);
    // Damping on: frames keep coming after the release and the sphere turns further than the drag alone.
    await fling(page, [0.45, 0.5], [0.55, 0.5]);
    const atRelease = await frames(page);
    await expect
      .poll(() => frames(page), { message: 'frames kept coming after the release', timeout: 20_000 })
      .toBeGreaterThan(atRelease + 3);
    // The spin rests by itself. Quiet for 600 ms, not settle's 200: a slow SwiftShader frame near the end of the
    // damped tail left more than 200 ms between two frames once, and a frame came after "rested" (171 → 172).
    await settle(page, 600);
    const rested = await frames(page);
    await page.waitForTimeout(500);
    expect(await frames(page)).toBe(rested);
    expect(await rotationY()).toBeGreaterThan(without * 1.5);
  });

  test('the depth buffer mode makes a new renderer in that mode; the scene and every edit carry over', async ({
    page,
  }) => {
    await open(page);
    await typeInto(page, 'Material.shininess', '5');
    await drag(page, [0.5, 0.5], [0.6, 0.45]);
    const standard = await picture(page);
    await expect(page.getByTestId('stats-depth')).toHaveText('standard');
    // [requested, what runs]: EXT_clip_control is there, so both reversed requests run reversed-Z.
    for (const [mode, runs] of [
      ['logarithmic', 'logarithmic'],
      ['reversed-or-logarithmic', 'reversed'],
      ['reversed', 'reversed'],
    ] as const) {
      await page.locator('[id="Camera.depth"]').selectOption({ label: mode });
      await expect(page.getByTestId('stats-depth')).toHaveText(runs);
      await settle(page);
      // One convex sphere: the depth mode changes no colour.
      expect(await picture(page), mode).toBe(standard);
      expect(((await urlState(page))['camera'] as { depth: string }).depth).toBe(mode);
    }
    await page.reload();
    await settle(page);
    await expect(page.getByTestId('stats-depth')).toHaveText('reversed');
    expect(await picture(page)).toBe(standard);
  });

  test('the wheel zooms, by zoomSpeed', async ({ page }) => {
    // A unit sphere, so that the eye stays outside it at the zoom limit (eye z = 3 / maxZoom = 2).
    await open(page, { model: { scale: [1, 1, 1] } });
    const canvas = page.getByTestId('viewport');
    const box = (await canvas.boundingBox())!;
    const wheel = async () => {
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.wheel(0, -50);
      await settle(page);
      return ((await urlState(page))['camera'] as { eye: number[] }).eye[2]!;
    };
    const area0 = await litArea(page);
    const z1 = await wheel();
    expect(z1).toBeLessThan(3);
    const area1 = await litArea(page);
    expect(area1).toBeGreaterThan(area0); // closer: the sphere covers more of the screen
    await typeInto(page, 'Trackball.zoomSpeed', '3');
    const z2 = await wheel();
    expect(3 - z2).toBeGreaterThan((3 - z1) * 1.5);
    const area2 = await litArea(page);
    // The same wheel step grows the sphere more at three times the speed.
    expect(area2 / area1).toBeGreaterThan(area1 / area0);
    // The zoom limit holds: the eye never comes closer than 3 / maxZoom, and the picture stops changing.
    await typeInto(page, 'Trackball.maxZoom', '1.5');
    let z = z2;
    for (let i = 0; i < 20 && z > 2 + 1e-9; i++) z = await wheel();
    expect(z).toBeCloseTo(2, 6);
    const atLimit = await picture(page);
    await wheel();
    expect(await picture(page)).toBe(atLimit);
  });

  test('the wheel zooms out no further than minZoom', async ({ page }) => {
    await open(page);
    const box = (await page.getByTestId('viewport').boundingBox())!;
    const wheelOut = async () => {
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.wheel(0, 400);
      await settle(page);
      return ((await urlState(page))['camera'] as { eye: number[] }).eye[2]!;
    };
    const area0 = await litArea(page);
    await typeInto(page, 'Trackball.minZoom', '0.5');
    let z = 3;
    for (let i = 0; i < 20 && z < 6 - 1e-9; i++) z = await wheelOut();
    // The eye never goes further than 3 / minZoom = 6 from the target.
    expect(z).toBeCloseTo(6, 6);
    expect(await wheelOut()).toBeCloseTo(6, 6);
    const atLimit = await picture(page);
    expect(await litArea(page)).toBeLessThan(area0 / 2);
    await wheelOut();
    expect(await picture(page)).toBe(atLimit);
    // A lower limit lets it go further.
    await typeInto(page, 'Trackball.minZoom', '0.4');
    expect(await wheelOut()).toBeGreaterThan(6.1);
    expect(await picture(page)).not.toBe(atLimit);
  });

  test('camera keys move the camera along its frame, by moveSpeed', async ({ page }) => {
    await open(page);
    const canvas = page.getByTestId('viewport');
    await canvas.focus();
    const before = await picture(page);
    await page.keyboard.press('KeyW');
    await settle(page);
    expect(await picture(page)).not.toBe(before);
    let camera = (await urlState(page))['camera'] as { eye: number[]; at: number[] };
    expect(camera.eye[2]).toBeCloseTo(2.9, 9);
    expect(camera.at[2]).toBeCloseTo(-0.1, 9);
    await page.keyboard.press('KeyD');
    await page.keyboard.press('KeyE');
    await settle(page);
    camera = (await urlState(page))['camera'] as { eye: number[]; at: number[] };
    expect(camera.eye[0]).toBeCloseTo(0.1, 9);
    expect(camera.eye[1]).toBeCloseTo(0.1, 9);
    // Back by the default speed, then by 0.5: the sphere shrinks on screen, much more for the larger step.
    const area0 = await litArea(page);
    await page.keyboard.press('KeyS');
    await settle(page);
    const area1 = await litArea(page);
    expect(area1).toBeLessThan(area0);
    await typeInto(page, 'Camera.moveSpeed', '0.5');
    await canvas.focus();
    await page.keyboard.press('KeyS');
    await settle(page);
    camera = (await urlState(page))['camera'] as { eye: number[]; at: number[] };
    expect(camera.eye[2]).toBeCloseTo(3.5, 9);
    const area2 = await litArea(page);
    expect(area1 - area2).toBeGreaterThan((area0 - area1) * 3);
  });

  test('a shared URL reproduces the same pixels', async ({ page, browser }) => {
    await open(page);
    await choose(page, 'Material.shading', 'gouraud');
    await typeInto(page, 'Material.celBands', '4');
    await drag(page, [0.4, 0.4], [0.6, 0.7]);
    const url = page.url();
    const original = await picture(page);
    const other = await browser.newPage(); // a fresh context: no localStorage
    await other.goto(url);
    await settle(other);
    expect(await picture(other)).toBe(original);
    await other.close();
  });

  test('the state survives a reload (localStorage) and the URL wins over it', async ({ page }) => {
    await open(page);
    await typeInto(page, 'Material.shininess', '7');
    await page.waitForTimeout(300);
    await page.goto('/');
    await settle(page);
    await expect(page.locator('[id="Material.shininess"]')).toHaveValue('7');
    await page.goto('about:blank');
    await page.goto(stateUrl({ material: { shininess: 9 } }));
    await settle(page);
    await expect(page.locator('[id="Material.shininess"]')).toHaveValue('9');
  });

  test('a broken shader edit shows the error line, keeps rendering and keeps the text after a reload', async ({
    page,
  }) => {
    await open(page);
    const text = page.getByTestId('shader-text');
    const good = await picture(page);
    const source = await text.inputValue();
    const lines = source.split('\n');
    const at = lines.findIndex((l) => l.includes('void main()'));
    lines.splice(at + 1, 0, '  this is not glsl;');
    const broken = lines.join('\n');
    await text.fill(broken);
    await expect(page.getByTestId('shader-errors')).toContainText(`fragment line ${at + 2}:`);
    await expect(page.getByTestId('shader-status')).toHaveText(/last good program keeps rendering/);
    // The page says where the edit lives: this browser, not the URL (the state in the hash has no GLSL).
    await expect(page.getByTestId('shader-note')).toContainText('not in the URL');
    expect(JSON.stringify(await urlState(page))).not.toContain('this is not glsl');
    await settle(page);
    expect(await picture(page)).toBe(good);
    // It keeps rendering: a change still draws a new frame with the last good program.
    const n = await frames(page);
    await typeInto(page, 'Material.shininess', '5');
    expect(await frames(page)).toBeGreaterThan(n);
    expect(Math.max(...(await pixel(page, 0.5, 0.5)).slice(0, 3))).toBeGreaterThan(40);
    // The edit is never lost.
    await page.reload();
    await settle(page);
    await expect(page.getByTestId('shader-text')).toHaveValue(broken);
    await expect(page.getByTestId('shader-errors')).toContainText(`fragment line ${at + 2}:`);
    // A working edit recompiles live.
    const red = source.replace(/}\s*$/, '  gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0);\n}\n');
    await page.getByTestId('shader-text').fill(red);
    await expect(page.getByTestId('shader-status')).toHaveText(/compiled and rendering/);
    await settle(page);
    const centre = await pixel(page, 0.5, 0.5);
    expect(centre.slice(0, 3)).toEqual([255, 0, 0]);
    await page.getByRole('button', { name: 'reset to generated' }).click();
    await settle(page);
    await typeInto(page, 'Material.shininess', '50');
    expect(await picture(page)).toBe(good);
  });

  test('bad typed values show an error naming the parameter and keep what was typed', async ({ page }) => {
    await open(page);
    const good = await picture(page);
    await typeInto(page, 'Camera.fovy', '200', { draws: false }); // refused by the schema: nothing drawn
    await expect(page.getByTestId('input-error')).toContainText('camera.fovy');
    await expect(page.locator('[id="Camera.fovy"]')).toHaveValue('200');
    expect(await picture(page)).toBe(good);
    await typeInto(page, 'Camera.fovy', '90');
    await expect(page.getByTestId('input-error')).toHaveCount(0);
    // A cross-parameter error comes from the package itself and names the parameter.
    await typeInto(page, 'Camera.near', '20');
    await expect(page.getByTestId('input-error')).toContainText(/camera: .*(far|near)/);
    await expect(page.locator('[id="Camera.near"]')).toHaveValue(/^20(\.0+)?$/);
    expect(await picture(page)).toBe(good);
    // A sphere too big to build is refused before allocating, and the page stays responsive.
    await typeInto(page, 'Camera.near', '0.1');
    await typeInto(page, 'Sphere.level', '16');
    await expect(page.getByTestId('input-error')).toContainText(/sphere|level/);
    expect(await picture(page)).toBe(good);
  });

  test('hostile URL state is refused with a message and never executed', async ({ page }) => {
    const hostile = [
      '{"__proto__":{"polluted":true}}',
      '{"view":"<img src=x onerror=window.__pwned=1>"}',
      `{"view":"single"${' '.repeat(20_000)}}`,
      '{"camera":{"fovy":1e308}}',
      '{not json',
    ];
    for (const text of hostile) {
      const params = new URLSearchParams();
      params.set('s', text);
      await page.goto('about:blank');
      await page.goto(`/#${params}`);
      await settle(page);
      await expect(page.getByTestId('notice').first()).toContainText('The state in the URL was refused');
      const pwned = await page.evaluate(() => ({
        pwned: (window as unknown as { __pwned?: number }).__pwned,
        polluted: ({} as Record<string, unknown>)['polluted'],
      }));
      expect(pwned).toEqual({ pwned: undefined, polluted: undefined });
      await expect(page.getByTestId('stats-triangles')).toHaveText(/\d/);
    }
  });

  test('WebGL context loss shows a message and recovers with the scene intact, its GPU timer too; the message is dismissed, or goes with the scene', async ({
    page,
  }) => {
    const webglWarnings: string[] = [];
    page.on('console', (m) => {
      if (m.type() === 'warning' && m.text().startsWith('WebGL:')) webglWarnings.push(m.text());
    });
    await open(page);
    await choose(page, 'Material.shading', 'flat');
    const before = await picture(page);
    await page.evaluate(() => {
      const canvas = document.querySelector('canvas')!;
      const ext = canvas.getContext('webgl2')!.getExtension('WEBGL_lose_context')!;
      (window as unknown as { __lose: WEBGL_lose_context }).__lose = ext;
      ext.loseContext();
    });
    await expect(page.getByTestId('context-message')).toContainText('lost');
    await page.evaluate(() => (window as unknown as { __lose: WEBGL_lose_context }).__lose.restoreContext());
    await expect(page.getByTestId('context-message')).toContainText('restored');
    await settle(page);
    expect(await picture(page)).toBe(before);
    await expect(page.locator('[id="Material.shading"]')).toHaveValue('0');
    // Frames on the restored context time themselves with its own timer-query extension (the lost context's is
    // refused: "beginQuery: invalid target", 126 warnings). (three's WebGLRenderer still deletes the buffers of
    // a geometry made before the loss when it is disposed after: "object does not belong to this context".)
    await choose(page, 'Material.shading', 'phong');
    await settle(page);
    expect(webglWarnings.filter((w) => /query|timer/i.test(w))).toEqual([]);
    await page.getByTestId('context-message').getByRole('button', { name: 'dismiss' }).click();
    await expect(page.getByTestId('context-message')).toHaveCount(0);
    // Lost and restored again: the message goes when the scene changes.
    await page.evaluate(() => {
      const lose = (window as unknown as { __lose: WEBGL_lose_context }).__lose;
      lose.loseContext();
      setTimeout(() => lose.restoreContext(), 0);
    });
    await expect(page.getByTestId('context-message')).toContainText('restored');
    await choose(page, 'View.scene', 'instanced spheres');
    await expect(page.getByTestId('context-message')).toHaveCount(0);
  });

  test('exports the canvas as PNG', async ({ page }) => {
    await open(page);
    const download = page.waitForEvent('download');
    await page.getByRole('button', { name: 'export PNG' }).click();
    const file = await download;
    expect(file.suggestedFilename()).toBe('shadelab.png');
    const stream = await file.createReadStream();
    const chunks: Buffer[] = [];
    for await (const chunk of stream) chunks.push(chunk as Buffer);
    expect(Buffer.concat(chunks).subarray(1, 4).toString()).toBe('PNG');
  });

  test('the controls are labelled and reachable by keyboard', async ({ page }) => {
    await open(page);
    await expect(page.getByLabel('shading')).toBeVisible();
    await expect(page.getByLabel('shininess')).toBeVisible();
    await expect(page.getByRole('img', { name: /Lit sphere/ })).toBeVisible();
    await expect(page.getByLabel('fragment shader GLSL')).toBeVisible();
    await expect(page.getByLabel('eye z', { exact: true })).toHaveValue('3.0');
    await expect(page.getByLabel('Ia (ambient) y', { exact: true })).toHaveValue('0.20');
    // Tab to the shading select and change it with the keyboard alone.
    await page.getByLabel('shading').focus();
    await page.keyboard.press('ArrowUp');
    await settle(page);
    expect(((await urlState(page))['material'] as { shading: string }).shading).toBe('gouraud');
    // A number is shown with its step's decimals: the concepts page's c = 0.002 is typed and kept.
    const c = page.locator('[id="Light 1.light1C"]');
    await expect(c).toHaveValue('0.000');
    await c.fill('0.002');
    await c.press('Enter');
    await settle(page);
    await expect(c).toHaveValue('0.002');
    const [light] = (await urlState(page))['lights'] as { attenuation: { c: number } }[];
    expect(light!.attenuation.c).toBe(0.002);
  });
});

test("the camera follows a resize: the aspect is the canvas's, so the sphere keeps its proportions", async ({
  page,
}) => {
  // The lecture's ellipsoid (2, 1, 2) seen from (0, 0, 6) (so that it fits the narrow canvas): the tangent
  // lines from the eye to its outline have slopes 2/√32 across (the circle of radius 2) and 1/√32 up (the
  // ellipse z²/4 + y² = 1), so with the right aspect the lit box is twice as wide as high on any canvas, and
  // (fovy 90°) 1/√32 of the canvas height high.
  await open(page, { camera: { eye: [0, 0, 6] } });
  const before = await litBox(page);
  await page.setViewportSize({ width: 1400, height: 500 });
  await expect.poll(async () => (await litBox(page)).canvasWidth).not.toBe(before.canvasWidth);
  await settle(page);
  const after = await litBox(page);
  expect(after.canvasWidth / after.canvasHeight).not.toBeCloseTo(before.canvasWidth / before.canvasHeight, 1);
  for (const box of [before, after]) {
    expect(Math.abs(box.height - box.canvasHeight / Math.sqrt(32))).toBeLessThanOrEqual(2);
    expect(Math.abs(box.width / box.height - 2)).toBeLessThan(0.02);
  }
});

test('a light moves with the gizmo', async ({ page }) => {
  await open(page);
  // The lecture's light 1 is behind the eye: its gizmo would be off the view, and the page says what to do.
  await press(page, 'move light 1 with the gizmo');
  await expect(page.getByTestId('notice')).toContainText(
    'Light 1 is behind the eye, so its gizmo is off the view',
  );
  // Turned off again (nothing to redraw: it was off the view).
  await page.getByRole('button', { name: 'move light 1 with the gizmo', exact: true }).click();
  await settle(page);
  await press(page, 'add light'); // light 2 at (0.4, 0.3, 2.4), in front of the sphere
  const before = await picture(page);
  await press(page, 'move light 2 with the gizmo');
  expect((await picture(page)) === before, 'the gizmo is drawn').toBe(false);
  // Project the light with the lecture camera (eye (0, 0, 3), fovy 90) to find the gizmo's centre.
  const box = (await page.getByTestId('viewport').boundingBox())!;
  const depth = 3 - 2.4;
  const x = box.x + box.width / 2 + ((0.4 / depth) * box.height) / 2;
  const y = box.y + box.height / 2 - ((0.3 / depth) * box.height) / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 30, y + 20, { steps: 6 });
  await page.mouse.up();
  await settle(page);
  const [lx, ly] = ((await urlState(page))['lights'] as { position: number[] }[])[1]!.position;
  expect(lx).toBeGreaterThan(0.44);
  expect(ly).toBeLessThan(0.29);
  // The drag moved the light, not the sphere.
  expect(((await urlState(page))['trackball'] as { rotation: number[] }).rotation).toEqual([0, 0, 0, 1]);
});

test('with "drag turns camera", a drag turns the gaze instead of the sphere', async ({ page }) => {
  await open(page);
  await toggle(page, 'Camera.dragTurns');
  const before = await picture(page);
  await drag(page, [0.5, 0.5], [0.6, 0.55]);
  expect((await picture(page)) === before, 'the drag changes the picture').toBe(false);
  const state = await urlState(page);
  const camera = state['camera'] as { eye: number[]; at: number[]; up: number[] };
  expect((state['trackball'] as { rotation: number[] }).rotation).toEqual([0, 0, 0, 1]);
  expect(camera.eye).toEqual([0, 0, 3]);
  // The gaze follows the pointer: right and down (yaw about v, pitch about u).
  expect(camera.at[0]).toBeGreaterThan(0);
  expect(camera.at[1]).toBeLessThan(0);
  expect(Math.hypot(...camera.at.map((x, i) => x - camera.eye[i]!))).toBeCloseTo(3, 9);
  expect(Math.hypot(...camera.up)).toBeCloseTo(1, 9);
});

test('turn speed scales how far a drag turns the gaze', async ({ page }) => {
  await open(page);
  await toggle(page, 'Camera.dragTurns');
  const gaze = async () => {
    const camera = (await urlState(page))['camera'] as { eye: number[]; at: number[] };
    return Math.atan2(camera.at[0]! - camera.eye[0]!, camera.eye[2]! - camera.at[2]!);
  };
  await drag(page, [0.5, 0.5], [0.6, 0.5]);
  const slow = await gaze();
  const slowPicture = await picture(page);
  expect(slow).toBeGreaterThan(0);
  await press(page, 'reset scene');
  await toggle(page, 'Camera.dragTurns');
  await typeInto(page, 'Camera.turnSpeed', '0.01'); // twice the default 0.005 rad/px
  await drag(page, [0.5, 0.5], [0.6, 0.5]);
  expect(await gaze()).toBeCloseTo(slow * 2, 6);
  expect(await picture(page)).not.toBe(slowPicture);
});

test('the damping factor sets how long a fling spins: a smaller factor turns further', async ({ page }) => {
  test.setTimeout(120_000);
  await open(page);
  await toggle(page, 'Trackball.damping');
  const angle = async () => 2 * Math.acos(Math.min(1, Math.abs((await urlRotation(page))[3]!)));
  const spin = async () => {
    if ((await urlRotation(page))[3] !== 1) await press(page, 'reset rotation');
    await fling(page, [0.45, 0.5], [0.55, 0.5]);
    await settle(page, 600);
    return { angle: await angle(), picture: await picture(page) };
  };
  await typeInto(page, 'Trackball.dampingFactor', '0.5');
  const short = await spin();
  await typeInto(page, 'Trackball.dampingFactor', '0.05');
  const long = await spin();
  // The spin after release sums to about (last step) / factor: ten times longer at 0.05 than at 0.5.
  expect(long.angle).toBeGreaterThan(short.angle * 1.5);
  expect(long.picture).not.toBe(short.picture);
});

test('"reset scene" goes back to the lecture scene', async ({ page }) => {
  await open(page);
  const start = await picture(page);
  const startState = await urlState(page);
  await typeInto(page, 'Material.shininess', '5');
  await choose(page, 'Material.shading', 'flat');
  await drag(page, [0.5, 0.5], [0.6, 0.6]);
  expect(await picture(page)).not.toBe(start);
  await press(page, 'reset scene');
  expect(await picture(page)).toBe(start);
  expect(await urlState(page)).toEqual(startState);
  await expect(page.locator('[id="Material.shininess"]')).toHaveValue('50');
});

test('"copy link" puts a URL on the clipboard that reproduces the picture', async ({
  page,
  context,
  browser,
}) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await open(page);
  await choose(page, 'Material.shading', 'gouraud');
  await drag(page, [0.4, 0.5], [0.6, 0.4]);
  const original = await picture(page);
  await page.getByRole('button', { name: 'copy link', exact: true }).click();
  await expect(page.getByTestId('notice')).toContainText('Link copied to the clipboard.');
  const link = await page.evaluate(() => navigator.clipboard.readText());
  expect(new URL(link).hash).toBe(new URL(page.url()).hash);
  const other = await browser.newPage(); // a fresh context: only the link carries the state
  await other.goto(link);
  await settle(other);
  expect(await picture(other)).toBe(original);
  await other.close();
});

test('compare view: one drag turns all four cells, and the rotation goes to the URL', async ({ page }) => {
  await open(page, { view: 'compare' });
  await expect(page.getByTestId('stats-triangles')).toHaveText(/\d/);
  const before = await cellPictures(page, 2, 2); // 460 × 600 canvas: 2 × 2
  expect(new Set(before).size).toBe(4); // four different shadings
  await drag(page, [0.4, 0.4], [0.6, 0.45]);
  const after = await cellPictures(page, 2, 2);
  after.forEach((cell, i) => {
    expect(cell, `cell ${i} changes`).not.toBe(before[i]);
  });
  const rotation = await urlRotation(page);
  expect(rotation[3]).toBeLessThan(1 - 1e-6);
  expect(Math.hypot(...rotation)).toBeCloseTo(1, 9);
});

test('compare view stats sum the vertices over the cells and count shared buffers once', async ({ page }) => {
  await open(page, { view: 'compare', sphere: { level: 2 } });
  // Level 2 tetrahedron: 64 triangles, 34 shared vertices (gouraud, phong, cel); flat: its own geometry.
  const stats = page.getByTestId('stats');
  await expect(stats).toContainText('vertices (4 cells)');
  const vertices = Number((await page.getByTestId('stats-vertices').textContent())!.replace(/,/g, ''));
  const bytes = Number((await page.getByTestId('stats-bytes').getAttribute('title'))!.replace(/\D/g, ''));
  await open(page, { view: 'single', sphere: { level: 2 }, material: { shading: 'flat' } });
  const flatVertices = Number(await page.getByTestId('stats-vertices').textContent());
  const flatBytes = Number((await page.getByTestId('stats-bytes').getAttribute('title'))!.replace(/\D/g, ''));
  await expect(page.getByTestId('stats-vertices')).toHaveText(String(flatVertices));
  expect(vertices).toBe(flatVertices + 3 * 34);
  expect(bytes).toBe(flatBytes + 34 * 3 * 4 + 64 * 3 * 2);
});

test('the keyboard alone adds a light, toggles a checkbox and turns the sphere', async ({ page }) => {
  await open(page);
  /** Tabs forward (as a keyboard user would) until the focused element matches a selector or has a text. */
  const tabTo = async (target: { selector?: string; text?: string }) => {
    for (let i = 0; i < 250; i++) {
      await page.keyboard.press('Tab');
      const hit = await page.evaluate(({ selector, text }) => {
        const el = document.activeElement;
        return !!el && (selector ? el.matches(selector) : el.textContent?.trim() === text);
      }, target);
      if (hit) return;
    }
    throw new Error(`Tab never reached ${JSON.stringify(target)}`);
  };
  const start = await picture(page);
  await tabTo({ text: 'add light' });
  await page.keyboard.press('Enter');
  await expect(page.locator('[id="Light 2.light2Position"]')).toBeVisible();
  await settle(page);
  expect((await urlState(page))['lights']).toHaveLength(2);
  const withLight = await picture(page);
  expect(withLight).not.toBe(start);
  await tabTo({ selector: '[id="Sphere.auto"]' });
  await page.keyboard.press('Space');
  await settle(page);
  expect(((await urlState(page))['sphere'] as { auto: boolean }).auto).toBe(true);
  // Turn keys on the focused canvas (none of them moves the camera): L turns as a drag to the right does.
  await tabTo({ selector: '[data-testid="viewport"]' });
  const eye = ((await urlState(page))['camera'] as { eye: number[] }).eye;
  const unturned = await picture(page);
  await page.keyboard.press('KeyL');
  await settle(page);
  let rotation = await urlRotation(page);
  expect(rotation[1]).toBeCloseTo(Math.sin(Math.PI / 72), 9); // 5° about the camera's up = world y
  expect(await picture(page)).not.toBe(unturned);
  await page.keyboard.press('KeyK');
  await page.keyboard.press('KeyI');
  await page.keyboard.press('KeyJ');
  await settle(page);
  rotation = await urlRotation(page);
  expect(Math.abs(rotation[3]!)).toBeCloseTo(1, 9);
  expect(((await urlState(page))['camera'] as { eye: number[] }).eye).toEqual(eye);
});
