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

/** One object or instance on screen, in CSS pixels of the canvas, and what it got. */
export interface AdaptiveUnit {
  x: number;
  y: number;
  r: number;
  key: string;
}

/** The adaptive picture against the full-detail Phong picture (8-bit sRGB levels, drawn pixels). */
export interface AdaptiveMeasured {
  budget: number;
  drawn: number;
  p99: number;
  max: number;
  /** Fraction of the drawn pixels over the budget. */
  over: number;
}

const GROUP_NAME = 'AdaptiveShading group';
const _m = new THREE.Matrix4();
const _world = new THREE.Matrix4();
const _centre = new THREE.Vector3();
const _sphere = new THREE.Sphere();

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

  /** Every object and instance as a disc on the canvas (its bounding sphere projected), with its choice. */
  units(): AdaptiveUnit[] {
    const { camera, canvas } = this.viewer;
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    const p = camera.projectionMatrix.elements;
    const ortho = p[15] !== 0;
    const focal = (h / 2) * Math.abs(p[5]);
    const eye = new THREE.Vector3().setFromMatrixPosition(camera.matrixWorld);
    const out: AdaptiveUnit[] = [];
    for (const o of this.managed) {
      const g = o.geometry;
      if (!g.boundingSphere) g.computeBoundingSphere();
      const im = (o as THREE.InstancedMesh).isInstancedMesh ? (o as THREE.InstancedMesh) : null;
      const n = im ? this.instanceCount(o) : 1;
      for (let i = 0; i < n; i++) {
        _world.copy(o.matrixWorld);
        if (im) _world.multiply(_m.fromArray(im.instanceMatrix.array, 16 * i));
        _sphere.copy(g.boundingSphere as THREE.Sphere).applyMatrix4(_world);
        _centre.copy(_sphere.center).project(camera);
        if (_centre.z < -1 || _centre.z > 1) continue;
        const d = _sphere.center.distanceTo(eye);
        const r = ortho ? _sphere.radius * focal : (_sphere.radius * focal) / Math.max(d, 1e-9);
        const key = choiceKey(this.adaptive.choiceOf(o, i));
        out.push({ x: ((_centre.x + 1) / 2) * w, y: ((1 - _centre.y) / 2) * h, r, key });
      }
    }
    return out;
  }

  /**
   * The adaptive picture against the same scene with every object put back (Phong shading at full detail: the
   * panel's shading is Phong while adaptive runs), both drawn offscreen at the canvas's size and read back as
   * 8-bit sRGB; the drawn pixels are those either picture covers (cleared transparent, background off).
   */
  measure(): AdaptiveMeasured {
    const { renderer, scene, camera } = this.viewer;
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    const target = new THREE.WebGLRenderTarget(size.x, size.y);
    target.texture.colorSpace = THREE.SRGBColorSpace;
    const background = scene.background;
    const clear = renderer.getClearColor(new THREE.Color());
    const alpha = renderer.getClearAlpha();
    const read = () => {
      renderer.setRenderTarget(target);
      renderer.clear();
      renderer.render(scene, camera);
      const px = new Uint8Array(size.x * size.y * 4);
      renderer.readRenderTargetPixels(target, 0, 0, size.x, size.y, px);
      return px;
    };
    try {
      scene.background = null;
      renderer.setClearColor(0x000000, 0);
      this.suspended = true;
      for (const o of this.managed) this.adaptive.remove(o);
      this.managed.clear();
      const reference = read();
      this.suspended = false;
      const picture = read();
      return compare(reference, picture, this.budget);
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

/** `pictureError` of the adaptive picture where either picture is drawn (alpha > 0), with its budget. */
export function compare(reference: Uint8Array, picture: Uint8Array, budget: number): AdaptiveMeasured {
  return { budget, ...pictureError(reference, picture, budget) };
}
