/**
 * The Mach-band plot (loaded lazily, with the first profile): the displayed intensity along the dragged line in
 * flat, Gouraud and Phong shading, each read back from that shading's draw of the same view, where the flat and
 * Gouraud profiles' slope jumps, and the lecture's explanation of the bands the eye sees there.
 */
import { SHADINGS } from '@shadelab/material';
import type { Shading } from '../state/schema';
import { Axes, FRAME, polyline, scale } from './profileAxes';
import { luma, slopeBreaks } from './profileLine';
import type { ProfileSamples } from './profileSample';

/** Each shading's line colour (the trade-off page's). */
const COLORS: Record<Shading, string> = { flat: '#e0a040', gouraud: '#60b0e0', phong: '#80d080' };
const LABELS: Record<Shading, string> = { flat: 'flat', gouraud: 'Gouraud', phong: 'Phong' };
/** Smallest jump of the slope marked as a band, luma per pixel². */
const BREAK = 3;

/** The plot of one profile: `pixels` along the line and each shading's colours there. */
export default function ProfilePlot({
  pixels,
  samples,
}: {
  pixels: readonly (readonly [number, number])[];
  samples: ProfileSamples;
}) {
  const n = pixels.length;
  const f = FRAME;
  const sx = scale([0, Math.max(1, n - 1)], [f.left, f.width - f.right]);
  const sy = scale([0, 255], [f.height - f.bottom, f.top]);
  const series = SHADINGS.map((shading) => {
    const values = samples[shading].map(luma);
    return { shading, values, breaks: shading === 'phong' ? [] : slopeBreaks(values, BREAK) };
  });
  return (
    <figure className="profile-plot" style={{ margin: 0 }}>
      <svg
        viewBox={`0 0 ${f.width} ${f.height}`}
        width="100%"
        role="img"
        aria-label={`Intensity along the line (${n} pixels) in flat, Gouraud and Phong shading`}
        data-testid="profile-plot"
        data-pixels={pixels.map(([x, y]) => `${x},${y}`).join(' ')}
      >
        <Axes
          x={[0, Math.max(1, n - 1)]}
          y={[0, 255]}
          xLabel="pixels along the line"
          yLabel="luma"
          clipId="profile-clip"
        >
          {series.map(({ shading, values, breaks }, k) => (
            <g key={shading}>
              {breaks.map((i) => (
                <line
                  key={i}
                  x1={sx(i)}
                  x2={sx(i)}
                  y1={f.top + k * 5}
                  y2={f.top + k * 5 + 4}
                  stroke={COLORS[shading]}
                  data-break={i}
                />
              ))}
              <polyline
                points={polyline(values.map((v, i) => [sx(i), sy(v)]))}
                fill="none"
                stroke={COLORS[shading]}
                strokeWidth={1}
                data-shading={shading}
                data-values={values.map((v) => v.toFixed(3)).join(' ')}
              />
            </g>
          ))}
        </Axes>
      </svg>
      <figcaption style={{ fontSize: 11, lineHeight: 1.35, color: '#ccc' }}>
        <span style={{ display: 'flex', flexWrap: 'wrap', columnGap: 10 }}>
          {series.map(({ shading, breaks }) => (
            <span key={shading} style={{ color: COLORS[shading] }}>
              ━ {LABELS[shading]}
              {shading !== 'phong' &&
                (breaks.length > 0
                  ? `: ${breaks.length} slope jumps ▮`
                  : `: no slope jump of ${BREAK} or more per pixel² (its slope still changes at every triangle edge, by less than that here)`)}
            </span>
          ))}
        </span>
        Luma (Rec. 709 weights on the 8-bit sRGB codes) of each shading&apos;s draw of this view, read back
        from the canvas; ▮ marks where a slope jumps by {BREAK} or more per pixel². <b>Mach bands</b>: the eye
        responds to changes of intensity and exaggerates every place where the <i>slope</i> of intensity
        jumps, so it sees a brighter band on the bright side of such an edge and a darker one on the dark
        side. Flat shading gives every facet one value: a staircase, and bands at every facet edge. Gouraud
        interpolates the vertices&apos; colours: the intensity is continuous, but its slope still jumps at
        every triangle edge, and the eye still sees (fainter) bands. Phong evaluates the equation per pixel
        with the interpolated normal: the slope varies smoothly and the bands are gone.
      </figcaption>
    </figure>
  );
}
