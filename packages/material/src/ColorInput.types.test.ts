import {
  type ColorInput,
  PhongLight,
  type PhongLightOptions,
  ShadingMaterial,
  type ShadingMaterialOptions,
} from '@shadelab/material';
import { SphereImpostorMaterial, type SphereImpostorMaterialOptions } from '@shadelab/material/impostor';
import { OutlineMaterial, type OutlineMaterialOptions } from '@shadelab/material/outline';
import { Color } from 'three';
import { describe, expect, expectTypeOf, it } from 'vitest';

// Type tests, both ways: `npx tsc -p tsconfig.test.json` fails if a case marked @ts-expect-error type-checks
// (the directive is then unused) or if a positive case does not. The cases also run, so what the types
// refuse is refused at run time too (a TypeError naming the parameter).

describe('ColorInput types', () => {
  it('accepts a grey number, a CSS string, a Color and a linear triple', () => {
    expectTypeOf<number>().toExtend<ColorInput>();
    expectTypeOf<string>().toExtend<ColorInput>();
    expectTypeOf<Color>().toExtend<ColorInput>();
    expectTypeOf<readonly [number, number, number]>().toExtend<ColorInput>();
    expectTypeOf<[number, number, number]>().toExtend<ColorInput>();
    const level: number = Number('0.5'); // a computed number (type number, not a literal)
    const options: ShadingMaterialOptions = { ka: level, kd: level, ks: level };
    expect(new ShadingMaterial(options).ka.toArray()).toEqual([0.5, 0.5, 0.5]);
    expectTypeOf<PhongLightOptions['ambient']>().toEqualTypeOf<ColorInput | undefined>();
    expectTypeOf<ShadingMaterialOptions['ks']>().toEqualTypeOf<ColorInput | undefined>();
    expectTypeOf<SphereImpostorMaterialOptions['kd']>().toEqualTypeOf<ColorInput | undefined>();
    expectTypeOf<OutlineMaterialOptions['color']>().toEqualTypeOf<ColorInput | undefined>();

    // The lecture's light and greys, as a user writes them: no cast, no error.
    const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
    light.ambient = 0.1;
    light.diffuse = '#ffe0c0';
    light.specular = new Color(0xffffff);
    const material = new ShadingMaterial({ ka: 0.5, kd: [0.6, 0.35, 0.2], ks: 1, lights: [light] });
    material.kd = 0.7;
    const impostor = new SphereImpostorMaterial({ ka: 0.5, kd: 0.5, ks: 0.5 });
    const outline = new OutlineMaterial({ color: 0 });
    outline.color = '#f2f2f2';
    // The getters still give a Color.
    expectTypeOf(light.diffuse).toEqualTypeOf<Color>();
    expectTypeOf(material.ka).toEqualTypeOf<Color>();
    expect([light.ambient.r, material.kd.g, impostor.ks.b, outline.color.r]).toEqual([
      0.1,
      0.7,
      0.5,
      new Color(0xf2f2f2).r,
    ]);
  });

  it('refuses other shapes at compile time and at run time', () => {
    expectTypeOf<readonly [number, number]>().not.toExtend<ColorInput>();
    expectTypeOf<readonly [number, number, number, number]>().not.toExtend<ColorInput>();
    expectTypeOf<boolean>().not.toExtend<ColorInput>();
    expectTypeOf<{ r: number }>().not.toExtend<ColorInput>();
    expectTypeOf<readonly [string, number, number]>().not.toExtend<ColorInput>();
    expectTypeOf<null>().not.toExtend<ColorInput>();

    // @ts-expect-error a pair is not a colour
    expect(() => new PhongLight({ diffuse: [1, 1] })).toThrow(TypeError);
    // @ts-expect-error four channels are not a colour
    expect(() => new PhongLight({ ambient: [1, 1, 1, 1] })).toThrow(TypeError);
    // @ts-expect-error a boolean is not a grey level
    expect(() => new PhongLight({ specular: true })).toThrow(TypeError);
    // @ts-expect-error an object with channels is not a THREE.Color
    expect(() => new ShadingMaterial({ ka: { r: 1 } })).toThrow(TypeError);
    // @ts-expect-error a channel must be a number
    expect(() => new ShadingMaterial({ kd: ['1', 1, 1] })).toThrow(TypeError);
    // @ts-expect-error null is not a colour
    expect(() => new SphereImpostorMaterial({ ks: null })).toThrow(TypeError);
    // @ts-expect-error the outline colour takes the same forms
    expect(() => new OutlineMaterial({ color: [0, 0] })).toThrow(TypeError);
    const light = new PhongLight();
    expect(() => {
      // @ts-expect-error the setter takes a ColorInput
      light.diffuse = [1, 1];
    }).toThrow(TypeError);
    expect(light.diffuse.toArray()).toEqual([1, 1, 1]);
  });
});
