import { useEffect, useRef } from 'react';
import * as THREE from 'three';

/** First page: the lecture's lit sphere. Grows into the full playground (issue 6). */
export function App() {
  const canvasRef = useRef<HTMLCanvasElement>(null);

  useEffect(() => {
    const canvas = canvasRef.current!;
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    renderer.setPixelRatio(1);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0x000000);
    const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
    camera.position.set(0, 0, 3);
    camera.lookAt(0, 0, 0);
    const geometry = new THREE.SphereGeometry(1, 64, 32);
    const material = new THREE.MeshPhongMaterial({ color: 0xcc6633 });
    const mesh = new THREE.Mesh(geometry, material);
    mesh.scale.set(2, 1, 2);
    scene.add(mesh);
    const light = new THREE.PointLight(0xffffff, 1, 0, 0);
    light.position.set(-5, 10, 20);
    scene.add(light, new THREE.AmbientLight(0x333333));

    const draw = () => {
      const { clientWidth: w, clientHeight: h } = canvas;
      renderer.setSize(w, h, false);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
      renderer.render(scene, camera);
      canvas.dataset.frames = String(Number(canvas.dataset.frames ?? 0) + 1);
    };
    const observer = new ResizeObserver(draw);
    observer.observe(canvas);
    draw();
    return () => {
      observer.disconnect();
      geometry.dispose();
      material.dispose();
      renderer.dispose();
    };
  }, []);

  return (
    <canvas
      ref={canvasRef}
      data-testid="viewport"
      style={{ width: '100%', height: '100%', display: 'block' }}
    />
  );
}
