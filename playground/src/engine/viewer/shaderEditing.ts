/**
 * The shader editor's side of the viewer: the current variant's generated GLSL, and an edit of it that replaces
 * the rendered program only once it compiles and links off-screen (kept until the variant changes).
 */
import type { ShadingMaterial } from '@shadelab/material';
import type * as THREE from 'three';
import { compiledSources } from '../../learn/compiledShaderGl';
import { type ShaderCheck, ShaderProbe, type ShaderSource, tagLines } from '../ShaderProbe';

/** The current variant for the GLSL view: its key, defines, generated GLSL and that GLSL as this scene compiles it. */
export type ShaderVariant = ShaderSource & {
  key: string;
  defines: Record<string, unknown>;
  /**
   * The generated GLSL with only the lines compiled for this scene (inactive `#if` branches and the conditionals
   * removed); null when it could not be compiled. Computed on the first call (one off-screen compile), then kept.
   */
  compiled?: () => ShaderSource | null;
};

/** A key naming the compiled variant (its defines), so per-variant shader edits are kept apart. */
export function variantKey(material: ShadingMaterial): string {
  const defines = material.defines ?? {};
  return Object.keys(defines)
    .sort()
    .map((k) => `${k}=${String(defines[k])}`)
    .join(',');
}

export class ShaderEditing {
  private readonly probe: ShaderProbe;
  /** The edit that renders, for the variant `key`; null when the generated program renders. */
  private override: (ShaderSource & { key: string }) | null = null;
  private generated: ShaderSource = { vertexShader: '', fragmentShader: '' };
  /** The variant last reported by {@link variantChanged}. */
  private reported = '';
  /** The last "as compiled" text, for the variant and generated GLSL it was computed from. */
  private compiledCache: { of: string; text: ShaderSource | null } | null = null;

  private readonly material: ShadingMaterial;

  /** Edits `viewer.material`'s program, checked by drawing `viewer.mesh` off-screen with `viewer.renderer`. */
  constructor(
    private readonly viewer: {
      readonly renderer: THREE.WebGLRenderer;
      readonly material: ShadingMaterial;
      readonly mesh: THREE.Mesh;
      readonly camera: THREE.Camera;
      readonly scene?: THREE.Scene;
      requestRender(): void;
    },
  ) {
    this.material = viewer.material;
    this.probe = new ShaderProbe(viewer.renderer);
  }

  /**
   * After the material's options changed: keeps its generated GLSL, and puts the edit back on it while the
   * variant is the edited one (a different variant drops the edit).
   */
  capture(): void {
    const { material } = this;
    const key = variantKey(material);
    if (this.override && this.override.key !== key) this.clear();
    if (!this.override) {
      this.generated = { vertexShader: material.vertexShader, fragmentShader: material.fragmentShader };
    } else {
      material.vertexShader = this.override.vertexShader;
      material.fragmentShader = this.override.fragmentShader;
      material.needsUpdate = true;
    }
  }

  /** After a frame: whether the variant changed since the last call (the material settles defines as it draws). */
  variantChanged(): boolean {
    const key = variantKey(this.material);
    if (key === this.reported) return false;
    this.reported = key;
    this.capture();
    return true;
  }

  /** The current variant's key and its generated GLSL (before any edit), and how this scene compiles it. */
  source(): ShaderVariant {
    return {
      ...this.generated,
      key: variantKey(this.material),
      defines: { ...(this.material.defines ?? {}) },
      compiled: this.compiled,
    };
  }

  /** The generated GLSL as this scene compiles it (see {@link ShaderVariant.compiled}). */
  private readonly compiled = (): ShaderSource | null => {
    const of = `${variantKey(this.material)}\n${this.generated.vertexShader}\n${this.generated.fragmentShader}`;
    if (this.compiledCache?.of !== of) {
      this.compiledCache = { of, text: compiledSources(this.viewer, this.material, this.generated) };
    }
    return this.compiledCache.text;
  };

  /**
   * Compiles an edited program for the current variant off-screen first; only a program that compiles and
   * links replaces the rendered one, so a broken edit leaves the last good program rendering.
   */
  tryEdit(edited: ShaderSource): ShaderCheck {
    const { material } = this;
    const source = {
      vertexShader: tagLines(edited.vertexShader),
      fragmentShader: tagLines(edited.fragmentShader),
    };
    const check = this.probe.check(material, this.viewer.mesh, this.viewer.camera, source);
    if (check.ok) {
      material.vertexShader = source.vertexShader;
      material.fragmentShader = source.fragmentShader;
      material.needsUpdate = true;
      this.override = { ...source, key: variantKey(material) };
      this.viewer.requestRender();
    }
    return check;
  }

  /** Drops the edit and goes back to the generated program. */
  clear(): void {
    if (!this.override) return;
    this.override = null;
    this.material.vertexShader = this.generated.vertexShader;
    this.material.fragmentShader = this.generated.fragmentShader;
    this.material.needsUpdate = true;
    this.viewer.requestRender();
  }

  dispose(): void {
    this.probe.dispose();
  }
}
