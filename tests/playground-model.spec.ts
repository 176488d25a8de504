import { expect, type Page } from '@playwright/test';
import type { RgbaImage } from '@shadelab/playwright/test';
import { MeshoptEncoder } from 'meshoptimizer';
import { dracoGlb, ktx2Glb } from './glb-compress';
import { test } from './harness-helpers';
import {
  choose,
  frames,
  HIDE_OVERLAYS,
  open,
  picture,
  settle,
  stateUrl,
  typeInto,
  urlState,
} from './playground-helpers';
import { difference, shot, toWebGPU } from './playground-webgpu-helpers';

// The playground shows the user's own model (issue 22): a .glb or .gltf opened with the file picker or dropped
// on the view, its materials swapped for ShadingMaterials, framed, lit by three's lights, animated, kept across
// reloads; every malformed file is refused with a message and the scene shown stays. The models are built in
// code and exported with three's GLTFExporter in the harness page tests/harness/gltf-maker.ts (nothing is
// downloaded); the malformed ones are made from them here. The visual baseline is pixel-exact (SwiftShader):
//   SHADELAB_E2E_PORT=4303 CI=1 npx playwright test tests/playground-model.spec.ts --update-snapshots

type Kind = 'textured' | 'vertexColours' | 'skinned';
const made = new Map<Kind, Buffer>();

/** A model's GLB, made once per worker in the harness page (three's GLTFExporter). */
async function model(page: Page, kind: Kind): Promise<Buffer> {
  const cached = made.get(kind);
  if (cached) return cached;
  const maker = await page.context().newPage();
  await maker.goto('/harness/?page=gltf-maker');
  await maker.waitForFunction(() => typeof window.makeModel === 'function');
  const bytes = Buffer.from(await maker.evaluate((k) => window.makeModel(k), kind));
  await maker.close();
  made.set(kind, bytes);
  return bytes;
}

/** Opens a file through the picker's input (as a user's choice), and waits until it is shown or refused. */
async function openFile(page: Page, name: string, buffer: Buffer, mimeType = 'model/gltf-binary') {
  await page.getByTestId('model-file').setInputFiles({ name, mimeType, buffer });
}

/** Waits until the model named `name` is shown (the note names it) and the page rests. */
async function shown(page: Page, name: string): Promise<void> {
  await expect(page.getByTestId('model-note')).toContainText(`“${name}”`, { timeout: 20_000 });
  await expect(page.getByTestId('model-message')).toHaveCount(0);
  await settle(page);
}

/** Drops a file on the view, as a drag from the desktop does (a DataTransfer holding the file). */
async function dropFile(page: Page, name: string, buffer: Buffer): Promise<void> {
  const dataTransfer = await page.evaluateHandle(
    ([n, bytes]) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([new Uint8Array(bytes)], n, { type: 'model/gltf-binary' }));
      return transfer;
    },
    [name, Array.from(buffer)] as const,
  );
  const canvas = page.getByTestId('viewport');
  await canvas.dispatchEvent('dragover', { dataTransfer });
  await canvas.dispatchEvent('drop', { dataTransfer });
}

/** The drawn pixels' bounds (any channel above 8) and the canvas size, rows from the top. */
async function litBounds(page: Page) {
  return page.getByTestId('viewport').evaluate((canvas: HTMLCanvasElement) => {
    const gl = canvas.getContext('webgl2')!;
    const [w, h] = [canvas.width, canvas.height];
    const out = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, out);
    let [x0, x1, y0, y1, n] = [w, -1, h, -1, 0];
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        const i = (y * w + x) * 4;
        if (out[i]! > 8 || out[i + 1]! > 8 || out[i + 2]! > 8) {
          [x0, x1, y0, y1] = [
            Math.min(x0, x),
            Math.max(x1, x),
            Math.min(y0, h - 1 - y),
            Math.max(y1, h - 1 - y),
          ];
          n++;
        }
      }
    }
    return { x0, x1, y0, y1, lit: n, w, h };
  });
}

// --- GLB surgery: the malformed files are made from a good one. ---

/** A GLB's JSON and binary chunk. */
function splitGlb(glb: Buffer): { json: Record<string, unknown>; bin: Buffer | null } {
  const jsonLength = glb.readUInt32LE(12);
  const json = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const at = 20 + jsonLength;
  return { json, bin: at < glb.length ? glb.subarray(at + 8, at + 8 + glb.readUInt32LE(at)) : null };
}

