/**
 * AdaptiveShading (`@shadelab/material/adaptive`) on the playground's picked scene: every Mesh and InstancedMesh
 * with a ShadingMaterial under the trackball's pivot is managed, and updated inside each render
 * (`scene.onBeforeRender`, so it runs for the viewer's camera and viewport, after the viewer set the panel's
 * options). What each object (and instance) got, for the heat map; the measured error of the picture against
 * the same scene drawn with Phong shading at full detail (two offscreen renders read back).
 */
import { ShadingMaterial } from '@shadelab/material';
import { type AdaptiveChoice, AdaptiveShading, pictureError } from '@shadelab/material/adaptive';
import * as THREE from 'three';
import type { Viewer } from '../engine/viewer/Viewer';

/**
 * One object or instance on screen and what it got: the outline of its bounding ellipsoid (its geometry's bounding
 * sphere under its world matrix: the object itself for a sphere), as a polygon in CSS pixels of the canvas.
 */
export interface AdaptiveUnit {
  outline: [number, number][];
  key: string;
}

/** The outline's corners. */
const OUTLINE_POINTS = 48;

/** The adaptive picture against the full-detail Phong picture (8-bit sRGB levels, drawn pixels). */
export interface AdaptiveMeasured {
  budget: number;
  drawn: number;
  p99: number;
  max: number;
  /** Fraction of the drawn pixels over the budget. */
  over: number;
  /** Frame time with adaptive and without (every object as it was), measured in the same cycle, ms. */
  frameMs: { adaptive: number; without: number };
}

const GROUP_NAME = 'AdaptiveShading group';
const _m = new THREE.Matrix4();
const _world = new THREE.Matrix4();
const _inverse = new THREE.Matrix4();
const _eye = new THREE.Vector3();
const _a = new THREE.Vector3();
const _b = new THREE.Vector3();
const _p = new THREE.Vector3();
const _centre = new THREE.Vector3();

/** A choice's name in the legend: "phong full", "phong 1", "gouraud full", "flat full prepared", … */
export function choiceKey(c: AdaptiveChoice | null): string {
  if (!c) return 'none';
  return `${c.shading} ${c.level ?? 'full'}${c.flatPath ? ` ${c.flatPath}` : ''}`;
}

export class AdaptiveRun {
  private adaptive: AdaptiveShading;
  private readonly managed = new Set<THREE.Mesh>();
  private previous: THREE.Scene['onBeforeRender'] | null = null;
  private suspended = false;

  constructor(
    private readonly viewer: Viewer,
    private budget: number,
  ) {
    this.adaptive = new AdaptiveShading({ maxError: budget });
    const scene = viewer.scene;
    this.previous = scene.onBeforeRender;
    const previous = this.previous;
    scene.onBeforeRender = (renderer, s, camera, target, material, group) => {
      previous.call(scene, renderer, s, camera, target, material, group);
      this.frame(renderer, camera);
    };
    viewer.requestRender();
  }

  /** A new budget: a new AdaptiveShading; the objects move to it at the next frame. */
  setBudget(budget: number): void {
    if (budget === this.budget) return;
    this.budget = budget;
    this.release();
    this.adaptive = new AdaptiveShading({ maxError: budget });
    this.viewer.requestRender();
  }

  /** Puts every object back and removes the hook. */
  dispose(): void {
    this.release();
    if (this.previous) this.viewer.scene.onBeforeRender = this.previous;
    this.previous = null;
    this.viewer.requestRender();
  }

  private release(): void {
    for (const o of this.managed) this.adaptive.remove(o);
    this.managed.clear();
    this.adaptive.dispose();
  }

