import { type ColorInput, PhongLight, ShadingMaterial, shade } from '@shadelab/material';
import { SphereImpostor, SphereImpostorMaterial } from '@shadelab/material/impostor';
import { createOutline, OutlineMaterial } from '@shadelab/material/outline';
import {
  Color,
  Group,
  IcosahedronGeometry,
  type Material,
  Mesh,
  PerspectiveCamera,
  Scene,
  type Vector4,
  type WebGLRenderer,
} from 'three';
import { describe, expect, it } from 'vitest';

// Issue 13: a bare number in a light's Ia/Id/Is or a material's ka/kd/ks is a grey level (the lecture writes
// Ia = .2, Id = 1, Is = .8), never a hex colour. The rule: packages/material/README.md, "Colours and intensities".

const rgb = (c: Color): number[] => [c.r, c.g, c.b];

/** The one renderer method the materials call (the impostor reads the viewport). */
const renderer = { getCurrentViewport: (v: Vector4) => v.set(0, 0, 800, 800) } as unknown as WebGLRenderer;

/** What three does before a draw: update the matrices, then call the material's onBeforeRender. */
function draw(material: Material, mesh: Mesh, camera = new PerspectiveCamera(90, 1, 0.1, 10)): void {
  mesh.updateMatrixWorld();
  camera.position.set(0, 0, 3);
  camera.updateMatrixWorld();
  material.onBeforeRender(renderer, new Scene(), camera, mesh.geometry, mesh, new Group());
}

function sphere(): IcosahedronGeometry {
  const g = new IcosahedronGeometry(1, 1);
  g.deleteAttribute('normal');
  g.userData.isSphere = true;
  return g;
}

/** Every uniform of `material` as plain numbers, for exact comparison. */
function uniformNumbers(material: ShadingMaterial): Record<string, unknown> {
  const out: Record<string, unknown> = {};
  for (const [name, { value }] of Object.entries(material.uniforms)) {
    if (value instanceof Float32Array) out[name] = Array.from(value);
    else if (value !== null && typeof value === 'object' && 'toArray' in value) out[name] = value.toArray();
    else out[name] = value;
  }
  return out;
}

