import { expect } from '@playwright/test';
import { test } from './harness-helpers';
import { frames, open, settle } from './playground-helpers';

// A long session of random option changes (issue 8): programs stay bounded, the heap stays flat, and no console
// error. `npm test` runs a short session; set SHADELAB_LONG_SESSION=10000 for the full one.
const CHANGES = Number(process.env['SHADELAB_LONG_SESSION'] ?? 120);

/** A small deterministic PRNG (mulberry32), so a failing session can be replayed. */
function random(seed: number) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

test(`a session of ${CHANGES} random option changes`, async ({ page }) => {
  test.setTimeout(60_000 + CHANGES * 2_000);
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
  await open(page);
  const cdp = await page.context().newCDPSession(page);
  const heap = async () => {
    await cdp.send('HeapProfiler.collectGarbage');
    return (await cdp.send('Runtime.getHeapUsage')).usedSize;
  };
  const rand = random(1234);
  const pick = <T>(xs: readonly T[]) => xs[Math.floor(rand() * xs.length)]!;
  let heapAfterWarmUp = 0;
  let maxPrograms = 0;
  for (let i = 0; i < CHANGES; i++) {
    const lights = Array.from({ length: pick([0, 1, 2, 3]) }, (_, k) => ({
      position: [k * 3 - 4, 8, 15],
      attenuation: { a: 1, b: pick([0, 0.02]), c: 0 },
    }));
    const state = {
      view: pick(['single', 'single', 'compare']),
      material: {
        shading: pick(['flat', 'gouraud', 'phong']),
        lighting: pick(['phong', 'blinn-phong']),
        celBands: pick([0, 0, 2, 3, 5]),
        outline: rand() < 0.3,
        shininess: 1 + i, // every state differs, so every change draws a frame
      },
      lights,
      sphere: { base: pick(['tetrahedron', 'octahedron', 'icosahedron']), level: pick([0, 1, 2, 3, 4]) },
      camera: { projection: pick(['perspective', 'orthographic']) },
    };
    const before = await frames(page);
    await page.evaluate((text) => {
      const params = new URLSearchParams();
      params.set('s', text);
      window.location.hash = params.toString();
    }, JSON.stringify(state));
    await expect.poll(() => frames(page)).toBeGreaterThan(before);
    maxPrograms = Math.max(maxPrograms, Number(await page.getByTestId('stats-programs').textContent()));
    if (i === Math.floor(CHANGES / 10)) heapAfterWarmUp = await heap();
  }
  await settle(page);
  const heapAtEnd = await heap();
  const line = `${CHANGES} changes: programs at most ${maxPrograms}; heap ${(heapAfterWarmUp / 2 ** 20).toFixed(1)} MiB after warm-up, ${(heapAtEnd / 2 ** 20).toFixed(1)} MiB at the end`;
  console.log(line);
  test.info().annotations.push({ type: 'long session', description: line });
  expect(errors).toEqual([]);
  expect(maxPrograms).toBeLessThanOrEqual(32);
  // Flat: no growth beyond noise (measured after a forced GC; generous bound, the numbers are logged).
  expect(heapAtEnd).toBeLessThan(heapAfterWarmUp * 1.5 + 8 * 2 ** 20);
});
