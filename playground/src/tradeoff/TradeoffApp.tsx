// The trade-off page: the measured Pareto chart (error against frame time, the current choice marked at its
// bench point), and
// the current view drawn with the chosen option beside its error heat map against the exact reference,
// recomputed live whenever the option or the zoom changes. The scene comes from the playground's URL state
// when there is one, else the lecture's (initialView.ts).
import { compareToReference, type ImageError } from '@shadelab/reference';
import { SPHERE_BASES, type SphereBase } from '@shadelab/sphere';
import { chooseSphereDetail, silhouetteErrorScalePx } from '@shadelab/sphere/detail';
import { useEffect, useMemo, useRef, useState } from 'react';
import { AdaptiveParetoChart } from './AdaptiveParetoChart';
import {
  cheapestMeeting,
  type ErrorMetric,
  TRADE_CONDITIONS,
  TRADE_POINTS,
  type TradePoint,
} from './benchData';
import { errorHeatmap } from './errorHeatmap';
import { HeatmapLegend } from './HeatmapLegend';
import { HEIGHT, initialFromUrl, MAX_LEVEL, WIDTH } from './initialView';
import { ParetoChart } from './ParetoChart';
import { optionCost, optionKey, type TradeOption } from './tradeOption';
import { TradeoffScene } from './tradeoffScene';

interface Live {
  error: ImageError;
  ms: number;
}

