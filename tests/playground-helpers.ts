import { expect, type Locator, type Page } from '@playwright/test';
import { timedLoad } from './harness-helpers';

/**
 * What is drawn over the canvas (messages, the compare view's labels, arrows to lights) and the render statistics
 * (they change every frame): hidden in screenshots.
 */
export const HIDE_OVERLAYS =
  '.stats-box, .messages, .compare-labels, .light-arrow { visibility: hidden !important; }';

/** The playground URL for a (partial) state: the same `#s=<json>` the app writes. */
export function stateUrl(state: object): string {
  const params = new URLSearchParams();
  params.set('s', JSON.stringify(state));
  return `/#${params}`;
}

/** Frames rendered so far (the canvas's `data-frames`). */
export async function frames(page: Page): Promise<number> {
  return Number((await page.getByTestId('viewport').getAttribute('data-frames')) ?? 0);
}

/**
 * Rendering is on demand: wait for a first frame, then until the page rests: no frame came for `quietMs` and none
 * is asked for (the canvas's `data-render-pending`, set while the viewer has a frame scheduled: an animation, such
 * as a damped spin, asks for its next frame while it draws, so it never looks at rest between two slow frames) and
 * nothing on the page is `aria-busy` (the playground's panels, which load after the first frame).
 * The page watches itself (every animation frame) rather than being asked every `quietMs` from here, so the wait
 * ends `quietMs` after the last frame; it gives up after 50 × `quietMs` of frames that never stop.
 */
export async function settle(page: Page, quietMs = 200): Promise<void> {
  const viewport = page.getByTestId('viewport');
  await expect(viewport).toHaveAttribute('data-frames', /[1-9]/);
  await viewport.evaluate(
    (canvas, quiet) =>
      new Promise<void>((resolve) => {
        const start = performance.now();
        let last = canvas.dataset['frames'];
        let since = start;
        const check = () => {
          const now = performance.now();
          const busy =
            canvas.hasAttribute('data-render-pending') ||
            canvas.ownerDocument.querySelector('[aria-busy="true"]');
          if (canvas.dataset['frames'] !== last || busy) {
            last = canvas.dataset['frames'];
            since = now;
          }
          if (now - since >= quiet || now - start >= 50 * quiet) resolve();
          else requestAnimationFrame(check);
        };
        requestAnimationFrame(check);
      }),
    quietMs,
  );
}

/**
 * Opens the playground (optionally on a state) with fresh storage and waits until it rests: for its first frame
 * as long as the test may.
 */
export async function open(page: Page, state?: object): Promise<void> {
  await timedLoad(async () => {
    await page.goto(state ? stateUrl(state) : '/');
    await expect(page.getByTestId('viewport')).toHaveAttribute('data-frames', /[1-9]/, { timeout: 0 });
    await settle(page, 400); // a page load also waits for what loads after the first frame
  });
}

/** The canvas's own pixels (no overlays) as a PNG data URL: equal strings = equal pixels. */
export async function picture(page: Page): Promise<string> {
  return page.getByTestId('viewport').evaluate((canvas: HTMLCanvasElement) => canvas.toDataURL('image/png'));
}

/** One pixel of the canvas (x, y as fractions of the size, y from the top), RGBA. */
export async function pixel(page: Page, fx: number, fy: number): Promise<number[]> {
  return page.getByTestId('viewport').evaluate(
    (canvas: HTMLCanvasElement, [x, y]) => {
      const gl = canvas.getContext('webgl2')!;
      const out = new Uint8Array(4);
      gl.readPixels(
        Math.floor(canvas.width * x),
        Math.floor(canvas.height * (1 - y)),
        1,
        1,
        gl.RGBA,
        gl.UNSIGNED_BYTE,
        out,
      );
      return Array.from(out);
    },
    [fx, fy] as const,
  );
}

/**
 * Runs an action that should draw (every accepted change renders at once): waits for a new frame, then for
 * the page to rest. `draws: false` for an action that must not render (a refused value).
 */
async function drawn(page: Page, action: () => Promise<void>, draws = true): Promise<void> {
  const before = await frames(page);
  await action();
  if (draws) {
    // Watched in the page, every animation frame, for at most 15 s.
    const drew = await page.getByTestId('viewport').evaluate(
      (canvas, n) =>
        new Promise<boolean>((resolve) => {
          const start = performance.now();
          const check = () => {
            if (Number(canvas.dataset['frames'] ?? 0) > n) resolve(true);
            else if (performance.now() - start > 15_000) resolve(false);
            else requestAnimationFrame(check);
          };
          check();
        }),
      before,
    );
    expect(drew, `a frame after frame ${before}, within 15 s`).toBe(true);
  }
  await settle(page);
}

