// The thread setting: the module is single-threaded, so it accepts a setting and reports 1.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, HedgeError, grid } from './support.mjs';

test('maxThreads reports 1 whatever setMaxThreads was given', () => {
  assert.equal(hedge.maxThreads(), 1);
  for (const n of [0, 1, 2, 16]) {
    hedge.setMaxThreads(n);
    assert.equal(hedge.maxThreads(), 1);
  }
  const mesh = grid(4);
  mesh.subdivide('loop', 1);
  assert.deepEqual(mesh.validate(), []);
  mesh.dispose();
});

test('setMaxThreads refuses what is not a whole number >= 0', () => {
  for (const n of [-1, 1.5, NaN, '2', undefined]) {
    assert.throws(
      () => hedge.setMaxThreads(n),
      (e) =>
        e instanceof HedgeError && e.kind === 'invalid-argument' && /setMaxThreads/.test(e.message),
    );
  }
});
