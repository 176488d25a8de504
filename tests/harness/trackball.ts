// Bare page for tests/trackball.spec.ts: a box under a perspective camera, turned by @shadelab/trackball.
// Renders only on the trackball's `change` events; exposes its state on the canvas's data attributes.
import { Trackball } from '@shadelab/trackball';
import {
  BoxGeometry,
  Mesh,
  MeshNormalMaterial,
  OrthographicCamera,
  PerspectiveCamera,
  Scene,
  WebGLRenderer,
} from 'three';

const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(400, 300, false);

const params = new URLSearchParams(location.search);
const scene = new Scene();
// ?camera=ortho: an orthographic camera showing the same box at about the same size.
const camera =
  params.get('camera') === 'ortho'
    ? new OrthographicCamera(-2, 2, 1.5, -1.5, 0.1, 100)
    : new PerspectiveCamera(45, 400 / 300, 0.1, 100);
camera.position.set(0, 0, 4);
camera.lookAt(0, 0, 0);

const box = new Mesh(new BoxGeometry(1.2, 1.2, 1.2), new MeshNormalMaterial());
box.rotation.set(0.3, 0.2, 0);
scene.add(box);

const mapping = params.get('mapping') === 'arcball' ? 'arcball' : 'bell';
const trackball = new Trackball(box, canvas, { camera, mapping });

let frames = 0;
function render(): void {
  renderer.render(scene, camera);
  frames++;
  canvas.dataset.frames = String(frames);
  canvas.dataset.quaternion = JSON.stringify(box.quaternion.toArray());
  canvas.dataset.distance = String(camera.position.length());
  canvas.dataset.zoom = String(trackball.zoom);
}

trackball.addEventListener('change', render);
trackball.addEventListener('start', () => {
  canvas.dataset.dragging = 'true';
});
trackball.addEventListener('end', () => {
  canvas.dataset.dragging = 'false';
});
canvas.dataset.dragging = 'false';
render();