/** A GLB from its JSON and (optional) binary chunk, each padded to 4 bytes. */
function joinGlb(json: object, bin: Buffer | null): Buffer {
  const pad = (b: Buffer, fill: number) => Buffer.concat([b, Buffer.alloc((4 - (b.length % 4)) % 4, fill)]);
  const text = pad(Buffer.from(JSON.stringify(json)), 0x20);
  const chunks = [Buffer.alloc(8), text];
  chunks[0]!.writeUInt32LE(text.length, 0);
  chunks[0]!.writeUInt32LE(0x4e4f534a, 4);
  if (bin) {
    const data = pad(bin, 0);
    const head = Buffer.alloc(8);
    head.writeUInt32LE(data.length, 0);
    head.writeUInt32LE(0x004e4942, 4);
    chunks.push(head, data);
  }
  const body = Buffer.concat(chunks);
  const header = Buffer.alloc(12);
  header.write('glTF', 0, 'latin1');
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + body.length, 8);
  return Buffer.concat([header, body]);
}

/** The .gltf of a GLB: the same JSON with its buffer as a data: URI (or `uri` instead). */
function toGltf(glb: Buffer, uri?: string): Buffer {
  const { json, bin } = splitGlb(glb);
  const buffers = json['buffers'] as { uri?: string; byteLength: number }[];
  buffers[0]!.uri = uri ?? `data:application/octet-stream;base64,${bin!.toString('base64')}`;
  return Buffer.from(JSON.stringify(json));
}

/**
 * The GLB with every buffer view compressed by meshopt (EXT_meshopt_compression, required): the views in buffer
 * 1, a fallback buffer with no data, their compressed bytes in buffer 0 (the binary chunk). Lossless: the model
 * decodes to the same numbers. Encoded with the meshoptimizer package's encoder (three's decoder reads it).
 */
async function meshopt(glb: Buffer): Promise<Buffer> {
  await MeshoptEncoder.ready;
  const { json, bin } = splitGlb(glb);
  const views = json['bufferViews'] as Record<string, unknown>[];
  const accessors = json['accessors'] as {
    bufferView?: number;
    type: string;
    componentType: number;
    count: number;
  }[];
  const parts: Buffer[] = [];
  let offset = 0;
  const sizes: Record<string, number> = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT4: 16 };
  const bytes: Record<number, number> = { 5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4 };
  views.forEach((view, i) => {
    const accessor = accessors.find((a) => a.bufferView === i);
    if (!accessor) return; // an image's view stays plain (in the fallback buffer, which has none: keep it)
    const stride = sizes[accessor.type]! * bytes[accessor.componentType]!;
    const source = new Uint8Array(
      bin!.subarray(
        Number(view['byteOffset'] ?? 0),
        Number(view['byteOffset'] ?? 0) + Number(view['byteLength']),
      ),
    );
    const index = view['target'] === 34963;
    if (!index && stride % 4 !== 0) return;
    const mode = index ? 'TRIANGLES' : 'ATTRIBUTES';
    const encoded = Buffer.from(MeshoptEncoder.encodeGltfBuffer(source, accessor.count, stride, mode));
    view['extensions'] = {
      EXT_meshopt_compression: {
        buffer: 0,
        byteOffset: offset,
        byteLength: encoded.length,
        byteStride: stride,
        mode,
        count: accessor.count,
      },
    };
    view['buffer'] = 1;
    const padded = Buffer.concat([encoded, Buffer.alloc((4 - (encoded.length % 4)) % 4)]);
    parts.push(padded);
    offset += padded.length;
  });
  const compressed = Buffer.concat(parts);
  json['buffers'] = [
    { byteLength: compressed.length },
    { byteLength: bin!.length, extensions: { EXT_meshopt_compression: { fallback: true } } },
  ];
  json['extensionsUsed'] = [...((json['extensionsUsed'] as string[]) ?? []), 'EXT_meshopt_compression'];
  json['extensionsRequired'] = ['EXT_meshopt_compression'];
  return joinGlb(json, compressed);
}

