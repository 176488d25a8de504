import type { BufferGeometry } from 'three';
import { linearToSrgb8Channel } from './linearToSrgb8.js';
import type { Shading } from './options.js';
import { type Lighting, type ShadeLight, type ShadeMaterial, shade } from './shade.js';
import type { Vec3 } from './vec3.js';

/** The budgets (8-bit sRGB levels) at which a {@link ShadingErrorTable} records its fractions. */
export const ERROR_BUDGETS: readonly number[] = Object.freeze([
  0, 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 255,
]);

/** The surface a {@link measureShadingError} table is measured for (a `ShadingMaterial`'s options). */
export interface ShadingErrorSurface {
  /** ka, linear RGB. @default [0.6, 0.35, 0.2] */
  readonly ka?: ArrayLike<number>;
  /** kd, linear RGB. @default [0.6, 0.35, 0.2] */
  readonly kd?: ArrayLike<number>;
  /** ks, linear RGB. @default [0.5, 0.5, 0.5] */
  readonly ks?: ArrayLike<number>;
  /** α. @default 32 */
  readonly shininess?: number;
  /** The lighting equation. @default 'phong' */
  readonly lighting?: Lighting;
  /** Cel bands (0 = off). @default 0 */
  readonly celBands?: number;
  /** Emissive, linear RGB. @default [0, 0, 0] */
  readonly emissive?: ArrayLike<number>;
}

/** One level of detail of a geometry, for {@link measureShadingError}. */
export interface ShadingErrorLevel {
  /** The geometry drawn at this level (indexed or not; `normal` attribute or a sphere centred at its origin). */
  readonly geometry: BufferGeometry;
  /** The level's name in the table (a sphere's subdivision level). */
  readonly level: number;
  /**
   * Its largest radial distance inside the full-detail surface, relative to the radius (a subdivision
   * sphere's `sphereError(base, level)`): the silhouette term, which the table leaves to the caller. 0 for the
   * full detail.
   */
  readonly silhouetteError: number;
}

/** Options of {@link measureShadingError}. */
export interface ShadingErrorModelOptions {
  /** The material's options the error is measured for. @default the lecture's material */
  surface?: ShadingErrorSurface;
  /**
   * Coarser levels of the same surface (a subdivision sphere's lower levels), each measured against the full
   * detail, `geometry`. The full-detail surface must be a sphere centred at its origin (the reference colour of
   * a pixel is that of the full-detail mesh where the ray through it hits; only spheres have the levels).
   * @default []
   */
  levels?: readonly ShadingErrorLevel[];
  /** Cells across the bounding disc of the CPU rasteriser, 8 … 512. @default 64 */
  resolution?: number;
  /** View directions sampled (a Fibonacci sphere), 1 … 64. @default 6 */
  views?: number;
  /** Light directions sampled per view (a Fibonacci sphere), 1 … 64. @default 6 */
  lights?: number;
  /** Id = Is of the one white directional light, in the lecture's units (three: colour × intensity / π). @default 1 */
  intensity?: number;
  /** Ia, white ambient, lecture units (three: an AmbientLight's colour × intensity / π). @default 0 */
  ambient?: number;
}

/** One candidate of a {@link ShadingErrorTable}: a shading at a level. */
export interface ShadingErrorRow {
  /** The shading drawn. */
  readonly shading: Shading;
  /** The level (`null`: the geometry as given, the full detail). */
  readonly level: number | null;
  /** Triangles drawn. */
  readonly triangles: number;
  /** The level's silhouette error relative to the radius (0 at full detail). */
  readonly silhouetteError: number;
  /**
   * For each budget of {@link ShadingErrorTable.budgets}: the fraction of the covered pixels whose error
   * exceeds it, the largest over the sampled view and light directions.
   */
  readonly over: readonly number[];
  /** The largest error seen at any pixel, 8-bit sRGB levels. */
  readonly max: number;
}

/**
 * The image error of every shading (and level) of one mesh and material against Phong shading at full detail:
 * plain data, JSON-serialisable (compute it ahead of time and ship it, or at load, or in a worker).
 */
