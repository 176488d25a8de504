import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { silhouetteErrorScalePx, sphereError } from '@shadelab/sphere/detail';
import {
  type BufferGeometry,
  type Camera,
  DynamicDrawUsage,
  InstancedBufferAttribute,
  InstancedMesh,
  type Material,
  Matrix4,
  type Mesh,
  Vector4,
  type WebGLRenderer,
} from 'three';
import { type CostedShading, shadingCost } from './adaptiveCosts.js';
import { type AllocationUnit, allocateShading } from './allocateShading.js';
import { flatShadingGeometry } from './flatShadingGeometry.js';
import { FLAT_CORNERS, SPHERE_FLAG } from './geometryFlags.js';
import { checkShading, SHADINGS, type Shading } from './options.js';
import { ShadingMaterial } from './ShadingMaterial.js';
import {
  measureShadingError,
  overFraction,
  type ShadingErrorLevel,
  type ShadingErrorModelOptions,
  type ShadingErrorRow,
  type ShadingErrorTable,
} from './shadingErrorModel.js';
import { MATERIAL_PROPERTIES, SHADING_MATERIAL_OPTION_KEYS } from './shadingOptionsOf.js';

/** Options of {@link AdaptiveShading}. */
export interface AdaptiveShadingOptions {
  /**
   * The budget: the largest difference at a pixel, in 8-bit sRGB levels, from the same scene drawn with Phong
   * shading at full detail, kept at all but `overFraction` of the drawn pixels. Finite, > 0 (255: anything goes
   * but the silhouette of a coarser level).
   */
  maxError: number;
  /**
   * The fraction of the drawn pixels allowed over `maxError` (the budget is a percentile: no cheaper shading
   * than Phong keeps every pixel of a curved mesh within a few levels at any size). In [0, 0.5]. @default 0.004
   */
  overFraction?: number;
  /** Hysteresis, relative: a choice changes back only after the cost or the total moved by this factor. @default 0.15 */
  hysteresis?: number;
  /** Levels below a subdivision sphere's own that may be drawn, 0 … 8. @default 3 */
  levelsBelow?: number;
  /** How the error tables are measured when `add` is given none (see `measureShadingError`). @default {} */
  model?: Omit<ShadingErrorModelOptions, 'surface' | 'levels'>;
}

/** Options of {@link AdaptiveShading.add}. */
export interface AdaptiveAddOptions {
  /** The object's error table, measured ahead of time (`measureShadingError`); measured at `add` when omitted. */
  table?: ShadingErrorTable;
  /**
   * The shadings it may take. `['flat']` keeps it flat and lets the measured costs pick flat shading's path
   * (prepared geometry or derivatives). @default ['flat', 'gouraud', 'phong']
   */
  shadings?: readonly Shading[];
}

/** What an object (or an instance) is drawn with now. */
export interface AdaptiveChoice {
  /** The shading. */
  readonly shading: Shading;
  /** The subdivision level, or `null` for the geometry as given. */
  readonly level: number | null;
  /** Flat shading's path (`null` for gouraud and phong). */
  readonly flatPath: 'prepared' | 'derivatives' | null;
}

/** One drawable choice of an object. */
interface Candidate extends AdaptiveChoice {
  readonly row: ShadingErrorRow;
  readonly costed: CostedShading;
  readonly geometry: BufferGeometry;
  readonly triangles: number;
}

/** A managed object. */
interface Entry {
  readonly object: Mesh;
  readonly instanced: InstancedMesh | null;
  readonly source: ShadingMaterial;
  readonly geometry: BufferGeometry;
  readonly table: ShadingErrorTable;
  readonly candidates: Candidate[];
  readonly variants: Map<Shading, ShadingMaterial>;
  /** Mesh: the current candidate. */
  choice: number;
  // Instanced.
  count: number;
  groups: (InstancedMesh | null)[];
  members: number[][]; // per candidate: instance ids by slot
  groupOf: Int32Array;
  slotOf: Int32Array;
  matrixVersion: number;
  colorVersion: number;
  // The cache of `update`: each unit's costs and over-budget pixels, and what they were computed from.
  /** Per unit (1 for a Mesh, one per instance): costs per candidate. */
  unitCosts: Float64Array[];
  /** Per unit: over-budget pixels per candidate. */
  unitOvers: Float64Array[];
  /** Per unit: the drawn pixels (the floor of the frame's allowance). */
  unitDrawn: Float64Array;
  /** The object's matrixWorld the units were computed with. */
  worldKey: Float64Array;
  /** The instance matrices' version (and count) the units were computed with; −1: never. */
  unitsVersion: number;
  unitsCount: number;
}