test('a model opened with the picker is framed, drawn with ShadingMaterial, and the shading switch changes it', async ({
  page,
}) => {
  // The loader is not in the first load: its chunk is requested when the first file is opened.
  const scripts: string[] = [];
  page.on('request', (request) => {
    if (request.resourceType() === 'script') scripts.push(request.url());
  });
  await open(page);
  const sphere = await picture(page);
  expect(scripts.filter((url) => /GLTFLoader|meshopt/.test(url))).toEqual([]);
  await openFile(page, 'ball.glb', await model(page, 'vertexColours'));
  await shown(page, 'ball.glb');
  expect(scripts.filter((url) => /GLTFLoader/.test(url))).toHaveLength(1);
  // meshopt's decoder only for a file that uses it.
  expect(scripts.filter((url) => /meshopt/.test(url))).toEqual([]);
  await expect(page.getByTestId('model-note')).toContainText('1 of 1 meshes drawn with ShadingMaterial');
  expect((await urlState(page))['scene']).toBe('model');
  await expect(page.locator('[id="View.scene"] option:checked')).toHaveText('your model (.glb / .gltf)');
  // Framed: its silhouette fills much of the canvas and stays inside it (no lit pixel on the border rows).
  const bounds = await litBounds(page);
  expect(bounds.lit).toBeGreaterThan(0.15 * bounds.w * bounds.h);
  expect(bounds.x0).toBeGreaterThan(0);
  expect(bounds.y0).toBeGreaterThan(0);
  expect(bounds.x1).toBeLessThan(bounds.w - 1);
  expect(bounds.y1).toBeLessThan(bounds.h - 1);
  const phong = await picture(page);
  expect(phong).not.toBe(sphere);
  // What the model keeps of its own (ka/kd/ks, α) and the panel's lights (it is lit by its rig) are greyed
  // out; the options that apply stay live. One cell: the stats count no cells.
  for (const id of [
    'Material.ka',
    'Material.kd',
    'Material.ks',
    'Material.shininess',
    'Light 1.light1Position',
  ])
    await expect(page.locator(`[id="${id}"]`).first(), id).toBeDisabled();
  for (const id of ['Material.shading', 'Material.lighting', 'Material.celBands'])
    await expect(page.locator(`[id="${id}"]`), id).toBeEnabled();
  await expect(page.getByTestId('stats')).toContainText(/triangles\s*\d/);
  // Every shading, lighting and cel option changes the picture; back to phong gives it again.
  const seen = new Set([phong]);
  for (const [id, value] of [
    ['Material.shading', 'flat'],
    ['Material.shading', 'gouraud'],
    ['Material.lighting', 'phong'],
  ] as const) {
    await choose(page, id, value);
    seen.add(await picture(page));
  }
  await typeInto(page, 'Material.celBands', '3');
  seen.add(await picture(page));
  expect(seen.size).toBe(5);
  await typeInto(page, 'Material.celBands', '0');
  await choose(page, 'Material.lighting', 'blinn-phong');
  await choose(page, 'Material.shading', 'phong');
  expect(await picture(page)).toBe(phong);
  // The compare view draws it four times (flat | Gouraud | Phong | cel), each cell different.
  await choose(page, 'View.view', 'flat | Gouraud | Phong | cel');
  const compare = await picture(page);
  expect(compare).not.toBe(phong);
  await expect(page.getByTestId('stats')).toContainText('triangles (4 cells)');
  await choose(page, 'View.view', 'single sphere');
  expect(await picture(page)).toBe(phong);
});

test('a dropped model is shown, replaces the previous one, and the picture is the baseline', async ({
  page,
}) => {
  await open(page);
  await dropFile(page, 'ball.glb', await model(page, 'vertexColours'));
  await shown(page, 'ball.glb');
  const ball = await picture(page);
  await dropFile(page, 'box.glb', await model(page, 'textured'));
  await shown(page, 'box.glb');
  // The box's checker map and its points (left as they are: glTF points are not a mesh).
  await expect(page.getByTestId('model-note')).toContainText('1 of 1 meshes drawn with ShadingMaterial');
  await expect(page.getByTestId('model-note')).toContainText('Left as they were: Points');
  expect(await picture(page)).not.toBe(ball);
  await page.addStyleTag({ content: HIDE_OVERLAYS });
  await expect(page.getByTestId('viewport')).toHaveScreenshot('playground-model-box.png');
});

