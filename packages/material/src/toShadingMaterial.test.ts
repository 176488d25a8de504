import { PhongLight, ShadingMaterial, toShadingMaterial } from '@shadelab/material';
import {
  AdditiveBlending,
  BackSide,
  Color,
  DataTexture,
  DoubleSide,
  GreaterDepth,
  LineBasicMaterial,
  type Material,
  MeshBasicMaterial,
  MeshDepthMaterial,
  MeshDistanceMaterial,
  MeshLambertMaterial,
  MeshMatcapMaterial,
  MeshNormalMaterial,
  MeshPhongMaterial,
  MeshPhysicalMaterial,
  MeshStandardMaterial,
  MeshToonMaterial,
  Plane,
  PointsMaterial,
  RawShaderMaterial,
  ShaderMaterial,
  ShadowMaterial,
  SpriteMaterial,
  Vector2,
  Vector3,
} from 'three';
import { describe, expect, it, vi } from 'vitest';

const texture = (width = 2) => new DataTexture(new Uint8Array(4 * width), width, 1);

/** Every common property set to a value other than its default, on `material`. */
function decorate<T extends Material>(material: T): T {
  const m = material as T & Record<string, unknown>;
  m.name = 'body';
  m.side = DoubleSide;
  m.shadowSide = BackSide;
  m.toneMapped = false;
  m.clippingPlanes = [new Plane(new Vector3(0, 1, 0), 0.5)];
  m.clipIntersection = true;
  m.clipShadows = true;
  m.depthTest = false;
  m.depthWrite = false;
  m.depthFunc = GreaterDepth;
  m.blending = AdditiveBlending;
  m.premultipliedAlpha = true;
  m.colorWrite = false;
  m.visible = false;
  m.polygonOffset = true;
  m.polygonOffsetFactor = 2;
  m.polygonOffsetUnits = 3;
  m.alphaToCoverage = true;
  m.dithering = true;
  m.opacity = 0.5;
  m.transparent = true;
  m.alphaTest = 0.25;
  m.vertexColors = true;
  if ('fog' in m) (m as unknown as { fog: boolean }).fog = false;
  return material;
}

/** The common properties came over (the clipping planes as the same array). */
function expectDecorated(made: ShadingMaterial, source: Material): void {
  expect(made.name).toBe('body');
  expect(made.side).toBe(DoubleSide);
  expect(made.shadowSide).toBe(BackSide);
  expect(made.toneMapped).toBe(false);
  expect(made.clippingPlanes).toBe(source.clippingPlanes);
  expect([made.clipIntersection, made.clipShadows, made.depthTest, made.depthWrite]).toEqual([
    true,
    true,
    false,
    false,
  ]);
  expect(made.depthFunc).toBe(GreaterDepth);
  expect(made.blending).toBe(AdditiveBlending);
  expect([made.premultipliedAlpha, made.colorWrite, made.visible]).toEqual([true, false, false]);
  expect([made.polygonOffset, made.polygonOffsetFactor, made.polygonOffsetUnits]).toEqual([true, 2, 3]);
  expect([made.alphaToCoverage, made.dithering]).toEqual([true, true]);
  expect([made.opacity, made.transparent, made.alphaTest, made.vertexColors]).toEqual([
    0.5,
    true,
    0.25,
    true,
  ]);
  expect(made.fog).toBe(false);
}

/** The surface maps of a lit material, set. */
function withMaps<
  T extends MeshLambertMaterial | MeshPhongMaterial | MeshStandardMaterial | MeshToonMaterial,
>(material: T) {
  const maps = { map: texture(), normalMap: texture(), emissiveMap: texture(), alphaMap: texture() };
  Object.assign(material, maps);
  material.normalScale.set(0.5, -2);
  material.emissive.setRGB(0.1, 0.2, 0.3);
  material.emissiveIntensity = 2;
  return { material, maps };
}

function expectMaps(made: ShadingMaterial, maps: Record<string, unknown>): void {
  expect(made.map).toBe(maps.map);
  expect(made.normalMap).toBe(maps.normalMap);
  expect(made.emissiveMap).toBe(maps.emissiveMap);
  expect(made.alphaMap).toBe(maps.alphaMap);
  expect(made.normalScale.toArray()).toEqual([0.5, -2]);
  expect(made.emissive.r).toBeCloseTo(0.2, 12);
  expect(made.emissive.g).toBeCloseTo(0.4, 12);
  expect(made.emissive.b).toBeCloseTo(0.6, 12);
}

const colour = new Color(0.5, 0.25, 0.125);

