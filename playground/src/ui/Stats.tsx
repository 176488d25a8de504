import { useEffect, useState } from 'react';
import type { FrameStats } from '../engine/viewer/stats';
import { rememberStatsOpen, statsOpen } from './panelLayout';

/** A tiny subscription so per-frame stats re-render only this panel, never the controls. */
export class StatsFeed {
  private listeners = new Set<(stats: FrameStats) => void>();
  last: FrameStats | null = null;
  firstFrameMs: number | null = null;
  push(stats: FrameStats) {
    this.last = { ...stats, cpuMs: Number.isNaN(stats.cpuMs) ? (this.last?.cpuMs ?? 0) : stats.cpuMs };
    for (const listener of this.listeners) listener(this.last);
  }
  subscribe(listener: (stats: FrameStats) => void) {
    this.listeners.add(listener);
    return () => {
      this.listeners.delete(listener);
    };
  }
}

const bytes = (n: number) =>
  n >= 1 << 20 ? `${(n / (1 << 20)).toFixed(2)} MiB` : n >= 1024 ? `${(n / 1024).toFixed(1)} KiB` : `${n} B`;

/**
 * The render statistics in the side column: a summary line (the CPU frame time and the triangles), and every row
 * when opened (the page remembers which).
 */
export function Stats({ feed }: { feed: StatsFeed }) {
  const [stats, setStats] = useState<FrameStats | null>(feed.last);
  const [open, setOpen] = useState(statsOpen);
  useEffect(() => feed.subscribe(setStats), [feed]);
  if (!stats) return null;
  const cells = stats.cells > 1 ? ` (${stats.cells} cells)` : '';
  return (
    <details
      className="stats-box"
      open={open}
      onToggle={(e) => {
        const now = e.currentTarget.open;
        if (now === open) return;
        setOpen(now);
        rememberStatsOpen(now);
      }}
    >
      <summary data-testid="stats-summary">
        render statistics: {stats.cpuMs.toFixed(2)} ms · {stats.triangles.toLocaleString('en-US')} triangles
      </summary>
      <dl className="stats" data-testid="stats" aria-label="render statistics">
        <dt>frame (CPU)</dt>
        <dd>{stats.cpuMs.toFixed(2)} ms</dd>
        <dt>frame (GPU)</dt>
        <dd data-testid="stats-gpu">
          {stats.gpuMs === null ? (stats.gpuNote ?? 'n/a (no timer query)') : `${stats.gpuMs.toFixed(2)} ms`}
        </dd>
        <dt>triangles{cells}</dt>
        <dd data-testid="stats-triangles">{stats.triangles.toLocaleString('en-US')}</dd>
        <dt>vertices{cells}</dt>
        <dd data-testid="stats-vertices">{stats.vertices.toLocaleString('en-US')}</dd>
        <dt>buffers{stats.cells > 1 ? ' (shared once)' : ''}</dt>
        <dd data-testid="stats-bytes" title={`${stats.bufferBytes.toLocaleString('en-US')} bytes`}>
          {bytes(stats.bufferBytes)} ({stats.bufferBytes.toLocaleString('en-US')} B)
        </dd>
        <dt>programs</dt>
        <dd data-testid="stats-programs">{stats.programs}</dd>
        <dt>depth</dt>
        <dd data-testid="stats-depth">{stats.depth}</dd>
        {stats.errorPx !== null && (
          <>
            <dt>silhouette error ≤</dt>
            <dd data-testid="stats-error">{stats.errorPx.toFixed(3)} px</dd>
          </>
        )}
        {stats.detail && (
          <>
            <dt>auto detail</dt>
            <dd data-testid="stats-detail">
              {stats.detail.base} {stats.detail.level} ({stats.detail.errorPx.toFixed(3)} px)
            </dd>
          </>
        )}
        {feed.firstFrameMs !== null && (
          <>
            <dt>first frame</dt>
            <dd data-testid="first-frame">{feed.firstFrameMs.toFixed(0)} ms</dd>
          </>
        )}
      </dl>
    </details>
  );
}