test('a .gltf with embedded resources and a meshopt-compressed GLB draw the same picture as the GLB', async ({
  page,
}) => {
  await open(page);
  const glb = await model(page, 'vertexColours');
  await openFile(page, 'ball.glb', glb);
  await shown(page, 'ball.glb');
  const reference = await picture(page);
  await openFile(page, 'ball.gltf', toGltf(glb), 'model/gltf+json');
  await shown(page, 'ball.gltf');
  expect(await picture(page)).toBe(reference);
  await openFile(page, 'ball-meshopt.glb', await meshopt(glb));
  await shown(page, 'ball-meshopt.glb');
  expect(await picture(page)).toBe(reference);
});

/**
 * A compressed copy's picture against the uncompressed model's, both opened with the picker: the same silhouette
 * but for a few pixels on its edge (Draco moves vertices by its quantization step), and the same colours away
 * from it within `maxDelta` (1/255).
 */
function expectSameModel(reference: RgbaImage, compressed: RgbaImage, maxDelta: number) {
  const d = difference(reference, compressed);
  console.log(`compressed vs uncompressed: ${JSON.stringify(d)}`);
  expect(d.covered, 'the model is drawn').toBeGreaterThan(20_000);
  expect(d.coverage, 'pixels covered in one picture only').toBeLessThanOrEqual(0.002 * d.covered);
  expect(d.compared, 'pixels compared away from the silhouette').toBeGreaterThan(0.9 * d.covered);
  expect(d.maxDelta, 'largest channel difference, 1/255').toBeLessThanOrEqual(maxDelta);
}

test('a Draco-compressed and a KTX2-textured GLB draw as the uncompressed model; each decoder loads only for its file', async ({
  page,
}) => {
  test.setTimeout(90_000);
  // Every decoder file and decoder loader chunk the page fetches (Vite's hashed names, the hash taken off), and
  // anything the console says at warning level or above.
  const decoders: string[] = [];
  page.on('request', (request) => {
    const file = new URL(request.url()).pathname.split('/').at(-1)!;
    if (/draco|basis|ktx2/i.test(file)) decoders.push(file.replace(/-[\w-]{8}\./, '.'));
  });
  const problems: string[] = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'warning' || m.type() === 'error') problems.push(`${m.type()}: ${m.text()}`);
  });
  // The compressed formats WebGL is given (three allocates a compressed texture with texStorage2D, then uploads
  // each level with compressedTexSubImage2D), from every WebGL2 context of the page.
  await page.addInitScript(() => {
    const formats: number[] = [];
    (window as unknown as { compressedFormats: number[] }).compressedFormats = formats;
    const proto = WebGL2RenderingContext.prototype;
    const upload = proto.compressedTexSubImage2D as (...args: unknown[]) => void;
    proto.compressedTexSubImage2D = function (this: WebGL2RenderingContext, ...args: unknown[]) {
      formats.push(args[6] as number);
      return upload.apply(this, args);
    } as typeof proto.compressedTexSubImage2D;
  });
  const compressedFormats = () =>
    page.evaluate(() => [
      ...new Set((window as unknown as { compressedFormats: number[] }).compressedFormats),
    ]);
  await open(page);
  const ball = await model(page, 'vertexColours');
  const box = await model(page, 'textured');
  await openFile(page, 'ball.glb', ball);
  await shown(page, 'ball.glb');
  const ballPicture = await shot(page);
  await openFile(page, 'box.glb', box);
  await shown(page, 'box.glb');
  const boxPicture = await shot(page);
  // Plain files load no decoder.
  expect(decoders).toEqual([]);

  // Draco: the glTF-only decoder's wrapper and WebAssembly, fetched once, for this file.
  const draco = await dracoGlb(ball);
  expect(splitGlb(draco).json['extensionsRequired']).toEqual(['KHR_draco_mesh_compression']);
  expect(draco.length).toBeLessThan(0.5 * ball.length);
  await openFile(page, 'ball-draco.glb', draco);
  await shown(page, 'ball-draco.glb');
  await expect(page.getByTestId('model-note')).toContainText('1 of 1 meshes drawn with ShadingMaterial');
  expectSameModel(ballPicture, await shot(page), 2);
  expect(decoders).toEqual(['DRACOLoader.js', 'draco_wasm_wrapper.js', 'draco_decoder.wasm']);

  // KTX2: the checker map as Basis UASTC, transcoded by three's Basis transcoder, fetched now.
  const ktx2 = await ktx2Glb(box);
  const { json } = splitGlb(ktx2);
  expect(json['extensionsRequired']).toEqual(['KHR_texture_basisu']);
  expect(json['images']).toEqual([expect.objectContaining({ mimeType: 'image/ktx2' })]);
  await openFile(page, 'box-ktx2.glb', ktx2);
  await shown(page, 'box-ktx2.glb');
  const ktx2Picture = await shot(page);
  expectSameModel(boxPicture, ktx2Picture, 2);
  expect(decoders.slice(3)).toEqual(['KTX2Loader.js', 'basis_transcoder.js', 'basis_transcoder.wasm']);
  // The map is uploaded as a compressed texture, in the format the transcoder chose for this GPU.
  const formats = await compressedFormats();
  console.log(`KTX2 map uploaded as ${formats.map((f) => `0x${f.toString(16)}`).join(', ')}`);
  expect(formats).toHaveLength(1);
  // WebGPU mode (its WebGL2 backend here) draws the same transcoded texture: the same picture.
  await toWebGPU(page);
  expectSameModel(ktx2Picture, await shot(page), 2);
  expect(await compressedFormats()).toEqual(formats);

  // A second Draco file reuses the loaded decoder.
  await choose(page, 'View.renderer', 'WebGL');
  await expect(page.getByTestId('viewport-webgpu')).toHaveCount(0);
  await openFile(page, 'ball-draco-2.glb', draco);
  await shown(page, 'ball-draco-2.glb');
  expect(decoders).toHaveLength(6);
  // Quiet: no warning but those the plain models give too (the swap naming what it left: the box's points, and
  // in WebGPU mode its outline material) and Chromium's note that it has no WebGPU adapter (WebGPU mode's probe).
  const known = [
    /^warning: swap(Node)?Materials: left \d+ material\(s\) in place:/,
    /^warning: No available adapters\.$/,
  ];
  expect(problems.filter((p) => !known.some((k) => k.test(p)))).toEqual([]);
});

