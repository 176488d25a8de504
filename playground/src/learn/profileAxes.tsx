/**
 * The learning plots' chart frame, hand-written SVG (the Mach-band profile's and the attenuation curve's): linear
 * scales, "nice" ticks, the axes with their labels, and a polyline's points. No chart library: these two plots
 * are lines over two axes, and SVG draws them in a few hundred bytes (playground/README.md says why).
 */
import type { ReactNode } from 'react';

/** The plot area inside the SVG's view box, in view-box units. */
export interface Frame {
  readonly width: number;
  readonly height: number;
  readonly left: number;
  readonly right: number;
  readonly top: number;
  readonly bottom: number;
}

/** The view box of the learning plots: 320 × 180 units with room for the tick labels. */
export const FRAME: Frame = { width: 320, height: 180, left: 38, right: 10, top: 8, bottom: 30 };

/** A linear map from a data interval onto a view-box interval. */
export function scale(
  domain: readonly [number, number],
  range: readonly [number, number],
): (v: number) => number {
  const [d0, d1] = domain;
  const [r0, r1] = range;
  if (!(Number.isFinite(d0) && Number.isFinite(d1) && d1 > d0)) {
    throw new RangeError(`scale: domain [${d0}, ${d1}] is not a finite interval with d1 > d0`);
  }
  return (v) => r0 + ((v - d0) / (d1 - d0)) * (r1 - r0);
}

/**
 * Tick values for an axis over [lo, hi]: multiples of 1, 2 or 5 × 10ⁿ, about `count` of them, inside the range.
 *
 * @param count - How many ticks to aim for. @default 5
 */
export function ticks(lo: number, hi: number, count = 5): number[] {
  if (!(Number.isFinite(lo) && Number.isFinite(hi) && hi > lo)) {
    throw new RangeError(`ticks: [${lo}, ${hi}] is not a finite interval with hi > lo`);
  }
  const raw = (hi - lo) / Math.max(1, count);
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) ?? 10 * power;
  const decimals = Math.max(0, -Math.floor(Math.log10(step)));
  const out: number[] = [];
  for (let k = Math.ceil(lo / step); k * step <= hi; k++) {
    const v = Number((k * step).toFixed(Math.min(decimals, 100)));
    if (v >= lo && v <= hi) out.push(v);
  }
  return out;
}

/** A tick label: up to 3 significant digits, no trailing zeros. */
export function tickLabel(v: number): string {
  return Number(v.toPrecision(3)).toString();
}

/** `points` as an SVG polyline's `points` attribute, rounded to 0.01 view-box units. */
export function polyline(points: readonly (readonly [number, number])[]): string {
  return points.map(([x, y]) => `${x.toFixed(2)},${y.toFixed(2)}`).join(' ');
}

/** The axes of a plot: ticks and labels on x and y, and its content clipped to the plot area. */
export function Axes({
  x,
  y,
  xLabel,
  yLabel,
  clipId,
  children,
}: {
  x: readonly [number, number];
  y: readonly [number, number];
  xLabel: string;
  yLabel: string;
  /** A page-unique id for the plot area's clip path. */
  clipId: string;
  children: ReactNode;
}) {
  const f = FRAME;
  const [x0, x1, y0, y1] = [f.left, f.width - f.right, f.height - f.bottom, f.top];
  const sx = scale(x, [x0, x1]);
  const sy = scale(y, [y0, y1]);
  const text = { fill: '#aaa', fontSize: 9 } as const;
  return (
    <>
      <defs>
        <clipPath id={clipId}>
          <rect x={x0} y={y1} width={x1 - x0} height={y0 - y1} />
        </clipPath>
      </defs>
      <rect x={x0} y={y1} width={x1 - x0} height={y0 - y1} fill="#0d0f12" stroke="#444" />
      {ticks(x[0], x[1]).map((v) => (
        <text key={`x${v}`} x={sx(v)} y={y0 + 11} textAnchor="middle" {...text}>
          {tickLabel(v)}
        </text>
      ))}
      {ticks(y[0], y[1], 4).map((v) => (
        <g key={`y${v}`}>
          <line x1={x0} x2={x1} y1={sy(v)} y2={sy(v)} stroke="#2a2f36" />
          <text x={x0 - 3} y={sy(v) + 3} textAnchor="end" {...text}>
            {tickLabel(v)}
          </text>
        </g>
      ))}
      <text x={(x0 + x1) / 2} y={f.height - 3} textAnchor="middle" {...text}>
        {xLabel}
      </text>
      <text
        x={9}
        y={(y0 + y1) / 2}
        textAnchor="middle"
        transform={`rotate(-90 9 ${(y0 + y1) / 2})`}
        {...text}
      >
        {yLabel}
      </text>
      <g clipPath={`url(#${clipId})`}>{children}</g>
    </>
  );
}
