// Robot drawing: a robot as per-link groups (its spheres, instanced, or its meshes), and the
// moving point of a box world; solid or ghostly, in its own colours or red when colliding.
import * as THREE from 'three';

const BLUE = 0x3b82c4;
const RED = 0xe02424;
const SPHERE = new THREE.SphereGeometry(1, 18, 12);

function material(colour, opacity) {
  const ghost = opacity < 1;
  return new THREE.MeshStandardMaterial({ color: colour, roughness: 0.55, transparent: ghost, opacity, depthWrite: !ghost });
}

/** Geometries of the robot's meshes, built once and shared by every figure. */
export function meshGeometries(robot) {
  return robot.links.map((link) => link.meshes.map((mesh) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(mesh.positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(mesh.indices, 1));
    geometry.computeVertexNormals();
    return { geometry, colour: new THREE.Color().setRGB(...mesh.colour) };
  }));
}

/** One robot drawn at one pose. */
export class RobotFigure {
  constructor(robot, geometries, opacity = 1) {
    this.group = new THREE.Group();
    this.red = material(RED, opacity);
    this.parts = [];
    this.links = robot.links.map((link, l) => {
      const linkGroup = new THREE.Group();
      linkGroup.matrixAutoUpdate = false;
      const n = link.spheres.length / 4;
      const spheres = new THREE.InstancedMesh(SPHERE, material(BLUE, opacity), Math.max(n, 1));
      spheres.count = n;
      const m = new THREE.Matrix4();
      for (let i = 0; i < n; i++) {
        const [x, y, z, r] = link.spheres.subarray(4 * i, 4 * i + 4);
        spheres.setMatrixAt(i, m.makeScale(r, r, r).setPosition(x, y, z));
      }
      spheres.computeBoundingSphere();
      const meshes = new THREE.Group();
      for (const { geometry, colour } of geometries[l]) meshes.add(new THREE.Mesh(geometry, material(colour, opacity)));
      linkGroup.add(spheres, meshes);
      this.parts.push(spheres, ...meshes.children);
      this.group.add(linkGroup);
      return { group: linkGroup, spheres, meshes };
    });
    this.own = this.parts.map((part) => part.material);
  }

  /** Draws the meshes (true; spheres for a link without any) or the spheres (false). */
  setMeshes(useMeshes) {
    for (const link of this.links) {
      const meshes = useMeshes && link.meshes.children.length > 0;
      link.meshes.visible = meshes;
      link.spheres.visible = !meshes;
    }
  }

  /** Places every link: `pose` holds links × (x, y, z, qx, qy, qz, qw). */
  setPose(pose) {
    const p = new THREE.Vector3();
    const q = new THREE.Quaternion();
    const one = new THREE.Vector3(1, 1, 1);
    this.links.forEach((link, l) => {
      p.fromArray(pose, 7 * l);
      q.fromArray(pose, 7 * l + 3);
      link.group.matrix.compose(p, q.normalize(), one);
      link.group.matrixWorldNeedsUpdate = true;
    });
  }

  /** Red (true) or its own colours. */
  setColliding(colliding) {
    this.parts.forEach((part, i) => { part.material = colliding ? this.red : this.own[i]; });
  }
}

/** The moving point of a box world: a small ball. */
export class PointFigure {
  constructor(radius, opacity = 1) {
    this.own = material(0x1d4ed8, opacity);
    this.red = material(RED, opacity);
    this.mesh = new THREE.Mesh(SPHERE, this.own);
    this.mesh.scale.setScalar(radius);
    this.group = this.mesh;
  }

  setMeshes() {}

  setPose(pose) {
    this.mesh.position.set(pose[0], pose[1], pose[2]);
  }

  setColliding(colliding) {
    this.mesh.material = colliding ? this.red : this.own;
  }
}

/** How far any part of the robot reaches from its links' origins. */
export function robotReach(robot) {
  let reach = 0;
  for (const link of robot.links) {
    for (let i = 0; i < link.spheres.length; i += 4) {
      const [x, y, z, r] = link.spheres.subarray(i, i + 4);
      reach = Math.max(reach, Math.hypot(x, y, z) + r);
    }
    for (const mesh of link.meshes) {
      for (let i = 0; i < mesh.positions.length; i += 3) {
        reach = Math.max(reach, Math.hypot(mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]));
      }
    }
  }
  return reach;
}
