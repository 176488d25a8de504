import {
  type BufferGeometry,
  type Camera,
  type Group,
  type Material,
  Mesh,
  type Scene,
  Vector4,
  type WebGLRenderer,
} from 'three';
import { chooseSphereDetail, type SphereDetail } from './chooseSphereDetail.js';
import { projectedRadiusPx, silhouetteErrorScalePx } from './projectedRadiusPx.js';
import { SPHERE_BASES, type SphereBase } from './SphereBase.js';
import type { SphereNormals } from './SphereOptions.js';
import { SubdivisionSphereGeometry } from './SubdivisionSphereGeometry.js';
import { sphereCounts } from './sphereCounts.js';
import { sphereError } from './sphereError.js';
import { fail } from './validate.js';

/** Options of {@link AutoDetailSphere}. */
export interface AutoDetailSphereOptions {
  /** Largest silhouette error on screen, in pixels (the budget). Finite, > 0. @default 0.5 */
  maxErrorPx?: number;
  /** Base solids to choose from. @default ['tetrahedron', 'octahedron', 'icosahedron'] */
  bases?: readonly SphereBase[];
  /** Highest level used, 0 … 10; when even it misses the budget the finest sphere is drawn. @default 8 */
  maxLevel?: number;
  /** Sphere radius in model space. @default 1 */
  radius?: number;
  /** Normals of the geometries, as in `SubdivisionSphereGeometry`. @default 'none' (shaders use the position) */
  normals?: SphereNormals;
  /** Indexed geometries (flat normals or flat shading need `false`). @default true, false with flat normals */
  indexed?: boolean;
}

/** The detail an {@link AutoDetailSphere} draws and why. */
export interface AutoDetail extends SphereDetail {
  /** The sphere's radius on screen in pixels when the detail was chosen (see `projectedRadiusPx`). */
  readonly radiusPx: number;
  /**
   * Pixels of silhouette error per unit of relative radial error when the detail was chosen (see
   * `silhouetteErrorScalePx`): `errorPx = errorScalePx · sphereError(base, level)`, an upper bound of the
   * distance on screen between the mesh's outline and the exact ellipsoid's.
   */
  readonly errorScalePx: number;
  /** Whether `errorPx ≤ maxErrorPx` (false when even `maxLevel` misses the budget: the finest is drawn). */
  readonly meetsBudget: boolean;
}

const _viewport = /* @__PURE__ */ new Vector4();

/**
 * A sphere mesh whose subdivision follows its size on screen: the cheapest base and level (fewest triangles)
 * whose silhouette error on screen, bounded by `silhouetteErrorScalePx · sphereError(base, level)`, stays
 * within `maxErrorPx` (see `chooseSphereDetail`). The bound holds for any camera, scale and place on screen,
 * near the camera too (where the error grows faster than the radius). Geometries are cached per (base, level)
 * and shared thereafter: zooming back and forth never rebuilds, and nothing is recomputed while the camera,
 * canvas and object stay put (the bound is compared first).
 *
 * Call {@link AutoDetailSphere.update} before `renderer.render` to have the right detail in the same frame.
 * The mesh also updates itself in `onBeforeRender`, but three has already picked the geometry for that frame
 * by then, so a change there shows from the next frame: it dispatches a `'change'` event so that
 * render-on-demand apps can draw again.
 *
 * @example
 * const sphere = new AutoDetailSphere(new ShadingMaterial({ lights: [light] }), { maxErrorPx: 0.5 });
 * scene.add(sphere);
 * function frame() { sphere.update(camera, renderer); renderer.render(scene, camera); }
 */
export class AutoDetailSphere extends Mesh<BufferGeometry, Material> {
  /** Always true. */
  readonly isAutoDetailSphere = true;
  /** three's type name: `'AutoDetailSphere'`. */
  override type = 'AutoDetailSphere';

  /** The resolved options (validated; change them through the constructor). */
  readonly parameters: Readonly<Required<AutoDetailSphereOptions>>;

  /** Geometries built so far, by `'base/level'`. */
  readonly #cache = new Map<string, SubdivisionSphereGeometry>();
  #detail: AutoDetail;
  #scalePx = Number.NaN;
  #builds = 0;

