/**
 * The probed triangle around the pixel, as the GPU's derivatives see it: the rays through nearby pixel centres
 * meet the triangle's plane, which gives the barycentric weights there, the uv's change across one pixel (a
 * texture's level of detail), the point's change (three's derivative tangent frame), and whether the pixel's
 * centre is within a rasteriser's sub-pixel precision of an edge.
 */
import * as THREE from 'three';
import { barycentric, ndcOfPixel, type V3 } from './probeMath';
import { sampleTexture, type TexelRead, transformedUv, type V4 } from './probeTexture';

/** A pixel centre this near an edge (in pixels: a rasteriser's sub-pixel precision) is a tie between faces. */
const EDGE_PIXELS = 1 / 64;
const neighbour = new THREE.Raycaster();
const v3 = (v: THREE.Vector3): V3 => [v.x, v.y, v.z];

/** What the probe knows of the hit triangle. */
export interface ProbedTriangle {
  readonly camera: THREE.Camera;
  readonly geometry: THREE.BufferGeometry;
  /** The triangle's vertex indices and object-space corners (deformed, as drawn). */
  readonly indices: readonly [number, number, number];
  readonly corners: readonly [THREE.Vector3, THREE.Vector3, THREE.Vector3];
  /** Object (or instance) to world. */
  readonly model: THREE.Matrix4;
  /** The weights at the pixel's centre, the device pixel and the canvas size. */
  readonly weights: V3;
  readonly pixel: readonly [number, number];
  readonly size: readonly [number, number];
}

/** The triangle's surface at the pixel: its textures' values and the frame a normal map needs. */
export function probedSurface(triangle: ProbedTriangle) {
  const { camera, geometry, indices, corners, model, weights, pixel, size } = triangle;
  const inverse = model.clone().invert();
  const plane = new THREE.Plane().setFromCoplanarPoints(
    ...(corners.map((p) => p.clone().applyMatrix4(model)) as [THREE.Vector3, THREE.Vector3, THREE.Vector3]),
  );
  const [pa, pb, pc] = corners.map(v3) as [V3, V3, V3];
  const onPlane = (x: number, y: number) => {
    const [nx, ny] = ndcOfPixel(x, y, size[0], size[1]);
    neighbour.setFromCamera(new THREE.Vector2(nx, ny), camera);
    const world = neighbour.ray.intersectPlane(plane, new THREE.Vector3());
    if (!world) return null;
    return { world, weights: barycentric(v3(world.clone().applyMatrix4(inverse)), pa, pb, pc) };
  };
  const here = onPlane(pixel[0], pixel[1]);
  const right = onPlane(pixel[0] + 1, pixel[1]);
  const up = onPlane(pixel[0], pixel[1] - 1);
  /** The texture's uv at the pixel and its change to the right and upper neighbours (transformed). */
  const uvsOf = (texture: THREE.Texture) => {
    const uv = geometry.getAttribute(texture.channel === 0 ? 'uv' : `uv${texture.channel}`);
    if (!uv || !right || !up) return null;
    const at = (w: V3) => {
      const sum = new THREE.Vector2();
      indices.forEach((index, k) => {
        sum.addScaledVector(new THREE.Vector2(uv.getX(index), uv.getY(index)), w[k]!);
      });
      return transformedUv(texture, sum);
    };
    const centre = at(weights);
    return { here: centre, dx: at(right.weights).sub(centre), dy: at(up.weights).sub(centre) };
  };
  return {
    /** The texture's value at the pixel, or null with the reason added to `unreproduced`. */
    sample(texture: THREE.Texture | null, what: string, unreproduced: string[]): V4 | null {
      if (!texture) return null;
      const uvs = uvsOf(texture);
      const read: TexelRead = uvs
        ? sampleTexture(texture, uvs.here, uvs.dx, uvs.dy)
        : { reason: 'the geometry has no uv for it' };
      if ('value' in read) return read.value;
      unreproduced.push(`The ${what}’s texel is not reproduced: ${read.reason}.`);
      return null;
    },
    /** The change of the point (world) and of the texture's uv to the right (q0, st0) and upwards (q1, st1). */
    frameOf(texture: THREE.Texture) {
      const uvs = uvsOf(texture);
      if (!uvs || !here || !right || !up) return null;
      return {
        q0: right.world.clone().sub(here.world),
        q1: up.world.clone().sub(here.world),
        st0: uvs.dx,
        st1: uvs.dy,
      };
    },
    /** Whether the pixel's centre is within {@link EDGE_PIXELS} of an edge of the triangle. */
    nearEdge(): boolean {
      return [
        [1, 0],
        [-1, 0],
        [0, 1],
        [0, -1],
      ].some(([dx, dy]) => {
        const moved = onPlane(pixel[0] + dx! * EDGE_PIXELS, pixel[1] + dy! * EDGE_PIXELS);
        return moved !== null && Math.min(...moved.weights) < 0;
      });
    },
  };
}
