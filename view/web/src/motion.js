// Motion and scrubbing: the current motion and frame, playback, the trace, collision markers
// and ghosts at waypoints.
import * as THREE from 'three';
import { frameAt, frameOfValue, progressOf, valueOfFrame } from './interpolation.js';

/** At most this many ghosts per motion. */
export const MAX_GHOSTS = 16;

/** At most `cap` of `items`, evenly chosen, first and last kept. */
export function evenly(items, cap) {
  if (items.length <= cap) return items;
  return Array.from({ length: cap }, (_, k) => items[Math.round((k * (items.length - 1)) / (cap - 1))]);
}

/** Where the hand (arms) or the point (box worlds) is at each frame, frames × 3. */
function tracePoints(motion, arm, links, hand, lift) {
  const out = new Float32Array(motion.frames * 3);
  for (let f = 0; f < motion.frames; f++) {
    const base = arm ? (f * links + hand) * 7 : f * 3;
    out[3 * f] = motion.poses[base];
    out[3 * f + 1] = motion.poses[base + 1];
    out[3 * f + 2] = motion.poses[base + 2] + lift;
  }
  return out;
}

/** One motion's drawing: its trace, red markers, ghosts. */
class MotionDrawing {
  constructor(motion, ctx) {
    this.motion = motion;
    this.stride = ctx.arm ? 7 * ctx.links : 3;
    this.progress = progressOf(motion, this.stride);
    this.colliding = new Uint8Array(motion.frames);
    for (const f of motion.colliding) this.colliding[f] = 1;
    this.group = new THREE.Group();
    const points = tracePoints(motion, ctx.arm, ctx.links, ctx.hand, ctx.lift);
    const line = new THREE.BufferGeometry();
    line.setAttribute('position', new THREE.BufferAttribute(points, 3));
    this.group.add(new THREE.Line(line, new THREE.LineBasicMaterial({ color: 0xb7791f })));
    if (motion.colliding.length > 0) {
      const marks = new Float32Array(motion.colliding.flatMap((f) => [points[3 * f], points[3 * f + 1], points[3 * f + 2]]));
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(marks, 3));
      this.group.add(new THREE.Points(geometry, new THREE.PointsMaterial({ color: 0xe02424, size: 7, sizeAttenuation: false })));
    }
    this.ghosts = new THREE.Group();
    const pose = new Float32Array(this.stride);
    for (const f of evenly(motion.waypoints, MAX_GHOSTS)) {
      const ghost = ctx.makeFigure(0.2);
      ghost.setPose(frameAt(motion.poses, this.stride, motion.frames, f, pose, ctx.arm));
      ghost.setColliding(this.colliding[f] === 1);
      ghost.group.userData.figure = ghost;
      this.ghosts.add(ghost.group);
    }
    this.group.add(this.ghosts);
  }
}

/** Plays and scrubs the motions of a document, moving `figure`. */
export class MotionPlayer {
  constructor(doc, figure, ctx, onFrame) {
    this.figure = figure;
    this.ctx = ctx;
    this.onFrame = onFrame;
    this.drawings = doc.motions.map((m) => new MotionDrawing(m, ctx));
    this.group = new THREE.Group();
    this.index = 0;
    this.frame = 0;
    this.playing = false;
    this.speed = 1;
    if (this.drawings.length > 0) this.setMotion(0);
  }

  get current() { return this.drawings[this.index]; }

  frameCount() { return this.current ? this.current.motion.frames : 0; }

  setMotion(k) {
    if (!this.drawings[k]) return;
    if (this.current) this.group.remove(this.current.group);
    this.index = k;
    this.group.add(this.current.group);
    this.setFrame(0);
  }

  /** Moves to (fractional) frame `f`. */
  setFrame(f) {
    const d = this.current;
    if (!d) return;
    const n = d.motion.frames;
    this.frame = Math.min(Math.max(f, 0), Math.max(n - 1, 0));
    if (n > 0) {
      this.pose ??= new Float32Array(d.stride);
      if (this.pose.length !== d.stride) this.pose = new Float32Array(d.stride);
      this.figure.setPose(frameAt(d.motion.poses, d.stride, n, this.frame, this.pose, this.ctx.arm));
      this.figure.setColliding(d.colliding[Math.round(this.frame)] === 1);
      this.ctx.placeMovers?.(d.motion.mover_positions, n, this.frame);
    }
    this.onFrame(this);
  }

  /** The slider's reading at the current frame: { kind: 'time' | 'fraction', value }. */
  reading() {
    const d = this.current;
    return { kind: d.progress.kind, value: valueOfFrame(d.progress.values, this.frame) };
  }

  /** Advances playback by `dt` seconds: real time for timed motions, a tenth of the path a
   * second otherwise; stops at the end. */
  tick(dt) {
    const d = this.current;
    if (!this.playing || !d) return;
    const values = d.progress.values;
    const rate = d.progress.kind === 'time' ? 1 : 0.1;
    const next = valueOfFrame(values, this.frame) + dt * rate * this.speed;
    if (next >= values[values.length - 1]) this.playing = false;
    this.setFrame(frameOfValue(values, next));
  }

  togglePlay() {
    const d = this.current;
    if (!d) return;
    if (!this.playing && this.frame >= d.motion.frames - 1) this.setFrame(0);
    this.playing = !this.playing;
  }

  setGhosts(visible) {
    for (const d of this.drawings) d.ghosts.visible = visible;
  }

  setMeshes(useMeshes) {
    for (const d of this.drawings) for (const g of d.ghosts.children) g.userData.figure.setMeshes(useMeshes);
  }
}
