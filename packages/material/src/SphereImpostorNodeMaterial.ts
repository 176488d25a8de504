// SphereImpostorMaterial's ray-cast sphere on three's WebGPURenderer (both of its backends): a node material whose
// vertex stage puts the quad on the projected ellipsoid's screen bounds and whose fragment stage intersects the
// pixel's ray with the unit sphere in model space, writes the hit's depth and lights it with ShadingNodeMaterial's
// lighting model.
import {
  abs,
  cameraFar,
  cameraNear,
  cameraProjectionMatrix,
  cameraProjectionMatrixInverse,
  clamp,
  Discard,
  depth,
  float,
  instancedBufferAttribute,
  instancedDynamicBufferAttribute,
  mat4,
  max,
  min,
  mix,
  modelViewMatrix,
  output,
  positionGeometry,
  renderGroup,
  select,
  sqrt,
  uniformArray,
  varying,
  vec2,
  vec3,
  vec4,
  viewportSize,
  viewZToLogarithmicDepth,
} from 'three/tsl';
import {
  DoubleSide,
  DynamicDrawUsage,
  type InstancedBufferAttribute,
  InterleavedBufferAttribute,
  WebGLCoordinateSystem,
} from 'three/webgpu';
import type { Shading } from './options.js';
import {
  ShadingNodeMaterial,
  type ShadingNodeMaterialOptions,
  towardsEye,
  unitOr,
} from './ShadingNodeMaterial.js';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

const OWNER = 'SphereImpostorNodeMaterial';

/** Options of {@link SphereImpostorNodeMaterial}: those of `ShadingNodeMaterial` except `shading` (always per fragment). */
export type SphereImpostorNodeMaterialOptions = Omit<ShadingNodeMaterialOptions, 'shading'>;

/** The ray-cast hit of one build, shared by the depth and the lighting (both in the fragment stage). */
interface Hit {
  /** The hit in view space. */
  view: N;
  /** The exact outward normal in view space, not normalised: sign(det)·cof(A)·p. */
  normal: N;
}

const _hits = /* @__PURE__ */ new WeakMap<object, Hit>();
// Per build: the quad's clip position (its xy is the NDC position) and the (instance's) model-view matrix.
const _clips = /* @__PURE__ */ new WeakMap<object, N>();
const _modelViews = /* @__PURE__ */ new WeakMap<object, N>();

/** (a, b) with D = diag(1, 1, 1, −1): a.xyz·b.xyz − a.w·b.w. */
const dotD = (a: N, b: N): N => a.xyz.dot(b.xyz).sub(a.w.mul(b.w));

/** The largest absolute component of a vec4. */
const maxAbs = (v: N): N => {
  const a: N = abs(v);
  return max(max(a.x, a.y), max(a.z, a.w));
};

/**
 * `SphereImpostorMaterial` for three's `WebGPURenderer` (`three/webgpu`), on its WebGPU and its WebGL2 backend:
 * the unit sphere (an ellipsoid under the object's scale) drawn as a screen-aligned quad whose fragment stage
 * intersects the pixel's ray with the exact surface (the numerically stable intersection of Ray Tracing Gems
 * ch. 7, in model space, as `SphereImpostorMaterial`'s GLSL), discards the pixels that miss, writes the hit's
 * exact depth and lights it with `ShadingNodeMaterial`'s lighting model (PhongLights and three's lights, in view
 * space) and the exact normal sign(det)·cof(A)·p (A the linear part of the model-view matrix).
 *
 * Use it on a mesh of the impostor's quad, `createImpostorQuad()` of `@shadelab/material/impostor`
 * (`new Mesh(createImpostorQuad(), material)`: `SphereImpostor` is typed for `SphereImpostorMaterial`). It takes
 * `ShadingNodeMaterial`'s options (lighting, cel bands, ka, kd, ks, shininess, lights), checked the same way and
 * named after this class; `shading` is always `'phong'` (anything else is a TypeError, as on
 * `SphereImpostorMaterial`).
 *
 * The quad covers the projected ellipsoid's exact screen bounds, computed in the vertex stage from T = P·V·M (the
 * planes x = a·w tangent to it in clip space, as `projectedBounds`), widened by one pixel; the whole viewport
 * when the eye plane touches the ellipsoid. Only the front surface between the near and far planes is drawn
 * (no caps); a singular model matrix (a zero scale) draws nothing. The columns of A are scaled to a largest
 * component of 1 before its cofactors are taken, so an object scaled by 1e±20 stays in 32-bit range. Depth is
 * written in the renderer's depth mode (WebGPU's [0, 1] or WebGL2's [−1, 1] clip space, reversed or
 * logarithmic depth), so meshes and impostors occlude each other exactly. Writing depth disables early depth
 * tests: overdraw costs a full fragment each.
 *
 * **Instanced**: on an `InstancedMesh` of `createImpostorQuad()`, each instance is one impostor whose model
 * matrix is the mesh's `matrixWorld` × the instance's matrix (a non-uniform or sheared instance matrix makes the
 * exact ellipsoid, normals included); `instanceColor` multiplies ka and kd (not ks), as on `ShadingNodeMaterial`.
 *
 * three's fog (range and density fogs) and a `ClippingGroup`'s clipping planes are applied at the hit (three's
 * height fog reads the world position, which is the quad's).
 *
 * @example
 * const material = new SphereImpostorNodeMaterial({ lighting: 'blinn-phong', lights: [light] });
 * const impostor = new Mesh(createImpostorQuad(), material);
 * impostor.scale.set(2, 1, 2); // the lecture's ellipsoid
 */
