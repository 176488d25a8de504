// Internal: the data textures through which flat shading's vertex shader reads the three vertices of its
// triangle: their positions (a triangle soup), and for a SkinnedMesh their skin indices and weights. One
// texture per geometry and kind, shared by every material and mesh that draws it, rebuilt when the attributes
// change, freed when the geometry is disposed.
import { type BufferGeometry, DataTexture, FloatType, NearestFilter, RGBAFormat, RGBFormat } from 'three';

/** Texels per row of the face textures (WebGL2 guarantees at least 2048). */
export const FACE_TEXTURE_WIDTH = 2048;

interface Entry {
  texture: DataTexture;
  versions: string;
  attributes: unknown[];
}

const cache = /* @__PURE__ */ new WeakMap<BufferGeometry, Map<string, Entry>>();

/**
 * The texture of `names` (attributes of `geometry`) for kind `key`: vertex i's attributes at texels
 * (k·i + j) for j < k = names.length, `components` floats each, rows of 2048 texels.
 */
function vertexTexture(geometry: BufferGeometry, key: string, names: readonly string[], components: 3 | 4) {
  const attributes = names.map((name) => geometry.getAttribute(name));
  let entries = cache.get(geometry);
  const entry = entries?.get(key);
  const versions = attributes.map((a) => ('version' in a ? a.version : 0)).join();
  if (entry?.versions === versions && entry.attributes.every((a, i) => a === attributes[i]))
    return entry.texture;
  const k = names.length;
  const count = attributes[0].count;
  const width = FACE_TEXTURE_WIDTH;
  const height = Math.max(1, Math.ceil((k * count) / width));
  const data = new Float32Array(width * height * components);
  for (let i = 0; i < count; i++) {
    for (let j = 0; j < k; j++) {
      const a = attributes[j];
      const o = (k * i + j) * components;
      data[o] = a.getX(i);
      data[o + 1] = a.getY(i);
      data[o + 2] = a.getZ(i);
      if (components === 4) data[o + 3] = a.getW(i);
    }
  }
  entry?.texture.dispose();
  const texture = new DataTexture(data, width, height, components === 3 ? RGBFormat : RGBAFormat, FloatType);
  texture.internalFormat = components === 3 ? 'RGB32F' : 'RGBA32F';
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  if (entries === undefined) {
    const created = new Map<string, Entry>();
    entries = created;
    cache.set(geometry, created);
    geometry.addEventListener('dispose', () => {
      for (const e of created.values()) e.texture.dispose();
      cache.delete(geometry);
    });
  }
  entries.set(key, { texture, versions, attributes });
  return texture;
}

/**
 * The object-space positions of `geometry`, vertex i at texel (i mod 2048, ⌊i / 2048⌋), RGB32F:
 * 12 bytes per vertex on the GPU (rows padded to 2048 texels), the same as the position attribute.
 */
export function facePositionTexture(geometry: BufferGeometry): DataTexture {
  return vertexTexture(geometry, 'position', ['position'], 3);
}

/**
 * The skin indices and weights of `geometry` (a SkinnedMesh's `skinIndex` and `skinWeight`), vertex i at
 * texels 2i and 2i + 1, RGBA32F: 32 bytes per vertex, so flat shading can skin a face's other corners.
 * @throws TypeError when the geometry has no `skinIndex` or `skinWeight` attribute.
 */
export function faceSkinTexture(geometry: BufferGeometry): DataTexture {
  if (geometry.getAttribute('skinIndex') === undefined || geometry.getAttribute('skinWeight') === undefined) {
    throw new TypeError(
      `ShadingMaterial: a SkinnedMesh needs skinIndex and skinWeight attributes on its ${geometry.type}`,
    );
  }
  return vertexTexture(geometry, 'skin', ['skinIndex', 'skinWeight'], 4);
}
