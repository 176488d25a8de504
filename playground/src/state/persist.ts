/**
 * Where the state lives outside the page: the URL hash (`#s=<json>`, shareable) and localStorage (kept across
 * reloads). Both are untrusted on the way in and go through the strict {@link parseState}.
 */
import { parseEmbedFlag } from './embed';
import { defaultState, type ParseResult, type PlaygroundState, parseState, serializeState } from './schema';

const STORAGE_KEY = 'shadelab.state';
const SHADER_PREFIX = 'shadelab.glsl.';
const HASH_KEY = 's';

/** The state to open with, and a message for each source that was refused. */
export interface InitialState {
  state: PlaygroundState;
  source: 'url' | 'storage' | 'default';
  refused: string[];
}

function readHash(): string | null {
  const hash = window.location.hash.replace(/^#/, '');
  if (!hash) return null;
  const params = new URLSearchParams(hash);
  return params.get(HASH_KEY);
}

function readStorage(key: string): string | null {
  try {
    return window.localStorage.getItem(key);
  } catch {
    return null;
  }
}

function writeStorage(key: string, value: string | null) {
  try {
    if (value === null) window.localStorage.removeItem(key);
    else window.localStorage.setItem(key, value);
  } catch {
    // Storage full or disabled: the URL still carries the state.
  }
}

/** The state in the URL hash now (after the user pasted a link into the same tab), or null if none. */
export function readUrlState(): ParseResult | null {
  const text = readHash();
  return text === null ? null : parseState(text);
}

/**
 * URL first (a shared link wins), then localStorage, then the lecture's scene. An embed (`?embed`) reads only the
 * URL: a slide shows the state its link gives, or the lecture's scene, never what this browser saved.
 */
export function loadInitialState(): InitialState {
  const refused: string[] = [];
  const embed = parseEmbedFlag(window.location.search);
  if (embed.error) refused.push(embed.error);
  const fromUrl = readHash();
  if (fromUrl !== null) {
    const result = parseState(fromUrl);
    if (result.ok) return { state: result.state, source: 'url', refused };
    refused.push(`The state in the URL was refused: ${result.error}`);
  }
  const stored = embed.embed ? null : readStorage(STORAGE_KEY);
  if (stored !== null) {
    const result = parseState(stored);
    if (result.ok) return { state: result.state, source: 'storage', refused };
    refused.push(`The saved state was refused: ${result.error}`);
  }
  return { state: defaultState(), source: 'default', refused };
}

/** Writes the state to the URL (replacing the history entry) and to localStorage (not from an embed). */
export function saveState(state: PlaygroundState) {
  const text = serializeState(state);
  const params = new URLSearchParams();
  params.set(HASH_KEY, text);
  window.history.replaceState(null, '', `${window.location.pathname}${window.location.search}#${params}`);
  if (!parseEmbedFlag(window.location.search).embed) writeStorage(STORAGE_KEY, text);
}

/** The shareable link to the current state. */
export function stateUrl(state: PlaygroundState): string {
  const params = new URLSearchParams();
  params.set(HASH_KEY, serializeState(state));
  return `${window.location.origin}${window.location.pathname}#${params}`;
}

/** A user's GLSL edit for one shader variant: kept until they reset it, even when it does not compile. */
export interface ShaderEdit {
  vertexShader: string;
  fragmentShader: string;
}

export function loadShaderEdit(variant: string): ShaderEdit | null {
  const text = readStorage(SHADER_PREFIX + variant);
  if (text === null || text.length > 1_000_000) return null;
  try {
    const value: unknown = JSON.parse(text);
    if (
      typeof value === 'object' &&
      value !== null &&
      typeof (value as ShaderEdit).vertexShader === 'string' &&
      typeof (value as ShaderEdit).fragmentShader === 'string'
    ) {
      return {
        vertexShader: (value as ShaderEdit).vertexShader,
        fragmentShader: (value as ShaderEdit).fragmentShader,
      };
    }
  } catch {
    // Malformed: ignore it.
  }
  return null;
}

export function saveShaderEdit(variant: string, edit: ShaderEdit | null) {
  writeStorage(SHADER_PREFIX + variant, edit === null ? null : JSON.stringify(edit));
}