export class SphereImpostorNodeMaterial extends ShadingNodeMaterial {
  /** three's type name. */
  static override get type(): string {
    return 'SphereImpostorNodeMaterial';
  }
  /** Always true. */
  readonly isSphereImpostorNodeMaterial = true;

  /**
   * @param options - Lighting, reflectances and lights; each one omitted takes its default (see
   *   {@link SphereImpostorNodeMaterialOptions}).
   */
  constructor(options: SphereImpostorNodeMaterialOptions = {}) {
    super({ shading: 'phong', ...options });
    // A mirrored object (det < 0) must not cull the quad.
    this.side = DoubleSide;
  }

  /** Always `'phong'`: the impostor lights every fragment. Setting anything else is a TypeError. */
  override get shading(): Shading {
    return super.shading;
  }
  override set shading(value: Shading) {
    if (value !== 'phong') {
      throw new TypeError(
        `${OWNER}.shading must be 'phong' (a ray-cast sphere is shaded per fragment), got ${String(value)}`,
      );
    }
    super.shading = value;
  }

  /**
   * The vertex stage: the quad's corners (`position.xy` = ±1) on the projected ellipsoid's screen bounds. three's
   * own vertex setup still runs (for what it registers); its clip position is replaced.
   */
  override setupVertex(builder: N): N {
    super.setupVertex(builder);
    const t = (cameraProjectionMatrix as N).mul(modelViewOf(builder));
    const columns = [0, 1, 2, 3].map((i) => t.element(i));
    // The rows scaled so that T's largest element is 1 (the bounds do not change; the products stay in range).
    const m = max(max(maxAbs(columns[0]), maxAbs(columns[1])), max(maxAbs(columns[2]), maxAbs(columns[3])));
    const row = (k: 'x' | 'y' | 'z' | 'w'): N =>
      vec4(columns[0][k], columns[1][k], columns[2][k], columns[3][k]).div(max(m, 1e-30));
    const r4 = row('w');
    const w4 = dotD(r4, r4);
    const interval = (r: N): [N, N] => {
      const b = dotD(r, r4);
      const s = sqrt(max(b.mul(b).sub(w4.mul(dotD(r, r))), 0));
      const a0 = b.add(s).div(w4);
      const a1 = b.sub(s).div(w4);
      return [min(a0, a1), max(a0, a1)];
    };
    const [x0, x1] = interval(row('x'));
    const [y0, y1] = interval(row('y'));
    const pixel = vec2(2).div(viewportSize as N);
    const tight = clamp(vec4(x0, y0, x1, y1).add(vec4(pixel.negate(), pixel)), -1, 1);
    const { det } = cofactors(linearColumns(builder));
    const bounds = select(
      det.equal(0).or(m.equal(0)),
      vec4(2),
      select(w4.lessThan(0).and(r4.w.greaterThan(0)), tight, vec4(-1, -1, 1, 1)),
    );
    const corner = (positionGeometry as N).xy.mul(0.5).add(0.5);
    const clip = vec4(mix(bounds.xy, bounds.zw, corner), 0, 1);
    _clips.set(builder, clip);
    return clip;
  }

  /** The hit's exact depth in the renderer's depth mode (three calls it when the target has a depth buffer). */
  override setupDepth(builder: N): void {
    const { view } = this.#hit(builder);
    const renderer = builder.renderer;
    let value: N;
    if (renderer.logarithmicDepthBuffer === true && builder.camera?.isOrthographicCamera !== true) {
      value = viewZToLogarithmicDepth(view.z, cameraNear, cameraFar);
    } else {
      const clip = (cameraProjectionMatrix as N).mul(vec4(view, 1));
      const z = clip.z.div(clip.w);
      // WebGL2's clip space is [−1, 1] unless reversed depth switches it to [0, 1] (clip control), as WebGPU's.
      const glDepth =
        renderer.coordinateSystem === WebGLCoordinateSystem && renderer.reversedDepthBuffer !== true;
      value = glDepth ? z.mul(0.5).add(0.5) : z;
    }
    (depth as N).assign(clamp(value, 0, 1)).toStack();
  }

