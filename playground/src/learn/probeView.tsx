/**
 * What the probe panel shows of a probe (presentational only): the point and n, the flat face or the Gouraud
 * vertices and weights, each light's vectors and terms, the sum, the clamp and the 8-bit colour beside the GPU's.
 */
import type { LightExplanation } from '@shadelab/material/explain';
import { ARROW_COLORS } from './probeArrows';
import { maxChannelDifference, type V3 } from './probeMath';
import type { ProbeHit, ProbeResult } from './probePick';

const f3 = (x: number) => {
  const rounded = Math.round(x * 1000) / 1000;
  return (rounded === 0 ? 0 : rounded).toFixed(3); // no "-0.000"
};
const vec = (v: ArrayLike<number> | null) => (v ? `(${Array.from(v, f3).join(', ')})` : '—');
const hex = (c: number) => `#${c.toString(16).padStart(6, '0')}`;
const clamp01 = (v: V3): V3 => v.map((c) => Math.min(Math.max(c, 0), 1)) as V3;

function Swatch({ rgb }: { rgb: V3 }) {
  return (
    <span
      aria-hidden="true"
      style={{
        display: 'inline-block',
        width: 12,
        height: 12,
        verticalAlign: 'middle',
        border: '1px solid #888',
        background: `rgb(${rgb.join(',')})`,
      }}
    />
  );
}

function Row({ name, color, children }: { name: string; color?: number; children: React.ReactNode }) {
  return (
    <>
      <dt style={color === undefined ? undefined : { color: hex(color) }}>{name}</dt>
      <dd>{children}</dd>
    </>
  );
}

function LightRows({ light, index, lighting }: { light: LightExplanation; index: number; lighting: string }) {
  const kind = light.kind === 'phong' ? 'PhongLight' : `three's ${light.kind} light`;
  return (
    <section data-testid="probe-light" aria-label={`light ${index + 1}`}>
      <h4 style={{ margin: '6px 0 2px' }}>
        Light {index + 1}: {kind}
      </h4>
      <dl className="probe-grid">
        {light.l && (
          <>
            <Row name="l" color={ARROW_COLORS.l}>
              {vec(light.l)}
            </Row>
            <Row name="t">{light.t === null ? '— (directional)' : f3(light.t)}</Row>
            <Row name="att">{f3(light.attenuation)}</Row>
            <Row name="v" color={ARROW_COLORS.v}>
              {vec(light.v)}
            </Row>
            {lighting === 'blinn-phong' ? (
              <Row name="h" color={ARROW_COLORS.h}>
                {vec(light.h)} n·h {f3(light.cosine)}
              </Row>
            ) : (
              <Row name="r" color={ARROW_COLORS.r}>
                {vec(light.r)} v·r {f3(light.cosine)}
              </Row>
            )}
            <Row name="l·n">{f3(light.lDotN ?? 0)}</Row>
            {light.band !== null && (
              <Row name="cel band">
                <span data-testid="probe-band">{light.band}</span> (diffuse {f3(light.diffuseFactor)},
                highlight {light.specularFactor ? 'on' : 'off'})
              </Row>
            )}
          </>
        )}
        <Row name="ka·Ia">{vec(light.ambient)}</Row>
        <Row name="att·kd·Id·max(l·n,0)">{vec(light.diffuse)}</Row>
        <Row name="att·ks·Is·spec">{vec(light.specular)}</Row>
      </dl>
    </section>
  );
}