  /**
   * @param material - drawn with every detail.
   * @param options - the budget and the geometry options.
   * @throws RangeError / TypeError naming the option, as `chooseSphereDetail` and `SubdivisionSphereGeometry` do.
   */
  constructor(material: Material, options: AutoDetailSphereOptions = {}) {
    super();
    const {
      maxErrorPx = 0.5,
      bases = SPHERE_BASES,
      maxLevel = 8,
      radius = 1,
      normals = 'none',
      indexed = normals !== 'flat',
    } = options;
    if (typeof maxLevel !== 'number' || !Number.isInteger(maxLevel) || maxLevel < 0 || maxLevel > 10) {
      fail('AutoDetailSphere', 'maxLevel', 'an integer from 0 to 10', maxLevel);
    }
    // Validates maxErrorPx and bases.
    chooseSphereDetail({ radiusPx: 0, maxErrorPx, bases, maxLevel });
    this.parameters = Object.freeze({
      maxErrorPx,
      bases: Object.freeze([...bases]),
      maxLevel,
      radius,
      normals,
      indexed,
    });
    this.material = material;
    // three ≥ 0.186 fires `dispose` from Object3D#dispose(); the event name is not in every @types/three.
    this.addEventListener('dispose' as never, () => this.disposeGeometries());
    // Until the first update: the coarsest sphere of the first base.
    this.#detail = this.#choose(0, 0);
    this.geometry = this.#geometry(this.#detail);
  }

  /** The detail drawn now (base, level, triangles, error bound on screen, projected radius, error scale). */
  get detail(): AutoDetail {
    return this.#detail;
  }

  /** How many geometries have been built (each (base, level) at most once). */
  get builds(): number {
    return this.#builds;
  }

  /**
   * Choose the detail for `camera` and a viewport of `viewportHeightPx` physical pixels (or the renderer's
   * current viewport), and swap the geometry when it changes. Updates `matrixWorld` first.
   * @returns whether the geometry changed.
   */
  update(camera: Camera, viewport: WebGLRenderer | number): boolean {
    const heightPx = typeof viewport === 'number' ? viewport : viewport.getCurrentViewport(_viewport).w;
    this.updateWorldMatrix(true, false);
    const view = {
      camera,
      matrixWorld: this.matrixWorld,
      viewportHeightPx: heightPx,
      radius: this.parameters.radius,
    };
    const scalePx = silhouetteErrorScalePx(view);
    if (scalePx === this.#scalePx) return false;
    this.#scalePx = scalePx;
    const detail = this.#choose(scalePx, projectedRadiusPx(view));
    const changed = detail.base !== this.#detail.base || detail.level !== this.#detail.level;
    this.#detail = detail;
    if (changed) this.geometry = this.#geometry(detail);
    return changed;
  }

  /** Keeps the detail current when the app does not call `update` (takes effect next frame, see the class). */
  override onBeforeRender(
    renderer: WebGLRenderer,
    _scene: Scene,
    camera: Camera,
    _geometry: BufferGeometry,
    _material: Material,
    _group: Group,
  ): void {
    if (this.update(camera, renderer)) this.dispatchEvent({ type: 'change' } as never);
  }

  /**
   * Dispose of every cached geometry (the material is the caller's). On three ≥ 0.186, `Object3D#dispose()`
   * does this too (through its `dispose` event); on older three, which has no `Object3D#dispose`, call this.
   */
  disposeGeometries(): void {
    for (const g of this.#cache.values()) g.dispose();
    this.#cache.clear();
  }

  #choose(errorScalePx: number, radiusPx: number): AutoDetail {
    const { maxErrorPx, bases, maxLevel } = this.parameters;
    if (Number.isFinite(errorScalePx)) {
      try {
        // chooseSphereDetail's error is radiusPx · sphereError: pass the error scale in its place.
        const d = chooseSphereDetail({ radiusPx: errorScalePx, maxErrorPx, bases, maxLevel });
        return { ...d, radiusPx, errorScalePx, meetsBudget: true };
      } catch (e) {
        if (!(e instanceof RangeError)) throw e;
      }
    }
    // Out of budget: the finest (smallest error) of the allowed spheres at maxLevel.
    let best = bases[0];
    for (const b of bases) if (sphereError(b, maxLevel) < sphereError(best, maxLevel)) best = b;
    return {
      base: best,
      level: maxLevel,
      triangles: sphereCounts(best, maxLevel).triangles,
      errorPx: errorScalePx * sphereError(best, maxLevel),
      radiusPx,
      errorScalePx,
      meetsBudget: false,
    };
  }

  #geometry({ base, level }: SphereDetail): SubdivisionSphereGeometry {
    const key = `${base}/${level}`;
    let g = this.#cache.get(key);
    if (g === undefined) {
      const { radius, normals, indexed } = this.parameters;
      g = new SubdivisionSphereGeometry({ base, level, radius, normals, indexed });
      this.#cache.set(key, g);
      this.#builds++;
    }
    return g;
  }
}
