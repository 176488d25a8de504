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

/** A comment line put before the user's text so error lines can be mapped back to it. */
const MARKER = '// shadelab: user source starts below';

/** Parses a GLSL info log ("ERROR: 0:12: 'x' : undeclared identifier") into diagnostics. */
export function parseInfoLog(
  log: string,
  stage: 'vertex' | 'fragment',
  fullSource: string,
  userLineCount: number,
): ShaderDiagnostic[] {
  const lines = fullSource.split('\n');
  const markerIndex = lines.findIndex((l) => l.trim() === MARKER);
  const out: ShaderDiagnostic[] = [];
  for (const raw of log.split('\n')) {
    const text = raw.trim();
    if (!text) continue;
    const match = /^(?:ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$/.exec(text);
    if (!match) {
      out.push({ stage, line: null, message: text });
      continue;
    }
    const fullLine = Number(match[1]);
    const userLine = markerIndex >= 0 ? fullLine - (markerIndex + 1) : null;
    out.push({
      stage,
      line: userLine !== null && userLine >= 1 && userLine <= userLineCount ? userLine : null,
      message: match[2]!,
    });
  }
  return out;
}

export class ShaderProbe {
  private readonly target = new THREE.WebGLRenderTarget(1, 1);
  private readonly scene = new THREE.Scene();
  private captured: ShaderDiagnostic[] | null = null;
  private pending: ShaderSource | null = null;

  constructor(private readonly renderer: THREE.WebGLRenderer) {
    renderer.debug.checkShaderErrors = true;
    renderer.debug.onShaderError = (gl, program, vertex, fragment) => {
      const diagnostics: ShaderDiagnostic[] = [];
      const userLines = (s: string) => s.split('\n').length;
      const vLog = gl.getShaderInfoLog(vertex) ?? '';
      const fLog = gl.getShaderInfoLog(fragment) ?? '';
      if (vLog.trim()) {
        diagnostics.push(
          ...parseInfoLog(
            vLog,
            'vertex',
            gl.getShaderSource(vertex) ?? '',
            userLines(this.pending?.vertexShader ?? ''),
          ),
        );
      }
      if (fLog.trim()) {
        diagnostics.push(
          ...parseInfoLog(
            fLog,
            'fragment',
            gl.getShaderSource(fragment) ?? '',
            userLines(this.pending?.fragmentShader ?? ''),
          ),
        );
      }
      const linkLog = (gl.getProgramInfoLog(program) ?? '').trim();
      if (!diagnostics.length)
        diagnostics.push({ stage: 'link', line: null, message: linkLog || 'link failed' });
      if (this.captured) this.captured.push(...diagnostics);
    };
  }

  /** Compiles `source` as a variant of `material` (same defines and uniforms) and reports what failed. */
  check(
    material: THREE.ShaderMaterial,
    mesh: THREE.Mesh,
    camera: THREE.Camera,
    source: ShaderSource,
  ): ShaderCheck {
    const candidate = material.clone();
    candidate.vertexShader = `${MARKER}\n${source.vertexShader}`;
    candidate.fragmentShader = `${MARKER}\n${source.fragmentShader}`;
    const probe = new THREE.Mesh(mesh.geometry, candidate);
    probe.onBeforeRender = mesh.onBeforeRender;
    this.scene.add(probe);
    this.captured = [];
    this.pending = source;
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
    this.pending = null;
    return diagnostics.length ? { ok: false, diagnostics } : { ok: true };
  }

  dispose() {
    this.target.dispose();
    this.renderer.debug.onShaderError = null;
  }
}