function Colour({ hit, gpu }: { hit: ProbeHit; gpu: V3 | null }) {
  const computed = hit.unreproduced.length === 0;
  const delta = gpu && computed ? maxChannelDifference(gpu, hit.srgb8) : null;
  return (
    <dl className="probe-grid">
      {hit.output !== 'color' && <Row name="output">the {hit.output} view (the material’s `output`)</Row>}
      <Row name={hit.gouraud ? 'Σ wᵢ·colourᵢ' : hit.output === 'color' ? 'sum' : hit.output}>
        {vec(hit.linear)}
      </Row>
      <Row name="clamped">{vec(clamp01(hit.linear))}</Row>
      {hit.fog !== null && <Row name="fog factor">{f3(hit.fog)}</Row>}
      <Row name="shade() → 8-bit">
        {computed ? (
          <span data-testid="probe-cpu" data-rgb={hit.srgb8.join(',')}>
            <Swatch rgb={hit.srgb8} /> ({hit.srgb8.join(', ')})
          </span>
        ) : (
          <span data-testid="probe-unreproduced">— {hit.unreproduced.join(' ')}</span>
        )}
      </Row>
      <Row name="GPU pixel">
        {gpu ? (
          <span data-testid="probe-gpu" data-rgb={gpu.join(',')}>
            <Swatch rgb={gpu} /> ({gpu.join(', ')})
          </span>
        ) : (
          'not read (the WebGL single view only)'
        )}
      </Row>
      {delta !== null && (
        <Row name="difference">
          <span data-testid="probe-delta" data-delta={delta}>
            {delta}/255 {delta <= 1 ? '✓ within 1/255' : '✗ more than 1/255'}
          </span>
        </Row>
      )}
    </dl>
  );
}

/** The probe's numbers: a probe off the object says so. */
export function ProbeView({ result, gpu }: { result: ProbeResult; gpu: V3 | null }) {
  if (!result.hit) {
    return (
      <p data-testid="probe-miss" role="status">
        {result.reason}
      </p>
    );
  }
  const { material, explanation: e } = result;
  const cel = material.celBands > 0 ? `, cel ${material.celBands} bands` : '';
  const name = result.mesh.name || 'mesh';
  return (
    <div data-testid="probe-hit" className="probe-columns">
      <div>
        <p style={{ margin: '2px 0' }}>
          {name}
          {result.instanceId !== null ? ` #${result.instanceId}` : ''}: {material.shading} shading,{' '}
          {material.lighting} lighting{cel}
        </p>
        <dl className="probe-grid">
          <Row name="point">{vec(result.point)}</Row>
          <Row name="n" color={ARROW_COLORS.n}>
            {vec(e.n)} at {result.atLabel}
          </Row>
          {result.flat && (
            <Row name="flat face">
              centroid {vec(result.flat.centroid)}, normal {vec(result.flat.normal)}
              {result.flat.perFragment ? ' (lit per fragment: no prepared corners)' : ''}
            </Row>
          )}
        </dl>
      </div>
      <Colour hit={result} gpu={gpu} />
      {result.gouraud && (
        <table data-testid="probe-gouraud" style={{ borderSpacing: '6px 0' }}>
          <thead>
            <tr>
              <th>vertex</th>
              <th>weight</th>
              <th>colour (linear)</th>
            </tr>
          </thead>
          <tbody>
            {result.gouraud.vertices.map((vertex, i) => (
              <tr key={vec(vertex.point)}>
                <td>{i + 1}</td>
                <td data-testid="probe-weight">{f3(result.gouraud!.weights[i]!)}</td>
                <td>
                  <Swatch rgb={vertex.explanation.srgb8} /> {vec(vertex.color)}
                </td>
              </tr>
            ))}
          </tbody>
        </table>
      )}
      {e.lights.map((light, i) => (
        // biome-ignore lint/suspicious/noArrayIndexKey: lights are listed in the equation's order.
        <LightRows key={i} light={light} index={i} lighting={material.lighting} />
      ))}
      {e.emissive.some((c) => c !== 0) && (
        <dl className="probe-grid">
          <Row name="emissive">{vec(e.emissive)}</Row>
        </dl>
      )}
      {result.notes.map((note) => (
        <p key={note} className="probe-note">
          {note}
        </p>
      ))}
    </div>
  );
}
