/**
 * A texture's value at a probed pixel, read on the CPU from the texture's own pixels as WebGL samples it: the
 * uv transform (`texture.matrix`), the rows in upload order (`flipY`), the wrap modes, sRGB decoding before
 * filtering, and the filter for the pixel's level of detail (from the uv's change across one pixel), with the
 * mipmap levels made as the GPU makes them (each the 2 × 2 mean of the one above, in linear, stored in the
 * texture's 8-bit format). What it cannot reproduce (a pixel at the switch between two filters, anisotropic
 * filtering, mipmaps of a texture whose sides are not powers of two, or given with the texture) the result
 * says, instead of a value.
 */
import * as THREE from 'three';

export type V4 = [number, number, number, number];

/** A texture sample: its value (linear RGBA, or raw for a non-colour texture), or why it was not computed. */
export type TexelRead = { readonly value: V4 } | { readonly reason: string };

interface Pixels {
  readonly data: ArrayLike<number>;
  readonly width: number;
  readonly height: number;
}

/** |log2 ρ| below this is too near the switch between the magnification and minification filters to call. */
const LOD_MARGIN = 0.05;
/** A texel coordinate this near a texel boundary (in texels: twice a GPU's 1/256 sub-texel step) is a tie. */
const SUBTEXEL = 1 / 128;

/** Each texture's pixels, read again when its image, `flipY` or version (a `needsUpdate`) changes. */
const cache = new WeakMap<
  THREE.Texture,
  { image: unknown; flipY: boolean; version: number; pixels: Pixels | null }
>();

/** The texture's RGBA bytes, rows in the order WebGL uploads them (row 0 is v = 0); null when unreadable. */
function pixelsOf(texture: THREE.Texture): Pixels | null {
  const image = texture.image as
    | { data?: ArrayLike<number>; width?: number; height?: number }
    | CanvasImageSource
    | null;
  if (!image || typeof image !== 'object') return null;
  const cached = cache.get(texture);
  if (
    cached &&
    cached.image === image &&
    cached.flipY === texture.flipY &&
    cached.version === texture.version
  )
    return cached.pixels;
  let read: Pixels | null = null;
  const { width, height } = image as { width?: number; height?: number };
  if (typeof width === 'number' && typeof height === 'number' && width > 0 && height > 0) {
    const data = (image as { data?: ArrayLike<number> }).data;
    if (data) {
      const bytes = data instanceof Uint8Array || data instanceof Uint8ClampedArray;
      if (bytes && texture.format === THREE.RGBAFormat && data.length === width * height * 4)
        read = { data, width, height };
    } else if (typeof OffscreenCanvas !== 'undefined') {
      const canvas = new OffscreenCanvas(width, height);
      const context = canvas.getContext('2d', { colorSpace: 'srgb' });
      if (context) {
        context.drawImage(image as CanvasImageSource, 0, 0);
        // A decoded image's rows run top to bottom: WebGL uploads the top row as v = 0 unless flipped.
        const top = context.getImageData(0, 0, width, height).data;
        read = { data: top, width, height };
      }
    }
    if (read && texture.flipY) {
      const source = read.data;
      const flipped = new Uint8Array(source.length);
      const row = width * 4;
      for (let y = 0; y < height; y++)
        for (let k = 0; k < row; k++) flipped[y * row + k] = source[(height - 1 - y) * row + k]!;
      read = { data: flipped, width, height };
    }
  }
  cache.set(texture, { image, flipY: texture.flipY, version: texture.version, pixels: read });
  return read;
}

function wrap(i: number, size: number, mode: THREE.Wrapping): number {
  if (mode === THREE.ClampToEdgeWrapping) return Math.min(Math.max(i, 0), size - 1);
  if (mode === THREE.MirroredRepeatWrapping) {
    const period = ((i % (2 * size)) + 2 * size) % (2 * size);
    return period < size ? period : 2 * size - 1 - period;
  }
  return ((i % size) + size) % size;
}

const srgbDecode = (c: number) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
const srgbEncode = (c: number) => (c <= 0.0031308 ? c * 12.92 : 1.055 * c ** (1 / 2.4) - 0.055);
const isPowerOfTwo = (n: number) => (n & (n - 1)) === 0;

const levelsCache = new WeakMap<Pixels, Pixels[]>();

/** The mipmap chain from `base` down to 1 × 1: each level the 2 × 2 mean of the one above, stored in 8 bits. */
function levelsOf(base: Pixels, srgb: boolean): Pixels[] {
  const cached = levelsCache.get(base);
  if (cached) return cached;
  const levels = [base];
  for (let above = base; above.width > 1 || above.height > 1; ) {
    const width = Math.max(above.width >> 1, 1);
    const height = Math.max(above.height >> 1, 1);
    const data = new Uint8Array(width * height * 4);
    for (let y = 0; y < height; y++)
      for (let x = 0; x < width; x++)
        for (let k = 0; k < 4; k++) {
          let sum = 0;
          for (const [dx, dy] of [
            [0, 0],
            [1, 0],
            [0, 1],
            [1, 1],
          ] as const) {
            const sx = Math.min(2 * x + dx, above.width - 1);
            const sy = Math.min(2 * y + dy, above.height - 1);
            const c = above.data[4 * (sy * above.width + sx) + k]! / 255;
            sum += srgb && k < 3 ? srgbDecode(c) : c;
          }
          const mean = sum / 4;
          data[4 * (y * width + x) + k] = Math.round((srgb && k < 3 ? srgbEncode(mean) : mean) * 255);
        }
    above = { data, width, height };
    levels.push(above);
  }
  levelsCache.set(base, levels);
  return levels;
}

