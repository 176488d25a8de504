// three's five light kinds as the harnesses light their spheres with them (the ambient, hemisphere, directional,
// point and spot lights of the 'three-lights' scenarios), with what shade() is given for each: the colours are
// three's colour × intensity, as its uniforms hold them.
import type { ShadeThreeLight } from '@shadelab/material';
import {
  AmbientLight,
  Color,
  DirectionalLight,
  HemisphereLight,
  type Light,
  PointLight,
  SpotLight,
} from 'three';

/** three's ambient, hemisphere, directional, point and spot lights, and shade()'s description of each. */
export function fiveThreeLights(): { lights: Light[]; shade: ShadeThreeLight[] } {
  const ambient = new AmbientLight(new Color(0.3, 0.25, 0.2), 0.5);
  const hemisphere = new HemisphereLight(new Color(0.2, 0.3, 0.5), new Color(0.3, 0.2, 0.1), 0.8);
  hemisphere.position.set(0.3, 1, 0.2);
  const directional = new DirectionalLight(new Color(1, 0.95, 0.9), 0.8);
  directional.position.set(-1, 2, 3);
  const point = new PointLight(new Color(0.9, 0.9, 1), 4, 0, 2);
  point.position.set(2, 1, 2);
  // Aimed at the origin (its target's default), the cone's soft edge across the sphere.
  const spot = new SpotLight(new Color(1, 0.8, 0.6), 6, 0, 0.35, 0.5, 2);
  spot.position.set(-1, -2, 2.5);
  spot.updateMatrixWorld();
  spot.target.updateMatrixWorld();
  const scaled = (c: Color, i: number) => [c.r * i, c.g * i, c.b * i];
  return {
    lights: [ambient, hemisphere, directional, point, spot],
    shade: [
      { type: 'ambient', color: scaled(ambient.color, ambient.intensity) },
      {
        type: 'hemisphere',
        color: scaled(hemisphere.color, hemisphere.intensity),
        groundColor: scaled(hemisphere.groundColor, hemisphere.intensity),
        direction: hemisphere.position.clone().normalize().toArray(),
      },
      {
        type: 'directional',
        color: scaled(directional.color, directional.intensity),
        direction: directional.position.clone().normalize().toArray(),
      },
      {
        type: 'point',
        color: scaled(point.color, point.intensity),
        position: point.position.toArray(),
        distance: 0,
        decay: 2,
      },
      {
        type: 'spot',
        color: scaled(spot.color, spot.intensity),
        position: spot.position.toArray(),
        direction: spot.position.clone().sub(spot.target.position).normalize().toArray(),
        distance: 0,
        decay: 2,
        coneCos: Math.cos(spot.angle),
        penumbraCos: Math.cos(spot.angle * (1 - spot.penumbra)),
      },
    ],
  };
}