export interface ShadingErrorTable {
  /** The budgets the fractions are recorded at (8-bit sRGB levels): {@link ERROR_BUDGETS}. */
  readonly budgets: readonly number[];
  /** The smallest covered fraction of the bounding disc over the sampled views (a floor of the drawn area). */
  readonly coverageMin: number;
  /** The largest covered fraction of the bounding disc over the sampled views. */
  readonly coverageMax: number;
  /** The bounding sphere's radius in model space the coverages are relative to. */
  readonly radius: number;
  /** Phong shading at full detail (error 0) first, then every other shading and level. */
  readonly rows: readonly ShadingErrorRow[];
}

/** The fraction of a row's covered pixels over `budget`: the recorded fraction at the largest grid budget ≤ it. */
export function overFraction(table: ShadingErrorTable, row: ShadingErrorRow, budget: number): number {
  const b = table.budgets;
  if (!(budget >= b[0])) return 1;
  let k = 0;
  while (k + 1 < b.length && b[k + 1] <= budget) k++;
  return row.over[k];
}

/** A mesh as the rasteriser reads it: world = model space. */
interface Mesh {
  readonly positions: Float64Array;
  readonly normals: Float64Array; // per vertex (smooth) for gouraud and phong
  readonly faces: Uint32Array;
  readonly faceNormals: Float64Array;
  readonly centroids: Float64Array;
}

function meshOf(geometry: BufferGeometry): Mesh {
  const position = geometry.getAttribute('position');
  if (position === undefined || position.itemSize !== 3) {
    throw new TypeError('measureShadingError: geometry must have a position attribute with 3 components');
  }
  const n = position.count;
  const positions = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    positions[3 * i] = position.getX(i);
    positions[3 * i + 1] = position.getY(i);
    positions[3 * i + 2] = position.getZ(i);
  }
  const normal = geometry.getAttribute('normal');
  const normals = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    // No normal attribute: a sphere centred at its origin (ShadingMaterial's analytic normal = position).
    normals[3 * i] = normal ? normal.getX(i) : positions[3 * i];
    normals[3 * i + 1] = normal ? normal.getY(i) : positions[3 * i + 1];
    normals[3 * i + 2] = normal ? normal.getZ(i) : positions[3 * i + 2];
  }
  const index = geometry.index;
  const count = index ? index.count : n;
  if (count % 3 !== 0)
    throw new TypeError(`measureShadingError: vertex count must be a multiple of 3, got ${count}`);
  const faces = new Uint32Array(count);
  for (let k = 0; k < count; k++) faces[k] = index ? index.getX(k) : k;
  const t = count / 3;
  const faceNormals = new Float64Array(3 * t);
  const centroids = new Float64Array(3 * t);
  for (let f = 0; f < t; f++) {
    const a = 3 * faces[3 * f];
    const b = 3 * faces[3 * f + 1];
    const c = 3 * faces[3 * f + 2];
    const ux = positions[b] - positions[a];
    const uy = positions[b + 1] - positions[a + 1];
    const uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a];
    const vy = positions[c + 1] - positions[a + 1];
    const vz = positions[c + 2] - positions[a + 2];
    faceNormals[3 * f] = uy * vz - uz * vy;
    faceNormals[3 * f + 1] = uz * vx - ux * vz;
    faceNormals[3 * f + 2] = ux * vy - uy * vx;
    for (let j = 0; j < 3; j++) {
      centroids[3 * f + j] = (positions[a + j] + positions[b + j] + positions[c + j]) / 3;
    }
  }
  return { positions, normals, faces, faceNormals, centroids };
}

/** `n` unit directions spread over the sphere (a Fibonacci lattice), deterministic. */
export function fibonacciDirections(n: number): Vec3[] {
  const out: Vec3[] = [];
  const golden = Math.PI * (3 - Math.sqrt(5));
  for (let i = 0; i < n; i++) {
    const y = 1 - (2 * (i + 0.5)) / n;
    const r = Math.sqrt(1 - y * y);
    const phi = i * golden + 0.3;
    out.push([r * Math.cos(phi), y, r * Math.sin(phi)]);
  }
  return out;
}

/** The visible face and barycentrics at each cell centre of an orthographic view. */
interface Raster {
  readonly face: Int32Array; // −1: empty
  readonly bary: Float64Array; // 3 per cell
}

