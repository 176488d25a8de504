import { useEffect, useRef, useState } from 'react';
import type { ShaderCheck, ShaderDiagnostic, ShaderSource } from '../engine/ShaderProbe';
import { loadShaderEdit, saveShaderEdit } from '../state/persist';

interface Props {
  /** The current variant: its key and its generated GLSL. */
  variant: ShaderSource & { key: string; defines: Record<string, unknown> };
  tryShader: (source: ShaderSource) => ShaderCheck;
  clearShader: () => void;
}

/**
 * The generated GLSL of the current variant, editable. Every keystroke is saved (localStorage, per variant)
 * so an edit is never lost; after a pause it is compiled off-screen, and only a program that compiles
 * replaces the rendered one. Errors are listed with their line in the edited text.
 */
export function ShaderEditor({ variant, tryShader, clearShader }: Props) {
  const [stage, setStage] = useState<'fragmentShader' | 'vertexShader'>('fragmentShader');
  const [source, setSource] = useState<ShaderSource>(() => loadShaderEdit(variant.key) ?? variant);
  const [edited, setEdited] = useState(() => loadShaderEdit(variant.key) !== null);
  const [diagnostics, setDiagnostics] = useState<ShaderDiagnostic[]>([]);
  const [status, setStatus] = useState('generated program');
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

  // A new variant (shading, lighting, bands, lights …): show its program, or the user's saved edit of it.
  // biome-ignore lint/correctness/useExhaustiveDependencies: reload only when the variant changes.
  useEffect(() => {
    const saved = loadShaderEdit(variant.key);
    setSource(saved ?? { vertexShader: variant.vertexShader, fragmentShader: variant.fragmentShader });
    setEdited(saved !== null);
    setDiagnostics([]);
    setStatus(saved ? 'edited program' : 'generated program');
    if (saved) compile(saved);
  }, [variant.key, variant.vertexShader, variant.fragmentShader]);

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
    setSource({ vertexShader: variant.vertexShader, fragmentShader: variant.fragmentShader });
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
