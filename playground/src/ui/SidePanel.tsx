import { Leva } from 'leva';
import { type ReactNode, useEffect, useRef, useState } from 'react';
import type { ShaderCheck, ShaderSource } from '../engine/ShaderProbe';
import { sceneNote } from '../engine/scenes';
import { backendLabel, type GeneratedShader, type WebGPUStatus, webgpuNotes } from '../engine/webgpu/status';
import type { PlaygroundState } from '../state/schema';
import { GeneratedShader as GeneratedShaderPanel } from './GeneratedShader';
import {
  PANEL_SHARE,
  panelShare,
  rememberPanelShare,
  rememberShaderCollapsed,
  shaderCollapsed,
  useRememberFolders,
} from './panelLayout';
import { ShaderEditor } from './ShaderEditor';

interface Props {
  state: PlaygroundState;
  /** The current WebGL variant and its GLSL (null before the first one). */
  variant: (ShaderSource & { key: string; defines: Record<string, unknown> }) | null;
  tryShader: (source: ShaderSource) => ShaderCheck;
  clearShader: () => void;
  /** WebGPU mode: the running backend (null while it starts) and the node material's generated code. */
  webgpu: WebGPUStatus | null;
  gpuShader: GeneratedShader | null;
  /** What the shown model is and what was swapped (scene `model`), or null. */
  modelNote?: string | null;
  /** The Learn panel, at the top of the column. */
  lesson?: ReactNode;
  /** The tools (under the Learn panel), the render statistics (under the notes). */
  tools?: ReactNode;
  stats?: ReactNode;
  /** Receives the dock, where the learning tools' panels open (under the tools). */
  dockRef?: (dock: HTMLElement | null) => void;
}

/**
 * The column beside the canvas: the Learn panel, the tools, the dock of the learning tools' panels, the leva panel
 * (its folders collapse), the scene note, WebGPU mode's notes, the render statistics and the shader view (it
 * collapses to its title), with a splitter between the panel and the shader view; the page remembers the folders,
 * the shader view, the statistics and the split (`panelLayout.ts`). Nothing of it lies over the view.
 */
export function SidePanel({
  state,
  variant,
  tryShader,
  clearShader,
  webgpu,
  gpuShader,
  modelNote,
  lesson,
  tools,
  stats,
  dockRef,
}: Props) {
  const panelRef = useRef<HTMLDivElement>(null);
  useRememberFolders(panelRef);
  useVectorLabels(panelRef);
  const webgpuMode = state.renderer === 'webgpu';
  const showEditor = !webgpuMode && variant && state.scene === 'sphere';
  const [collapsed, setCollapsed] = useState(shaderCollapsed);
  const toggle = () => {
    setCollapsed(!collapsed);
    rememberShaderCollapsed(!collapsed);
  };
  const [share, setShare] = useState(panelShare);
  const split = (webgpuMode || showEditor) && !collapsed;
  return (
    <aside className="side">
      {lesson}
      {tools}
      <div className="dock" ref={dockRef} data-testid="dock" />
      <div className="panel" ref={panelRef} style={split ? { flexBasis: `${share}%` } : undefined}>
        <Leva fill flat titleBar={false} hideCopyButton />
      </div>
      <p className="scene-note" data-testid="scene-note">
        {sceneNote(state.scene)}
        {modelNote && (
          <>
            {' '}
            <span data-testid="model-note">{modelNote}</span>
          </>
        )}
      </p>
      {webgpuMode && (
        <div className="renderer-note" data-testid="renderer-note">
          <p data-testid="renderer-backend" role="status">
            Renderer: {webgpu ? backendLabel(webgpu) : 'WebGPU mode: starting…'}
          </p>
          <ul>
            {webgpuNotes(state).map((note) => (
              <li key={note} data-testid="webgpu-note">
                {note}
              </li>
            ))}
          </ul>
        </div>
      )}
      {stats}
      {split && <Splitter share={share} onShare={setShare} />}
      {(webgpuMode || showEditor) && (
        <div
          className={`shader-view${collapsed ? ' collapsed' : ''}`}
          style={collapsed ? undefined : { flexBasis: `${100 - share}%` }}
        >
          <button
            type="button"
            className="shader-view-toggle"
            aria-expanded={!collapsed}
            aria-controls="shader-view-body"
            onClick={toggle}
          >
            {webgpuMode ? 'generated shader' : 'GLSL'}
          </button>
          <div className="shader-view-body" id="shader-view-body" hidden={collapsed}>
            {webgpuMode && <GeneratedShaderPanel shader={gpuShader} />}
            {showEditor && <ShaderEditor variant={variant} tryShader={tryShader} clearShader={clearShader} />}
          </div>
        </div>
      )}
    </aside>
  );
}