/**
 * Waits until leva's panel rests. leva opens or closes a folder in two moves, a height transition and then a
 * smooth scroll that brings an opened folder into view; a click during either can land on a neighbour that slid
 * under the pointer between mousedown and mouseup (seen in CI: the press went to "remove light 2", the release
 * to the button below it, and the click to neither). At rest: no folder's height set (leva sets it while it
 * animates, and keeps only a closed folder's 0px) and nothing in the panel moved for five animation frames.
 */
export async function panelAtRest(page: Page): Promise<void> {
  await page.locator('.panel').evaluate(
    (panel) =>
      new Promise<void>((resolve) => {
        let last = '';
        let still = 0;
        const step = () => {
          const elements = [...panel.querySelectorAll<HTMLElement>('*')];
          const folders = elements.filter(
            (e) => e.previousElementSibling?.firstElementChild instanceof SVGElement,
          );
          const animating = folders.some((e) => e.style.height !== '' && e.style.height !== '0px');
          const at = elements.map((e) => e.getBoundingClientRect().y).join(' ');
          still = !animating && at === last ? still + 1 : 0;
          last = at;
          if (still >= 5) resolve();
          else requestAnimationFrame(step);
        };
        requestAnimationFrame(step);
      }),
  );
}

/**
 * Opens the leva folder that holds an element if it is collapsed (the panel's Sphere, Camera, Trackball and
 * light folders start collapsed), by a click on its title as a user would (a collapsed folder's content takes
 * no pointer events), and waits for the panel to rest.
 */
export async function openFolderOf(target: Locator): Promise<void> {
  const title = await target.evaluate((element) => {
    for (let node = element.parentElement; node; node = node.parentElement) {
      const previous = node.previousElementSibling;
      if (node.style.height === '0px' && previous?.firstElementChild instanceof SVGElement)
        return previous.textContent;
    }
    return null;
  });
  if (title === null) return;
  await target.page().locator('.panel').getByText(title, { exact: true }).click();
  await expect(target).toHaveCSS('pointer-events', 'auto');
  await panelAtRest(target.page());
}

/** Types a value into a leva input (by its path id, e.g. `Material.shininess` or `Camera.eye.z`). */
export async function typeInto(page: Page, id: string, value: string, { draws = true } = {}): Promise<void> {
  const input = page.locator(`[id="${id}"]`);
  await drawn(
    page,
    async () => {
      await input.fill(value);
      await input.press('Enter');
    },
    draws,
  );
}

/** Picks an option of a leva select (by its path id) by its label. */
export async function choose(page: Page, id: string, label: string): Promise<void> {
  await drawn(page, async () => {
    await page.locator(`[id="${id}"]`).selectOption({ label });
  });
}

/** Toggles a leva checkbox (by its path id). */
export async function toggle(page: Page, id: string): Promise<void> {
  const label = page.locator(`label[for="${id}"]`).last();
  await openFolderOf(label);
  await drawn(page, () => label.click());
}

/** Clicks a leva button by its text. */
export async function press(page: Page, text: string): Promise<void> {
  const button = page.getByRole('button', { name: text, exact: true });
  await openFolderOf(button);
  await drawn(page, () => button.click());
}

/** The state the page last wrote to its URL. */
export async function urlState(page: Page): Promise<Record<string, unknown>> {
  await page.waitForTimeout(300);
  const hash = new URL(page.url()).hash.slice(1);
  return JSON.parse(new URLSearchParams(hash).get('s') ?? '{}');
}

/** Drags on the canvas from one point to another (fractions of its box), in steps. */
export async function drag(
  page: Page,
  from: [number, number],
  to: [number, number],
  steps = 12,
): Promise<void> {
  const box = (await page.getByTestId('viewport').boundingBox())!;
  const at = ([fx, fy]: [number, number]) => [box.x + box.width * fx, box.y + box.height * fy] as const;
  await page.mouse.move(...at(from));
  await page.mouse.down();
  await drawn(page, () => page.mouse.move(...at(to), { steps }));
  await page.mouse.up();
  await settle(page);
}

/**
 * A fling: press at `from`, move to `to` in `steps` moves and release there, all in one task of the page (fractions
 * of the canvas). A hand's fling releases within milliseconds of its last move; dispatched from here, a loaded
 * machine could hold the release back past the trackball's 100 ms and turn the fling into a drag that stops.
 */