/** What the last {@link AdaptiveShading.update} did: how much the cache saved. */
export interface AdaptiveUpdateStats {
  /** Units chosen for: one per Mesh, one per instance of each InstancedMesh. */
  readonly units: number;
  /** Units whose projected size, costs and over-budget pixels were computed again (the others came from the cache). */
  readonly recomputed: number;
  /** Whether the frame's allowance was spent again (`false`: nothing moved, every choice was kept as it was). */
  readonly allocated: boolean;
}

const _viewport = /* @__PURE__ */ new Vector4();
const _world = /* @__PURE__ */ new Matrix4();
const _instance = /* @__PURE__ */ new Matrix4();
const _view = /* @__PURE__ */ new Matrix4();

/** Geometries made by an AdaptiveShading, per source geometry: `level/path`. */
type Derived = Map<string, BufferGeometry>;

/**
 * Picks, every frame, the cheapest shading (flat, Gouraud or Phong) and detail (a subdivision sphere's level)
 * for each object, and for each instance of an `InstancedMesh`, that keeps a budget of image error against the
 * same scene drawn with Phong shading at full detail, from each one's size on screen.
 *
 * How. At `add`, the object's mesh and material get an error table (`measureShadingError`: the fraction of
 * covered pixels over each budget, per shading and level, measured on the CPU with `shade()`). Each `update`
 * estimates every object's covered pixels (its bounding disc on screen, perspective or orthographic, times the
 * table's coverage), prices each choice with the measured costs (`shadingCost`: by triangles per pixel, so flat
 * is not assumed cheapest) and its over-budget pixels (the table's fraction × its pixels, plus, for a coarser
 * sphere, its silhouette: perimeter × `silhouetteErrorScalePx` × `sphereError`), and spends the frame's
 * allowance (`overFraction` × the drawn pixels) where it saves the most (`allocateShading`), with hysteresis.
 * Small objects, whose over-budget pixels are few, get the cheap choices first.
 *
 * Drawing. A Mesh gets one of up to three variants of its ShadingMaterial (clones with `shading` set, synced
 * from the original at every `update`: edit the original) and, for a coarser level or flat shading's prepared
 * path, a geometry made once and cached. An `InstancedMesh` draws nothing itself (its `count` is set to 0 while
 * managed; set `count` to change the number of instances): its instances are drawn by one child `InstancedMesh`
 * per choice (`name` 'AdaptiveShading group'), and an instance is moved between them only when its choice
 * changes (one matrix written in each of two groups, one update range per group); all matrices are copied
 * again only when the original's `instanceMatrix` (or `instanceColor`) was flagged `needsUpdate`. The programs
 * are the material's own variants (one per shading and geometry kind, shared by every object): no shader is
 * made per object.
 *
 * @example
 * const adaptive = new AdaptiveShading({ maxError: 8 });
 * adaptive.add(mesh); // a Mesh or InstancedMesh with a ShadingMaterial
 * function frame() { adaptive.update(camera, renderer); renderer.render(scene, camera); }
 */
export class AdaptiveShading {
  /** The resolved options. */
  readonly parameters: Readonly<Required<AdaptiveShadingOptions>>;
  readonly #entries = new Map<Mesh, Entry>();
  readonly #derived = new WeakMap<BufferGeometry, Derived>();
  /** Tables measured so far, per geometry, by the surface's options. */
  readonly #tables = new WeakMap<BufferGeometry, Map<string, ShadingErrorTable>>();
  readonly #made = new Set<BufferGeometry>();
  #size: { width: number; height: number } | null = null;
  /** The camera's matrixWorld and projectionMatrix and the viewport's size at the last update. */
  readonly #cameraKey = new Float64Array(34).fill(Number.NaN);
  /** Objects were added, removed or resized since the last allocation. */
  #stale = true;
  #stats: AdaptiveUpdateStats = { units: 0, recomputed: 0, allocated: false };