  /** The hit lit by `ShadingNodeMaterial`'s lighting model with its exact normal. */
  override setupLighting(builder: N): N {
    const { view, normal } = this.#hit(builder);
    const v = builder.camera?.isOrthographicCamera === true ? vec3(0, 0, 1) : towardsEye(view);
    return this.lightSurface(builder, { n: unitOr(normal, v), v }, view);
  }

  /** No clip distances in the vertex stage (they would clip the quad): the hit is clipped in `setupClipping`. */
  override setupHardwareClipping(builder: N): void {
    builder.hardwareClipping = false;
  }

  /**
   * The clipping planes (the renderer's and the material's, `clipIntersection` included) at the hit, as three's
   * clipping node tests a mesh's fragment (three's would see the quad's position): a hit on the outer side of a
   * plane (in view space, n·p > d) of a union plane, or of every intersection plane, is discarded.
   */
  override setupClipping(builder: N): N {
    const context = builder.clippingContext;
    if (context === null || context === undefined) return null;
    const { unionPlanes, intersectionPlanes } = context as {
      unionPlanes: unknown[];
      intersectionPlanes: unknown[];
    };
    if (unionPlanes.length === 0 && intersectionPlanes.length === 0) return null;
    const { view } = this.#hit(builder);
    const outside = (planes: unknown[]): N[] => {
      const array = (uniformArray(planes as never) as N).setGroup(renderGroup);
      return planes.map((_, i) => {
        const plane = array.element(i);
        return view.dot(plane.xyz).greaterThan(plane.w);
      });
    };
    if (unionPlanes.length > 0) Discard(outside(unionPlanes).reduce((a, b) => a.or(b)));
    if (intersectionPlanes.length > 0) Discard(outside(intersectionPlanes).reduce((a, b) => a.and(b)));
    return null;
  }

  /**
   * three's fog (`scene.fog`) at the hit's view depth: its fog factor reads the depth through the builder
   * context's `getViewZ`, which is the hit's here (three's own would be the quad's).
   */
  override setupFog(builder: N, outputNode: N): N {
    const fogNode = builder.fogNode;
    if (!fogNode) return outputNode;
    const { view } = this.#hit(builder);
    (output as N).assign(outputNode);
    return vec4(fogNode.context({ getViewZ: () => view.z }).toVar());
  }

