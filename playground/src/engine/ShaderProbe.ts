/**
 * Compiles a candidate GLSL program off-screen (a clone of the material drawn into a 1×1 target) and reports
 * compile/link errors with the line numbers of the text the user typed, through three's
 * `renderer.debug.onShaderError`. The rendered material is never touched by a failing candidate.
 */
import * as THREE from 'three';

export interface ShaderSource {
  vertexShader: string;
  fragmentShader: string;
}

/** One diagnostic, with `line` counted in the user's text (1-based; null when it falls outside it). */
export interface ShaderDiagnostic {
  stage: 'vertex' | 'fragment' | 'link';
  line: number | null;
  message: string;
}

export type ShaderCheck = { ok: true } | { ok: false; diagnostics: ShaderDiagnostic[] };

const TAG = /\/\/ @L(\d+)$/;

/**
 * Tags each line of the user's GLSL with its line number (`… // @L12`), so an error line in the program three
 * actually compiles (after its prefix, `#include` expansion and loop unrolling) maps back to the text the
 * user typed. Preprocessor lines and the `}` closing an unrolled loop are left untouched (three's regexes
 * read them).
 */
export function tagLines(source: string): string {
  const lines = source.split('\n');
  return lines
    .map((line, i) => {
      const trimmed = line.trim();
      if (!trimmed || trimmed.startsWith('#') || line.endsWith('\\')) return line;
      const next = lines.slice(i + 1).find((l) => l.trim() !== '');
      if (next?.trim().startsWith('#pragma unroll_loop_end')) return line;
      return `${line} // @L${i + 1}`;
    })
    .join('\n');
}

/** The user's line for a line of the compiled source: its tag, or the nearest tag above it. */
function userLine(compiledLines: string[], line: number): number | null {
  for (let i = Math.min(line, compiledLines.length) - 1; i >= 0; i--) {
    const match = TAG.exec(compiledLines[i]!);
    if (match) return Number(match[1]);
  }
  return null;
}

/** Parses a GLSL info log ("ERROR: 0:12: 'x' : undeclared identifier") into diagnostics. */
export function parseInfoLog(
  log: string,
  stage: 'vertex' | 'fragment',
  compiledSource: string,
): ShaderDiagnostic[] {
  const compiledLines = compiledSource.split('\n');
  const out: ShaderDiagnostic[] = [];
  for (const raw of log.split('\n')) {
    const text = raw.replace(/\0/g, '').trim();
    if (!text) continue;
    const match = /^(?:ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$/.exec(text);
    out.push(
      match
        ? { stage, line: userLine(compiledLines, Number(match[1])), message: match[2]! }
        : { stage, line: null, message: text },
    );
  }
  return out;
}

export class ShaderProbe {
  private readonly target = new THREE.WebGLRenderTarget(1, 1);
  private readonly scene = new THREE.Scene();
  private captured: ShaderDiagnostic[] | null = null;

  constructor(private readonly renderer: THREE.WebGLRenderer) {
    renderer.debug.checkShaderErrors = true;
    renderer.debug.onShaderError = (gl, program, vertex, fragment) => {
      const diagnostics: ShaderDiagnostic[] = [];
      const vLog = gl.getShaderInfoLog(vertex) ?? '';
      const fLog = gl.getShaderInfoLog(fragment) ?? '';
      if (vLog.trim()) {
        diagnostics.push(...parseInfoLog(vLog, 'vertex', gl.getShaderSource(vertex) ?? ''));
      }
      if (fLog.trim()) {
        diagnostics.push(...parseInfoLog(fLog, 'fragment', gl.getShaderSource(fragment) ?? ''));
      }
      const linkLog = (gl.getProgramInfoLog(program) ?? '').trim();
      if (!diagnostics.length)
        diagnostics.push({ stage: 'link', line: null, message: linkLog || 'link failed' });
      if (this.captured) this.captured.push(...diagnostics);
    };
  }

  /**
   * Compiles `source` (already {@link tagLines tagged}) as a variant of `material` (same defines and
   * uniforms) and reports what failed.
   */
  check(
    material: THREE.ShaderMaterial,
    mesh: THREE.Mesh,
    camera: THREE.Camera,
    source: ShaderSource,
  ): ShaderCheck {
    const candidate = material.clone();
    candidate.vertexShader = source.vertexShader;
    candidate.fragmentShader = source.fragmentShader;
    const probe = new THREE.Mesh(mesh.geometry, candidate);
    probe.onBeforeRender = mesh.onBeforeRender;
    this.scene.add(probe);
    this.captured = [];
    const previousTarget = this.renderer.getRenderTarget();
    try {
      this.renderer.setRenderTarget(this.target);
      this.renderer.render(this.scene, camera);
    } finally {
      this.renderer.setRenderTarget(previousTarget);
      this.scene.remove(probe);
      candidate.dispose();
    }
    const diagnostics = this.captured;
    this.captured = null;
    return diagnostics.length ? { ok: false, diagnostics } : { ok: true };
  }

  dispose() {
    this.target.dispose();
    this.renderer.debug.onShaderError = null;
  }
}
