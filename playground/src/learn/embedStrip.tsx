/**
 * Embed mode (`?embed`, parsed strictly in `state/embed.ts`): the canvas alone, for slides and course pages, with a
 * minimal control strip under it (shading, lighting, cel bands) and a link that opens the same state in the full
 * playground. The state comes from the URL (`#s=…`, or the lecture's scene) and the strip's changes go back into
 * it; the page hides the side column (the panels, the stats, the tools and their dock). Renders nothing outside embed
 * mode.
 */
import { LIGHTINGS, SHADINGS } from '@shadelab/material';
import { useEffect } from 'react';
import { isEmbedded } from '../state/embed';
import { STATE_FIELDS } from '../state/fields';
import { stateUrl } from '../state/persist';
import type { Lighting, PlaygroundState, Shading } from '../state/schema';
import type { Update } from '../ui/useFolder';

/** Height of the control strip, CSS pixels. */
export const EMBED_STRIP_PX = 32;

/** What embed mode hides and how it lays the page out (the canvas above, the strip below). */
const EMBED_CSS = `
html.embed .app { flex-direction: column; }
html.embed .side { display: none; }
.embed-strip { flex: 0 0 ${EMBED_STRIP_PX}px; display: flex; align-items: center; gap: 12px; padding: 0 8px;
  box-sizing: border-box; background: #181c20; border-top: 1px solid #333; font: 12px system-ui, sans-serif;
  white-space: nowrap; overflow: hidden; }
.embed-strip label { display: flex; align-items: center; gap: 4px; color: #bbb; }
.embed-strip select { background: #2a2f36; color: #ddd; border: 1px solid #444; border-radius: 3px; font: inherit; }
.embed-strip a { margin-left: auto; color: #9bd; }
`;

const SHADING_LABELS: Record<Shading, string> = { flat: 'flat', gouraud: 'Gouraud', phong: 'Phong' };
const LIGHTING_LABELS: Record<Lighting, string> = { phong: 'Phong', 'blinn-phong': 'Blinn-Phong' };
const celKind = STATE_FIELDS.material.celBands.kind;
/** 0 (off), then 2 … the panel's largest number of bands (the field's range). */
const BANDS = [
  0,
  ...Array.from({ length: (celKind.type === 'number' ? celKind.max : 2) - 1 }, (_, i) => i + 2),
];

/** The strip (in embed mode only; see the module comment). */
export function EmbedStrip({ state, update }: { state: PlaygroundState; update: Update }) {
  const embedded = isEmbedded();
  useEffect(() => {
    if (!embedded) return;
    document.documentElement.classList.add('embed');
    return () => document.documentElement.classList.remove('embed');
  }, [embedded]);
  if (!embedded) return null;
  const m = state.material;
  return (
    <nav className="embed-strip" aria-label="embed controls" data-testid="embed-strip">
      <style>{EMBED_CSS}</style>
      <label>
        shading
        <select
          aria-label="shading"
          value={m.shading}
          onChange={(e) =>
            update((d) => {
              d.material.shading = e.target.value as Shading;
            })
          }
        >
          {SHADINGS.map((v) => (
            <option key={v} value={v}>
              {SHADING_LABELS[v]}
            </option>
          ))}
        </select>
      </label>
      <label>
        lighting
        <select
          aria-label="lighting"
          value={m.lighting}
          onChange={(e) =>
            update((d) => {
              d.material.lighting = e.target.value as Lighting;
            })
          }
        >
          {LIGHTINGS.map((v) => (
            <option key={v} value={v}>
              {LIGHTING_LABELS[v]}
            </option>
          ))}
        </select>
      </label>
      <label>
        cel
        <select
          aria-label="cel bands"
          value={m.celBands}
          onChange={(e) =>
            update((d) => {
              d.material.celBands = Number(e.target.value);
            })
          }
        >
          {BANDS.map((n) => (
            <option key={n} value={n}>
              {n === 0 ? 'off' : `${n} bands`}
            </option>
          ))}
        </select>
      </label>
      <a href={stateUrl(state)} target="_blank" rel="noopener" data-testid="embed-open">
        open in the playground ↗
      </a>
    </nav>
  );
}
