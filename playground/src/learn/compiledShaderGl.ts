/**
 * The GLSL view's "as compiled" text on WebGLRenderer: a material's own source with only the lines this scene
 * compiles. A clone of the material, its lines tagged ({@link tagForActive}), is compiled off-screen with the
 * mesh's geometry, the camera and the scene's fog, so three gives it the same program parameters (its prefix
 * of `#define`s: instancing, fog, clipping, depth buffer …) as the drawn one; the tags of the lines left active
 * in what the GPU got (`gl.getShaderSource`, three's prefix and chunks included) pick the lines shown.
 */
import * as THREE from 'three';
import { activeSource, activeTags, tagForActive } from './compiledShader';

/** A program's two stages. */
export interface StageSources {
  vertexShader: string;
  fragmentShader: string;
}

/** What {@link compiledSources} draws with. */
export interface CompileHost {
  readonly renderer: THREE.WebGLRenderer;
  readonly mesh: THREE.Mesh;
  readonly camera: THREE.Camera;
  /** The drawn scene (its fog is a program parameter); none: no fog. */
  readonly scene?: THREE.Scene;
}

/**
 * `source` (the material's generated GLSL) reduced to the lines compiled for `material` on `host`'s mesh, or
 * null when three did not compile the clone (a compile error: the full source is then the one to read).
 */
export function compiledSources(
  host: CompileHost,
  material: THREE.ShaderMaterial,
  source: StageSources,
): StageSources | null {
  const { renderer, mesh, camera } = host;
  const clone = material.clone();
  clone.vertexShader = tagForActive(source.vertexShader);
  clone.fragmentShader = tagForActive(source.fragmentShader);
  const probe = new THREE.Mesh(mesh.geometry, clone);
  probe.onBeforeRender = mesh.onBeforeRender;
  probe.matrixWorld.copy(mesh.matrixWorld);
  probe.matrixAutoUpdate = false;
  const scene = new THREE.Scene();
  scene.fog = host.scene?.fog ?? null;
  scene.add(probe);
  const target = new THREE.WebGLRenderTarget(1, 1);
  const previous = renderer.getRenderTarget();
  // This draw is not the scene's: the stats (renderer.info, summed over a frame's draws) must not count it.
  const counted = { ...renderer.info.render };
  try {
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    const program = (
      renderer.properties.get(clone) as {
        currentProgram?: { vertexShader: WebGLShader; fragmentShader: WebGLShader };
      }
    ).currentProgram;
    if (!program) return null;
    const gl = renderer.getContext();
    const read = (shader: WebGLShader, text: string) =>
      activeSource(text, activeTags(gl.getShaderSource(shader) ?? ''));
    return {
      vertexShader: read(program.vertexShader, source.vertexShader),
      fragmentShader: read(program.fragmentShader, source.fragmentShader),
    };
  } catch {
    return null;
  } finally {
    renderer.setRenderTarget(previous);
    Object.assign(renderer.info.render, counted);
    scene.remove(probe);
    clone.dispose();
    target.dispose();
  }
}
