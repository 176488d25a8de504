// ShadingNodeMaterial's normal map (phong shading): three's `normal_fragment_maps` on the material's own robust
// normal, as ShadingMaterial's SHADING_NORMALMAP does it: a tangent-space map through three's tangent frame from
// screen-space derivatives (`getTangentFrame`; a `tangent` attribute is not used), an object-space map through
// the object's robust normal matrix.
import { faceDirection, float, materialReference, normalize, select, uniform, uv, vec3 } from 'three/tsl';
import {
  BackSide,
  DoubleSide,
  Matrix3,
  ObjectSpaceNormalMap,
  type Side,
  type Texture,
  Vector2,
} from 'three/webgpu';

// biome-ignore lint/suspicious/noExplicitAny: TSL nodes are dynamically typed (their swizzles and operators).
type N = any;

/** What the normal map reads from the material. */
export interface NormalMapped {
  readonly normalMap: Texture | null;
  readonly normalMapType: number;
  readonly normalScale: Vector2;
  readonly side: Side;
}

/**
 * The unit normal `n` (view space, turned to the drawn side) perturbed by the material's normal map at the view
 * position `p`; `toView` takes an object-space normal to view space (unnormalised).
 */
export function normalMapped(material: NormalMapped, n: N, p: N, toView: (normal: N) => N): N {
  const map = material.normalMap as Texture;
  const texel = (materialReference('normalMap', 'texture') as N).xyz.mul(2).sub(1);
  if (material.normalMapType === ObjectSpaceNormalMap) {
    // Object space: turned round on the back side, then to view space through the robust normal matrix.
    let normal: N = texel;
    if (material.side === BackSide) normal = normal.negate();
    else if (material.side === DoubleSide) normal = normal.mul(faceDirection);
    const viewNormal = toView(normal);
    const length = viewNormal.length();
    return select(length.greaterThan(0), viewNormal.div(length), n);
  }
  // The uv the texel was sampled at (its channel, through the texture's transform), for its derivatives.
  const transform = uniform(new Matrix3()).onObjectUpdate(() => {
    const texture = material.normalMap;
    if (texture === null) return undefined;
    if (texture.matrixAutoUpdate) texture.updateMatrix();
    return texture.matrix;
  });
  const st: N = (transform as N).mul(vec3(uv(map.channel), 1)).xy;
  // three's normalScale; a BackSide material's tangent frame is turned round (three's refreshUniformsCommon).
  // Edited in place to a non-finite value: drawn with the last finite scale (the in-place check reports it).
  const sign = material.side === BackSide ? -1 : 1;
  const scaled = new Vector2(sign, sign);
  const scale = uniform(scaled).onRenderUpdate(() => {
    const { x, y } = material.normalScale;
    return Number.isFinite(x) && Number.isFinite(y) ? scaled.set(sign * x, sign * y) : undefined;
  });
  // getTangentFrame( eye_pos, surf_norm, uv ).
  const q0 = p.dFdx();
  const q1 = p.dFdy();
  const st0 = st.dFdx();
  const st1 = st.dFdy();
  const q1perp = q1.cross(n);
  const q0perp = n.cross(q0);
  let t: N = q1perp.mul(st0.x).add(q0perp.mul(st1.x));
  let b: N = q1perp.mul(st0.y).add(q0perp.mul(st1.y));
  const det = t.dot(t).max(b.dot(b));
  const s = select(det.equal(0), float(0), det.inverseSqrt());
  t = t.mul(s);
  b = b.mul(s);
  if (material.side === DoubleSide) {
    t = t.mul(faceDirection);
    b = b.mul(faceDirection);
  }
  const m = texel.xy.mul(scale);
  return normalize(t.mul(m.x).add(b.mul(m.y)).add(n.mul(texel.z)));
}