  /**
   * @param options - the budget and the tuning.
   * @throws RangeError naming `maxError` (not finite and > 0), `overFraction`, `hysteresis` or `levelsBelow`.
   */
  constructor(options: AdaptiveShadingOptions) {
    if (options === null || typeof options !== 'object') {
      throw new TypeError(`AdaptiveShading: options must be an object with maxError, got ${String(options)}`);
    }
    const { maxError, overFraction = 0.004, hysteresis = 0.15, levelsBelow = 3, model = {} } = options;
    if (typeof maxError !== 'number' || !Number.isFinite(maxError) || !(maxError > 0)) {
      throw new RangeError(
        `AdaptiveShading: maxError must be a finite number > 0 (8-bit sRGB levels, up to 255), got ${String(maxError)}`,
      );
    }
    if (typeof overFraction !== 'number' || !(overFraction >= 0 && overFraction <= 0.5)) {
      throw new RangeError(`AdaptiveShading: overFraction must be in [0, 0.5], got ${String(overFraction)}`);
    }
    if (typeof hysteresis !== 'number' || !(hysteresis >= 0 && hysteresis <= 10)) {
      throw new RangeError(`AdaptiveShading: hysteresis must be in [0, 10], got ${String(hysteresis)}`);
    }
    if (!Number.isInteger(levelsBelow) || levelsBelow < 0 || levelsBelow > 8) {
      throw new RangeError(
        `AdaptiveShading: levelsBelow must be an integer from 0 to 8, got ${String(levelsBelow)}`,
      );
    }
    this.parameters = Object.freeze({
      maxError: Math.min(maxError, 255),
      overFraction,
      hysteresis,
      levelsBelow,
      model,
    });
  }

