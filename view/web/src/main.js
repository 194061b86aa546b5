// The page: reads the embedded document, builds the view, exposes window.mitStarView.
import * as THREE from 'three';
import { decodeDocument } from './decode.js';
import { MAX_GHOSTS, MotionPlayer } from './motion.js';
import { buildPanel, showFrame } from './panel.js';
import { PointFigure, RobotFigure, meshGeometries, robotReach } from './robot.js';
import { buildMovers, buildScene, solidAt } from './scene.js';
import { buildSearch } from './search.js';
import { createStage, fitCamera, viewFromBehind, webglAvailable } from './stage.js';

const api = { ready: false };
const GHOST_TRIANGLES = 1_500_000;
window.mitStarView = api;

function fail(message) {
  api.error = message;
  const box = document.getElementById('message');
  box.textContent = message;
  box.hidden = false;
}

/** The box holding the scene and every pose of every motion. */
function extent(sceneGroup, doc, arm, reach) {
  const box = new THREE.Box3().setFromObject(sceneGroup);
  const p = new THREE.Vector3();
  for (const m of doc.motions) {
    const stride = arm ? 7 : 3;
    for (let i = 0; i + 2 < m.poses.length; i += stride) box.expandByPoint(p.fromArray(m.poses, i));
  }
  if (doc.search) for (let i = 0; i + 2 < doc.search.segments.length; i += 3) box.expandByPoint(p.fromArray(doc.search.segments, i));
  return box.isEmpty() ? box : box.expandByScalar(reach);
}

/** Names the solid under the pointer in a tooltip (looked up once per animation frame). */
function watchHover(stage, sceneGroup) {
  const tip = document.getElementById('tooltip');
  let pending = null;
  stage.renderer.domElement.addEventListener('pointermove', (event) => {
    if (pending === null) requestAnimationFrame(() => {
      const rect = stage.renderer.domElement.getBoundingClientRect();
      const pointer = new THREE.Vector2(((pending.clientX - rect.left) / rect.width) * 2 - 1, -((pending.clientY - rect.top) / rect.height) * 2 + 1);
      const name = pending.buttons === 0 ? solidAt(sceneGroup, stage.camera, pointer) : null;
      tip.hidden = name === null;
      if (name !== null) Object.assign(tip.style, { left: `${pending.clientX + 12}px`, top: `${pending.clientY + 12}px` });
      tip.textContent = name ?? '';
      pending = null;
    });
    pending = event;
  });
}

