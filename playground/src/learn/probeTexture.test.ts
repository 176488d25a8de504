import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { sampleTexture, transformedUv } from './probeTexture';

/** A 2 × 2 RGBA texture: red, green in row 0 (v = 0), blue, white in row 1. */
function texture(options: Partial<THREE.Texture> = {}): THREE.DataTexture {
  const data = new Uint8Array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255]);
  const t = new THREE.DataTexture(data, 2, 2);
  Object.assign(t, { magFilter: THREE.NearestFilter, minFilter: THREE.NearestFilter, ...options });
  return t;
}

const tiny = new THREE.Vector2(1e-3, 0);
const tinyY = new THREE.Vector2(0, 1e-3);
const at = (t: THREE.Texture, u: number, v: number, d = [tiny, tinyY]) =>
  sampleTexture(t, new THREE.Vector2(u, v), d[0]!, d[1]!);
const value = (read: ReturnType<typeof sampleTexture>) => {
  if (!('value' in read)) throw new Error(read.reason);
  return read.value.map((x) => Math.round(x * 1e6) / 1e6);
};

describe('sampleTexture (the probe reads a texel as WebGL samples it)', () => {
  it('nearest: row 0 is v = 0; flipY uploads the rows the other way round', () => {
    expect(value(at(texture(), 0.25, 0.25))).toEqual([1, 0, 0, 1]);
    expect(value(at(texture(), 0.75, 0.75))).toEqual([1, 1, 1, 1]);
    expect(value(at(texture({ flipY: true }), 0.25, 0.25))).toEqual([0, 0, 1, 1]);
  });

  it('reads the pixels again after needsUpdate or a change of flipY', () => {
    const t = texture();
    expect(value(at(t, 0.25, 0.25))).toEqual([1, 0, 0, 1]);
    (t.image.data as Uint8Array).set([0, 0, 0, 255], 0);
    t.needsUpdate = true;
    expect(value(at(t, 0.25, 0.25))).toEqual([0, 0, 0, 1]);
    t.flipY = true;
    expect(value(at(t, 0.25, 0.25))).toEqual([0, 0, 1, 1]);
  });

  it('linear: bilinear between texel centres; repeat wraps, clamp holds the edge', () => {
    const linear = { magFilter: THREE.LinearFilter };
    expect(value(at(texture(linear), 0.5, 0.25))).toEqual([0.5, 0.5, 0, 1]);
    expect(value(at(texture({ ...linear, wrapS: THREE.RepeatWrapping }), 0, 0.25))).toEqual([0.5, 0.5, 0, 1]);
    expect(value(at(texture({ ...linear, wrapS: THREE.ClampToEdgeWrapping }), 0, 0.25))).toEqual([
      1, 0, 0, 1,
    ]);
  });

  it('an sRGB texture is decoded before it is filtered', () => {
    const read = value(
      at(texture({ magFilter: THREE.LinearFilter, colorSpace: THREE.SRGBColorSpace }), 0.5, 0.25),
    );
    expect(read).toEqual([0.5, 0.5, 0, 1]);
  });

  it('minified with mipmaps: the levels below are 2 × 2 means; trilinear between two levels', () => {
    const mipmapped = texture({ minFilter: THREE.LinearMipmapLinearFilter, generateMipmaps: true });
    const oneTexel = [new THREE.Vector2(1, 0), new THREE.Vector2(0, 1)]; // λ = log2(2) = 1: level 1
    // Level 1 holds one texel, the mean of the four, stored in 8 bits: round(127.5) = 128 on red, green, blue.
    const mean = Math.round(127.5) / 255;
    expect(value(at(mipmapped, 0.3, 0.7, oneTexel))).toEqual(
      [mean, mean, mean, 1].map((x) => Math.round(x * 1e6) / 1e6),
    );
    const halfway = [new THREE.Vector2(Math.SQRT2 / 2, 0), new THREE.Vector2(0, Math.SQRT2 / 2)]; // λ = 0.5
    const blended = value(at(mipmapped, 0.25, 0.25, halfway));
    // Level 0 at (0.25, 0.25) with its neighbours is bilinear at a texel centre: red; half of it, half the mean.
    expect(blended[0]).toBeCloseTo(0.5 * 1 + 0.5 * mean, 6);
    expect(blended[2]).toBeCloseTo(0.5 * mean, 6);
  });

  it('says what it cannot reproduce', () => {
    const minified = [new THREE.Vector2(1, 0), new THREE.Vector2(0, 1)];
    const anisotropic = texture({ minFilter: THREE.LinearMipmapLinearFilter, anisotropy: 4 });
    expect(at(anisotropic, 0.5, 0.5, minified)).toEqual({ reason: expect.stringMatching(/anisotropic/) });
    const given = texture({ minFilter: THREE.LinearMipmapLinearFilter, generateMipmaps: false });
    expect(at(given, 0.5, 0.5, minified)).toEqual({ reason: expect.stringMatching(/mipmap levels/) });
    const edge = [new THREE.Vector2(0.5, 0), new THREE.Vector2(0, 0.5)]; // λ = 0: the switch
    expect(at(texture({ minFilter: THREE.LinearFilter }), 0.5, 0.5, edge)).toEqual({
      reason: expect.stringMatching(/switch/),
    });
    expect(at(texture(), 0.5 + 1e-4, 0.25)).toEqual({ reason: expect.stringMatching(/texel boundary/) });
    expect(sampleTexture(new THREE.Texture(), new THREE.Vector2(), tiny, tinyY)).toEqual({
      reason: expect.stringMatching(/cannot be read/),
    });
  });

  it("the uv is transformed by the texture's offset, repeat and rotation (three's mapTransform)", () => {
    const t = texture();
    t.repeat.set(2, 3);
    t.offset.set(0.1, 0.2);
    const uv = transformedUv(t, new THREE.Vector2(0.25, 0.5));
    expect(uv.x).toBeCloseTo(0.6, 12);
    expect(uv.y).toBeCloseTo(1.7, 12);
  });
});
