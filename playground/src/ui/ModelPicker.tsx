/**
 * The model's controls in the side column's tools: a button that opens the file picker (a .glb, or a .gltf with embedded
 * resources), the play/pause button of a model's animation, and the drop target on the canvas
 * ({@link modelDropProps}). What the model is and what was swapped is in the note beside the panel
 * ({@link modelNote}).
 */
import { type DragEvent, useRef } from 'react';
import { formatBytes, MODEL_MAX_BYTES } from '../engine/gltfCheck';
import type { ModelScene } from '../engine/scenes/model';
import type { ModelControls } from './useModel';

/** The file types the picker offers. */
const ACCEPT = '.glb,.gltf,model/gltf-binary,model/gltf+json';

/** The picker and the animation's button (inline, in the side column's tools). */
export function ModelPicker({ model }: { model: ModelControls }) {
  const input = useRef<HTMLInputElement>(null);
  const clip = model.shown?.clip;
  return (
    <>
      <button
        type="button"
        className="model-open"
        title={`A .glb, or a .gltf with embedded resources (data: URIs), up to ${formatBytes(MODEL_MAX_BYTES)}; or drop one on the view.`}
        onClick={() => input.current?.click()}
      >
        open a glTF model…
      </button>
      <input
        ref={input}
        type="file"
        accept={ACCEPT}
        hidden
        data-testid="model-file"
        aria-label="glTF model file"
        onChange={(e) => {
          const file = e.currentTarget.files?.[0];
          if (file) model.open(file);
          e.currentTarget.value = ''; // the same file again is a new choice
        }}
      />
      {clip && (
        <>
          {' '}
          <button type="button" className="model-play" onClick={() => model.setPlaying(!model.playing)}>
            {model.playing ? 'pause' : 'play'} animation
          </button>
        </>
      )}
    </>
  );
}

/** The canvas's drop target: a file dropped on the view is opened as a model. */
export function modelDropProps(open: (file: File) => void) {
  return {
    onDragOver: (e: DragEvent) => {
      if (e.dataTransfer.types.includes('Files')) {
        e.preventDefault();
        e.dataTransfer.dropEffect = 'copy';
      }
    },
    onDrop: (e: DragEvent) => {
      const file = e.dataTransfer.files[0];
      if (!file) return;
      e.preventDefault();
      open(file);
    },
  };
}

/** What the note says about the shown model: its name, what was swapped and what was left, its animation. */
export function modelNote(scene: ModelScene): string {
  const skipped = scene.skipped.length > 0 ? ` Left as they were: ${scene.skipped.join('; ')}.` : '';
  const clip = scene.clip
    ? ` Animation “${scene.clip.name}” (${scene.clip.seconds.toFixed(2)} s), looping.`
    : ' No animation.';
  return `“${scene.name}”: ${scene.shaded} of ${scene.meshes} meshes drawn with ShadingMaterial.${skipped}${clip}`;
}