test('an animated model plays (frames come without input, the picture moves) and pauses', async ({
  page,
}) => {
  await open(page);
  await openFile(page, 'bend.glb', await model(page, 'skinned'));
  await expect(page.getByTestId('model-note')).toContainText('“bend.glb”', { timeout: 20_000 });
  await expect(page.getByTestId('model-note')).toContainText('Animation “bend” (2.00 s)');
  const first = await frames(page);
  const a = await picture(page);
  await expect.poll(() => frames(page), { timeout: 10_000 }).toBeGreaterThan(first + 5);
  await expect.poll(() => picture(page), { timeout: 10_000 }).not.toBe(a);
  await page.getByRole('button', { name: 'pause animation' }).click();
  await settle(page);
  const paused = await picture(page);
  const count = await frames(page);
  await page.waitForTimeout(500);
  expect(await frames(page)).toBe(count);
  expect(await picture(page)).toBe(paused);
  // The shading switch still applies to the paused pose.
  await choose(page, 'Material.shading', 'flat');
  expect(await picture(page)).not.toBe(paused);
  await page.getByRole('button', { name: 'play animation' }).click();
  await expect.poll(() => frames(page), { timeout: 10_000 }).toBeGreaterThan(count + 5);
});

test('the model survives a reload (IndexedDB); another scene frees it and picking it again shows it', async ({
  page,
}) => {
  await open(page);
  await openFile(page, 'box.glb', await model(page, 'textured'));
  await shown(page, 'box.glb');
  await choose(page, 'Material.shading', 'gouraud');
  const box = await picture(page);
  await page.reload();
  await shown(page, 'box.glb');
  expect(await picture(page)).toBe(box);
  expect(await urlState(page)).toMatchObject({ scene: 'model', material: { shading: 'gouraud' } });
  await choose(page, 'View.scene', 'instanced spheres');
  await expect(page.getByTestId('model-note')).toHaveCount(0);
  await choose(page, 'View.scene', 'your model (.glb / .gltf)');
  await shown(page, 'box.glb');
  expect(await picture(page)).toBe(box);
});

