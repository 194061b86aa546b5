import assert from 'node:assert/strict';
import { test } from 'node:test';

import { evenly } from '../src/motion.js';

test('ghosts: at most the cap, evenly chosen, first and last kept', () => {
  const frames = Array.from({ length: 100 }, (_, i) => i * 10);
  const chosen = evenly(frames, 16);
  assert.equal(chosen.length, 16);
  assert.equal(chosen[0], 0);
  assert.equal(chosen[15], 990);
  assert.deepEqual(evenly([1, 2, 3], 16), [1, 2, 3]);
  for (let k = 1; k < chosen.length; k++) assert.ok(chosen[k] > chosen[k - 1]);
});
