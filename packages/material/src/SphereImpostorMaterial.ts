import {
  type BufferGeometry,
  type Camera,
  DoubleSide,
  type Group,
  Matrix4,
  type Object3D,
  type PerspectiveCamera,
  type Scene,
  Vector3,
  Vector4,
  type WebGLProgramParametersWithUniforms,
  type WebGLRenderer,
} from 'three';
import type { Shading } from './options.js';
import { ShadingMaterial, type ShadingMaterialOptions } from './ShadingMaterial.js';
import { impostorFragmentShader, impostorVertexShader } from './SphereImpostorMaterial.glsl.js';

/** Options of {@link SphereImpostorMaterial}: those of `ShadingMaterial` except `shading` (always per fragment). */
export type SphereImpostorMaterialOptions = Omit<ShadingMaterialOptions, 'shading'>;

const _mvp = /* @__PURE__ */ new Matrix4();
const _viewport = /* @__PURE__ */ new Vector4();
const _eye = /* @__PURE__ */ new Vector3();
const _inverse = /* @__PURE__ */ new Matrix4();

/**
 * The accurate end of the speed/accuracy trade: the unit sphere (an ellipsoid under the object's scale) drawn
 * as a screen-aligned quad whose fragment shader intersects the pixel's ray with the exact surface (the
 * numerically stable intersection of Ray Tracing Gems ch. 7, in model space), writes the exact depth
 * (`gl_FragDepth`) and lights the hit with `ShadingMaterial`'s own lighting code and the exact normal
 * sign(det)·cof(M)·p. Exact silhouette and normals with 2 triangles, whatever the size on screen.
 *
 * Use it on a {@link SphereImpostor} (or any geometry whose `position.xy` are the quad corners ±1). It takes
 * `ShadingMaterial`'s options (lighting, cel bands, ka, kd, ks, shininess, lights); `shading` is always
 * `'phong'` (per fragment: anything else is a TypeError).
 *
 * The quad covers the exact screen bounds of the projected ellipsoid, computed on the CPU per draw from the
 * quadric (the planes x = a·w tangent to it in clip space: a² (r₄Dr₄) − 2a (r₁Dr₄) + r₁Dr₁ = 0 with r the rows
 * of P·V·M and D = diag(1, 1, 1, −1)), widened by one pixel; when the eye plane touches the ellipsoid (camera
 * beside it) the quad covers the whole viewport. Only the front surface is drawn, clipped by the near and far
 * planes like a mesh (no caps): with a perspective camera inside the ellipsoid nothing is drawn (its front
 * surface is behind the eye). Depth is written in the renderer's depth mode (standard,
 * logarithmic or reversed-Z), as three's materials write theirs. The hit is clipped (`clippingPlanes`, the
 * renderer's), fogged (`scene.fog`, `fog`) and tone-mapped (`toneMapped`) by the same chunks as a mesh, at its
 * exact view position. A singular model matrix (a zero scale) draws nothing (unlike a mesh, which draws the
 * flattened shape). Writing depth disables early depth tests, so overdraw costs a full fragment each.
 *
 * **Instanced**: on an `InstancedMesh` of {@link createImpostorQuad} (three's USE_INSTANCING), each instance
 * is drawn as one impostor whose model matrix is the mesh's `matrixWorld` × the instance's matrix: a sphere
 * where that matrix puts it, and, like one impostor under a non-uniform scale, exactly the ellipsoid a
 * non-uniform (or sheared) instance matrix makes, normals included (no single radius is chosen). The bounds
 * and the inverse matrix are computed per instance in the vertex stage (in 32-bit floats: an instance scaled
 * by 1e±20 stays finite; a zero-scale instance draws nothing); `instanceColor` multiplies ka and kd (not ks)
 * as on `ShadingMaterial`. Only the instance matrix and colour are read: a `BatchedMesh`, skinning and morph
 * targets do not apply to a sphere.
 *
 * @example
 * const impostor = new SphereImpostor(new SphereImpostorMaterial({ lighting: 'blinn-phong', lights: [light] }));
 * impostor.scale.set(2, 1, 2); // the lecture's ellipsoid
 * scene.add(impostor, light);
 * // 1,000 spheres in one draw: an InstancedMesh of the impostor's quad
 * const field = new InstancedMesh(createImpostorQuad(), new SphereImpostorMaterial({ lights: [light] }), 1000);
 */
