/**
 * The adaptive shading tool (issue 25): in the instanced scene and a loaded model, a toggle that lets
 * `AdaptiveShading` choose each object's (and instance's) shading and detail under a budget (a slider, 8-bit
 * sRGB levels against Phong shading at full detail), a heat map over the view of what each one got, and the
 * measured error of the picture and frame time with and without (adaptiveRun.ts): measured again when the budget,
 * the scene or the view changes, "—" until then.
 * Adaptive starts from Phong shading (its reference): turning it on sets the panel's shading to Phong; it runs in
 * the single view on WebGL only, and turns itself off otherwise.
 */
import { type RefObject, useEffect, useRef, useState } from 'react';
import { createPortal } from 'react-dom';
import type { Viewer } from '../engine/viewer/Viewer';
import { isEmbedded } from '../state/embed';
import type { PlaygroundState } from '../state/schema';
import { useDock } from '../ui/dock';
import type { StatsFeed } from '../ui/Stats';
import type { Update } from '../ui/useFolder';
import type { AdaptiveMeasured, AdaptiveRun, AdaptiveUnit } from './adaptiveRun';
import { LEARN_PANEL } from './learnTool';

/** The heat map's colour of a choice: green Phong at full detail, teal coarser levels, blue Gouraud, orange flat. */
export function heatColor(key: string): string {
  if (key.startsWith('phong full')) return '#50c050';
  if (key.startsWith('phong')) return ['#1a8a8a', '#30a8a8', '#60c8c8'][Number(key.split(' ')[1]) % 3];
  if (key.startsWith('gouraud')) return key.includes('full') ? '#4080e0' : '#80a8f0';
  if (key.startsWith('flat')) return key.includes('derivatives') ? '#c06020' : '#f0a040';
  return '#888';
}

/** Budgets on the slider: 1 … 64 levels, in steps of a quarter power of two. */
const budgetAt = (step: number) => Math.round(2 ** (step / 4) * 100) / 100;

/** Why adaptive cannot run in `state` (null: it can). */
export function adaptiveUnavailable(state: PlaygroundState): string | null {
  if (state.scene !== 'instanced' && state.scene !== 'model')
    return 'Pick the instanced spheres or your model.';
  if (state.view !== 'single')
    return 'Adaptive runs in the single view (the compare view sets each column’s shading).';
  if (state.renderer === 'webgpu') return 'Adaptive runs on WebGL (ShadingMaterial).';
  if (state.material.shading !== 'phong')
    return 'Adaptive starts from Phong shading: set the shading to Phong.';
  return null;
}

