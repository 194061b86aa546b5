// Search overlay: the planner's edges coloured by cost-to-come, and the informed set.
import * as THREE from 'three';
import { colourOfCost, costRange } from './colour_map.js';
import { informedTransform } from './informed.js';

/** The overlay of `search` as a group, with the cost range its legend shows. */
export function buildSearch(search, flat, lift) {
  const group = new THREE.Group();
  const n = Math.min(search.segments.length / 6, search.costs.length);
  const range = costRange(search.costs.subarray(0, n));
  const positions = search.segments.slice(0, 6 * n);
  const colours = new Float32Array(6 * n);
  for (let i = 0; i < n; i++) {
    const c = colourOfCost(search.costs[i], range);
    colours.set(c, 6 * i);
    colours.set(c, 6 * i + 3);
    if (flat) { positions[6 * i + 2] += lift / 2; positions[6 * i + 5] += lift / 2; }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  group.add(new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true })));
  const informed = search.informed && informedTransform(search.informed.start, search.informed.goal, search.informed.cost);
  if (informed) {
    const material = new THREE.MeshBasicMaterial({ color: 0x16a34a, transparent: true, opacity: 0.15, depthWrite: false });
    const ellipsoid = new THREE.Mesh(new THREE.SphereGeometry(1, 48, 24), material);
    ellipsoid.position.fromArray(informed.centre);
    ellipsoid.quaternion.fromArray(informed.quaternion);
    const [a, b] = informed.semiAxes;
    ellipsoid.scale.set(a, b, flat ? 1e-3 * a : b);
    group.add(ellipsoid);
    if (flat) {
      const rim = Array.from({ length: 96 }, (_, i) => {
        const t = (2 * Math.PI * i) / 96;
        return new THREE.Vector3(a * Math.cos(t), b * Math.sin(t), 0);
      });
      const outline = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(rim), new THREE.LineBasicMaterial({ color: 0x16a34a }));
      outline.position.copy(ellipsoid.position);
      outline.quaternion.copy(ellipsoid.quaternion);
      group.add(outline);
    }
  }
  return { group, range };
}