  /** The objects managed, in the order added. */
  get objects(): Mesh[] {
    return [...this.#entries.keys()];
  }

  /**
   * Manage `object`: a `Mesh` or `InstancedMesh` whose material is a `ShadingMaterial` (the surface; its
   * `shading` is what this chooses) and whose geometry has normals (or is a sphere). Adding it again re-measures
   * its table when the material's options changed (tables are kept per geometry and options: objects sharing
   * both measure once).
   * @throws TypeError for anything else (named), once: nothing is managed then.
   */
  add(object: Mesh, options: AdaptiveAddOptions = {}): this {
    const m = object as Mesh & { isMesh?: boolean };
    if (m === null || typeof m !== 'object' || m.isMesh !== true) {
      throw new TypeError(
        `AdaptiveShading.add: object must be a THREE.Mesh or InstancedMesh, got ${describe(object)}`,
      );
    }
    if (this.#entries.has(object)) this.remove(object);
    const source = object.material as Material | Material[];
    if (!(source instanceof ShadingMaterial)) {
      throw new TypeError(
        `AdaptiveShading.add: ${object.type} '${object.name}' must have one ShadingMaterial, got ${Array.isArray(source) ? 'an array of materials' : describe(source)}`,
      );
    }
    const geometry = object.geometry;
    const sphere = geometry.type === 'SubdivisionSphereGeometry' || geometry.userData[SPHERE_FLAG] === true;
    if (geometry.getAttribute('normal') === undefined && !sphere) {
      throw new TypeError(
        `AdaptiveShading.add: ${object.type} '${object.name}': its ${geometry.type} needs a normal attribute (or to be a sphere) to be compared with Phong shading`,
      );
    }
    const shadings = (options.shadings ?? SHADINGS).map((s) =>
      checkShading('AdaptiveShading.add shadings', s),
    );
    if (shadings.length === 0)
      throw new RangeError('AdaptiveShading.add: shadings must name at least one shading');
    const levels = this.#levels(geometry);
    const table = options.table ?? this.#measure(geometry, source, levels);
    const variants = new Map<Shading, ShadingMaterial>();
    for (const s of shadings) {
      const v = source.clone();
      v.shading = s;
      v.name = `${source.name} (adaptive ${s})`;
      variants.set(s, v);
    }
    const candidates = this.#candidates(geometry, source, table, shadings, levels);
    const instanced = (object as InstancedMesh).isInstancedMesh === true ? (object as InstancedMesh) : null;
    const entry: Entry = {
      object,
      instanced,
      source,
      geometry,
      table,
      candidates,
      variants,
      choice: -1,
      count: 0,
      groups: candidates.map(() => null),
      members: candidates.map(() => []),
      groupOf: new Int32Array(0),
      slotOf: new Int32Array(0),
      matrixVersion: -1,
      colorVersion: -1,
      unitCosts: [],
      unitOvers: [],
      unitDrawn: new Float64Array(0),
      worldKey: new Float64Array(16).fill(Number.NaN),
      unitsVersion: -1,
      unitsCount: -1,
    };
    this.#entries.set(object, entry);
    this.#stale = true;
    if (instanced) this.#resize(entry, instanced.count);
    return this;
  }

  /** Stop managing `object` and put back its material, geometry (and an InstancedMesh's count). */
  remove(object: Mesh): this {
    const e = this.#entries.get(object);
    if (!e) return this;
    this.#entries.delete(object);
    this.#stale = true;
    object.material = e.source;
    object.geometry = e.geometry;
    if (e.instanced) {
      for (const g of e.groups) {
        if (!g) continue;
        e.instanced.remove(g);
        g.dispose();
      }
      e.instanced.count = e.count;
    }
    for (const v of e.variants.values()) v.dispose();
    return this;
  }

  /** The choice an object, or one instance of an InstancedMesh, is drawn with (null when not managed). */
  choiceOf(object: Mesh, instance = 0): AdaptiveChoice | null {
    const e = this.#entries.get(object);
    if (!e) return null;
    const k = e.instanced ? e.groupOf[instance] : e.choice;
    const c = e.candidates[k];
    return c ? { shading: c.shading, level: c.level, flatPath: c.flatPath } : null;
  }

  /** The error table of a managed object (null when not managed). */
  tableOf(object: Mesh): ShadingErrorTable | null {
    return this.#entries.get(object)?.table ?? null;
  }

  /** The child InstancedMeshes drawing a managed InstancedMesh's instances, one per choice in use. */
  groupsOf(object: Mesh): InstancedMesh[] {
    const e = this.#entries.get(object);
    return e ? (e.groups.filter((g) => g !== null && g.count > 0) as InstancedMesh[]) : [];
  }

  /** What the last `update` did (units, how many were computed again, whether the choices were made again). */
  get stats(): AdaptiveUpdateStats {
    return this.#stats;
  }

  /**
   * Choose for every managed object and instance, for `camera` and the viewport. Call before `renderer.render`.
   * Updates the camera's and the objects' world matrices first.
   *
   * The viewport is the size of the picture in physical pixels (what the projected sizes are measured in): pass
   * the `WebGLRenderer` (its current viewport: the canvas's drawing-buffer size, pixel ratio included, or what
   * `setViewport` set) or `{ width, height }` in physical pixels (CSS pixels × `devicePixelRatio`). It is
   * remembered: give it at least once, and again when it changes (`update(camera)` reuses the last one).
   *
   * Cached: each object's (and each instance's) projected size, costs and over-budget pixels are computed
   * again only when the camera (its `matrixWorld` or `projectionMatrix`), the viewport, the object's
   * `matrixWorld` or, for an InstancedMesh, its `instanceMatrix.version` (bumped by `needsUpdate = true`) or
   * count changed; the frame's allowance is spent again only when one of them did, or an object was added or
   * removed. A still scene costs a comparison of matrices per object. `stats` says what the last call did.
   * @throws TypeError when no viewport was ever given.
   */
  update(camera: Camera, viewport?: WebGLRenderer | { width: number; height: number }): void {
    if (viewport !== undefined) {
      if ('getCurrentViewport' in viewport) {
        const v = viewport.getCurrentViewport(_viewport);
        this.#size = { width: v.z, height: v.w };
      } else this.#size = { width: viewport.width, height: viewport.height };
    }
    const size = this.#size;
    if (size === null) {
      throw new TypeError(
        'AdaptiveShading.update: give the viewport (the renderer or { width, height }) at least once',
      );
    }
    camera.updateMatrixWorld();
    const key = this.#cameraKey;
    let cameraMoved = !same(key, 0, camera.matrixWorld.elements);
    cameraMoved = !same(key, 16, camera.projectionMatrix.elements) || cameraMoved;
    if (key[32] !== size.width || key[33] !== size.height) {
      key[32] = size.width;
      key[33] = size.height;
      cameraMoved = true;
    }
    const screen = Math.max(0, size.width * size.height) || 0;
    const p = camera.projectionMatrix.elements;
    const focal = (size.height / 2) * Math.abs(p[5]);
    const ortho = p[15] !== 0 || p[11] === 0;
    _view.copy(camera.matrixWorld).invert();
    const { maxError, overFraction: fraction, hysteresis } = this.parameters;

    let moved = this.#stale;
    let units = 0;
    let recomputed = 0;
    for (const e of this.#entries.values()) {
      this.#sync(e);
      const o = e.object;
      o.updateWorldMatrix(true, false);
      if (e.instanced) this.#adoptInstances(e);
      const n = e.instanced ? e.count : 1;
      units += n;
      const worldMoved = !same(e.worldKey, 0, o.matrixWorld.elements);
      const version = e.instanced ? e.instanced.instanceMatrix.version : 0;
      if (!cameraMoved && !worldMoved && e.unitsVersion === version && e.unitsCount === n) continue;
      moved = true;
      recomputed += n;
      e.unitsVersion = version;
      e.unitsCount = n;
      if (e.unitCosts.length !== n) {
        e.unitCosts = new Array(n);
        e.unitOvers = new Array(n);
        e.unitDrawn = new Float64Array(n);
      }
      for (let i = 0; i < n; i++) {
        if (e.instanced) {
          _instance.fromArray(e.instanced.instanceMatrix.array, 16 * i);
          _world.multiplyMatrices(o.matrixWorld, _instance);
        } else _world.copy(o.matrixWorld);
        const unit = this.#unit(e, _world, camera, size.height, focal, ortho, screen, maxError);
        e.unitCosts[i] = unit.costs;
        e.unitOvers[i] = unit.overs;
        e.unitDrawn[i] = unit.drawn;
      }
    }
    this.#stats = { units, recomputed, allocated: moved };
    if (!moved) {
      for (const e of this.#entries.values()) if (e.instanced) this.#flush(e);
      return;
    }
    this.#stale = false;
    const all: AllocationUnit[] = [];
    const owners: { entry: Entry; instance: number }[] = [];
    let drawn = 0;
    for (const e of this.#entries.values()) {
      for (let i = 0; i < e.unitCosts.length; i++) {
        drawn += e.unitDrawn[i];
        all.push({
          costs: e.unitCosts[i],
          overs: e.unitOvers[i],
          previous: e.instanced ? e.groupOf[i] : e.choice,
        });
        owners.push({ entry: e, instance: i });
      }
    }
    const allowance = fraction * Math.min(drawn, screen);
    const choice = allocateShading(all, allowance, hysteresis);
    for (let u = 0; u < owners.length; u++) {
      const { entry, instance } = owners[u];
      if (entry.instanced) this.#move(entry, instance, choice[u]);
      else this.#apply(entry, choice[u]);
    }
    for (const e of this.#entries.values()) if (e.instanced) this.#flush(e);
  }

  /** Stop managing every object (as `remove`) and dispose of the geometries made for them. */
  dispose(): void {
    for (const o of [...this.#entries.keys()]) this.remove(o);
    for (const g of this.#made) g.dispose();
    this.#made.clear();
  }

  /** The table of `geometry` drawn with `source`'s options: measured once per geometry and options. */
  #measure(
    geometry: BufferGeometry,
    source: ShadingMaterial,
    levels: ShadingErrorLevel[],
  ): ShadingErrorTable {
    const surface = surfaceOf(source);
    const key = JSON.stringify(surface);
    let known = this.#tables.get(geometry);
    if (!known) {
      known = new Map();
      this.#tables.set(geometry, known);
    }
    let table = known.get(key);
    if (!table) {
      table = measureShadingError(geometry, { ...this.parameters.model, surface, levels });
      known.set(key, table);
    }
    return table;
  }

  /** A subdivision sphere's coarser levels (none for any other geometry). */
  #levels(geometry: BufferGeometry): ShadingErrorLevel[] {
    if (geometry.type !== 'SubdivisionSphereGeometry') return [];
    const params = (geometry as SubdivisionSphereGeometry).parameters;
    if (!params || !Number.isInteger(params.level)) return [];
    const out: ShadingErrorLevel[] = [];
    const lowest = Math.max(0, params.level - this.parameters.levelsBelow);
    for (let level = lowest; level < params.level; level++) {
      out.push({
        geometry: this.#derive(
          geometry,
          `level ${level}`,
          () => new SubdivisionSphereGeometry({ ...params, level }),
        ),
        level,
        silhouetteError: sphereError(params.base, level),
      });
    }
    return out;
  }

  #derive(geometry: BufferGeometry, key: string, make: () => BufferGeometry): BufferGeometry {
    let d = this.#derived.get(geometry);
    if (!d) {
      d = new Map();
      this.#derived.set(geometry, d);
    }
    let g = d.get(key);
    if (!g) {
      g = make();
      d.set(key, g);
      this.#made.add(g);
    }
    return g;
  }

  #candidates(
    geometry: BufferGeometry,
    source: ShadingMaterial,
    table: ShadingErrorTable,
    shadings: readonly Shading[],
    levels: readonly ShadingErrorLevel[],
  ): Candidate[] {
    const out: Candidate[] = [];
    const geometryOf = (level: number | null) =>
      level === null ? geometry : (levels.find((l) => l.level === level)?.geometry ?? null);
    // The prepared path carries positions only: not for a surface that reads uv or colour attributes.
    const attributes =
      source.map !== null ||
      source.alphaMap !== null ||
      source.emissiveMap !== null ||
      source.normalMap !== null ||
      source.vertexColors;
    for (const row of table.rows) {
      if (!shadings.includes(row.shading)) continue;
      const g = geometryOf(row.level);
      if (g === null) continue;
      const triangles = row.triangles;
      if (row.shading !== 'flat') {
        out.push({ ...common(row, g, triangles), costed: row.shading, flatPath: null });
        continue;
      }
      const prepared = g.getAttribute(FLAT_CORNERS[0]) !== undefined || g.index === null;
      if (prepared) {
        out.push({ ...common(row, g, triangles), costed: 'flat-prepared', flatPath: 'prepared' });
        continue;
      }
      out.push({ ...common(row, g, triangles), costed: 'flat-derivatives', flatPath: 'derivatives' });
      if (!attributes) {
        const soup = this.#derive(g, 'prepared', () => flatShadingGeometry(g));
        out.push({ ...common(row, soup, triangles), costed: 'flat-prepared', flatPath: 'prepared' });
      }
    }
    // Phong at full detail (the reference, never over budget) is always there: the table's first row.
    if (!out.some((c) => c.shading === 'phong' && c.level === null) && shadings.includes('phong')) {
      throw new Error('AdaptiveShading: the error table has no Phong row at full detail');
    }
    return out;
  }

  /** Keep every variant equal to the source material (its options and Material properties), but its shading. */
  #sync(e: Entry): void {
    const s = e.source as unknown as Record<string, unknown>;
    for (const v of e.variants.values()) {
      const t = v as unknown as Record<string, unknown>;
      for (const key of SHADING_MATERIAL_OPTION_KEYS) {
        if (key === 'shading') continue;
        const prop = key === 'lights' ? 'phongLights' : key;
        const value = s[prop];
        const mine = t[prop];
        if (key === 'normalScale') v.normalScale.copy(e.source.normalScale);
        else if (isColor(value)) {
          if (!isColor(mine) || !mine.equals(value)) t[prop] = value;
        } else if (Array.isArray(value) && Array.isArray(mine)) {
          if (value.length !== mine.length || value.some((x, i) => x !== mine[i])) t[prop] = value;
        } else if (mine !== value) t[prop] = value;
      }
      let changed = false;
      for (const key of MATERIAL_PROPERTIES) {
        if (t[key] !== s[key]) {
          t[key] = s[key];
          changed = true;
        }
      }
      if (changed || v.userData.sourceVersion !== e.source.version) {
        v.userData.sourceVersion = e.source.version;
        v.needsUpdate = true;
      }
    }
  }

  /** One object's (or instance's) costs and over-budget pixels per candidate, for this camera. */
  #unit(
    e: Entry,
    world: Matrix4,
    camera: Camera,
    heightPx: number,
    focal: number,
    ortho: boolean,
    screen: number,
    maxError: number,
  ): { costs: Float64Array; overs: Float64Array; drawn: number } {
    const m = world.elements;
    const scale = Math.sqrt(
      Math.max(
        m[0] * m[0] + m[1] * m[1] + m[2] * m[2],
        m[4] * m[4] + m[5] * m[5] + m[6] * m[6],
        m[8] * m[8] + m[9] * m[9] + m[10] * m[10],
      ),
    );
    const R = e.table.radius * scale;
    let radiusPx: number;
    if (ortho) radiusPx = R * focal;
    else {
      const v = _view.elements;
      // Depth of the centre in front of the eye.
      const w = -(v[2] * m[12] + v[6] * m[13] + v[10] * m[14] + v[14]);
      const d = Math.hypot(
        m[12] - camera.matrixWorld.elements[12],
        m[13] - camera.matrixWorld.elements[13],
        m[14] - camera.matrixWorld.elements[14],
      );
      if (w < -R)
        radiusPx = 0; // wholly behind the eye
      else if (!(d > R)) radiusPx = Number.POSITIVE_INFINITY;
      else radiusPx = (R * focal) / Math.sqrt((d - R) * (d + R));
    }
    // Not a number (a degenerate camera, near = far): the largest, so the reference is drawn.
    if (Number.isNaN(radiusPx)) radiusPx = Number.POSITIVE_INFINITY;
    const disc = Math.min(Math.PI * radiusPx * radiusPx, screen);
    const covered = Math.min(disc * e.table.coverageMax, screen);
    const drawn = Math.min(disc * e.table.coverageMin, screen);
    const n = e.candidates.length;
    const costs = new Float64Array(n);
    const overs = new Float64Array(n);
    let silhouetteScale = Number.NaN;
    for (let c = 0; c < n; c++) {
      const cand = e.candidates[c];
      costs[c] = shadingCost(cand.costed, cand.triangles, covered);
      let over = overFraction(e.table, cand.row, maxError) * covered;
      if (cand.row.silhouetteError > 0 && covered > 0) {
        if (Number.isNaN(silhouetteScale)) {
          silhouetteScale = silhouetteErrorScalePx({
            camera,
            matrixWorld: world,
            viewportHeightPx: heightPx > 0 ? heightPx : 1,
            radius: e.table.radius > 0 ? e.table.radius : 1,
          });
        }
        // The pixels between the two outlines: the perimeter times the outline's displacement.
        const errorPx = silhouetteScale * cand.row.silhouetteError;
        const perimeter = 2 * Math.PI * Math.min(radiusPx, Math.sqrt(screen));
        over += Number.isFinite(errorPx) ? Math.min(perimeter * errorPx, screen) : screen;
      }
      overs[c] = Number.isFinite(over) ? over : screen;
      if (!Number.isFinite(costs[c])) costs[c] = Number.MAX_VALUE;
    }
    return { costs, overs, drawn: Number.isFinite(drawn) ? drawn : screen };
  }

