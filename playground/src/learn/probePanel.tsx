/**
 * The probe panel (loaded on the first Alt+click): probes the clicked pixel, shows its numbers (probeView.tsx)
 * beside the GPU's pixel read back from the canvas, draws the vectors as arrows (probeArrows.ts), publishes the
 * probe (probeStore.ts), and follows the probed point while it is open: after every frame whose view or state
 * changed, the point (kept in its object's own space) is projected again and the pixel it lands on re-probed.
 */
import { type RefObject, useCallback, useEffect, useRef, useState } from 'react';
import * as THREE from 'three';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { arrowsOf, ProbeArrows } from './probeArrows';
import { devicePixelOf, type V3 } from './probeMath';
import { type ProbeResult, pixelOfFollowed, probePixel, readCanvasPixel } from './probePick';
import { probeStore } from './probeStore';
import { ProbeView } from './probeView';

/** A click to probe at (client coordinates); `serial` tells two clicks at the same place apart. */
export interface ProbeRequest {
  readonly clientX: number;
  readonly clientY: number;
  readonly serial: number;
}

interface Props {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
  request: ProbeRequest;
  onClose: () => void;
}

/** What is followed: a surface point in its mesh's (or instance's) own space, or a pixel (after a miss). */
type Followed =
  | { kind: 'point'; mesh: THREE.Mesh; instanceId: number | null; local: V3 }
  | { kind: 'pixel'; pixel: [number, number] };

const PANEL_STYLE: React.CSSProperties = {
  flex: '0 0 auto',
  margin: 0,
  padding: '4px 8px',
  background: '#101010',
  color: '#ddd',
  font: '11px ui-monospace, monospace',
  borderRadius: 4,
};
const GRID_CSS = `.probe-grid{display:grid;grid-template-columns:auto 1fr;gap:0 8px;margin:2px 0}
.probe-grid dd{margin:0}.probe-note{color:#fb6;margin:4px 0}.probe h4{font-size:11px}
.probe-columns{display:grid;grid-template-columns:repeat(auto-fill,minmax(270px,1fr));gap:2px 14px}`;

/** Whether the probe can compare with the GPU: the single view of WebGL mode, drawing the mesh. */
function unsupported(state: PlaygroundState): string | null {
  if (state.view !== 'single') return 'The probe works in the single view: switch View → view to single.';
  if (state.scene === 'sphere' && state.sphere.render === 'impostor')
    return 'The ray-cast impostor is not probed: set Sphere → render to mesh.';
  return null;
}

/**
 * The probe panel for `request`'s pixel: its numbers, the GPU's pixel, the arrows' toggle and a close button;
 * follows the probed point until `onClose`.
 */
