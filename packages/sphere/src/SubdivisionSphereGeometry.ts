import { BufferAttribute, BufferGeometry, Sphere, Vector3 } from 'three';
import { resolveSphereOptions, type SphereParameters, type SubdivideSphereOptions } from './SphereOptions.js';
import { buildSphere } from './subdivideSphere.js';

/**
 * A three.js geometry of the subdivision sphere (see `subdivideSphere` for the construction): a `position`
 * attribute, a `normal` attribute unless `normals` is `'none'`, and an index unless `indexed` is false.
 *
 * Without a normal attribute a shader can use the exact sphere normal, normalize(position): shadelab's
 * material recognises this geometry by `type === 'SubdivisionSphereGeometry'` and `parameters.radius`.
 *
 * @example
 * ```ts
 * import { Mesh, MeshNormalMaterial } from 'three';
 * const sphere = new Mesh(new SubdivisionSphereGeometry({ level: 5, base: 'icosahedron', radius: 2 }),
 *   new MeshNormalMaterial());
 * ```
 */
export class SubdivisionSphereGeometry extends BufferGeometry {
  /** `'SubdivisionSphereGeometry'`. */
  override type = 'SubdivisionSphereGeometry';

  /** The resolved options this geometry was built from (defaults applied); changing them rebuilds nothing. */
  parameters: SphereParameters;

  /**
   * @param options - As for `subdivideSphere`; defaults: level 6, tetrahedron, radius 1, smooth normals,
   * indexed (non-indexed for flat normals), maxBytes 512 MiB.
   * @throws RangeError / TypeError naming the option for bad options, and RangeError with the estimated bytes
   * above `maxBytes`.
   */
  constructor(options: SubdivideSphereOptions = {}) {
    super();
    this.parameters = resolveSphereOptions('SubdivisionSphereGeometry', options);
    const { positions, normals, indices } = buildSphere('SubdivisionSphereGeometry', this.parameters);
    this.setAttribute('position', new BufferAttribute(positions, 3));
    if (normals) this.setAttribute('normal', new BufferAttribute(normals, 3));
    if (indices) this.setIndex(new BufferAttribute(indices, 1));
    this.computeBoundingSphere();
  }

  /** The exact bounding sphere: centre at the origin, radius `parameters.radius` (every vertex lies on it). */
  override computeBoundingSphere(): void {
    if (this.boundingSphere === null) this.boundingSphere = new Sphere();
    this.boundingSphere.set(new Vector3(), this.parameters.radius);
  }

  /** Copy `source`'s attributes, index, groups and bounds (three's `copy`) and its `parameters`. */
  override copy(source: SubdivisionSphereGeometry): this {
    super.copy(source);
    this.parameters = { ...source.parameters };
    return this;
  }

  /** A new geometry with copies of this one's arrays and `parameters` (does not subdivide again). */
  override clone(): this {
    const Self = this.constructor as new (options: SubdivideSphereOptions) => this;
    return new Self({ ...this.parameters, level: 0 }).copy(this);
  }

  /**
   * Rebuild a geometry from the `parameters` of its JSON (three's `toJSON` writes only those for a geometry with
   * parameters).
   * @param data - `{ level, base, radius, normals, indexed, maxBytes }` as in `toJSON().`
   */
  static fromJSON(data: SubdivideSphereOptions): SubdivisionSphereGeometry {
    // JSON writes maxBytes: Infinity as null.
    const { maxBytes, ...rest } = data;
    return new SubdivisionSphereGeometry(maxBytes == null ? rest : { ...rest, maxBytes });
  }
}
