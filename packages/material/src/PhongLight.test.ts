import { afterEach, describe, expect, it, vi } from 'vitest';
import { PhongLight } from './PhongLight.js';

describe('PhongLight.castShadow', () => {
  afterEach(() => vi.restoreAllMocks());

  it('stays false: a PhongLight casts no shadow; setting it true warns once per light, naming the parameter', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const light = new PhongLight();
    expect(light.castShadow).toBe(false);
    for (let i = 0; i < 3; i++) light.castShadow = true;
    expect(light.castShadow).toBe(false);
    expect(warn).toHaveBeenCalledTimes(1);
    expect(String(warn.mock.calls[0][0])).toMatch(/^PhongLight\.castShadow: a PhongLight casts no shadow/);
    light.castShadow = false;
    new PhongLight().castShadow = true; // another light says it once too
    expect(warn).toHaveBeenCalledTimes(2);
  });

  it('clone() and copy() keep working (three copies castShadow from the source)', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const light = new PhongLight({ diffuse: 0.5 });
    light.position.set(1, 2, 3);
    const copy = light.clone();
    expect(copy.castShadow).toBe(false);
    expect(copy.position.toArray()).toEqual([1, 2, 3]);
    expect(warn).not.toHaveBeenCalled();
  });
});