export async function fling(
  page: Page,
  from: [number, number],
  to: [number, number],
  steps = 3,
): Promise<void> {
  await page.getByTestId('viewport').evaluate(
    (canvas, { from, to, steps }) => {
      const rect = canvas.getBoundingClientRect();
      const send = (type: string, [fx, fy]: [number, number]) =>
        canvas.dispatchEvent(
          new PointerEvent(type, {
            pointerId: 1,
            pointerType: 'mouse',
            isPrimary: true,
            button: type === 'pointermove' ? -1 : 0,
            buttons: type === 'pointerup' ? 0 : 1,
            clientX: rect.left + rect.width * fx,
            clientY: rect.top + rect.height * fy,
            bubbles: true,
            cancelable: true,
            composed: true,
          }),
        );
      send('pointerdown', from);
      for (let i = 1; i <= steps; i++) {
        const t = i / steps;
        send('pointermove', [from[0] + (to[0] - from[0]) * t, from[1] + (to[1] - from[1]) * t]);
      }
      send('pointerup', to);
    },
    { from, to, steps },
  );
}

/** How many canvas pixels are not background (any channel above 8): the sphere's area on screen. */
export async function litArea(page: Page): Promise<number> {
  return page.getByTestId('viewport').evaluate((canvas: HTMLCanvasElement) => {
    const gl = canvas.getContext('webgl2')!;
    const out = new Uint8Array(canvas.width * canvas.height * 4);
    gl.readPixels(0, 0, canvas.width, canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, out);
    let n = 0;
    for (let i = 0; i < out.length; i += 4) if (out[i]! > 8 || out[i + 1]! > 8 || out[i + 2]! > 8) n++;
    return n;
  });
}

/** The lit pixels' bounding box on the canvas (pixels brighter than 8 in any channel), and the canvas size. */
export async function litBox(
  page: Page,
): Promise<{ width: number; height: number; canvasWidth: number; canvasHeight: number }> {
  return page.getByTestId('viewport').evaluate((canvas: HTMLCanvasElement) => {
    const gl = canvas.getContext('webgl2')!;
    const w = canvas.width;
    const h = canvas.height;
    const out = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, out);
    let [x0, x1, y0, y1] = [w, -1, h, -1];
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        const i = (y * w + x) * 4;
        if (out[i]! > 8 || out[i + 1]! > 8 || out[i + 2]! > 8) {
          x0 = Math.min(x0, x);
          x1 = Math.max(x1, x);
          y0 = Math.min(y0, y);
          y1 = Math.max(y1, y);
        }
      }
    }
    return { width: x1 - x0 + 1, height: y1 - y0 + 1, canvasWidth: w, canvasHeight: h };
  });
}

/** The canvas split into `cols` × `rows` cells, each cell's pixels as one string (equal = same picture). */
export async function cellPictures(page: Page, cols: number, rows: number): Promise<string[]> {
  return page.getByTestId('viewport').evaluate(
    (canvas: HTMLCanvasElement, [c, r]) => {
      const gl = canvas.getContext('webgl2')!;
      const cells: string[] = [];
      for (let row = 0; row < r; row++) {
        for (let col = 0; col < c; col++) {
          const x = Math.round((col * canvas.width) / c);
          const w = Math.round(((col + 1) * canvas.width) / c) - x;
          const y = Math.round(canvas.height - ((row + 1) * canvas.height) / r);
          const h = Math.round(canvas.height - (row * canvas.height) / r) - y;
          const out = new Uint8Array(w * h * 4);
          gl.readPixels(x, y, w, h, gl.RGBA, gl.UNSIGNED_BYTE, out);
          let hash = 0;
          for (let i = 0; i < out.length; i++) hash = (Math.imul(hash, 31) + out[i]!) | 0;
          cells.push(`${hash}:${out.reduce((a, b) => a + b, 0)}`);
        }
      }
      return cells;
    },
    [cols, rows] as const,
  );
}

/** The trackball rotation the page last wrote to its URL. */
export async function urlRotation(page: Page): Promise<number[]> {
  return ((await urlState(page))['trackball'] as { rotation: number[] }).rotation;
}

/** Every console warning and error, and every page error, from now on. */
export function listenConsole(page: Page): string[] {
  const heard: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'warning' || m.type() === 'error') heard.push(`${m.type()}: ${m.text()}`);
  });
  page.on('pageerror', (e) => heard.push(`page error: ${e.message}`));
  return heard;
}