/**
 * Rasterise `mesh` orthographically along `view` (unit, towards the viewer) onto `res`² cells spanning the disc
 * of radius `radius` about the origin, front faces only, nearest wins: each cell centre's face and barycentrics
 * (what a GPU's one sample per pixel sees).
 */
function rasterise(mesh: Mesh, view: Vec3, radius: number, res: number): Raster {
  // Screen axes u, w ⟂ view.
  const helper: Vec3 = Math.abs(view[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
  const u: Vec3 = [
    helper[1] * view[2] - helper[2] * view[1],
    helper[2] * view[0] - helper[0] * view[2],
    helper[0] * view[1] - helper[1] * view[0],
  ];
  const ul = Math.hypot(...u);
  u[0] /= ul;
  u[1] /= ul;
  u[2] /= ul;
  const w: Vec3 = [
    view[1] * u[2] - view[2] * u[1],
    view[2] * u[0] - view[0] * u[2],
    view[0] * u[1] - view[1] * u[0],
  ];
  const cells = res * res;
  const face = new Int32Array(cells).fill(-1);
  const bary = new Float64Array(3 * cells);
  const depth = new Float64Array(cells).fill(Number.NEGATIVE_INFINITY);
  const { positions: p, faces, faceNormals: fn } = mesh;
  const toCell = res / (2 * radius);
  const sx = [0, 0, 0];
  const sy = [0, 0, 0];
  const sz = [0, 0, 0];
  for (let f = 0; f < faces.length / 3; f++) {
    if (fn[3 * f] * view[0] + fn[3 * f + 1] * view[1] + fn[3 * f + 2] * view[2] <= 0) continue;
    for (let k = 0; k < 3; k++) {
      const i = 3 * faces[3 * f + k];
      sx[k] = (p[i] * u[0] + p[i + 1] * u[1] + p[i + 2] * u[2] + radius) * toCell;
      sy[k] = (p[i] * w[0] + p[i + 1] * w[1] + p[i + 2] * w[2] + radius) * toCell;
      sz[k] = p[i] * view[0] + p[i + 1] * view[1] + p[i + 2] * view[2];
    }
    const area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (!(Math.abs(area) > 1e-300)) continue;
    const x0 = Math.max(0, Math.floor(Math.min(sx[0], sx[1], sx[2]) - 0.5));
    const x1 = Math.min(res - 1, Math.ceil(Math.max(sx[0], sx[1], sx[2]) - 0.5));
    const y0 = Math.max(0, Math.floor(Math.min(sy[0], sy[1], sy[2]) - 0.5));
    const y1 = Math.min(res - 1, Math.ceil(Math.max(sy[0], sy[1], sy[2]) - 0.5));
    for (let y = y0; y <= y1; y++) {
      const cy = y + 0.5;
      for (let x = x0; x <= x1; x++) {
        const cx = x + 0.5;
        const b0 = ((sx[1] - cx) * (sy[2] - cy) - (sx[2] - cx) * (sy[1] - cy)) / area;
        const b1 = ((sx[2] - cx) * (sy[0] - cy) - (sx[0] - cx) * (sy[2] - cy)) / area;
        const b2 = 1 - b0 - b1;
        if (b0 < -1e-9 || b1 < -1e-9 || b2 < -1e-9) continue;
        const z = b0 * sz[0] + b1 * sz[1] + b2 * sz[2];
        const c = y * res + x;
        if (z <= depth[c]) continue;
        depth[c] = z;
        face[c] = f;
        bary[3 * c] = b0;
        bary[3 * c + 1] = b1;
        bary[3 * c + 2] = b2;
      }
    }
  }
  return { face, bary };
}

/** Largest |difference| of the 8-bit sRGB codes of two linear colours, over the channels. */
function levels(a: Vec3, b: Vec3): number {
  return Math.max(
    Math.abs(linearToSrgb8Channel(a[0]) - linearToSrgb8Channel(b[0])),
    Math.abs(linearToSrgb8Channel(a[1]) - linearToSrgb8Channel(b[1])),
    Math.abs(linearToSrgb8Channel(a[2]) - linearToSrgb8Channel(b[2])),
  );
}

function checkCount(name: string, value: unknown, min: number, max: number): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < min || value > max) {
    throw new RangeError(
      `measureShadingError: ${name} must be an integer from ${min} to ${max}, got ${String(value)}`,
    );
  }
  return value;
}