describe('toShadingMaterial: what each of three’s materials becomes, field by field', () => {
  it('MeshBasicMaterial: unlit, ka = kd = ks = 0, emissive = colour, emissiveMap = map (kept for its alpha)', () => {
    const map = texture();
    const source = decorate(new MeshBasicMaterial({ color: colour, map, alphaMap: texture() }));
    const made = toShadingMaterial(source);
    expect(made).toBeInstanceOf(ShadingMaterial);
    for (const k of [made.ka, made.kd, made.ks]) expect(k.toArray()).toEqual([0, 0, 0]);
    expect(made.emissive.equals(colour)).toBe(true);
    expect(made.emissive).not.toBe(source.color);
    expect(made.emissiveMap).toBe(map);
    expect(made.map).toBe(map);
    expect(made.alphaMap).toBe(source.alphaMap);
    expect(made.normalMap).toBeNull();
    expect([made.shading, made.celBands]).toEqual(['phong', 0]);
    expectDecorated(made, source);
  });

  it('MeshLambertMaterial: ka = kd = colour, ks = 0, maps and emissive × intensity', () => {
    const { material: source, maps } = withMaps(decorate(new MeshLambertMaterial({ color: colour })));
    const made = toShadingMaterial(source);
    expect(made.ka.equals(colour)).toBe(true);
    expect(made.kd.equals(colour)).toBe(true);
    expect(made.ks.toArray()).toEqual([0, 0, 0]);
    expect([made.shading, made.lighting, made.celBands]).toEqual(['phong', 'blinn-phong', 0]);
    expectMaps(made, maps);
    expectDecorated(made, source);
  });

  it('MeshPhongMaterial: ks = specular × (shininess + 2)/8, shininess, lighting blinn-phong (phong: shininess / 4)', () => {
    const { material: source, maps } = withMaps(
      decorate(new MeshPhongMaterial({ color: colour, shininess: 62, specular: new Color(0.2, 0.4, 0.8) })),
    );
    const made = toShadingMaterial(source);
    expect(made.ka.equals(colour)).toBe(true);
    expect(made.kd.equals(colour)).toBe(true);
    expect(made.shininess).toBe(62);
    expect(made.ks.r).toBeCloseTo(0.2 * 8, 12);
    expect(made.ks.g).toBeCloseTo(0.4 * 8, 12);
    expect(made.ks.b).toBeCloseTo(0.8 * 8, 12);
    expect(made.lighting).toBe('blinn-phong');
    expectMaps(made, maps);
    expectDecorated(made, source);
    const phong = toShadingMaterial(source, { lighting: 'phong' });
    expect([phong.lighting, phong.shininess]).toEqual(['phong', 62 / 4]);
    expect(phong.ks.equals(made.ks)).toBe(true);
  });

  it('MeshStandardMaterial: kd = colour × (1 − metalness) × 0.96, F0 = mix(0.04, colour, metalness) × (s + 2)/8', () => {
    const { material: source, maps } = withMaps(
      decorate(new MeshStandardMaterial({ color: colour, roughness: 0.5, metalness: 0.25 })),
    );
    const made = toShadingMaterial(source);
    const s = 2 / 0.25 ** 2 - 2; // α = 0.5² = 0.25: 30
    expect(made.shininess).toBeCloseTo(s, 12);
    expect(toShadingMaterial(source, { lighting: 'phong' }).shininess).toBeCloseTo(s / 4, 12);
    const channels = colour.toArray();
    made.kd.toArray().forEach((c, i) => {
      expect(c).toBeCloseTo(channels[i] * 0.75 * 0.96, 12);
    });
    expect(made.ka.equals(made.kd)).toBe(true);
    made.ks.toArray().forEach((c, i) => {
      expect(c).toBeCloseTo((0.04 * 0.75 + channels[i] * 0.25) * ((s + 2) / 8), 12);
    });
    expectMaps(made, maps);
    expectDecorated(made, source);
  });

  it('MeshStandardMaterial: metalness 1 has no diffuse; roughness below three’s 0.045 is clamped', () => {
    const made = toShadingMaterial(new MeshStandardMaterial({ color: colour, roughness: 0, metalness: 1 }));
    expect(made.kd.toArray()).toEqual([0, 0, 0]);
    const alpha = 0.045 ** 2;
    expect(made.shininess).toBeCloseTo(2 / alpha ** 2 - 2, 6);
    expect(made.ks.r).toBeCloseTo(colour.r / (4 * alpha ** 2), 6);
  });

  it('MeshPhysicalMaterial: the standard rule with F0 from ior × specularColor × specularIntensity', () => {
    const { material: source, maps } = withMaps(
      decorate(new MeshPhysicalMaterial({ color: colour, roughness: 1, metalness: 0, ior: 1.5 })),
    );
    const made = toShadingMaterial(source);
    expect(made.shininess).toBe(0);
    expect(made.ks.r).toBeCloseTo(0.04 / 4, 12);
    expect(made.kd.r).toBeCloseTo(colour.r * 0.96, 12);
    expectMaps(made, maps);
    expectDecorated(made, source);
  });

  it('MeshToonMaterial: cel bands from the gradient map’s width, 2 without one; ks = 0', () => {
    const { material: source, maps } = withMaps(decorate(new MeshToonMaterial({ color: colour })));
    const made = toShadingMaterial(source);
    expect(made.celBands).toBe(2);
    expect(made.ks.toArray()).toEqual([0, 0, 0]);
    expect(made.kd.equals(colour)).toBe(true);
    expectMaps(made, maps);
    expectDecorated(made, source);
    expect(toShadingMaterial(new MeshToonMaterial({ gradientMap: texture(3) })).celBands).toBe(3);
    expect(toShadingMaterial(new MeshToonMaterial({ gradientMap: texture(5) })).celBands).toBe(5);
  });

  it('flatShading → shading flat', () => {
    expect(toShadingMaterial(new MeshLambertMaterial({ flatShading: true })).shading).toBe('flat');
    expect(toShadingMaterial(new MeshStandardMaterial({ flatShading: true })).shading).toBe('flat');
  });

  it('the source is neither changed nor disposed', () => {
    const source = new MeshPhongMaterial({ color: colour, map: texture() });
    const before = JSON.stringify(source.toJSON());
    const dispose = vi.fn();
    source.addEventListener('dispose', dispose);
    const made = toShadingMaterial(source);
    made.dispose();
    expect(JSON.stringify(source.toJSON())).toBe(before);
    expect(dispose).not.toHaveBeenCalled();
  });
});

