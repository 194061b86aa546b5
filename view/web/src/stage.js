// The stage: WebGL renderer, z-up camera fitted to a box, orbit controls, lights.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

/** Whether this browser can give a WebGL 2 context (three.js needs one). */
export function webglAvailable() {
  try {
    return Boolean(document.createElement('canvas').getContext('webgl2'));
  } catch {
    return false;
  }
}

/** A renderer filling `container`, a camera and controls; `onChange` is called when the view moves. */
export function createStage(container, onChange) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f5f7);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f99, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(1, -0.6, 2);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.addEventListener('change', onChange);
  const resize = () => {
    const { clientWidth: w, clientHeight: h } = container;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    onChange();
  };
  window.addEventListener('resize', resize);
  resize();
  return { renderer, scene, camera, controls, render: () => renderer.render(scene, camera) };
}

/** Points the camera at `box` so all of it shows: from above for a plane, obliquely otherwise. */
/** The direction to look from at an arm's workspace: from behind the robot's base (`base`),
 * seen from the obstacles' centre (`obstacles`), turned 35° aside and raised 30°; null when the
 * two coincide in plan view. */
export function viewFromBehind(base, obstacles) {
  const h = new THREE.Vector3(base.x - obstacles.x, base.y - obstacles.y, 0);
  if (h.length() < 1e-6) return null;
  h.normalize().applyAxisAngle(new THREE.Vector3(0, 0, 1), THREE.MathUtils.degToRad(35));
  h.z = Math.tan(THREE.MathUtils.degToRad(30));
  return h.normalize();
}

export function fitCamera(stage, box, fromAbove, from = null) {
  const { camera, controls } = stage;
  if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
  const fov = THREE.MathUtils.degToRad(camera.fov);
  const distance = (radius / Math.sin(Math.min(fov, fov * camera.aspect) / 2)) * 0.9;
  const direction = fromAbove
    ? new THREE.Vector3(0, 0, 1)
    : from ?? new THREE.Vector3(1.1, -1.6, 1.0).normalize();
  if (fromAbove) {
    camera.up.set(0, 1, 0);
    controls.enableRotate = false;
  }
  camera.position.copy(centre).addScaledVector(direction, distance);
  camera.near = distance / 1000;
  camera.far = distance * 20;
  camera.updateProjectionMatrix();
  controls.target.copy(centre);
  controls.update();
}
