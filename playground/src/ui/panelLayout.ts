/**
 * The side column's layout: which panel folders are open, whether the shader view and the render statistics are,
 * and how the column's height is split between the panel and the shader view. The folders open on a first visit
 * are the ones used on every visit (the View folder's scene, renderer and export, the Material folder, the Lights
 * folder's "add light"); the others (Sphere, Camera, Trackball, each light) start collapsed; the statistics show
 * their summary line. What the user changes is kept in localStorage (this browser only, not in the URL: it is the
 * page's layout, not the scene's state).
 */
import { useEffect } from 'react';

const STORAGE_KEY = 'shadelab.layout';

/** Folders open on a first visit; every other folder starts collapsed. */
export const OPEN_FOLDERS: readonly string[] = ['View', 'Material', 'Lights'];

/** The folders created so far (by {@link folderCollapsed}): how a click on a title is told from others. */
const FOLDERS = new Set<string>();

/** What the user changed: folder name → collapsed, and the shader view. */
interface Remembered {
  folders: Record<string, boolean>;
  shaderCollapsed: boolean;
  /** The panel's share of the column's height when the shader view is open, percent. */
  panelShare: number;
  /** Whether the render statistics show every row (else their summary line only). */
  statsOpen: boolean;
}

/** The panel's share of the column by default, and the range the splitter allows, percent. */
export const PANEL_SHARE = { default: 55, min: 20, max: 85 } as const;

function load(): Remembered {
  try {
    const value: unknown = JSON.parse(window.localStorage.getItem(STORAGE_KEY) ?? '{}');
    const { folders, shaderCollapsed, panelShare, statsOpen } = (value ?? {}) as Partial<Remembered>;
    const clean = Object.fromEntries(
      Object.entries(typeof folders === 'object' && folders !== null ? folders : {}).filter(
        ([, collapsed]) => typeof collapsed === 'boolean',
      ),
    );
    const share =
      typeof panelShare === 'number' && panelShare >= PANEL_SHARE.min && panelShare <= PANEL_SHARE.max
        ? panelShare
        : PANEL_SHARE.default;
    return {
      folders: clean,
      shaderCollapsed: shaderCollapsed === true,
      panelShare: share,
      statsOpen: statsOpen === true,
    };
  } catch {
    // Malformed or storage disabled: the defaults.
    return { folders: {}, shaderCollapsed: false, panelShare: PANEL_SHARE.default, statsOpen: false };
  }
}

function save(change: (remembered: Remembered) => void) {
  const remembered = load();
  change(remembered);
  try {
    window.localStorage.setItem(STORAGE_KEY, JSON.stringify(remembered));
  } catch {
    // Storage full or disabled: the layout is only not remembered.
  }
}

/** Whether a panel folder opens collapsed: as the user left it, else collapsed unless in {@link OPEN_FOLDERS}. */
export function folderCollapsed(name: string): boolean {
  FOLDERS.add(name);
  return load().folders[name] ?? !OPEN_FOLDERS.includes(name);
}

/** Whether the shader view opens collapsed (as the user left it; open by default). */
export function shaderCollapsed(): boolean {
  return load().shaderCollapsed;
}

/** The panel's share of the column (percent) as the user left it, else {@link PANEL_SHARE}'s default. */
export function panelShare(): number {
  return load().panelShare;
}

/** Remembers the panel's share of the column, percent (kept within {@link PANEL_SHARE}'s range). */
export function rememberPanelShare(share: number) {
  save((r) => {
    r.panelShare = Math.min(PANEL_SHARE.max, Math.max(PANEL_SHARE.min, share));
  });
}

/** Whether the render statistics open with every row (as the user left them; their summary line by default). */
export function statsOpen(): boolean {
  return load().statsOpen;
}

/** Remembers whether the render statistics show every row. */
export function rememberStatsOpen(open: boolean) {
  save((r) => {
    r.statsOpen = open;
  });
}

/** Remembers the shader view's state. */
export function rememberShaderCollapsed(collapsed: boolean) {
  save((r) => {
    r.shaderCollapsed = collapsed;
  });
}

/**
 * Remembers every folder the user opens or closes in the panel. leva keeps a folder's open state inside its own
 * component and tells no one, so this follows the clicks on folder titles and flips the remembered state, which started as
 * the one the folder was created with ({@link folderCollapsed}).
 */
export function useRememberFolders(panel: React.RefObject<HTMLElement | null>) {
  useEffect(() => {
    const root = panel.current;
    if (!root) return;
    const onClick = (event: MouseEvent) => {
      const title = folderTitle(event.target, root);
      if (!title) return;
      const name = title.textContent ?? '';
      const collapsed = folderCollapsed(name);
      save((r) => {
        r.folders[name] = !collapsed;
      });
    };
    root.addEventListener('click', onClick);
    return () => root.removeEventListener('click', onClick);
  }, [panel]);
}

/** The folder title a click landed in (leva: a title holds the chevron `svg` and the folder's name), or null. */
function folderTitle(target: EventTarget | null, root: HTMLElement): HTMLElement | null {
  for (
    let node = target instanceof Element ? target : null;
    node && node !== root;
    node = node.parentElement
  ) {
    if (
      node instanceof HTMLElement &&
      node.firstElementChild instanceof SVGElement &&
      FOLDERS.has(node.textContent ?? '')
    ) {
      return node;
    }
  }
  return null;
}
