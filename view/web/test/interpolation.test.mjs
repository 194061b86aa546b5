import assert from 'node:assert/strict';
import { test } from 'node:test';
import { frameAt, frameOfValue, progressOf, slerp, valueOfFrame } from '../src/interpolation.js';

const close = (a, b, eps = 1e-6) => assert.ok(Math.abs(a - b) < eps, `${a} ≉ ${b}`);

test('positions lerp between neighbouring frames', () => {
  const poses = new Float32Array([0, 0, 0, 2, 4, 6, 4, 8, 12]);
  const out = new Float32Array(3);
  frameAt(poses, 3, 3, 0.5, out, false);
  assert.deepEqual(Array.from(out), [1, 2, 3]);
  frameAt(poses, 3, 3, 1.75, out, false);
  assert.deepEqual(Array.from(out), [3.5, 7, 10.5]);
  frameAt(poses, 3, 3, 7, out, false);
  assert.deepEqual(Array.from(out), [4, 8, 12], 'past the end: the last frame');
});

test('quaternions slerp at constant angular speed, the short way round', () => {
  const half = Math.SQRT1_2;
  // Identity to 90° about z; a quarter of the way is 22.5°.
  const q = slerp([0, 0, 0, 1], [0, 0, half, half], 0.25);
  close(q[2], Math.sin(Math.PI / 16));
  close(q[3], Math.cos(Math.PI / 16));
  // The same rotation written with the opposite sign: halfway stays near the identity side.
  const r = slerp([0, 0, 0, 1], [0, 0, -half, -half], 0.5);
  close(r[2], Math.sin(Math.PI / 8));
  close(r[3], Math.cos(Math.PI / 8));
});

test('link poses interpolate position and rotation per link', () => {
  const half = Math.SQRT1_2;
  const poses = new Float32Array([0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, half, half]);
  const out = new Float32Array(7);
  frameAt(poses, 7, 2, 0.5, out, true);
  close(out[0], 1);
  close(out[5], Math.sin(Math.PI / 8));
  close(out[6], Math.cos(Math.PI / 8));
});

test('progress is the times when given, else the fraction of path length', () => {
  const timed = { frames: 3, times: [0, 0.5, 2], joint_names: ['a'], joints: new Float32Array(3), poses: new Float32Array(9) };
  assert.deepEqual(Array.from(progressOf(timed, 3).values), [0, 0.5, 2]);
  assert.equal(progressOf(timed, 3).kind, 'time');
  const path = { frames: 3, times: null, joint_names: ['a', 'b'], joints: new Float32Array([0, 0, 3, 4, 3, 0]), poses: new Float32Array(9) };
  const p = progressOf(path, 3);
  assert.equal(p.kind, 'fraction');
  assert.deepEqual(Array.from(p.values), [0, 5 / 9, 1]);
});

test('the frame of a time and the time of a frame invert each other', () => {
  const values = Float64Array.from([0, 0.5, 2, 2, 3]);
  close(frameOfValue(values, 0.25), 0.5);
  close(frameOfValue(values, 1.25), 1.5);
  close(frameOfValue(values, -1), 0);
  close(frameOfValue(values, 9), 4);
  close(frameOfValue(values, 2.5), 3.5);
  for (const f of [0, 0.5, 1.5, 3.5, 4]) close(valueOfFrame(values, f), [0, 0.25, 1.25, 2.5, 3][[0, 0.5, 1.5, 3.5, 4].indexOf(f)]);
  for (const v of [0.1, 0.9, 2.7]) close(valueOfFrame(values, frameOfValue(values, v)), v);
});
