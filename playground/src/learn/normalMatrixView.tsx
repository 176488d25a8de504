/**
 * The normal matrix, live (loaded when first opened): the lecture's sphere as the view shows it (its geometry,
 * model matrix M, the panel's material and lights, the camera) drawn twice side by side in a canvas of its own,
 * with `normalMatrix` 'inverse-transpose' on the left and 'model' on the right, and at the probed point (or the
 * point under the view's centre) the tangent M·t and the normal each uses: (M⁻¹)ᵀ·n, perpendicular to it, and
 * M·n, which leans off it under a non-uniform scale. Redrawn after each of the view's frames.
 */
import { Camera } from '@shadelab/camera';
import { ShadingMaterial } from '@shadelab/material';
import { type RefObject, useEffect, useRef, useState } from 'react';
import * as THREE from 'three';
import { applyMaterial, applyProjection } from '../engine/viewer/applyState';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { type NormalMatrixVectors, normalMatrixVectors, objectNormalOf } from './normalMatrix';
import { probeStore } from './probeStore';

/** Arrow colours: the tangent, (M⁻¹)ᵀn, M·n. */
export const ARROW_COLORS = { tangent: 0xffd23f, inverseTranspose: 0x3ddc84, model: 0xff5a5f } as const;
const HALVES = ['inverse-transpose', 'model'] as const;

/** What the figure shows, or why it shows nothing. */
type Shown =
  | {
      ok: true;
      vectors: NormalMatrixVectors;
      source: 'probe' | 'centre';
      uniform: boolean;
      /** The point's pixel in each half (device pixels from the canvas's top left). */
      pixels: number[][];
      /** The directions the arrows were drawn with (read back from them): tangent, (M⁻¹)ᵀn, Mn. */
      drawn: string[];
    }
  | { ok: false; message: string };

const f3 = (v: readonly number[]) => v.map((c) => c.toFixed(3)).join(', ');

/** An arrow drawn over the surface (no depth test), in a fixed colour. */
function arrow(color: number, opacity = 1): THREE.ArrowHelper {
  const a = new THREE.ArrowHelper(new THREE.Vector3(0, 1, 0), new THREE.Vector3(), 1, color);
  for (const m of [a.line.material, a.cone.material] as THREE.Material[]) {
    m.depthTest = false;
    m.transparent = opacity < 1;
    m.opacity = opacity;
  }
  a.renderOrder = 10;
  return a;
}

/** One half: the object with one normal matrix, the tangent and the normals drawn. */
class Half {
  readonly scene = new THREE.Scene();
  readonly material = new ShadingMaterial();
  readonly mesh = new THREE.Mesh(new THREE.BufferGeometry(), this.material);
  readonly arrows: THREE.ArrowHelper[];

  constructor(readonly mode: (typeof HALVES)[number]) {
    this.scene.background = new THREE.Color(0);
    this.mesh.matrixAutoUpdate = false;
    this.scene.add(this.mesh);
    this.arrows =
      mode === 'model'
        ? [arrow(ARROW_COLORS.tangent), arrow(ARROW_COLORS.model), arrow(ARROW_COLORS.inverseTranspose, 0.35)]
        : [arrow(ARROW_COLORS.tangent), arrow(ARROW_COLORS.inverseTranspose)];
    for (const a of this.arrows) this.scene.add(a);
  }

  dispose() {
    this.material.dispose();
    for (const a of this.arrows) a.dispose();
  }
}

