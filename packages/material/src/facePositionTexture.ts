// Internal: the data texture through which flat shading's vertex shader reads the three vertices of its
// triangle. One texture per geometry, shared by every material and mesh that draws it, rebuilt when the
// position attribute changes, freed when the geometry is disposed.
import { type BufferGeometry, DataTexture, FloatType, NearestFilter, RGBFormat } from 'three';

/** Texels per row of the face-position texture (WebGL2 guarantees at least 2048). */
export const FACE_TEXTURE_WIDTH = 2048;

interface Entry {
  texture: DataTexture;
  version: number;
  attribute: unknown;
}

const cache = /* @__PURE__ */ new WeakMap<BufferGeometry, Entry>();

/**
 * The object-space positions of `geometry`, vertex i at texel (i mod 2048, ⌊i / 2048⌋), RGB32F:
 * 12 bytes per vertex on the GPU (rows padded to 2048 texels), the same as the position attribute.
 */
export function facePositionTexture(geometry: BufferGeometry): DataTexture {
  const position = geometry.getAttribute('position');
  const entry = cache.get(geometry);
  const version = 'version' in position ? (position.version as number) : 0;
  if (entry !== undefined && entry.attribute === position && entry.version === version) return entry.texture;
  const count = position.count;
  const width = FACE_TEXTURE_WIDTH;
  const height = Math.max(1, Math.ceil(count / width));
  const data = new Float32Array(width * height * 3);
  for (let i = 0; i < count; i++) {
    data[3 * i] = position.getX(i);
    data[3 * i + 1] = position.getY(i);
    data[3 * i + 2] = position.getZ(i);
  }
  if (entry !== undefined) entry.texture.dispose();
  const texture = new DataTexture(data, width, height, RGBFormat, FloatType);
  texture.internalFormat = 'RGB32F';
  texture.minFilter = NearestFilter;
  texture.magFilter = NearestFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.needsUpdate = true;
  if (entry === undefined) {
    geometry.addEventListener('dispose', () => {
      cache.get(geometry)?.texture.dispose();
      cache.delete(geometry);
    });
  }
  cache.set(geometry, { texture, version, attribute: position });
  return texture;
}
