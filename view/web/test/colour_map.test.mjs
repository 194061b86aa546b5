import assert from 'node:assert/strict';
import { test } from 'node:test';
import { GREY, colourAt, colourOfCost, costRange, cssGradient } from '../src/colour_map.js';

const luminance = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

test('the map runs from dark to bright, monotonically', () => {
  let last = -1;
  for (let i = 0; i <= 100; i++) {
    const l = luminance(colourAt(i / 100));
    assert.ok(l > last, `luminance falls at ${i / 100}`);
    last = l;
  }
  assert.deepEqual(colourAt(-3), colourAt(0));
  assert.deepEqual(colourAt(7), colourAt(1));
  assert.deepEqual(colourAt(NaN), colourAt(0));
});

test('the range ignores unreached costs; those are grey', () => {
  const costs = new Float32Array([3, 1, 3.4e38, 2, Infinity]);
  assert.deepEqual(costRange(costs), [1, 3]);
  assert.equal(costRange(new Float32Array([3.4e38])), null);
  assert.deepEqual(colourOfCost(3.4e38, [1, 3]), GREY);
  assert.deepEqual(colourOfCost(1, [1, 3]), colourAt(0));
  assert.deepEqual(colourOfCost(3, [1, 3]), colourAt(1));
  assert.deepEqual(colourOfCost(2, [2, 2]), colourAt(0.5));
  assert.match(cssGradient(), /^linear-gradient\(to right, rgb\(68,1,84\) 0%.*100%\)$/);
});
