import { lazy, Suspense, useCallback, useEffect, useMemo, useRef, useState } from 'react';
import type { ShaderSource } from './engine/ShaderProbe';
import { SCENE_LABELS } from './engine/scenes';
import { MOVE_KEYS, TURN_KEYS_TEXT } from './engine/viewer/input';
import { COMPARE_COLUMNS, compareLayout, type Layout } from './engine/viewer/layout';
import type { ParityResult } from './engine/viewer/parity';
import { type SectionErrors, Viewer } from './engine/viewer/Viewer';
import type { GeneratedShader, WebGPUStatus } from './engine/webgpu/status';
import { EmbedStrip } from './learn/embedStrip';
import { ParityPanel } from './parity/ParityPanel';
import { loadInitialState, readUrlState, saveState, stateUrl } from './state/persist';
import {
  DEPTH_MODES,
  defaultLight,
  defaultState,
  MAX_LIGHTS,
  type PlaygroundState,
  validateState,
} from './state/schema';
import { DockContext } from './ui/dock';
import { gizmoNotice } from './ui/gizmoNotice';
import { Messages } from './ui/Messages';
import { modelDropProps } from './ui/ModelPicker';
import { StatsFeed } from './ui/Stats';
import type { Update } from './ui/useFolder';
import { useModel } from './ui/useModel';
import { usePanelsShown } from './ui/usePanelsShown';

type Variant = ShaderSource & { key: string; defines: Record<string, unknown> };

/** The panels and leva, loaded after the first frame (ui/Panels.tsx): one chunk for both parts. */
const panels = () => import('./ui/Panels');
const Panels = lazy(() => panels().then((m) => ({ default: m.Panels })));
const StageTools = lazy(() => panels().then((m) => ({ default: m.StageTools })));
/** An empty column holds the panels' place until they load: the canvas keeps its size. */
const PANELS_PLACEHOLDER = <aside className="side" aria-busy="true" />;

