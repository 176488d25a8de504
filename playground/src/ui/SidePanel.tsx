import { Leva } from 'leva';
import { useEffect, useRef, useState } from 'react';
import type { ShaderCheck, ShaderSource } from '../engine/ShaderProbe';
import { sceneNote } from '../engine/scenes';
import { backendLabel, type GeneratedShader, type WebGPUStatus, webgpuNotes } from '../engine/webgpu/status';
import type { PlaygroundState } from '../state/schema';
import { GeneratedShader as GeneratedShaderPanel } from './GeneratedShader';
import { rememberShaderCollapsed, shaderCollapsed, useRememberFolders } from './panelLayout';
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
}

/**
 * The column beside the canvas: the leva panel (its folders collapse, remembered), the scene note, WebGPU mode's
 * notes, and the shader view (collapsible, remembered), which takes what the panel leaves (index.html's CSS).
 */
export function SidePanel({ state, variant, tryShader, clearShader, webgpu, gpuShader }: Props) {
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
  return (
    <aside className="side">
      <div className="panel" ref={panelRef}>
        <Leva fill flat titleBar={false} hideCopyButton />
      </div>
      <p className="scene-note" data-testid="scene-note">
        {sceneNote(state.scene)}
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
      {(webgpuMode || showEditor) && (
        <div className={`shader-view${collapsed ? ' collapsed' : ''}`}>
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
