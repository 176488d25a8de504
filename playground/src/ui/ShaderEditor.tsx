import { useEffect, useRef, useState } from 'react';
import type { ShaderCheck, ShaderDiagnostic, ShaderSource } from '../engine/ShaderProbe';
import type { ShaderVariant } from '../engine/viewer/shaderEditing';
import { loadShaderEdit, saveShaderEdit } from '../state/persist';

/** What the view shows of the generated GLSL: the lines this scene compiles, or the material's whole source. */
type View = 'compiled' | 'full';

interface Props {
  /** The current variant: its key, its generated GLSL and that GLSL as this scene compiles it. */
  variant: ShaderVariant;
  tryShader: (source: ShaderSource) => ShaderCheck;
  clearShader: () => void;
}

/**
 * The generated GLSL of the current variant, editable. By default it shows the program as this scene compiles
 * it (the material's source without its inactive `#if` branches: learn/compiledShaderGl.ts), with a toggle for
 * the full source; either is a valid program to edit. Every keystroke is saved (localStorage, per variant)
 * so an edit is never lost; after a pause it is compiled off-screen, and only a program that compiles
 * replaces the rendered one. Errors are listed with their line in the edited text.
 */
export function ShaderEditor({ variant, tryShader, clearShader }: Props) {
  const [stage, setStage] = useState<'fragmentShader' | 'vertexShader'>('fragmentShader');
  const [source, setSource] = useState<ShaderSource>(() => loadShaderEdit(variant.key) ?? variant);
  const [edited, setEdited] = useState(() => loadShaderEdit(variant.key) !== null);
  const [diagnostics, setDiagnostics] = useState<ShaderDiagnostic[]>([]);
  const [status, setStatus] = useState('generated program');
  const [view, setView] = useState<View>('compiled');
  /** The view the text shows (the full source when the compiled one could not be made). */
  const [shown, setShown] = useState<View>('full');
  const timer = useRef(0);
  const tryRef = useRef(tryShader);
  tryRef.current = tryShader;

  const compile = (next: ShaderSource) => {
    const check = tryRef.current(next);
    if (check.ok) {
      setDiagnostics([]);
      setStatus('edited program compiled and rendering');
    } else {
      setDiagnostics(check.diagnostics);
      setStatus('compile failed: the last good program keeps rendering');
    }
  };

  /** The generated program in `wanted` view, and the view it really is. */
  const generated = (wanted: View): [ShaderSource, View] => {
    const compiled = wanted === 'compiled' ? variant.compiled?.() : null;
    if (compiled) return [compiled, 'compiled'];
    return [{ vertexShader: variant.vertexShader, fragmentShader: variant.fragmentShader }, 'full'];
  };

  // A new variant (shading, lighting, bands, lights …) or view: show its program, or the user's saved edit of it.
  // biome-ignore lint/correctness/useExhaustiveDependencies: reload only when the variant or the view changes.
  useEffect(() => {
    const saved = loadShaderEdit(variant.key);
    const [text, as] = generated(view);
    setSource(saved ?? text);
    setShown(as);
    setEdited(saved !== null);
    setDiagnostics([]);
    setStatus(saved ? 'edited program' : 'generated program');
    if (saved) compile(saved);
  }, [variant.key, variant.vertexShader, variant.fragmentShader, view]);

  useEffect(() => () => window.clearTimeout(timer.current), []);

  const onEdit = (text: string) => {
    const next = { ...source, [stage]: text };
    setSource(next);
    setEdited(true);
    saveShaderEdit(variant.key, next);
    setStatus('edited, compiling…');
    window.clearTimeout(timer.current);
    timer.current = window.setTimeout(() => compile(next), 300);
  };

  const reset = () => {
    window.clearTimeout(timer.current);
    saveShaderEdit(variant.key, null);
    const [text, as] = generated(view);
    setSource(text);
    setShown(as);
    setEdited(false);
    setDiagnostics([]);
    setStatus('generated program');
    clearShader();
  };

  const defines = Object.entries(variant.defines)
    .map(([k, v]) => `#define ${k} ${String(v)}`)
    .join('\n');

  return (
    <section className="shader-editor" aria-label="GLSL editor">
      <div className="shader-toolbar" role="tablist" aria-label="shader stage">
        {(['vertexShader', 'fragmentShader'] as const).map((s) => (
          <button
            key={s}
            type="button"
            role="tab"
            aria-selected={stage === s}
            onClick={() => setStage(s)}
            className={stage === s ? 'active' : ''}
          >
            {s === 'vertexShader' ? 'vertex' : 'fragment'}
          </button>
        ))}
        <button type="button" onClick={reset} disabled={!edited}>
          reset to generated
        </button>
        <label
          className="shader-status"
          title={edited ? 'reset to generated to switch the view' : 'show every #if branch of the source'}
        >
          <input
            type="checkbox"
            data-testid="shader-full"
            checked={view === 'full'}
            disabled={edited}
            onChange={(e) => setView(e.target.checked ? 'full' : 'compiled')}
          />{' '}
          full source
        </label>
        <span data-testid="shader-status" className="shader-status">
          {status}
        </span>
      </div>
      {edited && (
        <p className="shader-note" data-testid="shader-note">
          This edit is kept in this browser only (localStorage, per variant), not in the URL or a copied link.
        </p>
      )}
      <pre className="shader-defines" title="defines of this variant (set by the material)">
        {defines || '(no defines)'}
      </pre>
      <textarea
        aria-label={`${stage === 'vertexShader' ? 'vertex' : 'fragment'} shader GLSL`}
        data-testid="shader-text"
        data-view={edited ? 'edited' : shown}
        title={
          edited
            ? 'your edit of the program'
            : shown === 'compiled'
              ? "as compiled for this scene: the material's source without its inactive #if branches"
              : "the material's full source; three puts this scene's #defines in front of it"
        }
        spellCheck={false}
        value={source[stage]}
        onChange={(e) => onEdit(e.target.value)}
      />
      {diagnostics.length > 0 && (
        <ul className="shader-errors" data-testid="shader-errors" role="alert">
          {diagnostics.map((d, i) => (
            // biome-ignore lint/suspicious/noArrayIndexKey: diagnostics have no identity.
            <li key={i}>
              {d.stage}
              {d.line !== null ? ` line ${d.line}` : ''}: {d.message}
            </li>
          ))}
        </ul>
      )}
    </section>
  );
}