/** The playground: the lecture's lit sphere, every package option live, state in the URL. */
export function App() {
  const initial = useMemo(loadInitialState, []);
  const [state, setState] = useState<PlaygroundState>(initial.state);
  const [notices, setNotices] = useState<string[]>(initial.refused);
  const [schemaError, setSchemaError] = useState<string | null>(null);
  const [sectionErrors, setSectionErrors] = useState<SectionErrors>({});
  const [context, setContext] = useState<'ok' | 'lost' | 'restored'>('ok');
  // The recovery message goes with the scene it was about (React's state adjusted while rendering).
  const [contextScene, setContextScene] = useState(state.scene);
  if (contextScene !== state.scene) {
    setContextScene(state.scene);
    if (context === 'restored') setContext('ok');
  }
  const [variant, setVariant] = useState<Variant | null>(null);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const viewerRef = useRef<Viewer | null>(null);
  const feed = useMemo(() => new StatsFeed(), []);
  const goodState = useRef<PlaygroundState | null>(null);
  const [renderError, setRenderError] = useState<string | null>(null);
  const [layout, setLayout] = useState<Layout>({ cols: 2, rows: 2 });
  const [webgpu, setWebgpu] = useState<WebGPUStatus | null>(null);
  const [gpuShader, setGpuShader] = useState<GeneratedShader | null>(null);
  const [parity, setParity] = useState<ParityResult | null>(null);
  const [dock, setDock] = useState<HTMLElement | null>(null);
  const errors = [
    ...(schemaError ? [`Not applied: ${schemaError}`] : []),
    ...Object.entries(sectionErrors).map(([section, message]) => `${section}: ${message}`),
    ...(renderError ? [`render: ${renderError}`] : []),
  ];
  const [panelsShown, panelsFirstFrame] = usePanelsShown(errors.length > 0 || context !== 'ok');

  const refreshVariant = useCallback((viewer: Viewer) => {
    const next = viewer.getShaderSource();
    setVariant((previous) =>
      previous &&
      previous.key === next.key &&
      previous.vertexShader === next.vertexShader &&
      previous.fragmentShader === next.fragmentShader
        ? previous
        : next,
    );
  }, []);

  const update: Update = useCallback((mutate) => {
    setState((previous) => {
      const next = structuredClone(previous);
      mutate(next);
      return JSON.stringify(next) === JSON.stringify(previous) ? previous : next;
    });
  }, []);

  // The depth mode is fixed for a renderer's life (and a WebGL context keeps its clip control): a new mode
  // gets a new canvas (keyed below) and a new viewer.
  const depth = DEPTH_MODES.includes(state.camera.depth) ? state.camera.depth : 'standard';

  // The viewer lives as long as the canvas; React only feeds it states.
  useEffect(() => {
    const canvas = canvasRef.current!;
    const viewer = new Viewer(
      canvas,
      {
        onView: ({ eye, at, up, zoom, rotation }) =>
          update((d) => {
            d.camera.eye = eye;
            d.camera.at = at;
            if (up) d.camera.up = up;
            d.camera.zoom = zoom;
            d.trackball.rotation = rotation;
          }),
        onVariant: () => refreshVariant(viewer),
        onRenderError: (message) => setRenderError(message),
        onLightMoved: (index, position) =>
          update((d) => {
            const light = d.lights[index];
            if (light) light.position = position;
          }),
        onStats: (stats) => feed.push(stats),
        onContext: (status) => setContext(status),
        onStatus: setWebgpu,
        onShader: setGpuShader,
        onParity: setParity,
        onFirstFrame: (ms) => {
          feed.firstFrameMs = ms;
          console.info(`[shadelab] first frame rendered ${ms.toFixed(1)} ms after navigation start`);
          panelsFirstFrame();
        },
      },
      depth,
    );
    viewerRef.current = viewer;
    const observer = new ResizeObserver(() => {
      setLayout(compareLayout(canvas.clientWidth || 1, canvas.clientHeight || 1));
      if (goodState.current) viewer.apply(goodState.current);
      viewer.requestRender();
    });
    observer.observe(canvas);
    return () => {
      observer.disconnect();
      viewer.dispose();
      viewerRef.current = null;
    };
  }, [feed, update, refreshVariant, depth, panelsFirstFrame]);

  // A link pasted into this tab changes only the hash: take its state (or refuse it) without a reload.
  useEffect(() => {
    const onHash = () => {
      const result = readUrlState();
      if (!result) return;
      if (result.ok) setState(result.state);
      else setNotices((n) => [...n, `The state in the URL was refused: ${result.error}`]);
    };
    window.addEventListener('hashchange', onHash);
    return () => window.removeEventListener('hashchange', onHash);
  }, []);

  // Every state change: validate against the schema, apply what changed, persist when it all held.
  useEffect(() => {
    const viewer = viewerRef.current;
    if (!viewer) return;
    const checked = validateState(state);
    if (!checked.ok) {
      setSchemaError(checked.error);
      return;
    }
    setSchemaError(null);
    const errors = viewer.apply(checked.state);
    setSectionErrors(errors);
    refreshVariant(viewer);
    if (Object.keys(errors).length === 0) {
      goodState.current = checked.state;
      const timer = window.setTimeout(() => saveState(checked.state), 150);
      return () => window.clearTimeout(timer);
    }
  }, [state, refreshVariant]);

  const actions = useMemo(
    () => ({
      exportPng: () => {
        const canvas = canvasRef.current;
        if (!canvas) return;
        viewerRef.current?.render();
        const link = document.createElement('a');
        link.download = 'shadelab.png';
        link.href = canvas.toDataURL('image/png');
        link.click();
      },
      copyLink: () => {
        const url = stateUrl(goodState.current ?? defaultState());
        navigator.clipboard?.writeText(url).then(
          () =>
            setNotices((n) => [...n.filter((m) => !m.startsWith('Link')), 'Link copied to the clipboard.']),
          () => setNotices((n) => [...n.filter((m) => !m.startsWith('Link')), `Link: ${url}`]),
        );
      },
      reset: () => setState(defaultState()),
      addLight: () =>
        update((d) => {
          if (d.lights.length < MAX_LIGHTS) d.lights.push({ ...defaultLight(), position: [0.4, 0.3, 2.4] });
        }),
    }),
    [update],
  );

  // The user's model (after the effects above: a new viewer and the state are in place when it looks).
  const model = useModel(viewerRef, state, update);

  const tryShader = useCallback(
    (source: ShaderSource) => viewerRef.current?.tryShader(source) ?? { ok: true as const },
    [],
  );
  const clearShader = useCallback(() => viewerRef.current?.clearShaderOverride(), []);
  const [gizmo, setGizmo] = useState<number | null>(null);
  const toggleGizmo = useCallback(
    (index: number) => {
      const notice = gizmo === index ? null : gizmoNotice(state, index);
      setGizmo(gizmo === index ? null : index);
      if (notice) setNotices((n) => (n.includes(notice) ? n : [...n, notice]));
    },
    [gizmo, state],
  );
  useEffect(() => {
    const index = gizmo !== null && gizmo < state.lights.length ? gizmo : null;
    viewerRef.current?.selectLight(index);
  }, [gizmo, state.lights.length]);

  return (
    <DockContext.Provider value={dock}>
      <div className="app">
        <main className="stage">
          <canvas
            key={depth}
            ref={canvasRef}
            data-testid="viewport"
            tabIndex={0}
            role="img"
            aria-label={`${state.scene === 'sphere' ? 'Lit sphere' : `Lit scene: ${SCENE_LABELS[state.scene]}`}. Drag or ${TURN_KEYS_TEXT} to turn it (trackball), wheel to zoom, Alt+click to probe a pixel; camera keys: ${MOVE_KEYS}.`}
            onPointerDown={(e) => e.currentTarget.focus()}
            {...modelDropProps(model.open)}
          />
          {state.view === 'parity' && <ParityPanel result={parity} layout={layout} status={webgpu} />}
          {state.view === 'compare' && (
            <ol
              className="compare-labels"
              aria-label="comparison columns"
              style={{
                gridTemplateColumns: `repeat(${layout.cols}, 1fr)`,
                gridTemplateRows: `repeat(${layout.rows}, 1fr)`,
              }}
            >
              {COMPARE_COLUMNS.map((c) => (
                <li key={c.label}>{c.label}</li>
              ))}
            </ol>
          )}
          <Messages
            context={context}
            dismissContext={() => setContext('ok')}
            notices={notices}
            dismissNotice={(n) => setNotices((all) => all.filter((m) => m !== n))}
            model={model.message}
            dismissModel={model.dismiss}
            errors={errors}
          />
          {panelsShown && (
            <Suspense fallback={null}>
              <StageTools viewerRef={viewerRef} state={state} feed={feed} />
            </Suspense>
          )}
        </main>
        <Suspense fallback={PANELS_PLACEHOLDER}>
          {panelsShown ? (
            <Panels
              state={state}
              update={update}
              viewerRef={viewerRef}
              feed={feed}
              model={model}
              actions={actions}
              variant={variant}
              tryShader={tryShader}
              clearShader={clearShader}
              webgpu={webgpu}
              gpuShader={gpuShader}
              onGizmo={toggleGizmo}
              dockRef={setDock}
            />
          ) : (
            PANELS_PLACEHOLDER
          )}
        </Suspense>
        <EmbedStrip state={state} update={update} />
      </div>
    </DockContext.Provider>
  );
}