export default function ProbePanel({ viewerRef, state, request, onClose }: Props) {
  const [result, setResult] = useState<ProbeResult | null>(null);
  const [gpu, setGpu] = useState<V3 | null>(null);
  const [showArrows, setShowArrows] = useState(true);
  const [probed, setProbed] = useState(0);
  const arrows = useRef<ProbeArrows | null>(null);
  const followed = useRef<Followed | null>(null);
  const settings = useRef({ state, showArrows });
  settings.current = { state, showArrows };
  const lastKey = useRef('');
  const stateSerial = useRef(0);

  /** Probes `pixel` (or reports why not), redraws the arrows, reads the GPU's pixel without them. */
  const probe = useCallback(
    (pixel: [number, number] | null, reason = 'The probed point left the view.') => {
      const viewer = viewerRef.current;
      if (!viewer) return null;
      const { state: s, showArrows: on } = settings.current;
      const { canvas, renderer, scene, camera } = viewer;
      arrows.current ??= new ProbeArrows();
      const group = arrows.current.group;
      const why = unsupported(s);
      const next: ProbeResult =
        pixel === null || why
          ? { hit: false, pixel: pixel ?? [-1, -1], reason: why ?? reason }
          : probePixel(scene, camera, pixel[0], pixel[1], canvas.width, canvas.height);
      if (next.hit) {
        const toEye = camera.getWorldPosition(new THREE.Vector3()).distanceTo(new THREE.Vector3(...next.at));
        const length = camera.isPerspectiveCamera ? 0.3 * toEye : 0.75;
        arrows.current.show(next.at, arrowsOf(next), length);
      } else arrows.current.clear();
      if (group.parent !== scene) scene.add(group);
      let read: V3 | null = null;
      if (s.renderer === 'webgl' && pixel && !why) {
        // The arrows start at the point (v points at the eye): read the pixel from a frame drawn without them.
        group.visible = false;
        if (next.hit && on) renderer.render(scene, camera);
        read = readCanvasPixel(renderer, pixel[0], pixel[1]);
      }
      group.visible = on && next.hit && !why;
      if (group.visible) renderer.render(scene, camera);
      setResult(next);
      setGpu(read);
      probeStore.set({
        pixel: next.pixel,
        point: next.hit ? next.point : null,
        normal: next.hit ? next.explanation.n : null,
        object: next.hit ? next.mesh : null,
        instanceId: next.hit ? next.instanceId : null,
      });
      return next;
    },
    [viewerRef],
  );

  /** The view's key: when it changes after a frame, the followed point is probed again. */
  const viewKey = useCallback((viewer: Viewer) => {
    const { camera, pivot, canvas } = viewer;
    const matrices = [camera.matrixWorld, camera.projectionMatrix, pivot.matrixWorld];
    return `${matrices.map((m) => m.elements.join(',')).join('|')}|${canvas.width}x${canvas.height}|${stateSerial.current}`;
  }, []);

  /** Probes the followed point (or pixel) again where it is now. */
  const follow = useCallback(() => {
    const viewer = viewerRef.current;
    const target = followed.current;
    if (!viewer || !target) return;
    lastKey.current = viewKey(viewer);
    if (target.kind === 'pixel') {
      probe(target.pixel);
      return;
    }
    const { canvas, camera } = viewer;
    probe(pixelOfFollowed(camera, target.mesh, target.instanceId, target.local, canvas.width, canvas.height));
  }, [viewerRef, probe, viewKey]);

  // A click: probe that pixel and follow what it hit.
  useEffect(() => {
    const viewer = viewerRef.current;
    if (!viewer) return;
    const { canvas } = viewer;
    const pixel = devicePixelOf(
      request.clientX,
      request.clientY,
      canvas.getBoundingClientRect(),
      canvas.width,
      canvas.height,
    );
    followed.current = null;
    if (!pixel) {
      probe(null, 'The click was outside the view.');
      setProbed(request.serial);
      return;
    }
    lastKey.current = viewKey(viewer);
    const next = probe(pixel);
    followed.current = next?.hit
      ? { kind: 'point', mesh: next.mesh, instanceId: next.instanceId, local: next.local }
      : { kind: 'pixel', pixel };
    setProbed(request.serial);
  }, [request, probe, viewKey, viewerRef]);

  // A state change (material, lights, scene, view): probe again after the frame that shows it.
  // biome-ignore lint/correctness/useExhaustiveDependencies: the state's identity is the trigger.
  useEffect(() => {
    stateSerial.current++;
  }, [state]);

  // After each frame: if the view or the state changed, follow.
  const viewer = viewerRef.current;
  useEffect(() => {
    if (!viewer) return;
    const observer = new MutationObserver(() => {
      if (viewKey(viewer) !== lastKey.current) follow();
    });
    observer.observe(viewer.canvas, { attributes: true, attributeFilter: ['data-frames'] });
    return () => observer.disconnect();
  }, [viewer, follow, viewKey]);

  // The arrows' toggle: shown or hidden at once.
  useEffect(() => {
    const group = arrows.current?.group;
    const v = viewerRef.current;
    if (!group || !v) return;
    group.visible = showArrows && result?.hit === true;
    v.requestRender();
  }, [showArrows, result, viewerRef]);

  // Closing: the arrows leave the scene, the store is cleared.
  useEffect(
    () => () => {
      const group = arrows.current?.group;
      arrows.current?.clear();
      group?.removeFromParent();
      probeStore.set(null);
      viewerRef.current?.requestRender();
    },
    [viewerRef],
  );

  return (
    <section
      className="probe"
      data-testid="probe-panel"
      data-probed={probed}
      aria-label="pixel probe"
      style={PANEL_STYLE}
    >
      <style>{GRID_CSS}</style>
      <header style={{ display: 'flex', gap: 8, alignItems: 'center' }}>
        <strong>Probe</strong>
        <span data-testid="probe-pixel">
          {result && result.pixel[0] >= 0 ? `pixel (${result.pixel[0]}, ${result.pixel[1]})` : ''}
        </span>
        <label style={{ marginLeft: 'auto' }}>
          <input
            type="checkbox"
            data-testid="probe-arrows"
            checked={showArrows}
            onChange={(e) => setShowArrows(e.target.checked)}
          />{' '}
          arrows
        </label>
        <button type="button" aria-label="close the probe" onClick={onClose}>
          ×
        </button>
      </header>
      {result && <ProbeView result={result} gpu={gpu} />}
    </section>
  );
}