/** The point shown: the probe's when it is on the lecture's sphere, else the sphere under the view's centre. */
function pointOf(
  viewer: Viewer,
): { point: THREE.Vector3; normal: number[]; source: 'probe' | 'centre' } | null {
  const { mesh } = viewer;
  const probe = probeStore.get();
  if (probe?.object === mesh && probe.point && probe.normal) {
    return {
      point: new THREE.Vector3(...probe.point),
      normal: objectNormalOf(mesh.matrixWorld, probe.normal),
      source: 'probe',
    };
  }
  const ray = new THREE.Raycaster();
  ray.setFromCamera(new THREE.Vector2(0, 0), viewer.camera);
  const hit = ray.intersectObject(mesh, false)[0];
  if (!hit) return null;
  const local = mesh.worldToLocal(hit.point.clone());
  // The sphere's normal is its position (no normal attribute: the material uses normalize(position) too).
  const normal = mesh.geometry.hasAttribute('normal') && hit.normal ? hit.normal : local.normalize();
  return { point: hit.point, normal: normal.toArray(), source: 'centre' };
}

/** The figure (see the module comment). */
export default function NormalMatrixView({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const stateRef = useRef(state);
  stateRef.current = state;
  const [arrows, setArrows] = useState(true);
  const arrowsRef = useRef(arrows);
  arrowsRef.current = arrows;
  const redraw = useRef<() => void>(() => {});
  const [shown, setShown] = useState<Shown | null>(null);

  // biome-ignore lint/correctness/useExhaustiveDependencies: the renderer lives as long as the figure; draws read refs.
  useEffect(() => {
    const canvas = canvasRef.current!;
    const renderer = new THREE.WebGLRenderer({ canvas, preserveDrawingBuffer: true });
    const halves = HALVES.map((mode) => new Half(mode));
    const camera = new Camera({ fovy: 90, aspect: 1, near: 0.1, far: 10 });
    const draw = () => {
      const viewer = viewerRef.current;
      const s = stateRef.current;
      if (!viewer) return;
      const w = Math.max(2, Math.round(canvas.clientWidth * devicePixelRatio));
      const h = Math.max(1, Math.round(canvas.clientHeight * devicePixelRatio));
      if (canvas.width !== w || canvas.height !== h) renderer.setSize(w, h, false);
      const half = Math.floor(w / 2);
      const { mesh } = viewer;
      mesh.updateWorldMatrix(true, false);
      camera.lookAt(s.camera.eye, s.camera.at, s.camera.up);
      applyProjection(camera, s.camera, half / h);
      camera.updateMatrixWorld(true);
      let next: Shown;
      try {
        const at = pointOf(viewer);
        if (!at) throw new RangeError('No point of the sphere under the view’s centre: probe a point on it.');
        const vectors = normalMatrixVectors(mesh.matrixWorld, at.point.toArray(), at.normal);
        const size = 0.4 * s.sphere.radius * Math.max(...s.model.scale.map(Math.abs));
        const pixels: number[][] = [];
        for (const [i, side] of halves.entries()) {
          side.mesh.geometry = mesh.geometry;
          side.mesh.matrix.copy(mesh.matrixWorld); // the scene's child: its world matrix is this
          applyMaterial(side.material, { ...s.material, normalMatrix: side.mode }, [
            ...viewer.material.phongLights,
          ]);
          const dirs = [vectors.tangent, side.mode === 'model' ? vectors.model : vectors.inverseTranspose];
          if (side.mode === 'model') dirs.push(vectors.inverseTranspose);
          side.arrows.forEach((a, k) => {
            a.visible = arrowsRef.current;
            a.position.copy(at.point);
            a.setDirection(new THREE.Vector3(...dirs[k]!));
            a.setLength(size, 0.2 * size, 0.1 * size);
          });
          renderer.setViewport(i * half, 0, half, h);
          renderer.setScissor(i * half, 0, half, h);
          renderer.setScissorTest(true);
          renderer.render(side.scene, camera);
          const ndc = at.point.clone().project(camera);
          pixels.push([i * half + ((ndc.x + 1) / 2) * half, ((1 - ndc.y) / 2) * h]);
        }
        renderer.setScissorTest(false);
        const [sx, sy, sz] = s.model.scale;
        const up = (a: THREE.ArrowHelper) =>
          new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion).toArray();
        const arrows = halves[1]!.arrows;
        const drawn = [arrows[0]!, arrows[2]!, arrows[1]!].map((a) => up(a).join(','));
        next = { ok: true, vectors, source: at.source, uniform: sx === sy && sy === sz, pixels, drawn };
      } catch (error) {
        renderer.setScissorTest(false);
        renderer.setClearColor(0x000000);
        renderer.clear();
        next = { ok: false, message: error instanceof Error ? error.message : String(error) };
      }
      setShown((previous) => (JSON.stringify(previous) === JSON.stringify(next) ? previous : next));
    };
    // After each of the view's frames (its canvas counts them in data-frames), and on a probe.
    const observer = new MutationObserver(draw);
    const viewport = document.querySelector('[data-testid="viewport"]');
    if (viewport) observer.observe(viewport, { attributes: true, attributeFilter: ['data-frames'] });
    const unsubscribe = probeStore.subscribe(draw);
    redraw.current = draw;
    draw();
    return () => {
      observer.disconnect();
      unsubscribe();
      for (const side of halves) side.dispose();
      renderer.dispose();
    };
  }, []);

  const v = shown?.ok ? shown.vectors : null;
  return (
    <figure style={{ margin: 0, font: '12px system-ui, sans-serif' }}>
      <label style={{ display: 'block' }}>
        <input
          type="checkbox"
          checked={arrows}
          onChange={(e) => {
            arrowsRef.current = e.target.checked;
            setArrows(e.target.checked);
            redraw.current();
          }}
        />{' '}
        draw the tangent and the normals
      </label>
      <div style={{ position: 'relative' }}>
        <canvas
          ref={canvasRef}
          data-testid="normal-matrix-canvas"
          role="img"
          aria-label="The sphere shaded with the normal matrix (M⁻¹)ᵀ on the left and with M on the right"
          style={{ width: '100%', height: 150, display: 'block' }}
          data-source={shown?.ok ? shown.source : ''}
          data-point={v ? v.point.join(',') : ''}
          data-tangent={shown?.ok ? shown.drawn[0] : ''}
          data-normal-it={shown?.ok ? shown.drawn[1] : ''}
          data-normal-m={shown?.ok ? shown.drawn[2] : ''}
          data-pixels={shown?.ok ? shown.pixels.map((p) => p.join(',')).join(';') : ''}
        />
        <span style={{ position: 'absolute', left: 4, top: 2, color: '#3ddc84' }}>(M⁻¹)ᵀ·n</span>
        <span style={{ position: 'absolute', left: '50%', top: 2, marginLeft: 4, color: '#ff5a5f' }}>
          M·n (wrong)
        </span>
      </div>
      <figcaption data-testid="normal-matrix-text" style={{ font: '11px ui-monospace, monospace' }}>
        {!shown ? (
          'Drawing…'
        ) : !shown.ok ? (
          <span role="alert">{shown.message}</span>
        ) : (
          <>
            At the {shown.source === 'probe' ? 'probed point' : 'point under the view’s centre'} (
            {f3(v!.point)}):
            <br />
            <span style={{ color: '#ffd23f' }}>tangent M·t</span> ({f3(v!.tangent)})
            <br />
            <span style={{ color: '#3ddc84' }}>(M⁻¹)ᵀ·n</span> ({f3(v!.inverseTranspose)}),{' '}
            <span data-testid="angle-it">{v!.angles.inverseTranspose.toFixed(1)}°</span> to the tangent
            <br />
            <span style={{ color: '#ff5a5f' }}>M·n</span> ({f3(v!.model)}),{' '}
            <span data-testid="angle-m">{v!.angles.model.toFixed(1)}°</span> to the tangent
            <br />
            {shown.uniform
              ? 'The model scale is uniform: M·n points the same way. Set a non-uniform one (the lecture’s 2, 1, 2) to see it lean.'
              : 'Under a non-uniform scale M·n leans towards the stretched axis: no longer perpendicular to the surface, so the right half is lit wrongly.'}
          </>
        )}
      </figcaption>
    </figure>
  );
}