  #apply(e: Entry, k: number): void {
    if (k === e.choice) return;
    e.choice = k;
    const c = e.candidates[k];
    e.object.geometry = c.geometry;
    e.object.material = e.variants.get(c.shading) as ShadingMaterial;
  }

  /** Take the original InstancedMesh's count, matrices and colours when they changed. */
  #adoptInstances(e: Entry): void {
    const im = e.instanced as InstancedMesh;
    if (im.count !== 0) this.#resize(e, im.count);
    const matrices = im.instanceMatrix;
    const colors = im.instanceColor;
    const all =
      matrices.version !== e.matrixVersion || (colors !== null && colors.version !== e.colorVersion);
    if (!all) return;
    e.matrixVersion = matrices.version;
    if (colors) e.colorVersion = colors.version;
    for (let k = 0; k < e.candidates.length; k++) {
      const g = e.groups[k];
      if (!g) continue;
      const ids = e.members[k];
      for (let s = 0; s < ids.length; s++) this.#write(e, g, s, ids[s]);
      markRange(g, 0, ids.length - 1);
    }
  }

  /** The number of instances changed: every instance starts again in the reference group. */
  #resize(e: Entry, count: number): void {
    const im = e.instanced as InstancedMesh;
    this.#stale = true;
    e.unitsCount = -1;
    for (const g of e.groups) {
      if (!g) continue;
      im.remove(g);
      g.dispose();
    }
    e.count = count;
    im.count = 0;
    e.groups = e.candidates.map(() => null);
    e.members = e.candidates.map(() => []);
    e.groupOf = new Int32Array(count).fill(-1);
    e.slotOf = new Int32Array(count).fill(-1);
    e.matrixVersion = im.instanceMatrix.version;
    e.colorVersion = im.instanceColor ? im.instanceColor.version : -1;
  }

  #group(e: Entry, k: number): InstancedMesh {
    let g = e.groups[k];
    if (g) return g;
    const im = e.instanced as InstancedMesh;
    const c = e.candidates[k];
    g = new InstancedMesh(c.geometry, e.variants.get(c.shading) as ShadingMaterial, Math.max(1, e.count));
    g.name = 'AdaptiveShading group';
    g.count = 0;
    g.instanceMatrix.setUsage(DynamicDrawUsage);
    if (im.instanceColor) {
      g.instanceColor = new InstancedBufferAttribute(new Float32Array(3 * Math.max(1, e.count)), 3);
      g.instanceColor.setUsage(DynamicDrawUsage);
    }
    g.frustumCulled = false;
    g.castShadow = im.castShadow;
    g.receiveShadow = im.receiveShadow;
    g.renderOrder = im.renderOrder;
    g.layers.mask = im.layers.mask;
    g.userData.dirty = [Number.POSITIVE_INFINITY, -1];
    e.groups[k] = g;
    im.add(g);
    return g;
  }

  #write(e: Entry, g: InstancedMesh, slot: number, id: number): void {
    const im = e.instanced as InstancedMesh;
    const src = im.instanceMatrix.array;
    const dst = g.instanceMatrix.array;
    for (let j = 0; j < 16; j++) dst[16 * slot + j] = src[16 * id + j];
    if (im.instanceColor && g.instanceColor) {
      const cs = im.instanceColor.array;
      const cd = g.instanceColor.array;
      for (let j = 0; j < 3; j++) cd[3 * slot + j] = cs[3 * id + j];
    }
  }

  /** Put instance `id` in candidate `k`'s group (swap-remove from its old group). */
  #move(e: Entry, id: number, k: number): void {
    const old = e.groupOf[id];
    if (old === k) return;
    if (old >= 0) {
      const g = e.groups[old] as InstancedMesh;
      const ids = e.members[old];
      const slot = e.slotOf[id];
      const last = ids.pop() as number;
      if (last !== id) {
        ids[slot] = last;
        e.slotOf[last] = slot;
        this.#write(e, g, slot, last);
        markRange(g, slot, slot);
      }
      g.count = ids.length;
    }
    const g = this.#group(e, k);
    const ids = e.members[k];
    const slot = ids.length;
    ids.push(id);
    e.groupOf[id] = k;
    e.slotOf[id] = slot;
    this.#write(e, g, slot, id);
    markRange(g, slot, slot);
    g.count = ids.length;
  }

  /** One update range per group that changed this frame. */
  #flush(e: Entry): void {
    for (const g of e.groups) {
      if (!g) continue;
      g.visible = g.count > 0;
      const dirty = g.userData.dirty as [number, number];
      if (dirty[1] < dirty[0]) continue;
      for (const a of g.instanceColor ? [g.instanceMatrix, g.instanceColor] : [g.instanceMatrix]) {
        a.clearUpdateRanges();
        a.addUpdateRange(dirty[0] * a.itemSize, (dirty[1] - dirty[0] + 1) * a.itemSize);
        a.needsUpdate = true;
      }
      dirty[0] = Number.POSITIVE_INFINITY;
      dirty[1] = -1;
    }
  }
}