describe('toShadingMaterial options', () => {
  it('override what was carried over; undefined entries are ignored', () => {
    const light = new PhongLight();
    const made = toShadingMaterial(new MeshPhongMaterial({ color: colour, flatShading: true }), {
      shading: 'gouraud',
      lighting: 'phong',
      celBands: 4,
      ks: 0.25,
      shininess: undefined,
      lights: [light],
      normalScale: new Vector2(3, 3),
    });
    expect([made.shading, made.lighting, made.celBands, made.shininess]).toEqual([
      'gouraud',
      'phong',
      4,
      30 / 4,
    ]);
    expect(made.ks.toArray()).toEqual([0.25, 0.25, 0.25]);
    expect(made.phongLights).toEqual([light]);
    expect(made.normalScale.toArray()).toEqual([3, 3]);
    expect(made.kd.equals(colour)).toBe(true);
  });
});

describe('toShadingMaterial refuses what does not convert, naming it', () => {
  it('not a Material: a TypeError naming the parameter', () => {
    for (const bad of [null, undefined, 3, {}, 'MeshBasicMaterial', new Color()]) {
      expect(() => toShadingMaterial(bad as never)).toThrow(
        /toShadingMaterial: material must be a THREE\.Material/,
      );
      expect(() => toShadingMaterial(bad as never)).toThrow(TypeError);
    }
  });

  it('other materials: a TypeError naming the material’s type', () => {
    const others: Material[] = [
      new ShaderMaterial(),
      new RawShaderMaterial(),
      new MeshNormalMaterial(),
      new MeshDepthMaterial(),
      new MeshDistanceMaterial(),
      new MeshMatcapMaterial(),
      new PointsMaterial(),
      new LineBasicMaterial(),
      new SpriteMaterial(),
      new ShadowMaterial(),
      new ShadingMaterial(),
    ];
    for (const material of others) {
      expect(() => toShadingMaterial(material)).toThrow(TypeError);
      expect(() => toShadingMaterial(material)).toThrow(new RegExp(`material ${material.type}`));
    }
  });

  it('bad options: TypeError or RangeError naming the option', () => {
    const source = new MeshLambertMaterial();
    expect(() => toShadingMaterial(source, 3 as never)).toThrow(
      /toShadingMaterial: options must be an options object/,
    );
    expect(() => toShadingMaterial(source, { celBands: 1 })).toThrow(RangeError);
    expect(() => toShadingMaterial(source, { celBands: 1 })).toThrow(/celBands/);
    expect(() => toShadingMaterial(source, { shading: 'smooth' as never })).toThrow(/shading/);
    expect(() => toShadingMaterial(source, { opacity: 2 })).toThrow(/opacity must be in 0 … 1/);
  });

  it('a carried-over value out of range: the RangeError naming it', () => {
    const source = new MeshLambertMaterial();
    source.opacity = 1.5;
    expect(() => toShadingMaterial(source)).toThrow(/opacity must be in 0 … 1, got 1.5/);
    const negative = new MeshPhongMaterial();
    negative.color.setRGB(-1, 0, 0);
    expect(() => toShadingMaterial(negative)).toThrow(/ShadingMaterial\.ka/);
  });
});
