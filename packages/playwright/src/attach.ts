import { test } from '@playwright/test';
import { encodePng, type RgbaImage } from './png.js';

/** The running test's info, or undefined outside a test (a matcher called from a script). */
export function currentTestInfo(): ReturnType<typeof test.info> | undefined {
  try {
    return test.info();
  } catch {
    return undefined;
  }
}

/** Attach an image to the running test's report as a PNG (nothing outside a test). */
export async function attachImage(name: string, image: RgbaImage): Promise<void> {
  await currentTestInfo()?.attach(name, { body: Buffer.from(encodePng(image)), contentType: 'image/png' });
}
