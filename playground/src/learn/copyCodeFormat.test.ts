// Copy as code: how numbers are written (num), and the install line's @shadelab dependencies.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, test } from 'vitest';
import { num } from './copyCodeFormat';
import { SHADELAB_DEPENDENCIES } from './copyCodeThree';

test("the install line's @shadelab dependencies are the packages' own (package.json dependencies and peers)", () => {
  const packages = new URL('../../../packages/', import.meta.url);
  const fromPackageJsons: Record<string, string[]> = {};
  for (const folder of readdirSync(packages)) {
    const json = JSON.parse(readFileSync(new URL(`${folder}/package.json`, packages), 'utf8'));
    const ours = Object.keys({ ...json.dependencies, ...json.peerDependencies })
      .filter((name) => name.startsWith('@shadelab/'))
      .sort();
    if (ours.length > 0) fromPackageJsons[json.name] = ours;
  }
  expect(SHADELAB_DEPENDENCIES).toEqual(fromPackageJsons);
});

describe('num: numbers in copied code', () => {
  test('15 significant digits, shortest form: the float noise goes; -0 as 0', () => {
    expect(num(-0.20000000000000018)).toBe('-0.2');
    expect(num(0.1 + 0.2)).toBe('0.3');
    expect(num(0.002)).toBe('0.002');
    expect(num(32)).toBe('32');
    expect(num(-0)).toBe('0');
    expect(num(1e-6)).toBe('0.000001');
    expect(num(Math.SQRT1_2)).toBe('0.707106781186548');
    expect(num(1e300)).toBe('1e+300');
  });

  test('property: 10,000 seeded values read back within half a unit of their 15th digit, never longer than String()', () => {
    let seed = 20261202;
    const random = () => {
      seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
      return seed / 2 ** 32;
    };
    for (let i = 0; i < 10_000; i++) {
      const value = (random() - 0.5) * 10 ** Math.floor(random() * 24 - 12);
      const text = num(value);
      expect(Math.abs(Number(text) - value), `${value} → ${text}`).toBeLessThanOrEqual(
        Math.abs(value) * 5e-15,
      );
      expect(text.length, `${value} → ${text}`).toBeLessThanOrEqual(String(value).length);
      // Typed values (at most 15 digits) are written as typed.
      expect(num(Number(text)), text).toBe(text);
    }
  });
});