function checkFinite(name: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < 0) {
    throw new RangeError(`measureShadingError: ${name} must be a finite number ≥ 0, got ${String(value)}`);
  }
  return value;
}

/**
 * The measured image error of flat, Gouraud and Phong shading of one mesh (and of coarser levels, where the
 * geometry has them) against Phong shading at full detail, in 8-bit sRGB levels.
 *
 * Method. The mesh is rasterised on the CPU, orthographically, onto `resolution`² cells over its bounding disc,
 * front faces only, nearest wins, one sample at each cell centre as a GPU samples a pixel centre; for each of
 * `views` view directions and `lights` directions of one white directional light (Id = Is = `intensity`,
 * Ia = `ambient`), every covered cell is shaded with `shade()` as each shading does: Phong with the normal
 * interpolated and renormalised at the cell's point; Gouraud with the colours `shade()` gives at the face's
 * three vertices, interpolated; flat with the face's colour at its centroid (the prepared path) and at the
 * cell's point with the face normal (the derivatives path), whichever errs more. Each is converted to 8-bit
 * sRGB as the canvas is, and compared channel by channel with Phong at full detail at the same cell. A coarser
 * level is rasterised on its own; a cell both levels cover compares the level's colour with the full
 * detail's there (the pixels one covers and the other does not are the silhouette, left to the caller's
 * exact bound: `silhouetteError`).
 *
 * What it bounds and what it estimates. The difference between Gouraud (or flat) and Phong shading at a
 * pixel does not shrink as the mesh shrinks on screen: each pixel shows one sample of the surface, and the
 * difference at that sample is set by the mesh in model space. What scales with the size is how many pixels
 * show it, so the table records, for each budget, the *fraction of the covered pixels* over it — the largest
 * fraction over the sampled directions, which is the same at any size under an orthographic camera. It is an
 * estimate, not a bound: directions between the samples, perspective (the view vector changes across the
 * mesh), several lights, brighter lights, textures and instance colours (a darker tint lowers the error in
 * levels, except in the sRGB curve's linear toe) and the GPU's float rounding (±1 level) are not covered.
 *
 * Cost: views × (a raster of each level + lights × about 6 `shade()` calls per covered cell); the defaults take
 * tens of milliseconds for a mesh of a few thousand triangles.
 *
 * @param geometry - the full-detail mesh: a `position` attribute and a `normal` attribute (or none, for a
 *   sphere centred at its origin, whose normal is its position).
 * @param options - the surface, the levels and the sampling.
 * @throws TypeError for a geometry without positions; RangeError naming a bad option.
 */