/** Whether `key[at … at + 16)` equals `m`; copies `m` there when not. */
function same(key: Float64Array, at: number, m: ArrayLike<number>): boolean {
  let equal = true;
  for (let i = 0; i < 16; i++) {
    if (key[at + i] !== m[i]) {
      key[at + i] = m[i];
      equal = false;
    }
  }
  return equal;
}

function markRange(g: InstancedMesh, from: number, to: number): void {
  if (to < from) return;
  const d = g.userData.dirty as [number, number];
  d[0] = Math.min(d[0], from);
  d[1] = Math.max(d[1], to);
}

function common(row: ShadingErrorRow, geometry: BufferGeometry, triangles: number) {
  return { row, geometry, triangles, shading: row.shading, level: row.level };
}

function isColor(v: unknown): v is { equals(o: unknown): boolean; isColor: true } {
  return typeof v === 'object' && v !== null && (v as { isColor?: boolean }).isColor === true;
}

function describe(v: unknown): string {
  if (v === null || v === undefined) return String(v);
  const t = (v as { type?: unknown }).type;
  return typeof t === 'string' ? t : typeof v;
}

/** A ShadingMaterial's options as the error model reads them. */
function surfaceOf(m: ShadingMaterial) {
  return {
    ka: [m.ka.r, m.ka.g, m.ka.b],
    kd: [m.kd.r, m.kd.g, m.kd.b],
    ks: [m.ks.r, m.ks.g, m.ks.b],
    shininess: m.shininess,
    lighting: m.lighting,
    celBands: m.celBands,
    emissive: [m.emissive.r, m.emissive.g, m.emissive.b],
  };
}
