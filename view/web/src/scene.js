// Scene building: solids (instanced by shape), point clouds, and a box world's bounds.
import * as THREE from 'three';

const SOLID = new THREE.MeshStandardMaterial({ color: 0x8d99ae, roughness: 0.8 });
const CLOUD_COLOURS = [0xd9822b, 0x2b8ad9, 0x6a994e, 0x9d4edd];

function unitGeometry(type) {
  if (type === 'cuboid') return new THREE.BoxGeometry(1, 1, 1);
  if (type === 'sphere') return new THREE.SphereGeometry(1, 20, 14);
  return new THREE.CylinderGeometry(1, 1, 1, 24).rotateX(Math.PI / 2);
}

function scaleOf(shape, flat, thickness) {
  if (shape.type === 'cuboid') {
    const [x, y, z] = shape.half_extents;
    return [2 * x, 2 * y, flat ? thickness : 2 * z];
  }
  if (shape.type === 'sphere') return [shape.radius, shape.radius, flat ? thickness / 2 : shape.radius];
  return [shape.radius, shape.radius, flat ? thickness : 2 * shape.half_height];
}

/** The obstacles of `doc` as a group; a 2-D world's solids are thin slabs under z = 0. */
export function buildScene(doc, thickness) {
  const group = new THREE.Group();
  const flat = doc.kind === 'world2d';
  const byType = new Map();
  for (const solid of doc.scene.solids) {
    if (!byType.has(solid.shape.type)) byType.set(solid.shape.type, []);
    byType.get(solid.shape.type).push(solid);
  }
  const m = new THREE.Matrix4();
  const p = new THREE.Vector3();
  const q = new THREE.Quaternion();
  const s = new THREE.Vector3();
  for (const [type, solids] of byType) {
    const mesh = new THREE.InstancedMesh(unitGeometry(type), SOLID, solids.length);
    solids.forEach((solid, i) => {
      s.fromArray(scaleOf(solid.shape, flat, thickness));
      p.fromArray(solid.position);
      if (flat) p.z = -thickness / 2;
      q.fromArray(solid.rotation).normalize();
      mesh.setMatrixAt(i, m.compose(p, q, s));
    });
    mesh.computeBoundingBox();
    mesh.computeBoundingSphere();
    mesh.userData.solids = solids;
    group.add(mesh);
  }
  doc.scene.clouds.forEach((cloud, i) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(cloud.points, 3));
    const material = new THREE.PointsMaterial({ color: CLOUD_COLOURS[i % CLOUD_COLOURS.length], size: 2 * cloud.radius });
    group.add(new THREE.Points(geometry, material));
  });
  if (doc.scene.bounds) group.add(boundsOutline(doc.scene.bounds, flat));
  return group;
}

function boundsOutline([lo, hi], flat) {
  const material = new THREE.LineBasicMaterial({ color: 0x334155 });
  if (flat) {
    const corners = [[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]];
    const geometry = new THREE.BufferGeometry().setFromPoints(corners.map(([x, y]) => new THREE.Vector3(x, y, 0)));
    return new THREE.LineLoop(geometry, material);
  }
  const size = [0, 1, 2].map((k) => hi[k] - lo[k]);
  const edges = new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.BoxGeometry(...size)), material);
  edges.position.set(...[0, 1, 2].map((k) => (lo[k] + hi[k]) / 2));
  return edges;
}

const MOVER = new THREE.MeshStandardMaterial({ color: 0xe07a1f, roughness: 0.6, transparent: true, opacity: 0.75 });

/** The obstacles that move, one mesh each at its frame-0 pose; `place(positions, k)` moves
 * them to the `k`-th frame of a motion's `mover_positions` (movers × 3 per frame, lerped). */
export function buildMovers(doc) {
  const group = new THREE.Group();
  const meshes = doc.scene.movers.map((solid) => {
    const mesh = new THREE.Mesh(unitGeometry(solid.shape.type), MOVER);
    mesh.scale.fromArray(scaleOf(solid.shape, false, 0));
    mesh.position.fromArray(solid.position);
    mesh.quaternion.fromArray(solid.rotation).normalize();
    mesh.userData.solids = [solid];
    group.add(mesh);
    return mesh;
  });
  const place = (positions, frames, f) => {
    const width = meshes.length * 3;
    if (width === 0 || positions.length !== frames * width) return;
    const i = Math.min(Math.floor(f), frames - 1);
    const j = Math.min(i + 1, frames - 1);
    const t = f - i;
    meshes.forEach((mesh, m) => {
      const a = i * width + 3 * m;
      const b = j * width + 3 * m;
      mesh.position.set(
        positions[a] + (positions[b] - positions[a]) * t,
        positions[a + 1] + (positions[b + 1] - positions[a + 1]) * t,
        positions[a + 2] + (positions[b + 2] - positions[a + 2]) * t,
      );
    });
  };
  return { group, place };
}

/** The name of the solid under `pointer` (normalised device coordinates), or null. */
export function solidAt(group, camera, pointer) {
  const raycaster = new THREE.Raycaster();
  raycaster.setFromCamera(pointer, camera);
  const solids = group.children.filter((child) => child.userData.solids);
  const hit = raycaster.intersectObjects(solids, false)[0];
  return hit ? hit.object.userData.solids[hit.instanceId].name : null;
}
