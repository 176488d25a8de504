// Adaptive shading's measured trade (bench/results/adaptive.json): frame time (/ all-Phong, same cycle) against
// the measured error of the picture (p99 of |Δ| against all-Phong's) for adaptive at its budgets, fixed flat,
// fixed Gouraud and all-Phong, in the realistic scene's published and deeper views; each view's Pareto front
// as a line.
import {
  CartesianGrid,
  Legend,
  ResponsiveContainer,
  Scatter,
  ScatterChart,
  Tooltip,
  XAxis,
  YAxis,
} from 'recharts';
import {
  ADAPTIVE_CONDITIONS,
  ADAPTIVE_POINTS,
  type AdaptiveKind,
  type AdaptivePoint,
  adaptiveFront,
  type BenchView,
} from './adaptiveBenchData';

const COLORS: Record<AdaptiveKind, string> = {
  flat: '#e0a040',
  gouraud: '#60b0e0',
  phong: '#80d080',
  adaptive: '#ff60c0',
};
const SHAPES: Record<BenchView, 'circle' | 'triangle'> = { published: 'circle', deep: 'triangle' };

interface Dot {
  x: number;
  y: number;
  point: AdaptivePoint;
}
const dots = (points: readonly AdaptivePoint[]): Dot[] =>
  points.map((p) => ({ x: p.frameRatio, y: p.p99, point: p }));
const pct = (x: number) => `${(100 * x).toFixed(2)} %`;

/** The chart of adaptive shading's bench (no props: the committed results). */
export function AdaptiveParetoChart() {
  const views = [...new Set(ADAPTIVE_POINTS.map((p) => p.view))];
  const budgets = ADAPTIVE_POINTS.filter((p) => p.kind === 'adaptive' && p.view === views[0])
    .map((p) => `maxError ${p.maxError}`)
    .join(', ');
  return (
    <div data-testid="adaptive-chart">
      <ResponsiveContainer width="100%" height={340}>
        <ScatterChart margin={{ top: 10, right: 20, bottom: 30, left: 10 }}>
          <CartesianGrid stroke="#333" />
          <XAxis
            type="number"
            dataKey="x"
            name="frame"
            domain={[0, 'auto']}
            tickFormatter={(v: number) => v.toFixed(2)}
            stroke="#aaa"
            label={{ value: 'frame time / all-Phong (same cycle)', position: 'bottom', fill: '#aaa' }}
          />
          <YAxis
            type="number"
            dataKey="y"
            name="error"
            domain={[0, 'auto']}
            stroke="#aaa"
            label={{
              value: 'error p99 (8-bit levels)',
              angle: -90,
              position: 'insideLeft',
              fill: '#aaa',
              dy: 80,
            }}
          />
          <Tooltip
            cursor={{ strokeDasharray: '3 3' }}
            contentStyle={{ background: '#222', border: '1px solid #444' }}
            formatter={(value, name, item) => {
              const p = (item as { payload?: Dot }).payload?.point;
              if (!p) return [String(value), String(name)];
              if (name === 'frame')
                return [`${p.frameRatio.toFixed(3)} × all-Phong`, `${p.name} (${p.view})`];
              return [`p99 ${p.p99}, max ${p.max}, > 8: ${pct(p.over8)}, > 32: ${pct(p.over32)}`, 'error'];
            }}
          />
          <Legend verticalAlign="top" />
          {views.flatMap((view) =>
            (['adaptive', 'flat', 'gouraud', 'phong'] as const).map((kind) => (
              <Scatter
                key={`${view} ${kind}`}
                name={`${kind} (${view === 'published' ? 'published view' : 'deeper view'})`}
                data={dots(ADAPTIVE_POINTS.filter((p) => p.view === view && p.kind === kind))}
                fill={COLORS[kind]}
                shape={SHAPES[view]}
                legendType={SHAPES[view]}
                isAnimationActive={false}
              />
            )),
          )}
          {views.map((view) => (
            <Scatter
              key={`${view} front`}
              name={`Pareto front (${view === 'published' ? 'published' : 'deeper'})`}
              data={dots(adaptiveFront(ADAPTIVE_POINTS.filter((p) => p.view === view)))}
              line={{ stroke: '#ddd', strokeDasharray: view === 'published' ? '4 3' : '1 3' }}
              fill="none"
              shape={() => <g />}
              isAnimationActive={false}
              legendType="none"
            />
          ))}
        </ScatterChart>
      </ResponsiveContainer>
      <p className="note">
        The realistic scene (1,000 instanced spheres, three's lights, fog, 1280×720),{' '}
        {ADAPTIVE_CONDITIONS.frames} cycles
        {ADAPTIVE_CONDITIONS.load
          ? `, load average ${ADAPTIVE_CONDITIONS.load.map((l) => l.toFixed(1)).join(' ')} at the start`
          : ''}
        . Adaptive's points are labelled by budget in the tooltip ({budgets}); its frame time includes its
        update. Numbers: BENCHMARKS.md, “Adaptive shading under an error budget”.
      </p>
    </div>
  );
}