export class SphereImpostorMaterial extends ShadingMaterial {
  /** Always true. */
  readonly isSphereImpostorMaterial = true;
  /** three's type name: `'SphereImpostorMaterial'`. */
  override type = 'SphereImpostorMaterial';
  // The ray-cast hit is lit in world space, also with three's lights.
  protected override readonly viewSpaceLighting = false;

  constructor(options: SphereImpostorMaterialOptions = {}) {
    super({ shading: 'phong', ...options });
    Object.assign(this.uniforms, {
      impostorMvp: { value: new Matrix4() },
      impostorInverseMvp: { value: new Matrix4() },
      impostorModelMatrix: { value: new Matrix4() },
      impostorViewProjection: { value: new Matrix4() },
      impostorViewport: { value: new Vector4(0, 0, 1, 1) },
      impostorBounds: { value: new Vector4(-1, -1, 1, 1) },
    });
    this.side = DoubleSide; // a mirrored object (det < 0) flips three's front face; the quad must stay drawn
    // The impostor's own shaders, composed of ShadingMaterial's chunks; the variants are defines (the light count
    // too), so they are never set again.
    this.vertexShader = impostorVertexShader;
    this.fragmentShader = impostorFragmentShader;
  }

  /** Always `'phong'`: the impostor lights every fragment. Setting anything else is a TypeError. */
  override get shading(): Shading {
    return super.shading;
  }
  override set shading(value: Shading) {
    if (value !== 'phong') {
      throw new TypeError(
        `SphereImpostorMaterial.shading must be 'phong' (a ray-cast sphere is shaded per fragment), got ${String(value)}`,
      );
    }
    super.shading = value;
  }

  /**
   * three's hook before it compiles a program: three defines USE_INSTANCING (and USE_INSTANCING_COLOR) in the
   * vertex stage only, so the fragment stage of an instanced program gets IMPOSTOR_INSTANCED (and
   * IMPOSTOR_INSTANCED_COLOR) here; other programs are left as they are. If you replace `onBeforeCompile`, call
   * this one from yours.
   */
  override onBeforeCompile(shader: WebGLProgramParametersWithUniforms, _renderer: WebGLRenderer): void {
    let defines = '';
    if (shader.instancing) defines += '#define IMPOSTOR_INSTANCED\n';
    if (shader.instancing && shader.instancingColor) defines += '#define IMPOSTOR_INSTANCED_COLOR\n';
    shader.fragmentShader = defines + shader.fragmentShader;
  }

