// What R3F does with the props of the elements @shadelab/react registers, on the real objects: R3F's own
// applyProps (the function its reconciler calls for every prop), so the rules the guide states are checked
// against R3F itself, not a model of it. Rendering is tested in tests/react.spec.ts.
import { applyProps } from '@react-three/fiber';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { OutlineMaterial } from '@shadelab/material/outline';
import type { ShadelabElements } from '@shadelab/react';
import { Color, Vector3 } from 'three';
import { describe, expect, expectTypeOf, it } from 'vitest';

describe('props as R3F applies them', () => {
  it('phongLights goes through the setter: the list is kept, a wrong entry is a TypeError naming it', () => {
    const light = new PhongLight();
    const material = new ShadingMaterial();
    applyProps(material as never, { phongLights: [light] });
    expect(material.phongLights).toEqual([light]);
    expect(Object.isFrozen(material.phongLights)).toBe(true);
    expect(() => applyProps(material as never, { phongLights: [new Vector3()] })).toThrow(
      /ShadingMaterial\.lights\[0\] must be a PhongLight/,
    );
  });

  it('three’s boolean `lights` is left as it is by a JSX `lights` flag, apart from the PhongLight list', () => {
    const light = new PhongLight();
    const material = new ShadingMaterial({ lights: [light] });
    const flag = material.lights;
    expectTypeOf<ShadelabElements['shadingMaterial']['lights']>().toEqualTypeOf<boolean | undefined>();
    applyProps(material as never, { lights: flag });
    expect(material.phongLights).toEqual([light]);
  });

  it('colour props: a CSS string, a Color and linear [r, g, b] give what the constructors give', () => {
    const material = new ShadingMaterial();
    applyProps(material as never, { ka: '#ff8000' });
    expect(material.ka.equals(new ShadingMaterial({ ka: '#ff8000' }).ka)).toBe(true);
    applyProps(material as never, { kd: [0.1, 0.2, 0.3] });
    expect(material.kd.toArray()).toEqual(new ShadingMaterial({ kd: [0.1, 0.2, 0.3] }).kd.toArray());
    applyProps(material as never, { ks: new Color(0.4, 0.5, 0.6) });
    expect(material.ks.toArray()).toEqual([0.4, 0.5, 0.6]);
    const light = new PhongLight();
    applyProps(light as never, { diffuse: [0.2, 0.2, 0.2] });
    expect(light.diffuse.toArray()).toEqual(new PhongLight({ diffuse: 0.2 }).diffuse.toArray());
    const outline = new OutlineMaterial();
    applyProps(outline as never, { color: '#102030' });
    expect(outline.color.equals(new OutlineMaterial({ color: '#102030' }).color)).toBe(true);
  });

  it('a bare number is written as a hex colour (Color.set), not a grey level: why ColorProp refuses it', () => {
    const material = new ShadingMaterial();
    applyProps(material as never, { ka: 0.2 });
    expect(material.ka.toArray()).toEqual([0, 0, 0]); // black, where new ShadingMaterial({ ka: 0.2 }) is grey
    expect(new ShadingMaterial({ ka: 0.2 }).ka.toArray()).toEqual([0.2, 0.2, 0.2]);
    expectTypeOf<number>().not.toExtend<NonNullable<ShadelabElements['shadingMaterial']['ka']>>();
    expectTypeOf<[number, number, number]>().toExtend<
      NonNullable<ShadelabElements['phongLight']['ambient']>
    >();
  });

  it('a hostile colour is written in place, bypassing the setter (the material reports it before the draw)', () => {
    const material = new ShadingMaterial();
    expect(() => applyProps(material as never, { ka: [Number.NaN, -1, 0] })).not.toThrow();
    expect(material.ka.toArray()).toEqual([Number.NaN, -1, 0]);
    // Through a setter, the same value is refused at once.
    expect(() => {
      material.ka = [Number.NaN, -1, 0];
    }).toThrow(RangeError);
  });

  it('attenuation and the scalar options go through their setters and are validated', () => {
    const light = new PhongLight();
    applyProps(light as never, { attenuation: { a: 1, b: 0, c: 0.1 } });
    expect(light.attenuation).toEqual({ a: 1, b: 0, c: 0.1 });
    expect(() => applyProps(light as never, { attenuation: { a: 0, b: 0, c: 0 } })).toThrow(RangeError);
    const material = new ShadingMaterial();
    expect(() => applyProps(material as never, { shininess: -1 })).toThrow(/shininess/);
    expect(() => applyProps(material as never, { shading: 'smooth' })).toThrow(/shading/);
  });
});
