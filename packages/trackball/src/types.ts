/** A 3-vector as `[x, y, z]`. */
export type Vec3 = [number, number, number];

/** A quaternion as `[x, y, z, w]` (three.js order: vector part first, scalar last). */
export type Quat = [number, number, number, number];

/**
 * How a pointer position is lifted onto the virtual ball.
 *
 * - `'arcball'`: Shoemake's arcball. Inside the rim the point lies on the unit hemisphere facing the viewer;
 *   on and outside the rim it is pulled radially onto the rim (the equator, z = 0), so a drag outside the
 *   rim rolls about the view axis. The surface has a kink at the rim.
 * - `'bell'`: Bell's trackball. Inside radius 1/√2 the point lies on the unit sphere; outside, on the
 *   hyperbolic sheet z = 1 / (2r), which meets the sphere with the same value and slope (C¹): no kink, and
 *   far from the ball the point tends to the equator, so the drag turns smoothly into a roll.
 */
export type BallMapping = 'arcball' | 'bell';
