// The lecture's scene from the published packages: a tetrahedron subdivided 6 times, scaled (2, 1, 2), seen by
// the lecture's camera, lit by one Phong light, shaded per fragment, turned by a trackball.
import { Camera } from '@shadelab/camera';
import { PhongLight, ShadingMaterial } from '@shadelab/material';
import { SubdivisionSphereGeometry } from '@shadelab/sphere';
import { Trackball } from '@shadelab/trackball';
import { Mesh, Scene, WebGLRenderer } from 'three';

const size = 400;
const renderer = new WebGLRenderer({ antialias: false });
renderer.setPixelRatio(1);
renderer.setSize(size, size);
document.body.append(renderer.domElement);

const scene = new Scene();

const light = new PhongLight({ ambient: [0.2, 0.2, 0.2], diffuse: [1, 1, 1], specular: [0.8, 0.8, 0.8] });
light.position.set(-5, 10, 20);
scene.add(light);

const material = new ShadingMaterial({ shading: 'phong', lighting: 'phong', lights: [light] });
const sphere = new Mesh(new SubdivisionSphereGeometry({ level: 6, base: 'tetrahedron' }), material);
sphere.scale.set(2, 1, 2);
scene.add(sphere);

const camera = new Camera();
camera.lookAt([0, 0, 3], [0, 0, 0], [0, 1, 0]);
camera.setPerspective(90, size / size, 0.1, 10);

const trackball = new Trackball(sphere, renderer.domElement, { camera });
let frames = 0;
const render = (): void => {
  renderer.render(scene, camera);
  frames += 1;
  renderer.domElement.dataset['frames'] = String(frames);
};
trackball.addEventListener('change', render);
render();