test('a link to the model where it cannot be restored says so and opens the lecture sphere, the rest of the state kept', async ({
  page,
}) => {
  await open(page, { material: { shading: 'flat' } });
  const flatSphere = await picture(page);
  await page.goto('about:blank');
  await page.goto(stateUrl({ scene: 'model', material: { shading: 'flat' } }));
  await expect(page.getByTestId('model-message')).toContainText(
    'Your model could not be shown: no model was opened in this browser',
  );
  await settle(page);
  await expect.poll(async () => (await urlState(page))['scene']).toBe('sphere');
  expect(await urlState(page)).toMatchObject({ material: { shading: 'flat' } });
  expect(await picture(page)).toBe(flatSphere);
  // The picker's model entry without a model: the same message, and the scene shown stays.
  await choose(page, 'View.scene', 'instanced spheres');
  const instanced = await picture(page);
  await page.locator('[id="View.scene"]').selectOption({ label: 'your model (.glb / .gltf)' });
  await expect(page.getByTestId('model-message')).toContainText('Showing the previous scene instead');
  await expect.poll(async () => (await urlState(page))['scene']).toBe('instanced');
  await settle(page);
  expect(await picture(page)).toBe(instanced);
});

test('every malformed or unsupported file is refused with a message; the model shown stays and the page works', async ({
  page,
}) => {
  await open(page);
  const glb = await model(page, 'textured');
  await openFile(page, 'box.glb', glb);
  await shown(page, 'box.glb');
  const box = await picture(page);
  const { json, bin } = splitGlb(glb);
  const huge = Buffer.from(glb);
  huge.writeUInt32LE(2 ** 31, 8);
  const wrongMagic = Buffer.from(glb);
  wrongMagic.write('glTX', 0, 'latin1');
  const unknown = { ...json, extensionsUsed: ['EXT_made_up'], extensionsRequired: ['EXT_made_up'] };
  const png = Buffer.from('89504e470d0a1a0a0000000d49484452', 'hex');
  const cases: [string, Buffer, string][] = [
    ['truncated.glb', glb.subarray(0, glb.length - 100), '"truncated.glb" is truncated: its GLB header says'],
    [
      'wrong-magic.glb',
      wrongMagic,
      '"wrong-magic.glb" is not a glTF file: it starts with the bytes 67 6c 54 58',
    ],
    [
      'no-buffer.glb',
      joinGlb(json, null),
      '"no-buffer.glb" is not valid glTF: the Khronos glTF Validator found an error: /buffers/0: Buffer refers to an unresolved GLB binary chunk.',
    ],
    [
      'huge.glb',
      huge,
      '"huge.glb": its GLB header claims 2.0 GiB, more than the playground\'s limit of 64 MiB',
    ],
    [
      'unknown.glb',
      joinGlb(unknown, bin),
      "needs the extension EXT_made_up, which three's GLTFLoader does not read",
    ],
    ['external.gltf', toGltf(glb, 'box.bin'), 'buffer 0 refers to the external file "box.bin"'],
    ['picture.png', png, '"picture.png" is not a glTF file: it starts with the bytes 89 50 4e 47'],
    ['notes.gltf', Buffer.from('{"asset": '), '"notes.gltf": its JSON is malformed'],
    ['empty.glb', Buffer.alloc(0), '"empty.glb" is empty'],
  ];
  for (const [name, bytes, message] of cases) {
    await openFile(page, name, bytes);
    await expect(page.getByTestId('model-message'), name).toContainText(message);
    await settle(page);
    expect(await picture(page), name).toBe(box);
    await expect(page.getByTestId('model-note')).toContainText('“box.glb”');
  }
  // The page keeps working: an option changes the picture, a good file is shown.
  await choose(page, 'Material.shading', 'flat');
  expect(await picture(page)).not.toBe(box);
  await openFile(page, 'ball.glb', await model(page, 'vertexColours'));
  await shown(page, 'ball.glb');
  // A refused file over another scene: that scene stays.
  await choose(page, 'View.scene', "the lecture's sphere");
  const sphere = await picture(page);
  await openFile(page, 'truncated.glb', glb.subarray(0, 40));
  await expect(page.getByTestId('model-message')).toContainText('is truncated');
  expect((await urlState(page))['scene']).toBe('sphere');
  expect(await picture(page)).toBe(sphere);
});