export function TradeoffApp() {
  const initial = useMemo(initialFromUrl, []);
  const [option, setOption] = useState<TradeOption>(initial.option);
  const [zoom, setZoom] = useState(1);
  const [metric, setMetric] = useState<ErrorMetric>('rmse');
  const [targetRmse, setTargetRmse] = useState(2);
  const [targetSilhouette, setTargetSilhouette] = useState(0.5);
  const [auto, setAuto] = useState(false);
  const [live, setLive] = useState<Live | null>(null);
  const [failure, setFailure] = useState<string | null>(null);
  const viewCanvas = useRef<HTMLCanvasElement>(null);
  const heatCanvas = useRef<HTMLCanvasElement>(null);
  const trade = useRef<TradeoffScene | null>(null);

  useEffect(() => {
    const canvas = viewCanvas.current;
    if (canvas === null) return;
    try {
      trade.current = new TradeoffScene(canvas);
    } catch (e) {
      setFailure(`WebGL2 is not available: ${String(e)}`);
    }
    return () => {
      trade.current?.dispose();
      trade.current = null;
    };
  }, []);

  useEffect(() => {
    const scene = trade.current;
    const heat = heatCanvas.current?.getContext('2d');
    if (!scene || !heat) return;
    const eye = (initial.view.eye ?? [0, 0, 3]).map((c) => c * zoom) as [number, number, number];
    try {
      scene.setView({ ...initial.view, eye });
      if (auto && option.shading !== 'impostor') {
        // detail 'auto': the cheapest base and level within 0.5 px on screen for this view, from the bound on
        // the outline's error in pixels per unit of radial error (not the projected radius, which understates
        // it near the camera).
        scene.impostor.updateMatrixWorld();
        const radiusPx = silhouetteErrorScalePx({
          camera: scene.camera,
          matrixWorld: scene.impostor.matrixWorld,
          viewportHeightPx: HEIGHT,
        });
        const detail = chooseSphereDetail({ radiusPx, maxErrorPx: 0.5, maxLevel: MAX_LEVEL });
        if (detail.base !== option.base || detail.level !== option.level) {
          setOption({ ...option, base: detail.base, level: detail.level });
          return;
        }
      }
      scene.setOption(option);
      scene.render();
      const t0 = performance.now();
      const pixels = scene.readPixels();
      const reference = scene.reference();
      const error = compareToReference(pixels, reference);
      const ms = performance.now() - t0;
      heat.putImageData(new ImageData(errorHeatmap(error, reference), WIDTH, HEIGHT), 0, 0);
      setLive({ error, ms });
      setFailure(null);
    } catch (e) {
      setFailure(String(e));
    }
  }, [option, zoom, initial, auto]);

  const name = optionKey(option);
  const cost = optionCost(option);
  const shading = option.shading;
  const base: SphereBase = option.shading === 'impostor' ? 'icosahedron' : option.base;
  const level = option.shading === 'impostor' ? 4 : option.level;
  const setShading = (s: TradeOption['shading']) =>
    setOption(s === 'impostor' ? { shading: 'impostor' } : { shading: s, base, level });
  const pick = (p: TradePoint) => setOption(p.option);
  const cheapest = cheapestMeeting(targetRmse, targetSilhouette);
  const bench = TRADE_POINTS.find((p) => p.name === name);
  return (
    <div className="tradeoff">
      <h1>Speed against accuracy: the lit sphere against its exact image</h1>
      {initial.otherScene && (
        <p className="note" data-testid="other-scene">
          Opened from the playground's {initial.otherScene} scene: the trade measured here is the lecture's
          sphere (its detail and shading), so this page draws the sphere, with that state's camera, lights and
          material.
        </p>
      )}
      <div className="controls">
        <label>
          shading
          <select
            data-testid="shading"
            value={shading}
            onChange={(e) => setShading(e.target.value as TradeOption['shading'])}
          >
            {(['flat', 'gouraud', 'phong', 'impostor'] as const).map((s) => (
              <option key={s}>{s}</option>
            ))}
          </select>
        </label>
        <label>
          base
          <select
            data-testid="base"
            value={base}
            disabled={shading === 'impostor'}
            onChange={(e) =>
              option.shading !== 'impostor' && setOption({ ...option, base: e.target.value as SphereBase })
            }
          >
            {SPHERE_BASES.map((b) => (
              <option key={b}>{b}</option>
            ))}
          </select>
        </label>
        <label>
          level
          <input
            data-testid="level"
            type="range"
            min={0}
            max={MAX_LEVEL}
            value={level}
            disabled={shading === 'impostor'}
            onChange={(e) =>
              option.shading !== 'impostor' && setOption({ ...option, level: Number(e.target.value) })
            }
          />
          {level}
        </label>
        <label>
          <input
            data-testid="auto"
            type="checkbox"
            checked={auto}
            onChange={(e) => setAuto(e.target.checked)}
          />
          auto detail (0.5 px)
        </label>
        <label>
          eye distance ×
          <input
            data-testid="zoom"
            type="range"
            min={0.8}
            max={6}
            step={0.05}
            value={zoom}
            onChange={(e) => setZoom(Number(e.target.value))}
          />
          {zoom.toFixed(2)}
        </label>
        <label>
          chart
          <select value={metric} onChange={(e) => setMetric(e.target.value as ErrorMetric)}>
            <option value="rmse">RMSE</option>
            <option value="silhouettePx">silhouette</option>
          </select>
        </label>
        <label>
          target RMSE ≤
          <input
            type="number"
            min={0}
            step={0.5}
            value={targetRmse}
            onChange={(e) => setTargetRmse(Number(e.target.value))}
            style={{ width: '4em' }}
          />
        </label>
        <label>
          silhouette ≤
          <input
            type="number"
            min={0}
            step={0.25}
            value={targetSilhouette}
            onChange={(e) => setTargetSilhouette(Number(e.target.value))}
            style={{ width: '4em' }}
          />
          px
        </label>
        <button
          type="button"
          data-testid="cheapest"
          disabled={!cheapest}
          onClick={() => cheapest && pick(cheapest)}
        >
          {cheapest ? `cheapest: ${cheapest.name}` : 'no option meets it'}
        </button>
      </div>
      <section>
        <h2>
          {name} — {cost.triangles} triangles, {cost.bytes} B of buffers
        </h2>
        <canvas ref={viewCanvas} width={WIDTH} height={HEIGHT} data-testid="view" />
      </section>
      <section>
        <h2>error against the exact reference</h2>
        <canvas ref={heatCanvas} width={WIDTH} height={HEIGHT} data-testid="heatmap" />
        <HeatmapLegend />
        {live && (
          <dl className="stats" data-testid="stats">
            <dt>RMSE</dt>
            <dd data-testid="rmse">{live.error.rmse.toFixed(2)}</dd>
            <dt>max</dt>
            <dd>{live.error.max}</dd>
            <dt>silhouette</dt>
            <dd data-testid="silhouette">{live.error.silhouettePx.toFixed(2)} px</dd>
            <dt>mismatched</dt>
            <dd>{live.error.mismatchedPixels} px</dd>
            <dt>compare</dt>
            <dd>{live.ms.toFixed(0)} ms (CPU reference + metrics)</dd>
          </dl>
        )}
        <p className="note" data-testid="bench-point">
          {bench
            ? `The ★ in the chart is this option's bench point (lecture scene, ${TRADE_CONDITIONS.width}×${TRADE_CONDITIONS.height}): ${bench.frameMs.toFixed(1)} ms, RMSE ${bench.rmse.toFixed(2)}, silhouette ${bench.silhouettePx.toFixed(2)} px. The numbers above are this view's, live.`
            : 'The bench has not measured this option (no ★ in the chart); the numbers above are this view, live.'}
        </p>
        {failure && <p className="note">{failure}</p>}
      </section>
      <section className="chart">
        <h2>measured trade (click a point to draw it)</h2>
        <ParetoChart metric={metric} current={option} onPick={pick} />
        <p className="note">
          Lecture scene at {TRADE_CONDITIONS.width}×{TRADE_CONDITIONS.height}, median of{' '}
          {TRADE_CONDITIONS.frames} frames; {TRADE_CONDITIONS.note}; load average when measured{' '}
          {TRADE_CONDITIONS.load.map((l: number) => l.toFixed(1)).join(' ')}. The live heat map above is the
          current view ({WIDTH}×{HEIGHT}); the chart is the benchmark's.
        </p>
      </section>
      <section className="chart">
        <h2>adaptive shading: frame time against measured error (realistic scene)</h2>
        <AdaptiveParetoChart />
      </section>
    </div>
  );
}
