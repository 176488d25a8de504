/**
 * The attenuation plot (loaded lazily, when it is first opened): 1/(a + b·t + c·t²) of each light over the
 * distances the scene spans, with the range of t over which the light reaches the object marked on each curve
 * (from the object's bounding sphere and the light's position), and the factor at both ends of that range.
 */
import { type RefObject, useEffect, useState } from 'react';
import type { Viewer } from '../engine/viewer/Viewer';
import type { PlaygroundState } from '../state/schema';
import { attenuationPlot, type BoundingSphere } from './attenuation';
import { objectBounds } from './attenuationBounds';
import { Axes, FRAME, polyline, scale } from './profileAxes';

/** One colour per light (up to MAX_LIGHTS). */
const COLORS = ['#ffd166', '#60b0e0', '#ef476f', '#80d080', '#c77dff', '#ff9f1c', '#2ec4b6', '#e0e0e0'];

const fixed = (v: number) =>
  Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-3) ? v.toExponential(2) : v.toFixed(3);

/** The plot of the current state's lights against the object's bounding sphere. */
export default function AttenuationPlot({
  viewerRef,
  state,
}: {
  viewerRef: RefObject<Viewer | null>;
  state: PlaygroundState;
}) {
  const [bounds, setBounds] = useState<BoundingSphere | null>(null);
  // After the viewer applied this state (the app's effect runs after this child's).
  // biome-ignore lint/correctness/useExhaustiveDependencies: a new state may move or scale the object.
  useEffect(() => {
    const timer = window.setTimeout(() => {
      const viewer = viewerRef.current;
      setBounds(viewer ? objectBounds(viewer) : null);
    }, 50);
    return () => window.clearTimeout(timer);
  }, [state, viewerRef]);
  if (!bounds) return <p style={{ margin: 0 }}>The view shows no object yet.</p>;
  if (state.lights.length === 0) return <p style={{ margin: 0 }}>No light: add one in the Lights folder.</p>;

  const data = attenuationPlot(state.lights, bounds);
  const f = FRAME;
  const sx = scale([0, data.tMax], [f.left, f.width - f.right]);
  const sy = scale([0, data.yMax], [f.height - f.bottom, f.top]);
  const c = bounds.center.map((v) => fixed(v)).join(', ');
  return (
    <figure style={{ margin: 0 }}>
      <svg
        viewBox={`0 0 ${f.width} ${f.height}`}
        width="100%"
        role="img"
        aria-label="Attenuation 1/(a + b·t + c·t²) of each light against the distance t"
        data-testid="attenuation-plot"
        data-t-max={data.tMax}
        data-y-max={data.yMax}
        data-bounds={`${bounds.center.join(',')},${bounds.radius}`}
      >
        <Axes
          x={[0, data.tMax]}
          y={[0, data.yMax]}
          xLabel="distance t (world units)"
          yLabel="attenuation"
          clipId="att-clip"
        >
          {data.curves.map((curve, i) => {
            const color = COLORS[i % COLORS.length];
            const [near, far] = curve.range;
            const inRange = curve.points.filter(([t]) => t >= near && t <= far);
            const ends: [number, number][] = [[near, curve.atRange[0]], ...inRange, [far, curve.atRange[1]]];
            return (
              // biome-ignore lint/suspicious/noArrayIndexKey: lights are addressed by index in the state.
              <g key={i} data-light={i + 1}>
                <rect
                  x={sx(near)}
                  width={Math.max(1, sx(far) - sx(near))}
                  y={f.height - f.bottom - 4 - 4 * i}
                  height={3}
                  fill={color}
                  data-range={`${near},${far}`}
                />
                <polyline
                  points={polyline(curve.points.map(([t, v]) => [sx(t), sy(v)]))}
                  fill="none"
                  stroke={color}
                  strokeOpacity={0.6}
                  data-values={curve.points.map(([t, v]) => `${t},${v}`).join(' ')}
                />
                <polyline
                  points={polyline(ends.map(([t, v]) => [sx(t), sy(v)]))}
                  fill="none"
                  stroke={color}
                  strokeWidth={3}
                  data-testid="attenuation-range"
                />
              </g>
            );
          })}
        </Axes>
      </svg>
      <figcaption style={{ fontSize: 11, lineHeight: 1.35, color: '#ccc' }}>
        <ul style={{ margin: '2px 0', paddingLeft: 16 }}>
          {data.curves.map((curve, i) => {
            const l = state.lights[i]!;
            return (
              // biome-ignore lint/suspicious/noArrayIndexKey: lights are addressed by index in the state.
              <li key={i} style={{ color: COLORS[i % COLORS.length] }} data-testid="attenuation-light">
                light {i + 1}: 1/({l.attenuation.a} + {l.attenuation.b}·t + {l.attenuation.c}·t²); the object
                at t = {fixed(curve.range[0])} … {fixed(curve.range[1])}: factor {fixed(curve.atRange[0])} …{' '}
                {fixed(curve.atRange[1])}
              </li>
            );
          })}
        </ul>
        The thick part of each curve is the object&apos;s range of t: the distances from the light to the
        object&apos;s bounding sphere (centre {c}, radius {fixed(bounds.radius)}). The factor divides the
        light&apos;s diffuse and specular terms (not its ambient); with b = c = 0 it is constant, and the
        whole object gets the same share.
      </figcaption>
    </figure>
  );
}
