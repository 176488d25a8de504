// The heat map's legend: which colour means exact, how far off an interior pixel is, how far the silhouette is,
// and the background (the colours are errorHeatmap.ts's).
import {
  HEAT_BACKGROUND,
  HEAT_EXACT,
  HEAT_RAMP_STOPS,
  heatColor,
  type Rgb8,
  silhouetteColor,
} from './errorHeatmap';

function swatch(c: Rgb8, label: string) {
  return (
    <span className="swatch" key={label}>
      <span
        style={{
          display: 'inline-block',
          width: '0.9em',
          height: '0.9em',
          background: `rgb(${c.join(',')})`,
        }}
      />{' '}
      {label}
    </span>
  );
}

/** The legend under the heat map. */
export function HeatmapLegend() {
  return (
    <p className="legend" data-testid="legend">
      {swatch(HEAT_EXACT, 'exact (or within 1 px of the edge, not compared)')} ·{' '}
      {HEAT_RAMP_STOPS.map((e) => swatch(heatColor(e), `${e}${e === 16 ? '+' : ''}`))} interior colour error
      (8-bit codes) · {swatch(silhouetteColor(0.5), '→')}
      {swatch(silhouetteColor(2.6), 'silhouette off (brighter = farther)')} ·{' '}
      {swatch(HEAT_BACKGROUND, 'background')}
    </p>
  );
}
