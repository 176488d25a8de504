// Compressed copies of a GLB, made in node for tests/playground-model.spec.ts: the same model with its meshes
// compressed by Draco (KHR_draco_mesh_compression, Google's encoder from the draco3dgltf package) or its PNG
// textures re-encoded as KTX2 / Basis Universal UASTC (KHR_texture_basisu, the ktx2-encoder package's Basis
// encoder), written with glTF Transform. Both extensions are required in the output: a viewer without the decoder
// cannot draw the file.
import { inflateSync } from 'node:zlib';
import { type Document, NodeIO, Primitive } from '@gltf-transform/core';
import { KHRDracoMeshCompression, KHRTextureBasisu } from '@gltf-transform/extensions';
import draco3d from 'draco3dgltf';
import { encodeToKTX2 } from 'ktx2-encoder';

/** Draco's quantization for the copy: bits per component of each attribute kind (the encoder's defaults are 14,
 * 10, 8, 12, 12); fine enough that the compressed model draws as the original within a few levels. */
const DRACO_BITS = { POSITION: 16, NORMAL: 12, COLOR: 10, TEX_COORD: 14, GENERIC: 14 };

async function io(): Promise<NodeIO> {
  return new NodeIO()
    .registerExtensions([KHRDracoMeshCompression, KHRTextureBasisu])
    .registerDependencies({ 'draco3d.encoder': await draco3d.createEncoderModule() });
}

/**
 * The GLB with every triangle primitive Draco-compressed (edgebreaker, {@link DRACO_BITS}). Draco compresses
 * indexed triangles only: a primitive without indices (what three's exporter writes for a non-indexed geometry)
 * is indexed first, its equal vertices merged ({@link weld}).
 */
export async function dracoGlb(glb: Buffer): Promise<Buffer> {
  const writer = await io();
  const document = await writer.readBinary(new Uint8Array(glb));
  for (const mesh of document.getRoot().listMeshes())
    for (const primitive of mesh.listPrimitives())
      if (primitive.getMode() === Primitive.Mode.TRIANGLES && !primitive.getIndices())
        weld(document, primitive);
  document.createExtension(KHRDracoMeshCompression).setRequired(true).setEncoderOptions({
    method: KHRDracoMeshCompression.EncoderMethod.EDGEBREAKER,
    quantizationBits: DRACO_BITS,
  });
  return Buffer.from(await writer.writeBinary(document));
}

/** Gives a non-indexed primitive an index: vertices equal in every attribute become one. */
function weld(document: Document, primitive: Primitive): void {
  const attributes = primitive.listAttributes();
  const count = attributes[0]!.getCount();
  const first = new Map<string, number>();
  const kept: number[] = [];
  const index = new Uint32Array(count);
  for (let i = 0; i < count; i++) {
    const key = attributes.map((a) => a.getElement(i, []).join(',')).join('|');
    let at = first.get(key);
    if (at === undefined) {
      at = kept.length;
      first.set(key, at);
      kept.push(i);
    }
    index[i] = at;
  }
  for (const attribute of attributes) {
    const size = attribute.getElementSize();
    const source = attribute.getArray()!;
    const array = new (source.constructor as new (n: number) => typeof source)(kept.length * size);
    kept.forEach((from, to) => {
      for (let k = 0; k < size; k++) array[to * size + k] = source[from * size + k]!;
    });
    attribute.setArray(array);
  }
  const buffer = document.getRoot().listBuffers()[0]!;
  const indices = document.createAccessor().setType('SCALAR').setBuffer(buffer);
  primitive.setIndices(indices.setArray(kept.length > 65535 ? index : Uint16Array.from(index)));
}

/**
 * The GLB with every PNG texture re-encoded as a KTX2 file of Basis UASTC blocks (Zstandard-supercompressed, with
 * mipmaps, sRGB as a base colour map is): what `toktx --uastc` or glTF Transform's `uastc` writes.
 */
export async function ktx2Glb(glb: Buffer): Promise<Buffer> {
  const writer = await io();
  const document: Document = await writer.readBinary(new Uint8Array(glb));
  const textures = document.getRoot().listTextures();
  if (!textures.some((t) => t.getMimeType() === 'image/png')) throw new TypeError('ktx2Glb: no PNG texture');
  for (const texture of textures) {
    if (texture.getMimeType() !== 'image/png') continue;
    const image = texture.getImage()!;
    const ktx2 = await encodeToKTX2(image, {
      isUASTC: true,
      generateMipmap: true,
      imageDecoder: async (png: Uint8Array) => decodePng(png),
    });
    texture.setImage(ktx2).setMimeType('image/ktx2');
    texture.setURI(texture.getURI().replace(/\.png$/, '.ktx2'));
  }
  document.createExtension(KHRTextureBasisu).setRequired(true);
  return Buffer.from(await writer.writeBinary(document));
}

/** An 8-bit RGB or RGBA, non-interlaced PNG's pixels as RGBA rows from the top (what three's exporter writes). */
export function decodePng(png: Uint8Array): { data: Uint8Array; width: number; height: number } {
  const bytes = Buffer.from(png.buffer, png.byteOffset, png.byteLength);
  let width = 0;
  let height = 0;
  let channels = 0;
  const idat: Buffer[] = [];
  for (let at = 8; at < bytes.length; ) {
    const length = bytes.readUInt32BE(at);
    const type = bytes.toString('latin1', at + 4, at + 8);
    const body = bytes.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      const [depth, colour, , , interlace] = body.subarray(8, 13);
      channels = colour === 6 ? 4 : colour === 2 ? 3 : 0;
      if (depth !== 8 || channels === 0 || interlace !== 0)
        throw new TypeError(`decodePng: only 8-bit RGB(A) non-interlaced (depth ${depth}, colour ${colour})`);
    } else if (type === 'IDAT') idat.push(body);
    at += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const rows = new Uint8Array(height * stride);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)]!;
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? rows[y * stride + x - channels]! : 0;
      const b = y > 0 ? rows[(y - 1) * stride + x]! : 0;
      const c = x >= channels && y > 0 ? rows[(y - 1) * stride + x - channels]! : 0;
      const p = a + b - c;
      const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - c)];
      const predictor = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
      if (predictor === undefined) throw new TypeError(`decodePng: filter ${filter}`);
      rows[y * stride + x] = (line[x]! + predictor) & 0xff;
    }
  }
  const data = new Uint8Array(width * height * 4).fill(255);
  for (let i = 0; i < width * height; i++)
    data.set(rows.subarray(i * channels, i * channels + channels), i * 4);
  return { data, width, height };
}