export function AdaptiveTool({
  viewerRef,
  state,
  feed,
  update,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
  feed: StatsFeed;
  update: Update;
}) {
  const dock = useDock();
  const [open, setOpen] = useState(false);
  const [on, setOn] = useState(false);
  const [step, setStep] = useState(12); // 8 levels
  const [heat, setHeat] = useState(true);
  const [choices, setChoices] = useState<Record<string, number>>({});
  const [measured, setMeasured] = useState<AdaptiveMeasured | null>(null);
  /** Changes of the view (camera, projection, canvas size) since the run began: each measures again. */
  const [moved, setMoved] = useState(0);
  /** Measurements shown so far (the panel's data-measurements). */
  const [measurements, setMeasurements] = useState(0);
  const measureNow = () => {
    const m = run.current?.measure() ?? null;
    setMeasured(m);
    if (m) setMeasurements((n) => n + 1);
  };
  const run = useRef<AdaptiveRun | null>(null);
  const overlay = useRef<HTMLCanvasElement>(null);
  const budget = budgetAt(step);
  /** The budget now, for a run made after its code has loaded. */
  const budgetNow = useRef(budget);
  budgetNow.current = budget;
  /** Counts the runs made, so that the error is measured once a run exists. */
  const [made, setMade] = useState(0);
  const unavailable = adaptiveUnavailable(state);
  const active = on && unavailable === null;

  // The run lives while active (and the scene stays); the budget is set on it.
  // biome-ignore lint/correctness/useExhaustiveDependencies: the budget is set on the run below; a new scene restarts it.
  useEffect(() => {
    const viewer = viewerRef.current;
    if (!active || !viewer) return;
    // AdaptiveShading and the run load on first use: they stay out of the page's first load (issue 24's
    // "the lazy parts stay lazy", gated by tests/playground-learn.spec.ts).
    let r: AdaptiveRun | null = null;
    let gone = false;
    void import('./adaptiveRun').then(({ AdaptiveRun }) => {
      if (gone) return;
      r = new AdaptiveRun(viewer, budgetNow.current);
      run.current = r;
      setMade((n) => n + 1);
    });
    return () => {
      gone = true;
      r?.dispose();
      run.current = null;
      setMeasured(null);
      setChoices({});
    };
  }, [active, viewerRef, state.scene]);
  useEffect(() => {
    run.current?.setBudget(budget);
    setMeasured(null);
  }, [budget]);

  // Every frame: the choices and the heat map; a view other than the measured one (the camera, the trackball's
  // turn, the canvas size) makes the measurement stale.
  useEffect(() => {
    let view = '';
    return feed.subscribe(() => {
      const r = run.current;
      if (r) setChoices(r.choices());
      drawHeat(overlay.current, r && heat ? r.units() : []);
      const viewer = viewerRef.current;
      if (!viewer) return;
      const { camera, canvas, pivot } = viewer;
      const now = `${camera.matrixWorld.elements} ${camera.projectionMatrix.elements} ${pivot.matrixWorld.elements} ${canvas.width}×${canvas.height}`;
      if (view && now !== view) {
        setMeasured(null);
        setMoved((n) => n + 1);
      }
      view = now;
    });
  }, [feed, heat, viewerRef]);

  // The error and frame times, measured once the choice settles (400 ms after the last change of the budget, the
  // scene or the view) and again on demand.
  // biome-ignore lint/correctness/useExhaustiveDependencies: measured again when the budget, the scene or the view changes.
  useEffect(() => {
    if (!active) return;
    const timer = window.setTimeout(measureNow, 400);
    return () => window.clearTimeout(timer);
  }, [active, budget, state.scene, made, moved]);

  if (isEmbedded()) return null;
  const toggle = (value: boolean) => {
    if (value && state.material.shading !== 'phong') {
      update((d) => {
        d.material.shading = 'phong';
      });
    }
    setOn(value);
  };
  // The heat map goes over the canvas, in the stage; the panel in the dock.
  const stage = viewerRef.current?.canvas.parentElement ?? null;
  const panel = (
    <section
      style={{ ...LEARN_PANEL, font: '12px system-ui, sans-serif' }}
      aria-label="Adaptive shading"
      data-testid="adaptive-panel"
    >
      <label>
        <input
          type="checkbox"
          checked={on}
          data-testid="adaptive-toggle"
          onChange={(e) => toggle(e.target.checked)}
        />{' '}
        adaptive
      </label>{' '}
      <label>
        <input type="checkbox" checked={heat} onChange={(e) => setHeat(e.target.checked)} /> heat map
      </label>
      <label style={{ display: 'block' }}>
        budget{' '}
        <input
          type="range"
          min={0}
          max={24}
          step={1}
          value={step}
          data-testid="adaptive-budget"
          aria-label="error budget, 8-bit sRGB levels"
          onChange={(e) => setStep(Number(e.target.value))}
        />{' '}
        <output data-testid="adaptive-budget-value">{budget}</output> levels
      </label>
      {on && unavailable && <p data-testid="adaptive-unavailable">{unavailable}</p>}
      <dl
        className="stats"
        style={{ position: 'static' }}
        data-testid="adaptive-stats"
        data-measurements={measurements}
      >
        <dt title="median of 5 frames each, interleaved, to a 1×1 read-back; adaptive's update included">
          frame, adaptive
        </dt>
        <dd data-testid="adaptive-frame-on">
          {measured ? `${measured.frameMs.adaptive.toFixed(2)} ms` : '—'}
        </dd>
        <dt>frame, without</dt>
        <dd data-testid="adaptive-frame-off">
          {measured ? `${measured.frameMs.without.toFixed(2)} ms` : '—'}
        </dd>
        <dt>measured error</dt>
        <dd data-testid="adaptive-error">
          {measured
            ? `p99 ${measured.p99}, max ${measured.max}, ${(100 * measured.over).toFixed(2)} % over ${measured.budget}`
            : '—'}
        </dd>
      </dl>
      {active && (
        <button type="button" onClick={measureNow}>
          measure again
        </button>
      )}
      <ul style={{ listStyle: 'none', padding: 0, margin: '4px 0 0' }} data-testid="adaptive-choices">
        {Object.entries(choices)
          .sort((a, b) => b[1] - a[1])
          .map(([key, n]) => (
            <li key={key}>
              <span style={{ display: 'inline-block', width: 10, height: 10, background: heatColor(key) }} />{' '}
              {key}: {n}
            </li>
          ))}
      </ul>
    </section>
  );
  return (
    <>
      <button
        type="button"
        aria-pressed={open}
        title="Let AdaptiveShading choose each object's shading and detail under an error budget"
        onClick={() => setOpen(!open)}
      >
        adaptive shading
      </button>
      {stage &&
        active &&
        heat &&
        createPortal(
          <canvas
            ref={overlay}
            data-testid="adaptive-heatmap"
            style={{ position: 'absolute', inset: 0, width: '100%', height: '100%', pointerEvents: 'none' }}
          />,
          stage,
        )}
      {dock && open && createPortal(panel, dock)}
    </>
  );
}

/** Each unit's outline filled with its colour over the view (the overlay canvas at the view's size in CSS pixels). */
function drawHeat(canvas: HTMLCanvasElement | null, units: AdaptiveUnit[]): void {
  if (!canvas) return;
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  if (canvas.width !== w || canvas.height !== h) {
    canvas.width = w;
    canvas.height = h;
  }
  const ctx = canvas.getContext('2d');
  if (!ctx) return;
  ctx.clearRect(0, 0, w, h);
  ctx.globalAlpha = 0.45;
  for (const u of units) {
    ctx.fillStyle = heatColor(u.key);
    ctx.beginPath();
    for (const [x, y] of u.outline) ctx.lineTo(x, y);
    ctx.closePath();
    ctx.fill();
  }
}
