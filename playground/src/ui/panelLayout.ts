/**
 * Which parts of the side column are open: the panel's folders and the shader view. Folders open by default are
 * the ones used on every visit (the View folder's scene and export, the Material folder, the Lights folder's
 * "add light"); the others (Sphere, Camera, Trackball, each light) start collapsed so that the material fits
 * without scrolling at 1280 × 800. What the user opens or closes is kept in localStorage (this browser only, not
 * in the URL: it is the page's layout, not the scene's state).
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
}

function load(): Remembered {
  try {
    const value: unknown = JSON.parse(window.localStorage.getItem(STORAGE_KEY) ?? '{}');
    const { folders, shaderCollapsed } = (value ?? {}) as Partial<Remembered>;
    const clean = Object.fromEntries(
      Object.entries(typeof folders === 'object' && folders !== null ? folders : {}).filter(
        ([, collapsed]) => typeof collapsed === 'boolean',
      ),
    );
    return { folders: clean, shaderCollapsed: shaderCollapsed === true };
  } catch {
    // Malformed or storage disabled: the defaults.
    return { folders: {}, shaderCollapsed: false };
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