/**
 * The handle between the panel and the shader view: drag it (or focus it and press ↑/↓, Home/End) to give one
 * more of the column's height; the share is remembered on release.
 */
function Splitter({ share, onShare }: { share: number; onShare: (share: number) => void }) {
  const set = (next: number) => {
    const clamped = Math.round(Math.min(PANEL_SHARE.max, Math.max(PANEL_SHARE.min, next)));
    onShare(clamped);
    return clamped;
  };
  // The panel and the shader view split what the notes between them leave (flex-basis share% and the rest):
  // the share that puts the shader view's top edge (this handle) at the pointer.
  const shareAt = (element: HTMLElement, clientY: number) => {
    const column = element.parentElement!;
    const height = (selector: string) => column.querySelector(selector)?.getBoundingClientRect().height ?? 0;
    const shared = height('.panel') + height('.shader-view');
    const notes = column.getBoundingClientRect().height - shared;
    return ((clientY - column.getBoundingClientRect().top - notes) / shared) * 100;
  };
  const keys: Record<string, number> = {
    ArrowUp: share - 5,
    ArrowDown: share + 5,
    Home: PANEL_SHARE.min,
    End: PANEL_SHARE.max,
  };
  return (
    // biome-ignore lint/a11y/useSemanticElements: a focusable separator (a window splitter) has no element of its own.
    <div
      className="splitter"
      role="separator"
      aria-orientation="horizontal"
      aria-label="panel height"
      aria-valuemin={PANEL_SHARE.min}
      aria-valuemax={PANEL_SHARE.max}
      aria-valuenow={share}
      tabIndex={0}
      onPointerDown={(e) => {
        e.currentTarget.setPointerCapture(e.pointerId);
        e.preventDefault();
      }}
      onPointerMove={(e) => {
        if (e.currentTarget.hasPointerCapture(e.pointerId)) set(shareAt(e.currentTarget, e.clientY));
      }}
      onPointerUp={(e) => {
        if (e.currentTarget.hasPointerCapture(e.pointerId))
          rememberPanelShare(set(shareAt(e.currentTarget, e.clientY)));
      }}
      onKeyDown={(e) => {
        const next = keys[e.key];
        if (next === undefined) return;
        e.preventDefault();
        rememberPanelShare(set(next));
      }}
    />
  );
}

/** leva labels only the first field of a vector (x/r); names the others for screen readers ("ka y", …). */
function useVectorLabels(panelRef: React.RefObject<HTMLDivElement | null>) {
  useEffect(() => {
    const panel = panelRef.current;
    if (!panel) return;
    const name = () => {
      for (const input of panel.querySelectorAll<HTMLInputElement>('input[id$=".y"], input[id$=".z"]')) {
        const base = input.id.slice(0, -2);
        const label = panel.querySelector(`label[for="${CSS.escape(base)}"]`)?.textContent;
        const wanted = `${label ?? base} ${input.id.slice(-1)}`;
        if (label && input.getAttribute('aria-label') !== wanted) input.setAttribute('aria-label', wanted);
      }
    };
    name();
    const observer = new MutationObserver(name);
    observer.observe(panel, { childList: true, subtree: true });
    return () => observer.disconnect();
  }, [panelRef]);
}
