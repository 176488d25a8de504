/**
 * The views' drawing calls (`CellRenderer`: WebGL's viewport and scissor, from the bottom left) on WebGPURenderer
 * (whose viewport and scissor are from the top left), for one frame: the target is cleared once to the scene's
 * background, and every draw (one per compare cell) goes on over it with the node materials swapped in
 * (`nodeMirror.ts`). WebGPU clears a whole attachment, not a scissored cell: so no draw of the frame clears.
 */
import type * as THREE from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import type { CellRenderer } from '../viewer/layout';
import type { NodeMirror } from './nodeMirror';

export class GpuCells implements CellRenderer {
  private cleared = false;

  /** @param height - The drawing buffer's height, px (to turn WebGL's rectangles upside down). */
  constructor(
    private readonly renderer: WebGPURenderer,
    private readonly height: number,
    private readonly mirror: NodeMirror,
  ) {}

  setScissorTest(on: boolean): void {
    this.renderer.setScissorTest(on);
  }

  setViewport(x: number, y: number, width: number, height: number): void {
    this.renderer.setViewport(x, this.height - y - height, width, height);
  }

  setScissor(x: number, y: number, width: number, height: number): void {
    this.renderer.setScissor(x, this.height - y - height, width, height);
  }

  render(root: THREE.Object3D, camera: THREE.Camera): void {
    const { renderer } = this;
    const scene = root as THREE.Scene;
    const background = scene.background;
    if (!this.cleared) {
      this.cleared = true;
      const scissor = renderer.getScissorTest();
      renderer.setScissorTest(false);
      renderer.setClearColor(
        (background as THREE.Color | null)?.isColor ? (background as THREE.Color) : 0x000000,
        1,
      );
      renderer.clear();
      renderer.setScissorTest(scissor);
    }
    const autoClear = renderer.autoClear;
    scene.background = null;
    renderer.autoClear = false;
    try {
      this.mirror.draw(root, () => renderer.render(root, camera));
    } finally {
      scene.background = background;
      renderer.autoClear = autoClear;
    }
  }
}
