/**
 * The leva inputs of the panel, derived from the table of fields (`state/fields.ts`): one input per row that has
 * a panel entry, in the table's order, in its group's folder; each reads and writes its path of the state.
 */
import {
  type FieldSpec,
  FOLDER_OF,
  isField,
  LIGHT_FIELDS,
  type PanelInput,
  STATE_FIELDS,
  type Table,
} from '../state/fields';
import { defaultLight, type PlaygroundState } from '../state/schema';
import type { Field } from './useFolder';

/** A folder of the panel that holds rows of {@link STATE_FIELDS}. */
export type FolderName = (typeof FOLDER_OF)[keyof typeof FOLDER_OF];

/** A row that has a panel input, with its path in the state (`['camera', 'eye']`). */
export interface PanelRow {
  path: readonly string[];
  field: FieldSpec<unknown>;
  input: PanelInput;
}

/** Every row of a table that the panel shows, in the table's order. */
export function panelRows(table: Table, prefix: readonly string[] = []): PanelRow[] {
  return Object.entries(table).flatMap(([key, entry]): PanelRow[] => {
    const path = [...prefix, key];
    if (!isField(entry)) return panelRows(entry, path);
    return 'label' in entry.panel ? [{ path, field: entry, input: entry.panel }] : [];
  });
}

/** The decimals `step` is written with: 0.001 → 3, 0.1 → 1, 5 → 0, 1e-7 → 7. */
export function stepDecimals(step: number): number {
  const [mantissa, exponent] = String(step).split('e');
  return Math.max(0, (mantissa!.split('.')[1]?.length ?? 0) - Number(exponent ?? 0));
}

/**
 * The leva settings of a row: exactly the settings given (no `undefined` keys), options from the values, and a
 * number shown with its step's decimals (leva's own choice stops at 2, so c = 0.002 would read 0.00).
 */
export function levaInput({ field, input }: PanelRow): Record<string, unknown> {
  const out: Record<string, unknown> = { label: input.label };
  if (field.kind.type === 'enum')
    out['options'] = Array.isArray(input.options)
      ? [...input.options]
      : (input.options ?? [...field.kind.values]);
  for (const key of ['step', 'min', 'max'] as const) {
    if (input[key] !== undefined) out[key] = input[key];
  }
  if (input.step !== undefined) out['pad'] = stepDecimals(input.step);
  return out;
}

/** The value at a path of an object. */
export function getPath(root: unknown, path: readonly string[]): unknown {
  return path.reduce<unknown>((value, key) => (value as Record<string, unknown>)[key], root);
}

/** Sets the value at a path of an object (the parent objects exist). */
export function setPath(root: unknown, path: readonly string[], value: unknown) {
  const parent = getPath(root, path.slice(0, -1)) as Record<string, unknown>;
  parent[path[path.length - 1]!] = value;
}

/** The bound inputs of one folder of the scene controls (leva key: the row's name, or its `key`). */
export function folderFields(folder: FolderName): Record<string, Field> {
  const rows = panelRows(STATE_FIELDS).filter(
    (row) => FOLDER_OF[row.path[0] as keyof typeof FOLDER_OF] === folder,
  );
  return Object.fromEntries(
    rows.map((row) => [
      row.input.key ?? row.path[row.path.length - 1]!,
      {
        input: levaInput(row),
        read: (s: PlaygroundState) => getPath(s, row.path),
        write: (d: PlaygroundState, v: never) => setPath(d, row.path, v),
      },
    ]),
  );
}

/** The bound inputs of light `index`'s folder (leva keys `light<n><key>`). */
export function lightFields(index: number): Record<string, Field> {
  const n = index + 1;
  return Object.fromEntries(
    panelRows(LIGHT_FIELDS).map((row) => [
      `light${n}${row.input.key ?? row.path[row.path.length - 1]}`,
      {
        input: levaInput(row),
        read: (s: PlaygroundState) => getPath(s.lights[index] ?? defaultLight(), row.path),
        write: (d: PlaygroundState, v: never) => {
          const light = d.lights[index];
          if (light) setPath(light, row.path, v);
        },
      },
    ]),
  );
}
