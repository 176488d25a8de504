// What the trade-off page compares: an option (a subdivision mesh with flat, Gouraud or Phong shading, or the
// ray-cast impostor), the view it is drawn in, and what the option costs; no three.js objects (the scene that
// draws them is tradeoffScene.ts).
import type { Attenuation, Lighting } from '@shadelab/material';
import { type SphereBase, sphereCounts } from '@shadelab/sphere';

/** One point of the trade: a mesh option or the impostor. */
export type TradeOption =
  | { readonly shading: 'flat' | 'gouraud' | 'phong'; readonly base: SphereBase; readonly level: number }
  | { readonly shading: 'impostor' };

/** One Phong light of a {@link TradeView} (linear RGB; `PhongLight`'s defaults, the lecture's). */
export interface TradeLight {
  /** World position. */
  position: [number, number, number];
  /** @default [0.2, 0.2, 0.2] */
  ambient?: [number, number, number];
  /** @default [1, 1, 1] */
  diffuse?: [number, number, number];
  /** @default [0.8, 0.8, 0.8] */
  specular?: [number, number, number];
  /** @default { a: 1, b: 0, c: 0 } (none) */
  attenuation?: Partial<Attenuation>;
}

/** The view and lighting (the lecture's scene by default). */
export interface TradeView {
  width: number;
  height: number;
  /** @default 'perspective' */
  projection?: 'perspective' | 'orthographic';
  /** @default 90 */
  fovy?: number;
  /** @default [0, 0, 3] */
  eye?: [number, number, number];
  /** @default [2, 1, 2] */
  scale?: [number, number, number];
  /** Euler angles, radians. @default [0, 0, 0] */
  rotation?: [number, number, number];
  /** The position of the one default light. @default [-5, 10, 20] */
  light?: [number, number, number];
  /** Every light, with its intensities and attenuation; replaces `light` when given. */
  lights?: TradeLight[];
  /** Near plane distance. @default 0.1 */
  near?: number;
  /** Far plane distance. @default max(10, 2·|eye| + 4) */
  far?: number;
  /** @default 'phong' */
  lighting?: Lighting;
  /** @default 0 */
  celBands?: number;
  /** @default 32 */
  shininess?: number;
  ka?: [number, number, number];
  kd?: [number, number, number];
  ks?: [number, number, number];
}

/** What an option costs in memory and work. */
export interface OptionCost {
  triangles: number;
  vertices: number;
  /** GPU buffer bytes: attributes, index and (flat) the face-position texture. */
  bytes: number;
  /** Bytes per vertex of the attributes the shading reads. */
  bytesPerVertex: number;
  /** Buffer bytes per triangle (index included). */
  bytesPerTriangle: number;
}

/** The option's name, as the bench names its points ("phong tetrahedron 6", "impostor"). */
export function optionKey(option: TradeOption): string {
  return option.shading === 'impostor' ? 'impostor' : `${option.shading} ${option.base} ${option.level}`;
}

/** Triangles, vertices and bytes of an option, from the sphere counts (no geometry built). */
export function optionCost(option: TradeOption): OptionCost {
  if (option.shading === 'impostor') {
    return { triangles: 2, vertices: 4, bytes: 4 * 12 + 6 * 2, bytesPerVertex: 12, bytesPerTriangle: 30 };
  }
  const { triangles } = sphereCounts(option.base, option.level);
  // flatShadingGeometry gives every face a provoking vertex of its own: on a subdivision sphere V′ = T (its
  // greedy pass duplicates one corner of the bare octahedron and icosahedron, level 0: V′ = T + 1), each with
  // its position and the face's two other corners (36 B). Gouraud and Phong read the position only (exact
  // sphere normals from it): V = 2 + T/2 shared vertices of 12 B. Uint16 indices while they fit.
  const flat = option.shading === 'flat';
  const duplicated = option.level === 0 && option.base !== 'tetrahedron' ? 1 : 0;
  const vertices = flat ? triangles + duplicated : 2 + triangles / 2;
  const bytesPerVertex = flat ? 36 : 12;
  const indexBytes = vertices <= 65536 ? 2 : 4;
  const bytes = vertices * bytesPerVertex + 3 * triangles * indexBytes;
  return { triangles, vertices, bytes, bytesPerVertex, bytesPerTriangle: bytes / triangles };
}

/** A view with every default filled in (the lecture's scene). */
export function resolveView({
  width,
  height,
  projection = 'perspective',
  fovy = 90,
  eye = [0, 0, 3],
  scale = [2, 1, 2],
  rotation = [0, 0, 0],
  light = [-5, 10, 20],
  lights = [{ position: light }],
  near = 0.1,
  far = Math.max(10, 2 * Math.hypot(...eye) + 4),
  lighting = 'phong',
  celBands = 0,
  shininess = 32,
  ka = [0.6, 0.35, 0.2],
  kd = [0.6, 0.35, 0.2],
  ks = [0.5, 0.5, 0.5],
}: TradeView): Required<TradeView> {
  return {
    width,
    height,
    projection,
    fovy,
    eye,
    scale,
    rotation,
    light,
    lights,
    near,
    far,
    lighting,
    celBands,
    shininess,
    ka,
    kd,
    ks,
  };
}
