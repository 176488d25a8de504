/**
 * The embed flag: `?embed` in the page's query (not in the `#s=` state) shows the canvas with a minimal control
 * strip, for slides and course pages (`learn/embedStrip.tsx`). Parsed strictly, as the state is: only `?embed`,
 * `?embed=1` (on) and `?embed=0` (off) are understood; any other value, or the flag given twice, is refused with
 * a message naming it, and the page opens as the full playground.
 */

/** What the query asks for: embed mode or not, and why a value was refused (null when none was). */
export interface EmbedFlag {
  readonly embed: boolean;
  readonly error: string | null;
}

/** Longest value shown back in a refusal, characters. */
const SHOWN = 40;

/**
 * Reads the embed flag from a query string (`window.location.search`, with or without its `?`). Never throws.
 *
 * @param search - The query string.
 */
export function parseEmbedFlag(search: string): EmbedFlag {
  const values = new URLSearchParams(search).getAll('embed');
  if (values.length === 0) return { embed: false, error: null };
  if (values.length > 1) {
    return { embed: false, error: `?embed is given ${values.length} times: give it once (?embed)` };
  }
  const value = values[0]!;
  if (value === '' || value === '1') return { embed: true, error: null };
  if (value === '0') return { embed: false, error: null };
  const shown = value.length > SHOWN ? `${value.slice(0, SHOWN)}…` : value;
  return {
    embed: false,
    error: `?embed=${JSON.stringify(shown)} is not understood: use ?embed (or ?embed=1, ?embed=0)`,
  };
}

/** Whether this page is in embed mode (`?embed` in its URL). */
export function isEmbedded(): boolean {
  return typeof window !== 'undefined' && parseEmbedFlag(window.location.search).embed;
}