  /** Per draw: ShadingMaterial's uniforms, then the ray-casting matrices, viewport and the quad's bounds. */
  override onBeforeRender(
    renderer: WebGLRenderer,
    scene: Scene,
    camera: Camera,
    geometry: BufferGeometry,
    object: Object3D,
    group: Group,
  ): void {
    super.onBeforeRender(renderer, scene, camera, geometry, object, group);
    // A reversed-depth renderer switches the camera to reversed depth when it sets up the first program of a
    // frame, which may come after this: switch it now, as three does, so that the matrices below are the ones
    // the depth buffer expects.
    if (renderer.capabilities?.reversedDepthBuffer && !camera.reversedDepth) {
      (camera as unknown as { _reversedDepth: boolean })._reversedDepth = true;
      (camera as unknown as { updateProjectionMatrix?: () => void }).updateProjectionMatrix?.();
    }
    const u = this.uniforms;
    const mvp = _mvp
      .multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse)
      .multiply(object.matrixWorld);
    u.impostorViewProjection.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    u.impostorMvp.value.copy(mvp);
    scaleToUnitW(u.impostorInverseMvp.value.copy(mvp).invert());
    u.impostorModelMatrix.value.copy(object.matrixWorld);
    const viewport = renderer.getCurrentViewport(_viewport);
    u.impostorViewport.value.copy(viewport);
    const det = mvp.determinant();
    // A singular model matrix, or a perspective eye inside the ellipsoid (its front surface is behind the eye):
    // nothing to draw, an empty quad off screen (the ray casting would find no hit either, but at a scale of
    // 1e20 the model-space ray, about 1e−20 long, underflows in 32-bit floats).
    const inside =
      (camera as PerspectiveCamera).isPerspectiveCamera === true &&
      _eye
        .setFromMatrixPosition(camera.matrixWorld)
        .applyMatrix4(_inverse.copy(object.matrixWorld).invert())
        .lengthSq() < 1;
    if (det !== 0 && Number.isFinite(det) && !inside)
      projectedBounds(mvp, viewport.z, viewport.w, u.impostorBounds.value);
    else u.impostorBounds.value.set(2, 2, 2, 2);
  }
}

/**
 * Scales (P·V·M)⁻¹ by a power of two that brings its w row's largest element into [1/√2, √2]. A positive factor
 * changes no ray (the points are homogeneous: the origin o = xyz/w, the direction and the near–far length are
 * ratios), but it keeps the fragment stage's products of w and xyz in 32-bit range: for a whole scene scaled by
 * 1e-18 the w row is about 1/near ≈ 1e19, and those products (≈ 1e38, squared in |d|²) overflowed, so nothing
 * was drawn (at 1e15, the coverage was wrong). A power of two changes no rounding either: every other scene
 * draws the same pixels. A zero or non-finite w row is left as it is (nothing is drawn then).
 */
function scaleToUnitW(inverse: Matrix4): Matrix4 {
  const e = inverse.elements;
  const w = Math.max(Math.abs(e[3]), Math.abs(e[7]), Math.abs(e[11]), Math.abs(e[15]));
  return w > 0 && Number.isFinite(w) ? inverse.multiplyScalar(2 ** -Math.round(Math.log2(w))) : inverse;
}

/**
 * The NDC bounds (min x, min y, max x, max y) of the unit sphere under `mvp` (P·V·M), widened by one pixel
 * of a `width`×`height` viewport, or the whole viewport when the eye plane touches the sphere or the sphere
 * is behind the camera. Exact for ellipsoids (any affine M) under perspective and orthographic projection.
 * @param target receives the bounds.
 * @returns `target`.
 */
export function projectedBounds(mvp: Matrix4, width: number, height: number, target: Vector4): Vector4 {
  const e = mvp.elements;
  // Rows of T = P·V·M (column-major storage); D-products with D = diag(1, 1, 1, −1).
  const row = (i: number): [number, number, number, number] => [e[i], e[4 + i], e[8 + i], e[12 + i]];
  const dotD = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2] - a[3] * b[3];
  const r4 = row(3);
  const w4 = dotD(r4, r4);
  if (!(w4 < 0) || !(r4[3] > 0)) return target.set(-1, -1, 1, 1);
  const bounds = (r: number[]): [number, number] => {
    const b = dotD(r, r4);
    const c = dotD(r, r);
    const s = Math.sqrt(Math.max(b * b - w4 * c, 0));
    const a0 = (b + s) / w4;
    const a1 = (b - s) / w4;
    return [Math.min(a0, a1), Math.max(a0, a1)];
  };
  const [x0, x1] = bounds(row(0));
  const [y0, y1] = bounds(row(1));
  const px = 2 / width;
  const py = 2 / height;
  const clamp = (v: number) => Math.min(Math.max(v, -1), 1);
  if (![x0, x1, y0, y1].every(Number.isFinite)) return target.set(-1, -1, 1, 1);
  return target.set(clamp(x0 - px), clamp(y0 - py), clamp(x1 + px), clamp(y1 + py));
}
