import assert from 'node:assert/strict';
import { test } from 'node:test';
import { informedTransform } from '../src/informed.js';

const close = (a, b, eps = 1e-9) => assert.ok(Math.abs(a - b) < eps, `${a} ≉ ${b}`);

// Rotates v by the unit quaternion q = [x, y, z, w].
function rotate([x, y, z, w], v) {
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]), v[2] + w * t[2] + (x * t[1] - y * t[0])];
}

test('centre, semi-axes and the focal axis of the informed set', () => {
  const start = [1, 1, 0];
  const goal = [4, 5, 0]; // d = 5
  const e = informedTransform(start, goal, 13);
  assert.deepEqual(e.centre, [2.5, 3, 0]);
  close(e.semiAxes[0], 6.5);
  close(e.semiAxes[1], 6); // sqrt(169 − 25) / 2
  close(e.semiAxes[2], 6);
  const x = rotate(e.quaternion, [1, 0, 0]);
  close(x[0], 0.6);
  close(x[1], 0.8);
  close(x[2], 0);
  // A point on the surface: the sum of its distances to the foci is the cost.
  const local = [0.3 * 6.5, 0.8 * 6, 0.52 * 6];
  const n = Math.hypot(local[0] / 6.5, local[1] / 6, local[2] / 6);
  const p = rotate(e.quaternion, [local[0] / n, local[1] / n, local[2] / n]).map((v, k) => v + e.centre[k]);
  close(Math.hypot(...p.map((v, k) => v - start[k])) + Math.hypot(...p.map((v, k) => v - goal[k])), 13, 1e-9);
});

test('degenerate cases: opposite axis, one focus, cost below the distance, no cost', () => {
  const back = informedTransform([1, 0, 0], [0, 0, 0], 2);
  const x = rotate(back.quaternion, [1, 0, 0]);
  close(x[0], -1);
  const ball = informedTransform([0, 0, 0], [0, 0, 0], 2);
  assert.deepEqual(ball.quaternion, [0, 0, 0, 1]);
  assert.deepEqual(ball.semiAxes, [1, 1, 1]);
  assert.equal(informedTransform([0, 0, 0], [3, 0, 0], 2).semiAxes[1], 0);
  assert.equal(informedTransform([0, 0, 0], [1, 0, 0], Infinity), null);
  assert.equal(informedTransform([0, 0, 0], [1, 0, 0], 0), null);
});
