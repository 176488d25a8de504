// useTrackball on a bare R3F root (`createRoot`, no pointer events: `events.connected` stays `false`), as an app
// that owns its canvas makes one: the trackball must listen on the renderer's canvas. The canvas and renderer are
// stand-ins (node has no DOM or WebGL): an EventTarget with a style, and an object R3F takes as a renderer.
import { createRoot } from '@react-three/fiber';
import type { Trackball } from '@shadelab/trackball';
import { createElement } from 'react';
import { PerspectiveCamera, Scene } from 'three';
import { describe, expect, it } from 'vitest';
import { useTrackball } from './useTrackball.js';

function Probe({ out }: { out: { trackball?: Trackball } }) {
  out.trackball = useTrackball(null);
  return null;
}

describe('useTrackball on a root without R3F events', () => {
  it('connects to the renderer’s canvas (gl.domElement), not to `events.connected` (false)', async () => {
    const canvas = Object.assign(new EventTarget(), { style: { touchAction: '' } });
    const gl = { render: () => {}, domElement: canvas, setSize: () => {}, setPixelRatio: () => {} };
    const root = createRoot(canvas as never);
    await root.configure({
      gl: gl as never,
      camera: new PerspectiveCamera(),
      scene: new Scene(),
      frameloop: 'never',
      dpr: 1,
      size: { width: 100, height: 100, top: 0, left: 0 },
    });
    const out: { trackball?: Trackball } = {};
    root.render(createElement(Probe, { out }));
    expect(out.trackball?.domElement).toBe(canvas);
    expect(canvas.style.touchAction).toBe('none');
    root.unmount();
  });
});
