/**
 * The user's model on the app's side: a file opened or dropped is checked, parsed (the loader arrives on first
 * use), framed and swapped (`engine/scenes/model.ts`), kept in this browser (IndexedDB) and shown (`scene:
 * 'model'`); a file that is refused leaves the scene as it was and says why. When the state asks for the model
 * and the viewer has none (a reload, a link, the picker, a new canvas), it is built again from the file in
 * memory or in IndexedDB; when there is none, the page says so and shows the previous scene (the lecture's
 * sphere after a reload), the rest of the state untouched.
 */
import { type RefObject, useCallback, useEffect, useRef, useState } from 'react';
import { checkModelSize, ModelError } from '../engine/gltfCheck';
import { loadModel } from '../engine/modelLoader';
import { loadStoredModel, type StoredModel, saveModel } from '../engine/modelStore';
import type { ModelScene } from '../engine/scenes/model';
import type { Viewer } from '../engine/viewer/Viewer';
import { rememberOriginals } from '../engine/webgpu/originals';
import type { PlaygroundState, SceneName } from '../state/schema';
import type { Update } from './useFolder';

/** A line about the model in the page: an error (a refused file) or information (loading, not kept). */
export interface ModelMessage {
  readonly kind: 'error' | 'info';
  readonly text: string;
}

/** What the app renders and calls. */
export interface ModelControls {
  /** Opens a file (the picker's or a drop's). */
  open(file: File): void;
  /** The model shown (null when none): its name, meshes, swap and animation, for the note. */
  shown: ModelScene | null;
  message: ModelMessage | null;
  dismiss(): void;
  /** Whether the shown model's animation plays; `setPlaying` plays or pauses it. */
  playing: boolean;
  setPlaying(playing: boolean): void;
}

const errorText = (error: unknown) => (error instanceof Error ? error.message : String(error));

/**
 * Parses the file and builds its scene (the scene's module and the loader arrive on first use); KTX2 textures are
 * transcoded for `viewer`'s renderer.
 */
async function build(source: StoredModel, viewer: Viewer | null): Promise<ModelScene> {
  const loaded = await loadModel(source.name, source.bytes, viewer?.renderer ?? null);
  // WebGPU mode swaps the same originals with swapNodeMaterials.
  rememberOriginals(loaded.scene);
  const { createModelScene } = await import('../engine/scenes/model');
  return createModelScene(loaded);
}

export function useModel(
  viewerRef: RefObject<Viewer | null>,
  state: PlaygroundState,
  update: Update,
): ModelControls {
  const [shown, setShown] = useState<ModelScene | null>(null);
  const [message, setMessage] = useState<ModelMessage | null>(null);
  const [playing, setPlayingState] = useState(true);
  /** The model's file this session (the last one shown). */
  const source = useRef<StoredModel | null>(null);
  /** Each load's number: only the latest one's result is used. */
  const loads = useRef(0);
  const loading = useRef(false);
  /** The last scene shown other than the model (where a model that cannot be shown falls back to). */
  const fallback = useRef<SceneName>(state.scene === 'model' ? 'sphere' : state.scene);
  if (state.scene !== 'model') fallback.current = state.scene;

  /** Hands a built scene to the viewer, if this load is still the latest and the viewer is there. */
  const show = useCallback(
    (load: number, scene: ModelScene): boolean => {
      const viewer = viewerRef.current;
      if (load !== loads.current || !viewer) {
        scene.dispose();
        return false;
      }
      viewer.setModel(scene);
      setShown(scene);
      setPlayingState(scene.playing);
      return true;
    },
    [viewerRef],
  );

  const open = useCallback(
    (file: File) => {
      const load = ++loads.current;
      loading.current = true;
      setMessage({ kind: 'info', text: `Loading "${file.name}"…` });
      void (async () => {
        try {
          checkModelSize(file.name, file.size);
          const bytes = await file.arrayBuffer();
          const scene = await build({ name: file.name, bytes }, viewerRef.current);
          if (!show(load, scene)) return;
          source.current = { name: file.name, bytes };
          update((d) => {
            d.scene = 'model';
          });
          const notKept = await saveModel({ name: file.name, bytes });
          setMessage(
            notKept === null
              ? null
              : { kind: 'info', text: `"${file.name}" is shown but not kept for a reload: ${notKept}.` },
          );
        } catch (error) {
          if (load !== loads.current) return;
          // The scene shown stays as it was.
          setMessage({
            kind: 'error',
            text: `${error instanceof ModelError ? '' : 'Not shown: '}${errorText(error)}`,
          });
        } finally {
          if (load === loads.current) loading.current = false;
        }
      })();
    },
    [show, update, viewerRef],
  );

  // The state shows the model but the viewer has none: build it again from the file in memory or in IndexedDB.
  useEffect(() => {
    const viewer = viewerRef.current;
    if (state.scene !== 'model') {
      setShown(null);
      return;
    }
    if (!viewer || viewer.model() !== null || loading.current) return;
    const load = ++loads.current;
    loading.current = true;
    const back = fallback.current;
    void (async () => {
      let stored = source.current;
      let why = 'no model was opened in this browser';
      try {
        if (!stored) {
          const found = await loadStoredModel();
          stored = found.model;
          if (found.error) why = `this browser's storage could not be read (${found.error})`;
        }
        if (stored) {
          setMessage({ kind: 'info', text: `Loading "${stored.name}"…` });
          const scene = await build(stored, viewer);
          source.current = stored;
          if (show(load, scene)) setMessage(null);
          return;
        }
      } catch (error) {
        why = errorText(error);
      } finally {
        if (load === loads.current) loading.current = false;
      }
      if (load !== loads.current) return;
      setMessage({
        kind: 'error',
        text: `Your model could not be shown: ${why}. Showing ${back === 'sphere' ? 'the lecture’s sphere' : 'the previous scene'} instead; open a .glb or .gltf (below the view) or drop one on the view.`,
      });
      update((d) => {
        if (d.scene === 'model') d.scene = back;
      });
    })();
  }, [state, viewerRef, show, update]);

  const dismiss = useCallback(() => setMessage(null), []);
  const setPlaying = useCallback(
    (play: boolean) => {
      if (!shown) return;
      shown.playing = play;
      setPlayingState(play);
      viewerRef.current?.requestRender();
    },
    [shown, viewerRef],
  );
  return { open, shown, message, dismiss, playing, setPlaying };
}