const MIPMAP_FILTERS = new Set<THREE.TextureFilter>([
  THREE.NearestMipmapNearestFilter,
  THREE.NearestMipmapLinearFilter,
  THREE.LinearMipmapNearestFilter,
  THREE.LinearMipmapLinearFilter,
]);

/** The uv the texture samples at a surface uv: its transform applied (three's `mapTransform`). */
export function transformedUv(texture: THREE.Texture, uv: THREE.Vector2): THREE.Vector2 {
  if (texture.matrixAutoUpdate) texture.updateMatrix();
  return uv.clone().applyMatrix3(texture.matrix);
}

/**
 * The texture at `uv` (already transformed) for a pixel whose uv changes by `dx` and `dy` (transformed) to its
 * right and upper neighbours.
 */
export function sampleTexture(
  texture: THREE.Texture,
  uv: THREE.Vector2,
  dx: THREE.Vector2,
  dy: THREE.Vector2,
): TexelRead {
  const pixels = pixelsOf(texture);
  if (!pixels) return { reason: 'its pixels cannot be read here (not an image or RGBA bytes)' };
  const { width, height } = pixels;
  const rho = Math.max(Math.hypot(dx.x * width, dx.y * height), Math.hypot(dy.x * width, dy.y * height));
  const lod = Math.log2(rho);
  const magnified = lod <= 0;
  const filter = magnified ? texture.magFilter : texture.minFilter;
  if (Math.abs(lod) < LOD_MARGIN && texture.magFilter !== texture.minFilter)
    return { reason: 'the pixel is at the switch between its magnification and minification filters' };
  if (!magnified && texture.anisotropy > 1)
    return { reason: 'it is minified here with anisotropic filtering' };
  const decode = texture.colorSpace === THREE.SRGBColorSpace;
  const texel = (level: Pixels, i: number, j: number): V4 => {
    const at = 4 * (wrap(j, level.height, texture.wrapT) * level.width + wrap(i, level.width, texture.wrapS));
    const c = [0, 1, 2, 3].map((k) => level.data[at + k]! / 255);
    return (decode ? [srgbDecode(c[0]!), srgbDecode(c[1]!), srgbDecode(c[2]!), c[3]!] : c) as V4;
  };
  // Nearest filtering at a texel boundary (null): a tie that the GPU's sub-texel precision breaks.
  const sampleLevel = (level: Pixels, linear: boolean): V4 | null => {
    const s = uv.x * level.width;
    const t = uv.y * level.height;
    if (!linear) {
      const fraction = (x: number) => x - Math.floor(x);
      const edge = (x: number) => Math.min(fraction(x), 1 - fraction(x)) < SUBTEXEL;
      return edge(s) || edge(t) ? null : texel(level, Math.floor(s), Math.floor(t));
    }
    const [i, j] = [Math.floor(s - 0.5), Math.floor(t - 0.5)];
    const [a, b] = [s - 0.5 - i, t - 0.5 - j];
    const [t00, t10, t01, t11] = [
      texel(level, i, j),
      texel(level, i + 1, j),
      texel(level, i, j + 1),
      texel(level, i + 1, j + 1),
    ];
    return t00.map(
      (_, k) => (1 - b) * ((1 - a) * t00[k]! + a * t10[k]!) + b * ((1 - a) * t01[k]! + a * t11[k]!),
    ) as V4;
  };
  const sampled = (value: V4 | null): TexelRead =>
    value
      ? { value }
      : { reason: 'the pixel is on a texel boundary, which nearest filtering breaks either way' };
  if (magnified || !MIPMAP_FILTERS.has(filter))
    return sampled(sampleLevel(pixels, filter !== THREE.NearestFilter));
  if (texture.mipmaps.length > 0 || !texture.generateMipmaps)
    return { reason: 'it is minified here, with mipmap levels the probe does not have' };
  if (!isPowerOfTwo(width) || !isPowerOfTwo(height))
    return { reason: 'it is minified here, and its sides are not powers of two (mipmaps made by the GPU)' };
  const levels = levelsOf(pixels, decode);
  const d = Math.min(lod, levels.length - 1);
  const linear = filter === THREE.LinearMipmapLinearFilter || filter === THREE.LinearMipmapNearestFilter;
  if (filter === THREE.NearestMipmapNearestFilter || filter === THREE.LinearMipmapNearestFilter) {
    if (Math.abs(d - Math.floor(d) - 0.5) < LOD_MARGIN)
      return { reason: 'the pixel is at the switch between two mipmap levels' };
    return sampled(sampleLevel(levels[Math.min(Math.round(d), levels.length - 1)]!, linear));
  }
  const upper = Math.floor(d);
  const lower = Math.min(upper + 1, levels.length - 1);
  const f = d - upper;
  const [p, q] = [sampleLevel(levels[upper]!, linear), sampleLevel(levels[lower]!, linear)];
  return sampled(p && q ? (p.map((x, k) => (1 - f) * x + f * q[k]!) as V4) : null);
}
