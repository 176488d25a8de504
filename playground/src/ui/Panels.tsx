/**
 * What the playground shows around the canvas: the side column (Learn panel, tools, dock, leva panel, notes,
 * statistics, shader view), the leva folders of the scene and the lights, and the stage's tools (the probe, the
 * arrows to off-screen lights). App loads this module after the canvas's first frame (`lazy` in App.tsx), so that
 * leva and the panels are neither loaded nor mounted before the picture is drawn.
 */
import type { RefObject } from 'react';
import type { ShaderCheck, ShaderSource } from '../engine/ShaderProbe';
import type { Viewer } from '../engine/viewer/Viewer';
import type { GeneratedShader, WebGPUStatus } from '../engine/webgpu/status';
import { Lesson } from '../learn/Lesson';
import { ProbeLauncher } from '../learn/probeLauncher';
import type { PlaygroundState } from '../state/schema';
import { LightControls, SceneControls } from './Controls';
import { LightArrows } from './LightArrows';
import { modelNote } from './ModelPicker';
import { SidePanel } from './SidePanel';
import { Stats, type StatsFeed } from './Stats';
import { Tools } from './Tools';
import type { Update } from './useFolder';
import type { ModelControls } from './useModel';

export interface PanelsProps {
  state: PlaygroundState;
  update: Update;
  viewerRef: RefObject<Viewer | null>;
  feed: StatsFeed;
  model: ModelControls;
  /** The leva panel's buttons. */
  actions: { exportPng: () => void; copyLink: () => void; reset: () => void; addLight: () => void };
  /** The current WebGL variant and its GLSL (null before the first one). */
  variant: (ShaderSource & { key: string; defines: Record<string, unknown> }) | null;
  tryShader: (source: ShaderSource) => ShaderCheck;
  clearShader: () => void;
  webgpu: WebGPUStatus | null;
  gpuShader: GeneratedShader | null;
  /** Puts the move gizmo on light `index` or takes it off. */
  onGizmo: (index: number) => void;
  /** Receives the dock, where the learning tools' panels open. */
  dockRef: (dock: HTMLElement | null) => void;
}

/** The side column and the leva folders (after the `<main>` stage). */
export function Panels({
  state,
  update,
  viewerRef,
  feed,
  model,
  actions,
  variant,
  tryShader,
  clearShader,
  webgpu,
  gpuShader,
  onGizmo,
  dockRef,
}: PanelsProps) {
  return (
    <>
      <SidePanel
        state={state}
        variant={variant}
        tryShader={tryShader}
        clearShader={clearShader}
        webgpu={webgpu}
        gpuShader={gpuShader}
        modelNote={state.scene === 'model' && model.shown ? modelNote(model.shown) : null}
        lesson={<Lesson update={update} />}
        tools={<Tools viewerRef={viewerRef} state={state} feed={feed} update={update} model={model} />}
        stats={<Stats feed={feed} />}
        dockRef={dockRef}
      />
      <SceneControls state={state} update={update} actions={actions} />
      {state.lights.map((_, i) => (
        // biome-ignore lint/suspicious/noArrayIndexKey: lights are addressed by index in the state.
        <LightControls key={i} index={i} state={state} update={update} onGizmo={onGizmo} />
      ))}
    </>
  );
}

/** The tools that live on the stage, over the canvas (inside `<main>`). */
export function StageTools({ viewerRef, state, feed }: Pick<PanelsProps, 'viewerRef' | 'state' | 'feed'>) {
  return (
    <>
      <ProbeLauncher viewerRef={viewerRef} state={state} />
      <LightArrows viewerRef={viewerRef} state={state} feed={feed} />
    </>
  );
}