describe('a number is a grey level (lights and reflectances)', () => {
  it("new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 }) is the lecture's light", () => {
    const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
    expect(rgb(light.ambient)).toEqual([0.2, 0.2, 0.2]);
    expect(rgb(light.diffuse)).toEqual([1, 1, 1]);
    expect(rgb(light.specular)).toEqual([0.8, 0.8, 0.8]);
    // The same as the default light and as the [r, g, b] form.
    const tuple = new PhongLight({ ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [0.8, 0.8, 0.8] });
    for (const other of [new PhongLight(), tuple]) {
      expect(light.ambient.equals(other.ambient)).toBe(true);
      expect(light.diffuse.equals(other.diffuse)).toBe(true);
      expect(light.specular.equals(other.specular)).toBe(true);
    }
    light.diffuse = 0.5;
    expect(rgb(light.diffuse)).toEqual([0.5, 0.5, 0.5]);
    light.specular = 0; // no highlight
    expect(rgb(light.specular)).toEqual([0, 0, 0]);
    light.ambient = 3; // intensities above 1 are allowed (a bright light, or one made up for attenuation)
    expect(rgb(light.ambient)).toEqual([3, 3, 3]);
  });

  it('ka, kd, ks: 0.5 is (0.5, 0.5, 0.5), in ShadingMaterial and SphereImpostorMaterial alike', () => {
    for (const Material of [ShadingMaterial, SphereImpostorMaterial]) {
      const m = new Material({ ka: 0.5, kd: 0.25, ks: 1 });
      expect(rgb(m.ka)).toEqual([0.5, 0.5, 0.5]);
      expect(rgb(m.kd)).toEqual([0.25, 0.25, 0.25]);
      expect(rgb(m.ks)).toEqual([1, 1, 1]);
      m.ka = 0;
      m.kd = 0.75;
      m.ks = 2;
      expect([rgb(m.ka), rgb(m.kd), rgb(m.ks)]).toEqual([
        [0, 0, 0],
        [0.75, 0.75, 0.75],
        [2, 2, 2],
      ]);
    }
  });

  it('a grey number that is not finite or is negative is refused, naming the parameter, value and range', () => {
    const light = new PhongLight();
    const material = new ShadingMaterial();
    const cases: [string, (v: number) => void][] = [
      ['PhongLight.ambient', (v) => new PhongLight({ ambient: v })],
      ['PhongLight.diffuse', (v) => new PhongLight({ diffuse: v })],
      ['PhongLight.specular', (v) => new PhongLight({ specular: v })],
      ['PhongLight.diffuse', (v) => (light.diffuse = v)],
      ['ShadingMaterial.ka', (v) => new ShadingMaterial({ ka: v })],
      ['ShadingMaterial.kd', (v) => new ShadingMaterial({ kd: v })],
      ['ShadingMaterial.ks', (v) => new ShadingMaterial({ ks: v })],
      ['ShadingMaterial.ks', (v) => (material.ks = v)],
      ['ShadingMaterial.ka', (v) => new SphereImpostorMaterial({ ka: v })],
    ];
    for (const [name, set] of cases) {
      for (const v of [
        -1,
        -Number.MIN_VALUE,
        Number.NaN,
        Number.POSITIVE_INFINITY,
        Number.NEGATIVE_INFINITY,
        1e19,
      ]) {
        expect(() => set(v)).toThrow(
          new RangeError(
            `${name} as a number is a grey level (the same linear value on r, g and b) in 0 … 1e18, got ${v}`,
          ),
        );
      }
    }
    // A refused value changes nothing.
    expect(rgb(light.diffuse)).toEqual([1, 1, 1]);
    expect(rgb(material.ks)).toEqual([0.5, 0.5, 0.5]);
    // The largest grey accepted is the largest channel accepted.
    expect(rgb(new PhongLight({ diffuse: 1e18 }).diffuse)).toEqual([1e18, 1e18, 1e18]);
  });

  it('a CSS hex string is sRGB and a Color is copied (linear), as before', () => {
    const orange = new Color(0xff8000); // three: a hex number in a Color is sRGB, stored linear
    expect(orange.r).toBe(1);
    expect(orange.g).toBeCloseTo(0.2158605, 6); // sRGB 128/255 → linear
    expect(orange.b).toBe(0);
    const light = new PhongLight({ ambient: '#ff8000', diffuse: orange, specular: 'rgb(255, 128, 0)' });
    const material = new ShadingMaterial({ ka: '#ff8000', kd: new Color(0.25, 0.5, 1), ks: 'orange' });
    expect(light.ambient.equals(orange)).toBe(true);
    expect(light.diffuse.equals(orange)).toBe(true);
    expect(light.diffuse).not.toBe(orange); // copied
    expect(light.specular.equals(orange)).toBe(true);
    expect(material.ka.equals(orange)).toBe(true);
    expect(rgb(material.kd)).toEqual([0.25, 0.5, 1]);
    expect(material.ks.equals(new Color('orange'))).toBe(true);
    // A white CSS colour and the grey 1 are the same light.
    expect(
      new PhongLight({ diffuse: '#ffffff' }).diffuse.equals(new PhongLight({ diffuse: 1 }).diffuse),
    ).toBe(true);
  });

  it('renders the same uniforms as the [r, g, b] form, and they are the equation of shade()', () => {
    const grey = (v: number): [number, number, number] => [v, v, v];
    const scalarLight = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
    const tupleLight = new PhongLight({ ambient: grey(0.2), diffuse: grey(1), specular: grey(0.8) });
    for (const light of [scalarLight, tupleLight]) light.position.set(-5, 10, 20);
    const scalar = new ShadingMaterial({ ka: 0.5, kd: 0.7, ks: 0.3, lights: [scalarLight] });
    const tuple = new ShadingMaterial({ ka: grey(0.5), kd: grey(0.7), ks: grey(0.3), lights: [tupleLight] });
    draw(scalar, new Mesh(sphere(), scalar));
    draw(tuple, new Mesh(sphere(), tuple));
    expect(uniformNumbers(scalar)).toEqual(uniformNumbers(tuple));
    expect(scalar.defines).toEqual(tuple.defines);

    // The colour the uniforms give, against the CPU reference at two points of the unit sphere.
    const u = scalar.uniforms;
    const f32 = (name: string) => Array.from(u[name].value as Float32Array);
    const lightAt = [-5, 10, 20];
    const length = Math.hypot(...lightAt);
    const material = { ka: grey(0.5), kd: grey(0.7), ks: grey(0.3), shininess: 32 };
    const lights = [{ position: lightAt, ambient: grey(0.2), diffuse: grey(1), specular: grey(0.8) }];
    // Facing away from the light: ka·Ia only, the ambient uniform.
    const away = lightAt.map((c) => -c / length);
    const dark = shade({ position: away, normal: away, eye: [0, 0, 3] }, material, lights);
    f32('ambientTerm').forEach((c, i) => {
      expect(c).toBeCloseTo(dark[i], 6);
    });
    // Facing the light and seen along its direction (l = n = v = r): ka·Ia + kd·Id + ks·Is.
    const toward = lightAt.map((c) => c / length);
    const eye = toward.map((c) => 3 * c);
    const lit = shade({ position: toward, normal: toward, eye }, material, lights);
    const sum = [0, 1, 2].map(
      (i) => f32('ambientTerm')[i] + f32('lightDiffuse')[i] + f32('lightSpecular')[i],
    );
    sum.forEach((c, i) => {
      expect(c).toBeCloseTo(lit[i], 6);
    });
    expect(lit).toEqual([
      expect.closeTo(0.5 * 0.2 + 0.7 + 0.3 * 0.8, 12),
      expect.closeTo(0.5 * 0.2 + 0.7 + 0.3 * 0.8, 12),
      expect.closeTo(0.5 * 0.2 + 0.7 + 0.3 * 0.8, 12),
    ]);
  });

  it('the impostor material fills the same lighting uniforms from greys as from tuples', () => {
    const light = new PhongLight({ ambient: 0.2, diffuse: 1, specular: 0.8 });
    light.updateMatrixWorld();
    const scalar = new SphereImpostorMaterial({ ka: 0.5, kd: 0.7, ks: 0.3, lights: [light] });
    const tuple = new SphereImpostorMaterial({
      ka: [0.5, 0.5, 0.5],
      kd: [0.7, 0.7, 0.7],
      ks: [0.3, 0.3, 0.3],
      lights: [light],
    });
    draw(scalar, new SphereImpostor(scalar));
    draw(tuple, new SphereImpostor(tuple));
    expect(uniformNumbers(scalar)).toEqual(uniformNumbers(tuple));
  });
});

