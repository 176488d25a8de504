// Harness of tests/playwright-kit.spec.ts: draws buildKitScene(options) once, the options read as JSON from the
// URL's query (?page=kit&scene={"shininess":8}; a query, not a hash, so that each scene loads a new page).
import { WebGLRenderer } from 'three';
import { buildKitScene, type KitSceneOptions } from './kitScene';

const options = JSON.parse(new URLSearchParams(location.search).get('scene') ?? '{}') as KitSceneOptions;
const kit = buildKitScene(options);
const canvas = document.getElementById('viewport') as HTMLCanvasElement;
const renderer = new WebGLRenderer({ canvas, antialias: kit.antialias });
renderer.setPixelRatio(1);
renderer.setSize(kit.width, kit.height);
renderer.setClearColor(kit.clearColor, 1);
renderer.render(kit.scene, kit.camera);