function start() {
  const t0 = performance.now();
  const doc = decodeDocument(JSON.parse(document.getElementById('mit-star-view-data').textContent));
  const t1 = performance.now();
  document.title = doc.title;
  const panelRoot = document.getElementById('panel-body');
  if (!webglAvailable()) {
    buildPanel(panelRoot, { ...doc, motions: [], search: null, robot: null }, {});
    fail('This view needs WebGL 2, which this browser does not provide. Enable hardware acceleration (or WebGL) in the browser settings, or open the file in a recent Chrome, Firefox or Safari.');
    return;
  }
  let pending = false;
  let last = 0;
  let stage = null;
  let player = null;
  const frame = (now) => {
    pending = false;
    if (player?.playing) {
      player.tick(Math.min((now - last) / 1000, 0.1));
      last = now;
      if (player.playing) request();
    }
    stage.render();
    if (!api.ready) api.timings = { decode: t1 - t0, build: t2 - t1, firstFrame: performance.now() - t2, ready: performance.now() };
    api.ready = true;
  };
  const request = () => {
    if (!pending && stage) { pending = true; requestAnimationFrame(frame); }
  };
  stage = createStage(document.getElementById('stage'), request);

  const arm = doc.kind === 'arm' && doc.robot;
  const flat = doc.kind === 'world2d';
  const probe = extent(new THREE.Group(), doc, arm, 0);
  const size = probe.isEmpty() ? 1 : probe.getSize(new THREE.Vector3()).length();
  const sceneGroup = buildScene(doc, 0.01 * Math.max(size, 1e-3));
  const box = extent(sceneGroup, doc, arm, arm ? robotReach(doc.robot) : 0.02 * size);
  const radius = 0.012 * Math.max(box.getSize(new THREE.Vector3()).length(), 1e-3);
  const lift = flat ? radius : 0;
  const geometries = arm ? meshGeometries(doc.robot) : null;
  const hasMeshes = arm && doc.robot.links.some((l) => l.meshes.length > 0);
  // Ghosts are drawn with meshes only while all of them together stay under GHOST_TRIANGLES:
  // sixteen Baxters of 150 000 triangles each would make every frame slow on a laptop.
  const triangles = arm ? doc.robot.links.reduce((n, l) => n + l.meshes.reduce((m, x) => m + x.indices.length / 3, 0), 0) : 0;
  const ghostMeshes = triangles * MAX_GHOSTS <= GHOST_TRIANGLES;
  const makeFigure = (opacity) => {
    const figure = arm ? new RobotFigure(doc.robot, geometries, opacity) : new PointFigure(radius, opacity);
    figure.setMeshes(hasMeshes && (opacity === 1 || ghostMeshes));
    return figure;
  };
  const figure = makeFigure(1);
  const movers = buildMovers(doc);
  sceneGroup.add(movers.group);
  const ctx = { arm, links: arm ? doc.robot.links.length : 0, hand: arm ? doc.robot.hand : 0, lift, makeFigure, placeMovers: movers.place };
  let view = null;
  player = new MotionPlayer(doc, figure, ctx, (p) => { if (view) showFrame(view, p); });
  if (arm && doc.motions.length === 0) figure.group.visible = doc.robot.links.length === 0;
  stage.scene.add(sceneGroup, figure.group, player.group);
  if (!flat) {
    const grid = new THREE.GridHelper(2 * Math.max(box.max.x - box.min.x, box.max.y - box.min.y), 20, 0xc8ccd4, 0xdde0e6);
    grid.rotateX(Math.PI / 2);
    grid.position.set((box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2, Math.min(box.min.z, 0));
    stage.scene.add(grid);
  }
  let searchGroup = null;
  let costRange = null;
  const searchShown = Boolean(doc.search) && doc.motions.length === 0 && doc.scene.solids.length === 0 && doc.scene.clouds.length === 0;
  if (doc.search) {
    const overlay = buildSearch(doc.search, flat, lift);
    searchGroup = overlay.group;
    costRange = overlay.range;
    searchGroup.visible = searchShown;
    stage.scene.add(searchGroup);
  }
  const redraw = () => { request(); };
  view = buildPanel(panelRoot, doc, {
    setMotion: (k) => { player.setMotion(k); redraw(); },
    setFrame: (f) => { player.playing = false; player.setFrame(f); redraw(); },
    togglePlay: () => { player.togglePlay(); last = performance.now(); showFrame(view, player); redraw(); },
    setSpeed: (s) => { player.speed = s; },
    setMeshes: (on) => { figure.setMeshes(on); player.setMeshes(on && ghostMeshes); redraw(); },
    setGhosts: (on) => { player.setGhosts(on); redraw(); },
    setSearch: (on) => { if (searchGroup) searchGroup.visible = on; redraw(); },
    searchShown,
    costRange,
  });
  showFrame(view, player);
  // An arm is watched from behind its base, looking at the obstacles it works among.
  const obstacles = new THREE.Box3().setFromObject(sceneGroup);
  const first = doc.motions[0];
  const from = arm && first && !obstacles.isEmpty()
    ? viewFromBehind(new THREE.Vector3().fromArray(first.poses, 0), obstacles.getCenter(new THREE.Vector3()))
    : null;
  fitCamera(stage, box, flat, from);
  watchHover(stage, sceneGroup);
  const t2 = performance.now();

  const now = () => { stage.render(); api.ready = true; };
  Object.assign(api, {
    frameCount: () => player.frameCount(),
    frame: () => player.frame,
    setFrame: (i) => { player.playing = false; player.setFrame(i); now(); },
    motionCount: () => doc.motions.length,
    setMotion: (k) => { player.setMotion(k); now(); },
    render: now,
  });
  request();
}

try {
  start();
} catch (error) {
  fail(`This view could not be drawn: ${error && error.message ? error.message : error}`);
  throw error;
}