  /** Inside the render: take new objects, drop gone ones, choose for this camera and viewport. */
  private frame(renderer: THREE.WebGLRenderer, camera: THREE.Camera): void {
    if (this.suspended) return;
    const found = new Set<THREE.Mesh>();
    this.viewer.pivot.traverseVisible((o) => {
      const mesh = o as THREE.Mesh;
      if (mesh.isMesh !== true || o.name === GROUP_NAME) return;
      if (this.managed.has(mesh) || mesh.material instanceof ShadingMaterial) found.add(mesh);
    });
    for (const o of this.managed) {
      if (!found.has(o)) {
        this.adaptive.remove(o);
        this.managed.delete(o);
      }
    }
    for (const o of found) {
      if (this.managed.has(o)) continue;
      try {
        this.adaptive.add(o);
        this.managed.add(o);
      } catch (error) {
        console.warn(`adaptive shading leaves '${o.name}' as it is: ${String(error)}`);
      }
    }
    this.adaptive.update(camera, renderer);
    // The groups it may have just added under an InstancedMesh: placed before three draws them.
    for (const o of this.managed) if ((o as THREE.InstancedMesh).isInstancedMesh) o.updateMatrixWorld(true);
  }

  /** How many objects and instances took each choice. */
  choices(): Record<string, number> {
    const out: Record<string, number> = {};
    for (const o of this.managed) {
      const n = (o as THREE.InstancedMesh).isInstancedMesh ? this.instanceCount(o) : 1;
      for (let i = 0; i < n; i++) {
        const k = choiceKey(this.adaptive.choiceOf(o, i));
        out[k] = (out[k] ?? 0) + 1;
      }
    }
    return out;
  }

  private instanceCount(o: THREE.Mesh): number {
    return this.adaptive.groupsOf(o).reduce((s, g) => s + g.count, 0);
  }

  /** Every object and instance in front of the camera as its outline on the canvas, with its choice. */
  units(): AdaptiveUnit[] {
    const { camera, canvas } = this.viewer;
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    const ortho = camera.projectionMatrix.elements[15] !== 0;
    const out: AdaptiveUnit[] = [];
    for (const o of this.managed) {
      const g = o.geometry;
      if (!g.boundingSphere) g.computeBoundingSphere();
      const { center, radius } = g.boundingSphere as THREE.Sphere;
      const im = (o as THREE.InstancedMesh).isInstancedMesh ? (o as THREE.InstancedMesh) : null;
      const n = im ? this.instanceCount(o) : 1;
      for (let i = 0; i < n; i++) {
        // The unit sphere's frame: world = A · u for the unit sphere's points u.
        _world.copy(o.matrixWorld);
        if (im) _world.multiply(_m.fromArray(im.instanceMatrix.array, 16 * i));
        _world.multiply(_m.makeTranslation(center)).multiply(_m.makeScale(radius, radius, radius));
        if (_world.determinant() === 0) continue;
        const outline = ellipsoidOutline(_world, camera, ortho, w, h);
        if (outline) out.push({ outline, key: choiceKey(this.adaptive.choiceOf(o, i)) });
      }
    }
    return out;
  }