  /**
   * The pixel's ray cast against the unit sphere in model space, once per build; the misses are discarded. The
   * ray's ends at the near and far planes come from the interpolated NDC position of the quad, through three's
   * inverse projection and the inverse of the model-view matrix's affine part (A⁻¹ = cof(A)ᵀ/det).
   */
  #hit(builder: N): Hit {
    const cached = _hits.get(builder);
    if (cached !== undefined) return cached;
    const renderer = builder.renderer;
    const [a0, a1, a2, c] = [...linearColumns(builder), translationOf(builder)].map(
      (x): N => (varying(x) as N).setInterpolation('flat'),
    );
    const reversed = renderer.reversedDepthBuffer === true;
    const gl = renderer.coordinateSystem === WebGLCoordinateSystem && !reversed;
    const zNear = reversed ? 1 : gl ? -1 : 0;
    const zFar = reversed ? 0 : 1;
    // The pixel's NDC position: the quad's, interpolated (its clip w is 1: linear in screen space).
    const xy = varying(_clips.get(builder).xy) as N;
    const {
      scale,
      k: [k0, k1, k2],
      det,
    } = cofactors([a0, a1, a2]);
    // A⁻¹u = diag(1/scale)·cof(Â)ᵀu/det(Â).
    const toModel = (h: N): N => {
      const u = h.xyz.sub(c.mul(h.w));
      return vec4(vec3(k0.dot(u), k1.dot(u), k2.dot(u)).div(scale).div(det), h.w);
    };
    const inverseP = cameraProjectionMatrixInverse as N;
    const nearH = toModel(inverseP.mul(vec4(xy, zNear, 1))).toVar();
    const farH = toModel(inverseP.mul(vec4(xy, zFar, 1))).toVar();
    const o = nearH.xyz.div(nearH.w).toVar();
    // far − near without dividing by farH.w (about near/far: 0 for a far plane at infinity).
    // d and the product s of the w's rescaled together (neither the length nor the direction changes), so that
    // |d|² stays in range at a scale of 1e±20.
    const dRaw = farH.xyz.mul(nearH.w).sub(nearH.xyz.mul(farH.w)).toVar();
    const dMax = max(max(abs(dRaw.x), abs(dRaw.y)), abs(dRaw.z));
    const dScale = select(dMax.greaterThan(0), dMax, float(1)).toVar();
    const d0 = dRaw.div(dScale);
    const s = nearH.w.mul(farH.w.div(dScale));
    const len = select(s.greaterThan(0), d0.length().div(s), float(1e38));
    const d = d0
      .normalize()
      .mul(select(nearH.w.lessThan(0), float(-1), float(1)))
      .toVar();
    // Ray Tracing Gems ch. 7: b' = o·d, Δ = 1 − |o − b'd|², q = −b' − sign(b')√Δ, t0 = c/q, t1 = q.
    const b = o.dot(d).toVar();
    const f = o.sub(d.mul(b));
    const delta = float(1).sub(f.dot(f)).toVar();
    Discard(delta.lessThan(0).or(det.equal(0)));
    const cc = o.dot(o).sub(1);
    const q = b
      .negate()
      .sub(select(b.greaterThanEqual(0), float(1), float(-1)).mul(sqrt(max(delta, 0))))
      .toVar();
    const t0 = select(q.equal(0), float(0), min(cc.div(q), q)).toVar();
    Discard(t0.lessThan(0).or(t0.greaterThan(len)));
    const p = o.add(d.mul(t0)).toVar();
    const view = a0.mul(p.x).add(a1.mul(p.y)).add(a2.mul(p.z)).add(c).toVar();
    // sign(det)·cof(A)·p ∝ sign(det(Â))·cof(Â)·(p/scale).
    const ps = p.div(scale);
    const normal = k0
      .mul(ps.x)
      .add(k1.mul(ps.y))
      .add(k2.mul(ps.z))
      .mul(select(det.lessThan(0), float(-1), float(1)));
    const hit = { view, normal };
    _hits.set(builder, hit);
    return hit;
  }
}

/**
 * A = Â·diag(scale), each column of Â scaled to a largest component of 1 (so that the cofactors and the
 * determinant stay in 32-bit range for an object scaled by 1e±20): the scales, the columns k of cof(Â)
 * (â1×â2, â2×â0, â0×â1) and det(Â); det is 0 for a singular A (a zero column included).
 */
function cofactors(a: [N, N, N]): { scale: N; k: [N, N, N]; det: N } {
  const s = a.map((column: N) => max(max(abs(column.x), abs(column.y)), abs(column.z)));
  const unit = a.map((column: N, i) => column.div(select(s[i].greaterThan(0), s[i], float(1))));
  const k: [N, N, N] = [unit[1].cross(unit[2]), unit[2].cross(unit[0]), unit[0].cross(unit[1])];
  const det = select(
    s[0].greaterThan(0).and(s[1].greaterThan(0)).and(s[2].greaterThan(0)),
    unit[0].dot(k[0]),
    float(0),
  );
  return { scale: vec3(s[0], s[1], s[2]), k, det };
}

/** The model-view matrix of the object, × the instance's matrix on an InstancedMesh. */
function modelViewOf(builder: N): N {
  const cached = _modelViews.get(builder);
  if (cached !== undefined) return cached;
  const object = builder.object;
  const matrices: InstancedBufferAttribute | undefined = object?.isInstancedMesh
    ? object.instanceMatrix
    : undefined;
  if (matrices === undefined) {
    _modelViews.set(builder, modelViewMatrix);
    return modelViewMatrix;
  }
  const column =
    matrices.usage === DynamicDrawUsage ? instancedDynamicBufferAttribute : instancedBufferAttribute;
  const columns = [0, 4, 8, 12].map((offset) =>
    column(new InterleavedBufferAttribute(matrices as never, 4, offset) as never),
  );
  const modelView = (modelViewMatrix as N).mul((mat4 as N)(...columns));
  _modelViews.set(builder, modelView);
  return modelView;
}

/** The columns of A, the linear part of the (instance's) model-view matrix. */
function linearColumns(builder: N): [N, N, N] {
  const mv = modelViewOf(builder);
  return [mv.element(0).xyz, mv.element(1).xyz, mv.element(2).xyz];
}

/** The translation of the (instance's) model-view matrix. */
function translationOf(builder: N): N {
  return modelViewOf(builder).element(3).xyz;
}
