import { levaStore, useControls } from 'leva';
import { useEffect, useRef, useState } from 'react';
import type { PlaygroundState } from '../state/schema';
import { folderCollapsed } from './panelLayout';

type LooseUseControls = (
  name: string,
  schema: () => Record<string, unknown>,
  settings: { order: number; collapsed: boolean },
  deps: unknown[],
) => [unknown, (values: Record<string, unknown>) => void];

/** Mutates a copy of the state (the App clones, applies, validates). */
export type Update = (mutate: (draft: PlaygroundState) => void) => void;

/** One leva input bound to one state field. */
export interface Field {
  /** leva input settings without `value`/`onChange` (options, step, min, max, label, …). */
  input?: Record<string, unknown>;
  read: (state: PlaygroundState) => unknown;
  write: (draft: PlaygroundState, value: never) => void;
}

/** leva buttons and other inputs that are not bound to the state. */
export type Extra = Record<string, unknown>;

/**
 * A leva folder whose inputs edit the state both ways: an edit in the panel calls `update`, and a change of
 * the state from elsewhere (URL, trackball, movement keys) is pushed back into the panel. The inputs for which
 * `idle(path)` holds (leva path `name.key`) are greyed out, the others live.
 */
export function useFolder(
  name: string,
  fields: Record<string, Field>,
  state: PlaygroundState,
  update: Update,
  extra: Extra = {},
  order = 0,
  idle: (path: string) => boolean = () => false,
) {
  // Read once: leva takes a folder's settings when it creates the folder.
  const [collapsed] = useState(() => folderCollapsed(name));
  const fieldsRef = useRef(fields);
  fieldsRef.current = fields;
  const updateRef = useRef(update);
  updateRef.current = update;
  const values = Object.fromEntries(Object.entries(fields).map(([key, field]) => [key, field.read(state)]));
  const [, set] = (useControls as unknown as LooseUseControls)(
    name,
    () => ({
      ...Object.fromEntries(
        Object.entries(fieldsRef.current).map(([key, field]) => [
          key,
          {
            ...field.input,
            value: field.read(state),
            onChange: (value: unknown, _path: string, context: { initial: boolean }) => {
              if (context.initial) return;
              updateRef.current((draft) => {
                const current = fieldsRef.current[key];
                current?.write(draft, value as never);
              });
            },
            transient: false,
          },
        ]),
      ),
      ...extra,
    }),
    { order, collapsed },
    [],
  );
  const text = JSON.stringify(values);
  useEffect(() => {
    set(JSON.parse(text) as Record<string, unknown>);
  }, [text, set]);
  // After leva has the folder's inputs (its own effect, above): each input greyed out or live.
  const paths = [...Object.keys(fields), ...Object.keys(extra)].map((key) => `${name}.${key}`);
  const idleText = JSON.stringify(paths.map((path) => [path, idle(path)]));
  useEffect(() => {
    const data = levaStore.getData();
    for (const [path, isIdle] of JSON.parse(idleText) as [string, boolean][]) {
      if (data[path]) levaStore.disableInputAtPath(path, isIdle);
    }
  }, [idleText]);
}