export function measureShadingError(
  geometry: BufferGeometry,
  options: ShadingErrorModelOptions = {},
): ShadingErrorTable {
  const {
    surface = {},
    levels: coarser = [],
    resolution = 64,
    views = 6,
    lights = 6,
    intensity = 1,
    ambient = 0,
  } = options;
  checkCount('resolution', resolution, 8, 512);
  checkCount('views', views, 1, 64);
  checkCount('lights', lights, 1, 64);
  checkFinite('intensity', intensity);
  checkFinite('ambient', ambient);
  const material: ShadeMaterial = {
    ka: surface.ka ?? [0.6, 0.35, 0.2],
    kd: surface.kd ?? [0.6, 0.35, 0.2],
    ks: surface.ks ?? [0.5, 0.5, 0.5],
    shininess: surface.shininess ?? 32,
    lighting: surface.lighting ?? 'phong',
    celBands: surface.celBands ?? 0,
    emissive: surface.emissive ?? [0, 0, 0],
  };
  const full = meshOf(geometry);
  if (geometry.boundingSphere === null) geometry.computeBoundingSphere();
  const bs = geometry.boundingSphere;
  // The disc is centred on the model origin: its radius reaches the farthest vertex.
  let radius = 0;
  for (let i = 0; i < full.positions.length; i += 3) {
    radius = Math.max(radius, Math.hypot(full.positions[i], full.positions[i + 1], full.positions[i + 2]));
  }
  if (!(radius > 0) || !Number.isFinite(radius)) radius = bs?.radius && bs.radius > 0 ? bs.radius : 1;
  radius *= 1.0001;
  const meshes = [
    { mesh: full, level: null as number | null, silhouetteError: 0, triangles: full.faces.length / 3 },
  ];
  for (const l of coarser) {
    const mesh = meshOf(l.geometry);
    meshes.push({
      mesh,
      level: l.level,
      silhouetteError: l.silhouetteError,
      triangles: mesh.faces.length / 3,
    });
  }
  const shadings: Shading[] = ['phong', 'gouraud', 'flat'];
  const nb = ERROR_BUDGETS.length;
  // Per candidate (mesh × shading): worst fraction over budgets, and max.
  const worst = meshes.map(() => shadings.map(() => new Float64Array(nb)));
  const maxSeen = meshes.map(() => shadings.map(() => 0));
  let coverageMin = 1;
  let coverageMax = 0;
  const discCells = (Math.PI * resolution * resolution) / 4;
  const viewDirs = fibonacciDirections(views);
  const lightDirs = fibonacciDirections(lights);
  // Scratch.
  const ref: Vec3 = [0, 0, 0];
  const cand: Vec3 = [0, 0, 0];
  const tmp: Vec3 = [0, 0, 0];
  const va: Vec3 = [0, 0, 0];
  const vb: Vec3 = [0, 0, 0];
  const vc: Vec3 = [0, 0, 0];
  const pos: Vec3 = [0, 0, 0];
  const nrm: Vec3 = [0, 0, 0];
  const counts = new Float64Array(nb);
  const far = 1e6 * radius;
  const cells = resolution * resolution;
  const refs = new Float64Array(3 * cells);
  const vertexColours = meshes.map((m) => new Float64Array(m.mesh.positions.length));
  const vertexStamps = meshes.map((m) => new Int32Array(m.mesh.positions.length / 3));
  let stamp = 0;
  const fn: Vec3 = [0, 0, 0];
  const centroid: Vec3 = [0, 0, 0];
  const point: Vec3 = [0, 0, 0];
  /** The point of cell c on mesh m. */
  const pointOf = (m: Mesh, r: Raster, c: number, out: Vec3) => {
    const f = r.face[c];
    out[0] = out[1] = out[2] = 0;
    for (let k = 0; k < 3; k++) {
      const b = r.bary[3 * c + k];
      const i = 3 * m.faces[3 * f + k];
      out[0] += b * m.positions[i];
      out[1] += b * m.positions[i + 1];
      out[2] += b * m.positions[i + 2];
    }
    return out;
  };
  for (const view of viewDirs) {
    const eye = [view[0], view[1], view[2], 0];
    const rasters = meshes.map((m) => rasterise(m.mesh, view, radius, resolution));
    const fullRaster = rasters[0];
    let covered = 0;
    for (let c = 0; c < fullRaster.face.length; c++) if (fullRaster.face[c] >= 0) covered++;
    coverageMin = Math.min(coverageMin, covered / discCells);
    coverageMax = Math.max(coverageMax, covered / discCells);
    if (covered === 0) continue;
    for (const ld of lightDirs) {
      const light: ShadeLight = {
        position: [ld[0] * far, ld[1] * far, ld[2] * far],
        ambient: [ambient, ambient, ambient],
        diffuse: [intensity, intensity, intensity],
        specular: [intensity, intensity, intensity],
      };
      const lightList = [light];
      const shadeAt = (m: Mesh, vertex: number, out: Vec3) => {
        const i = 3 * vertex;
        pos[0] = m.positions[i];
        pos[1] = m.positions[i + 1];
        pos[2] = m.positions[i + 2];
        nrm[0] = m.normals[i];
        nrm[1] = m.normals[i + 1];
        nrm[2] = m.normals[i + 2];
        return shade({ position: pos, normal: nrm, eye }, material, lightList, out);
      };
      /** Phong at cell c of raster r on mesh m into out; the point into pos. */
      const phongAt = (m: Mesh, r: Raster, c: number, out: Vec3) => {
        const f = r.face[c];
        pos[0] = pos[1] = pos[2] = 0;
        nrm[0] = nrm[1] = nrm[2] = 0;
        for (let k = 0; k < 3; k++) {
          const b = r.bary[3 * c + k];
          const i = 3 * m.faces[3 * f + k];
          pos[0] += b * m.positions[i];
          pos[1] += b * m.positions[i + 1];
          pos[2] += b * m.positions[i + 2];
          nrm[0] += b * m.normals[i];
          nrm[1] += b * m.normals[i + 1];
          nrm[2] += b * m.normals[i + 2];
        }
        return shade({ position: pos, normal: nrm, eye }, material, lightList, out);
      };
      // Phong at full detail at every covered cell, once per configuration.
      for (let c = 0; c < cells; c++) {
        if (fullRaster.face[c] < 0) continue;
        phongAt(full, fullRaster, c, ref);
        refs[3 * c] = ref[0];
        refs[3 * c + 1] = ref[1];
        refs[3 * c + 2] = ref[2];
      }
      stamp++;
      for (let mi = 0; mi < meshes.length; mi++) {
        const m = meshes[mi].mesh;
        const r = rasters[mi];
        const vcol = vertexColours[mi];
        const vstamp = vertexStamps[mi];
        /** Gouraud's colour of vertex v (computed once per configuration). */
        const vertexColour = (v: number, out: Vec3) => {
          if (vstamp[v] !== stamp) {
            shadeAt(m, v, tmp);
            vcol[3 * v] = tmp[0];
            vcol[3 * v + 1] = tmp[1];
            vcol[3 * v + 2] = tmp[2];
            vstamp[v] = stamp;
          }
          out[0] = vcol[3 * v];
          out[1] = vcol[3 * v + 1];
          out[2] = vcol[3 * v + 2];
          return out;
        };
        for (let s = 0; s < shadings.length; s++) {
          if (mi === 0 && s === 0) continue; // the reference itself
          counts.fill(0);
          let compared = 0;
          for (let c = 0; c < cells; c++) {
            const f = r.face[c];
            if (f < 0 || fullRaster.face[c] < 0) continue;
            compared++;
            ref[0] = refs[3 * c];
            ref[1] = refs[3 * c + 1];
            ref[2] = refs[3 * c + 2];
            let e: number;
            if (shadings[s] === 'phong') {
              e = levels(phongAt(m, r, c, cand), ref);
            } else if (shadings[s] === 'gouraud') {
              vertexColour(m.faces[3 * f], va);
              vertexColour(m.faces[3 * f + 1], vb);
              vertexColour(m.faces[3 * f + 2], vc);
              const b0 = r.bary[3 * c];
              const b1 = r.bary[3 * c + 1];
              const b2 = r.bary[3 * c + 2];
              for (let j = 0; j < 3; j++) cand[j] = b0 * va[j] + b1 * vb[j] + b2 * vc[j];
              e = levels(cand, ref);
            } else {
              fn[0] = m.faceNormals[3 * f];
              fn[1] = m.faceNormals[3 * f + 1];
              fn[2] = m.faceNormals[3 * f + 2];
              centroid[0] = m.centroids[3 * f];
              centroid[1] = m.centroids[3 * f + 1];
              centroid[2] = m.centroids[3 * f + 2];
              shade({ position: centroid, normal: fn, eye }, material, lightList, cand);
              // The derivatives path: the cell's own point with the face normal.
              pointOf(m, r, c, point);
              shade({ position: point, normal: fn, eye }, material, lightList, tmp);
              e = Math.max(levels(cand, ref), levels(tmp, ref));
            }
            if (e > maxSeen[mi][s]) maxSeen[mi][s] = e;
            for (let k = 0; k < nb; k++) {
              if (e > ERROR_BUDGETS[k]) counts[k]++;
              else break;
            }
          }
          if (compared === 0) continue;
          const w = worst[mi][s];
          for (let k = 0; k < nb; k++) w[k] = Math.max(w[k], counts[k] / compared);
        }
      }
    }
  }
  const rows: ShadingErrorRow[] = [];
  meshes.forEach((m, mi) => {
    shadings.forEach((shading, s) => {
      rows.push({
        shading,
        level: m.level,
        triangles: m.triangles,
        silhouetteError: m.silhouetteError,
        over: Array.from(worst[mi][s], (x) => Math.round(x * 1e6) / 1e6),
        max: maxSeen[mi][s],
      });
    });
  });
  return {
    budgets: ERROR_BUDGETS,
    coverageMin: Math.min(coverageMin, coverageMax),
    coverageMax,
    radius: radius / 1.0001,
    rows,
  };
}