  /**
   * The adaptive picture against the same scene with every object put back (Phong shading at full detail: the
   * panel's shading is Phong while adaptive runs), both drawn offscreen at the canvas's size and read back as
   * 8-bit sRGB; the drawn pixels are those either picture covers (cleared transparent, background off). Then the
   * frame time of each, in the same cycle: {@link FRAME_ROUNDS} interleaved frames of each, each timed from the
   * render call to a 1×1 read-back (the GPU's work finished), adaptive's with its update; the medians.
   */
  measure(): AdaptiveMeasured {
    const { renderer, scene, camera } = this.viewer;
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    const target = new THREE.WebGLRenderTarget(size.x, size.y);
    target.texture.colorSpace = THREE.SRGBColorSpace;
    const background = scene.background;
    const clear = renderer.getClearColor(new THREE.Color());
    const alpha = renderer.getClearAlpha();
    const one = new Uint8Array(4);
    /** Draws the scene into the target; its time until a 1×1 read-back, ms. */
    const draw = () => {
      const t0 = performance.now();
      renderer.setRenderTarget(target);
      renderer.clear();
      renderer.render(scene, camera);
      renderer.readRenderTargetPixels(target, 0, 0, 1, 1, one);
      return performance.now() - t0;
    };
    const read = () => {
      draw();
      const px = new Uint8Array(size.x * size.y * 4);
      renderer.readRenderTargetPixels(target, 0, 0, size.x, size.y, px);
      return px;
    };
    /** Every object put back as it was; adaptive waits. */
    const without = () => {
      this.suspended = true;
      for (const o of this.managed) this.adaptive.remove(o);
      this.managed.clear();
    };
    /** Adaptive takes the objects again and chooses, outside the timed frame. */
    const adaptive = () => {
      this.suspended = false;
      this.frame(renderer, camera);
    };
    try {
      scene.background = null;
      renderer.setClearColor(0x000000, 0);
      without();
      const reference = read();
      adaptive();
      const picture = read();
      const times = { adaptive: [] as number[], without: [] as number[] };
      for (let round = 0; round < FRAME_ROUNDS; round++) {
        without();
        times.without.push(draw());
        adaptive();
        times.adaptive.push(draw());
      }
      return {
        ...compare(reference, picture, this.budget),
        frameMs: { adaptive: median(times.adaptive), without: median(times.without) },
      };
    } finally {
      this.suspended = false;
      renderer.setRenderTarget(null);
      renderer.setClearColor(clear, alpha);
      scene.background = background;
      target.dispose();
      this.viewer.requestRender();
    }
  }
}

/** The frames of each kind {@link AdaptiveRun.measure} times. */
const FRAME_ROUNDS = 5;

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[xs.length >> 1];

/** `pictureError` of the adaptive picture where either picture is drawn (alpha > 0), with its budget. */
export function compare(
  reference: Uint8Array,
  picture: Uint8Array,
  budget: number,
): Omit<AdaptiveMeasured, 'frameMs'> {
  return { budget, ...pictureError(reference, picture, budget) };
}

/**
 * The outline on the canvas (CSS pixels, y down) of the ellipsoid A · (unit sphere) seen by `camera`: the image of
 * the unit sphere's circle of tangency, u · e′ = 1 for the eye e′ = A⁻¹ · eye (perspective), or u ⊥ A⁻¹ · d for the
 * view direction d (orthographic): exact under the projection, off-axis and wide-angle too. Null when the eye is
 * inside the ellipsoid or a point of the outline is outside the clip volume's depth.
 */
function ellipsoidOutline(
  A: THREE.Matrix4,
  camera: THREE.Camera,
  ortho: boolean,
  w: number,
  h: number,
): [number, number][] | null {
  _inverse.copy(A).invert();
  let radius: number;
  if (ortho) {
    // The view direction (the camera's −z in world space), as a direction in the unit sphere's frame.
    _eye.set(0, 0, -1).transformDirection(camera.matrixWorld).transformDirection(_inverse);
    _centre.set(0, 0, 0);
    radius = 1;
  } else {
    _eye.setFromMatrixPosition(camera.matrixWorld).applyMatrix4(_inverse);
    const d2 = _eye.lengthSq();
    if (d2 <= 1) return null;
    _centre.copy(_eye).divideScalar(d2);
    radius = Math.sqrt(1 - 1 / d2);
  }
  // An orthonormal pair across the axis _eye.
  _a.set(1, 0, 0);
  if (Math.abs(_eye.x) > 0.9 * _eye.length()) _a.set(0, 1, 0);
  _a.cross(_eye).normalize();
  _b.crossVectors(_eye, _a).normalize();
  const outline: [number, number][] = [];
  for (let k = 0; k < OUTLINE_POINTS; k++) {
    const t = (2 * Math.PI * k) / OUTLINE_POINTS;
    _p.copy(_centre)
      .addScaledVector(_a, radius * Math.cos(t))
      .addScaledVector(_b, radius * Math.sin(t))
      .applyMatrix4(A)
      .project(camera);
    if (!(_p.z >= -1 && _p.z <= 1)) return null;
    outline.push([((_p.x + 1) / 2) * w, ((1 - _p.y) / 2) * h]);
  }
  return outline;
}
