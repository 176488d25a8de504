// Error against frame time for every measured option (recharts), the Pareto front as a line, and the
// current choice marked on its own bench point (the bench's numbers, not the live view's).
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
  type ChartPoint,
  chartPoints,
  currentMarker,
  type ErrorMetric,
  logTicks,
  paretoFront,
  TRADE_POINTS,
  type TradePoint,
} from './benchData';
import type { TradeOption } from './tradeOption';

const COLORS: Record<TradePoint['shading'], string> = {
  flat: '#e0a040',
  gouraud: '#60b0e0',
  phong: '#80d080',
  impostor: '#ff60c0',
};

export interface ParetoChartProps {
  metric: ErrorMetric;
  /** The current option: marked at its bench point (when the bench measured it). */
  current: TradeOption;
  onPick?: (point: TradePoint) => void;
}

export function ParetoChart({ metric, current, onPick }: ParetoChartProps) {
  const label = metric === 'rmse' ? 'interior RMSE (8-bit sRGB)' : 'silhouette error (px)';
  const front = chartPoints(paretoFront(TRADE_POINTS, metric), metric);
  const chosen = currentMarker(current, metric);
  const all = chartPoints(TRADE_POINTS, metric);
  const xTicks = logTicks(all.map((p) => p.x));
  const yTicks = logTicks(all.map((p) => p.y));
  const tick = (v: number) => String(Number(v.toPrecision(2)));
  const pick = (data: unknown) => {
    const name = (data as { payload?: ChartPoint } | undefined)?.payload?.name;
    const point = TRADE_POINTS.find((p) => p.name === name);
    if (point && onPick) onPick(point);
  };
  return (
    <ResponsiveContainer width="100%" height={380}>
      <ScatterChart margin={{ top: 10, right: 40, bottom: 30, left: 10 }}>
        <CartesianGrid stroke="#333" />
        <XAxis
          type="number"
          dataKey="x"
          name="frame"
          unit=" ms"
          scale="log"
          domain={[xTicks[0], xTicks.at(-1)!]}
          ticks={xTicks}
          interval={0}
          tickFormatter={tick}
          stroke="#aaa"
          label={{ value: 'frame time at 1280×720 (ms, log)', position: 'bottom', fill: '#aaa' }}
        />
        <YAxis
          type="number"
          dataKey="y"
          name={label}
          scale="log"
          domain={[yTicks[0], yTicks.at(-1)!]}
          ticks={yTicks}
          interval={0}
          tickFormatter={tick}
          stroke="#aaa"
          label={{ value: `${label}, log`, angle: -90, position: 'insideLeft', fill: '#aaa', dy: 90 }}
        />
        <Tooltip
          cursor={{ strokeDasharray: '3 3' }}
          contentStyle={{ background: '#222', border: '1px solid #444' }}
          formatter={(value, name, item) => {
            const p = (item as { payload?: ChartPoint }).payload;
            if (name === 'frame') return [`${Number(value).toFixed(1)} ms`, p?.name ?? ''];
            return [
              `${(p?.error ?? Number(value)).toFixed(2)} (${p?.triangles} triangles, ${p?.bytes} B)`,
              label,
            ];
          }}
        />
        <Legend verticalAlign="top" />
        {(['flat', 'gouraud', 'phong', 'impostor'] as const).map((shading) => (
          <Scatter
            key={shading}
            name={shading}
            data={chartPoints(
              TRADE_POINTS.filter((p) => p.shading === shading),
              metric,
            )}
            fill={COLORS[shading]}
            onClick={pick}
            isAnimationActive={false}
          />
        ))}
        <Scatter
          name="Pareto front"
          data={front}
          line={{ stroke: '#ddd', strokeDasharray: '4 3' }}
          fill="#ddd"
          shape={() => <g />}
          legendType="plainline"
          isAnimationActive={false}
        />
        <Scatter
          name="current option (bench point)"
          data={chosen}
          fill="#ff3030"
          shape="star"
          legendType="star"
          isAnimationActive={false}
        />
      </ScatterChart>
    </ResponsiveContainer>
  );
}