describe('the outline colour: a number is a grey level in 0 … 1', () => {
  it('0 is black, 1 white, 0.5 a linear grey; CSS strings are sRGB', () => {
    expect(rgb(new OutlineMaterial().color)).toEqual([0, 0, 0]);
    expect(rgb(new OutlineMaterial({ color: 0 }).color)).toEqual([0, 0, 0]);
    expect(rgb(new OutlineMaterial({ color: 1 }).color)).toEqual([1, 1, 1]);
    const m = new OutlineMaterial({ color: 0.5 });
    expect(rgb(m.color)).toEqual([0.5, 0.5, 0.5]);
    expect(m.uniforms.outlineColor.value.toArray()).toEqual([0.5, 0.5, 0.5]);
    // The playground's outline, '#f2f2f2', is exactly three's hex 0xf2f2f2.
    const mesh = new Mesh(sphere(), new ShadingMaterial());
    const outline = createOutline(mesh, { color: '#f2f2f2' });
    expect(outline.material.color.equals(new Color(0xf2f2f2))).toBe(true);
    expect(outline.material.color.equals(new Color().setHex(0xf2f2f2))).toBe(true);
  });

  it('a three-style hex number is refused with its CSS spelling, never read as a grey', () => {
    const m = new OutlineMaterial({ color: '#f2f2f2' });
    const before = rgb(m.color);
    expect(() => (m.color = 0xff8000)).toThrow(
      new RangeError(
        "OutlineMaterial.color as a number is a grey level (the same linear value on r, g and b) in 0 … 1 (a hex colour is written '#ff8000' or new Color(0xff8000)), got 16744448",
      ),
    );
    expect(() => new OutlineMaterial({ color: 0x0000ff })).toThrow(/'#0000ff' or new Color\(0x0000ff\)/);
    for (const v of [-0.5, 1.5, Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => new OutlineMaterial({ color: v })).toThrow(
        new RangeError(
          `OutlineMaterial.color as a number is a grey level (the same linear value on r, g and b) in 0 … 1, got ${v}`,
        ),
      );
    }
    expect(rgb(m.color)).toEqual(before);
  });
});

describe('shapes that are no colour input', () => {
  it('are refused with a TypeError naming the parameter and the accepted forms', () => {
    const forms = "a grey level (number), a CSS colour string ('#rrggbb'), a Color or linear [r, g, b]";
    const bad: unknown[] = [[1, 1], [1, 1, 1, 1], ['1', 1, 1], true, { r: 1 }, null, 1n];
    for (const value of bad) {
      const shown = Array.isArray(value)
        ? `[${value.map((v) => (typeof v === 'string' ? JSON.stringify(v) : String(v))).join(', ')}]`
        : String(value);
      expect(() => new PhongLight({ diffuse: value as ColorInput })).toThrow(
        new TypeError(`PhongLight.diffuse must be ${forms}, got ${shown}`),
      );
      expect(() => new ShadingMaterial({ kd: value as ColorInput })).toThrow(TypeError);
      expect(() => new OutlineMaterial({ color: value as ColorInput })).toThrow(TypeError);
    }
  });
});
